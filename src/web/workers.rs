//! The page's workers: a pool of Web Workers (`www/worker.js`, one per core but the page's own,
//! at most eight; `workers=N` in the address's query sets another number, for tests and
//! benchmarks), each running the core's host, with the core's [`Pool`] sharing requests out.
//! Requests and replies cross as bytes in transferred `ArrayBuffer`s. A worker that throws, or
//! keeps a request past its allowance, is terminated and replaced, and its jobs are sent again;
//! from the second time the page's status line says so ([`Replaced::words`]). A reply is read
//! (copied and decoded) in its `message` event as it comes; one of megabytes is taken in a
//! frame later, so that reading it and taking it in fall in different frames (see
//! [`crate::view::draw_pacing`]). Where workers cannot start (or with `workers=0`), one host
//! runs on the thread of the pool's owner (the page's, or the worker that draws the view) a
//! frame's budget at a time, and [`Workers::status`] says so.
//! Nothing here writes on the page: the page shows what these return. The pool's size and its
//! test-only faults come from the address's query, as [`PoolPlan`] reads it;
//! `debug_crash_worker_on_fill` (`debug.rs`) makes the worker holding the sessions throw when
//! next asked for rows of a previewed pattern.

use super::clock::now;
use super::debug;
use super::scope;
use crate::view::draw_pacing::HEAVY_BYTES;
use crate::work::host::{Budget, Host};
use crate::work::message::{Request, decode_reply, encode_request};
use crate::work::pool::{
    Faults, Polled, Pool, PoolPlan, Replaced, SESSIONS, WorkerEvent, given_up_status, local_status,
};
use crate::work::viewer_driver::PoolWorkers;
use js_sys::{Array, Uint8Array};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{ErrorEvent, MessageEvent, Worker, WorkerOptions, WorkerType};

type Inbox = Rc<RefCell<Vec<WorkerEvent>>>;

/// One Web Worker with its listeners.
struct Slot {
    worker: Worker,
    _on_message: Closure<dyn FnMut(MessageEvent)>,
    _on_error: Closure<dyn FnMut(ErrorEvent)>,
}

impl Drop for Slot {
    fn drop(&mut self) {
        self.worker.set_onmessage(None);
        self.worker.set_onerror(None);
        self.worker.terminate();
    }
}

/// Where requests are worked on.
enum Backend {
    Workers {
        slots: Vec<Slot>,
        inbox: Inbox,
        faults: Faults,
    },
    /// The page's own thread.
    Local(Box<Host>),
}

pub struct Workers {
    pool: Pool,
    backend: Backend,
    /// Milliseconds of a frame the page's own thread may work, without workers.
    budget_ms: f64,
    /// Least milliseconds a worker is given to grow the shell per request (`grow-budget=N` in
    /// the query sets another, for benchmarks).
    worker_growth_ms: f64,
    /// Where the shells grow, in words for the status line.
    status: String,
}

/// Starts a worker named `name` for slot `slot` in generation `generation`, its events going
/// to `inbox`.
fn spawn(slot: usize, generation: u32, inbox: &Inbox, name: &str) -> Result<Slot, JsValue> {
    let options = WorkerOptions::new();
    options.set_type(WorkerType::Module);
    options.set_name(name);
    let worker = Worker::new_with_options("./worker.js", &options)?;
    let to = Rc::clone(inbox);
    let on_message = Closure::<dyn FnMut(MessageEvent)>::new(move |e: MessageEvent| {
        let bytes = Uint8Array::new(&e.data()).to_vec();
        to.borrow_mut().push(WorkerEvent::Reply {
            slot,
            generation,
            reply: Box::new(decode_reply(&bytes)),
            heavy: bytes.len() > HEAVY_BYTES,
        });
    });
    let to = Rc::clone(inbox);
    let on_error = Closure::<dyn FnMut(ErrorEvent)>::new(move |e: ErrorEvent| {
        e.prevent_default();
        to.borrow_mut().push(WorkerEvent::Died {
            slot,
            generation,
            why: e.message(),
        });
    });
    worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
    Ok(Slot {
        worker,
        _on_message: on_message,
        _on_error: on_error,
    })
}

impl Workers {
    /// The pool this browser gets, or the page's own thread where workers cannot start.
    pub fn start(budget_ms: f64) -> Self {
        let plan = PoolPlan::from_query(scope::query, scope::cores());
        let (size, mut faults) = (plan.size, plan.faults);
        let local = |why: &str| Self {
            pool: Pool::new(1),
            backend: Backend::Local(Box::default()),
            budget_ms,
            worker_growth_ms: budget_ms,
            status: local_status(scope::thread_name(), why),
        };
        if size == 0 {
            return local("workers are off (workers=0 in the address)");
        }
        let inbox: Inbox = Rc::default();
        let mut slots = Vec::new();
        for slot in 0..size {
            match spawn(slot, 0, &inbox, faults.next_name()) {
                Ok(s) => slots.push(s),
                Err(e) => {
                    let why = e
                        .as_string()
                        .or_else(|| e.dyn_ref::<js_sys::Error>().map(|e| e.message().into()))
                        .unwrap_or_else(|| "this browser cannot start workers".into());
                    return local(&format!("workers could not start ({why})"));
                }
            }
        }
        Self {
            status: plan.status(),
            pool: Pool::new(size).with_patience(plan.patience),
            backend: Backend::Workers {
                slots,
                inbox,
                faults,
            },
            budget_ms,
            worker_growth_ms: plan.worker_growth_ms,
        }
    }

