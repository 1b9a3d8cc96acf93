//! The entry of a Web Worker (`www/worker.js` loads this same module): it runs a
//! [`Host`] with the worker's whole thread, reading each request from the bytes the page sent
//! and answering with the bytes of its replies, each in its own `ArrayBuffer` for the script
//! to transfer back (no copy of a mesh on the way).

use super::clock::now;
use crate::work::host::{Budget, Host};
use crate::work::message::{decode_request, encode_reply};
use js_sys::{Array, Uint8Array};
use wasm_bindgen::prelude::*;

/// The benchmark's figures of one core (`crate::bench::one_core`), as text: run by `make
/// bench` on a worker and on the page's thread of the same browser, to compare them.
#[wasm_bindgen]
pub fn benchmark_one_core() -> String {
    crate::bench::report(&crate::bench::one_core(&now))
}

/// What a worker holds: its host.
#[wasm_bindgen]
#[derive(Default)]
pub struct WorkerHost {
    host: Host,
}

#[wasm_bindgen]
impl WorkerHost {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Self {
        Self::default()
    }

    /// Answers the request in `bytes`: the replies' bytes, one `ArrayBuffer` each.
    pub fn handle(&mut self, bytes: &[u8]) -> Result<Array, JsValue> {
        let (ticket, request) =
            decode_request(bytes).map_err(|e| JsValue::from_str(&e.to_string()))?;
        self.host.push(ticket, request);
        let replies = Array::new();
        for (ticket, reply) in self.host.work(&now, Budget::Unbounded) {
            replies.push(&Uint8Array::from(&encode_reply(ticket, &reply)[..]).buffer());
        }
        Ok(replies)
    }
}
