//! Opening a drawing device again after the browser took one away, on the canvas the core's
//! [`Survival`] asks for (the same one, or a fresh one the page made in its place); the shell
//! itself lives outside the renderer and is uploaded again by the viewer.
//!
//! [`Survival`]: crate::work::device_survival::Survival

use crate::render::{Canvas, Renderer};
use std::cell::RefCell;
use std::rc::Rc;

/// A renderer opened again, and the canvas it draws on (the old one, or a fresh one).
pub struct Reopened {
    pub renderer: Renderer,
    pub canvas: Canvas,
}

/// An attempt to open a renderer, answered in the background (opening a device takes the
/// browser's time).
pub type Attempt = Rc<RefCell<Option<Result<Reopened, String>>>>;

/// Starts opening a renderer on `canvas`.
pub fn attempt(canvas: Canvas) -> Attempt {
    let slot: Attempt = Rc::default();
    let filled = Rc::clone(&slot);
    wasm_bindgen_futures::spawn_local(async move {
        let opened = Renderer::new(&canvas)
            .await
            .map(|renderer| Reopened { renderer, canvas });
        *filled.borrow_mut() = Some(opened);
    });
    slot
}