    /// The workers in the pool: 0 on the page's own thread.
    pub fn count(&self) -> usize {
        match &self.backend {
            Backend::Workers { slots, .. } => slots.len(),
            Backend::Local(_) => 0,
        }
    }

    /// Where the shells grow, in words for the status line.
    pub fn status(&self) -> &str {
        &self.status
    }

    /// Asks for `request` (sent in the next [`Self::poll`]).
    pub fn submit(&mut self, request: Request) {
        self.pool.submit(request);
    }

    /// Drops the jobs not yet sent that `drop` picks.
    pub fn cancel(&mut self, drop: impl FnMut(&Request) -> bool) {
        self.pool.cancel(drop);
    }

    /// Workers cannot run here: the pool's owner's thread takes their work (a frame's budget
    /// at a time); the pool has handed back the sessions they held, to be grown again there.
    fn run_here(&mut self, polled: &mut Polled, why: String) {
        self.backend = Backend::Local(Box::default());
        self.worker_growth_ms = self.budget_ms;
        self.status = given_up_status(scope::thread_name(), &why);
        polled.replaced = Some(Replaced {
            deaths: self.pool.deaths(),
            why,
            given_up: Some(self.status.clone()),
        });
    }
}

impl PoolWorkers for Workers {
    /// Sends what waits, replaces workers that died or hang, and returns what came back, as
    /// the pool's rules take its workers' events in ([`Pool::take_events`]).
    fn poll(&mut self) -> Polled {
        self.send();
        let Self {
            pool,
            backend,
            budget_ms,
            ..
        } = self;
        let (slots, inbox, faults) = match backend {
            Backend::Local(host) => {
                let mut polled = Polled::default();
                for (ticket, reply) in host.work(&now, Budget::Until(now() + *budget_ms)) {
                    if let Some(request) = pool.answered(SESSIONS, ticket, now()) {
                        polled.replies.push((request, reply));
                    }
                }
                return polled;
            }
            Backend::Workers {
                slots,
                inbox,
                faults,
            } => (slots, inbox, faults),
        };
        let mut events = std::mem::take(&mut *inbox.borrow_mut());
        let mut polled = pool.take_events(&mut events, now());
        // What came while the events were taken in follows what waits for the next frame.
        let mut held = inbox.borrow_mut();
        events.append(&mut held);
        *held = events;
        drop(held);
        for (slot, generation, why) in std::mem::take(&mut polled.start) {
            web_sys::console::info_1(
                &format!("Worker {slot} of the pool was replaced: {why}.").into(),
            );
            // A worker that cannot start is found out by its silence, as a hung one.
            if let Ok(fresh) = spawn(slot, generation, inbox, faults.next_name()) {
                slots[slot] = fresh;
            }
        }
        if let Some(why) = polled.given_up.clone() {
            self.run_here(&mut polled, why);
        }
        polled
    }

    /// The least milliseconds one request grows the shell for: none on the page's thread (a
    /// frame's budget), the plan's least growth on a worker ([`PoolPlan`]).
    fn min_growth_ms(&self) -> f64 {
        match self.backend {
            Backend::Local(_) => 0.0,
            Backend::Workers { .. } => self.worker_growth_ms,
        }
    }

    /// The pool the requests wait in, for the core's rules to submit to.
    fn pool(&mut self) -> &mut Pool {
        &mut self.pool
    }

    /// Sends what waits: called at the end of each frame, so that a request asked in a frame
    /// is worked on while the page waits for the next, not a frame later.
    fn send(&mut self) {
        let sends = self.pool.dispatch(now());
        match &mut self.backend {
            Backend::Local(host) => {
                for send in sends {
                    host.push(send.ticket, send.request);
                }
            }
            Backend::Workers { slots, .. } => {
                for send in sends {
                    let fill = matches!(send.request, Request::Fill { .. });
                    let bytes = if fill && debug::crash_on_fill_asked() {
                        // Bytes no worker can read: it throws, as a worker that fails would.
                        Vec::new()
                    } else {
                        encode_request(send.ticket, &send.request)
                    };
                    let buffer = Uint8Array::from(&bytes[..]).buffer();
                    let transfer = Array::of1(&buffer);
                    // A worker that cannot take a message is found out by its silence.
                    let _ = slots[send.slot]
                        .worker
                        .post_message_with_transfer(&buffer, &transfer);
                }
            }
        }
    }
}
