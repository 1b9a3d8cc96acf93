//! Opening a drawing device again after the browser took one away (a WebGPU device lost or
//! destroyed, a driver reset, a WebGL context lost). The new renderer is opened on the same
//! canvas when its context can still be had (WebGPU's, or a WebGL context the browser gave
//! back); otherwise, or when that fails — WebGPU gone for good, so only WebGL2 is left, which a
//! canvas that once had a WebGPU context cannot give —, on a fresh copy of the canvas that takes
//! its place in the page. The shell itself lives outside the renderer and is uploaded again by
//! the viewer.

use super::view_canvas::ViewCanvas;
use crate::render::Renderer;
use std::cell::RefCell;
use std::rc::Rc;

/// Milliseconds a lost WebGL context is given to come back before a fresh canvas is used.
pub const RESTORE_WAIT_MS: f64 = 1500.0;

/// A renderer opened again, and the canvas it draws on (the old one, or its fresh copy).
pub struct Reopened {
    pub renderer: Renderer,
    pub canvas: ViewCanvas,
}

/// A renderer being opened, in the background (opening a device takes the browser's time).
pub struct Reopening {
    slot: Rc<RefCell<Option<Result<Reopened, String>>>>,
}

impl Reopening {
    /// Starts opening a renderer for `canvas`; with `fresh`, on a copy of it at once.
    pub fn start(canvas: ViewCanvas, fresh: bool) -> Self {
        let slot = Rc::new(RefCell::new(None));
        let filled = Rc::clone(&slot);
        wasm_bindgen_futures::spawn_local(async move {
            let opened = reopen(canvas, fresh).await;
            *filled.borrow_mut() = Some(opened);
        });
        Self { slot }
    }

    /// The renderer, or why none could be opened, once the browser has answered.
    pub fn take(&self) -> Option<Result<Reopened, String>> {
        self.slot.borrow_mut().take()
    }
}

async fn reopen(canvas: ViewCanvas, fresh: bool) -> Result<Reopened, String> {
    let mut first = None;
    if !fresh {
        match Renderer::new(canvas.offscreen.clone()).await {
            Ok(renderer) => return Ok(Reopened { renderer, canvas }),
            Err(e) => first = Some(e),
        }
    }
    let canvas = canvas.fresh_copy()?;
    match Renderer::new(canvas.offscreen.clone()).await {
        Ok(renderer) => Ok(Reopened { renderer, canvas }),
        Err(e) => Err(match first {
            Some(first) => format!("{first} On a fresh canvas: {e}"),
            None => e,
        }),
    }
}
