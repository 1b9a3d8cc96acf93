//! Opening a drawing device again after the browser took one away (a WebGPU device lost or
//! destroyed, a driver reset, a WebGL context lost). The new renderer is opened on the same
//! canvas when its context can still be had (WebGPU's, or a WebGL context the browser gave
//! back); otherwise, or when that fails — WebGPU gone for good, so only WebGL2 is left, which a
//! canvas that once had a WebGPU context cannot give —, on a fresh canvas, which the page makes
//! (a copy of its element taking the old one's place) and gives: the viewer touches no element,
//! so that it can draw in a worker. The shell itself lives outside the renderer and is uploaded
//! again by the viewer.

use crate::render::{Canvas, Renderer};
use std::cell::RefCell;
use std::rc::Rc;

/// Milliseconds a lost WebGL context is given to come back before a fresh canvas is used.
pub const RESTORE_WAIT_MS: f64 = 1500.0;

/// A renderer opened again, and the canvas it draws on (the old one, or a fresh one).
pub struct Reopened {
    pub renderer: Renderer,
    pub canvas: Canvas,
}

/// An attempt to open a renderer, answered in the background (opening a device takes the
/// browser's time).
type Attempt = Rc<RefCell<Option<Result<Reopened, String>>>>;

/// Where the reopening stands.
enum Stage {
    /// Opening on the same canvas.
    Same(Attempt),
    /// Waiting for the page's fresh canvas; why the same one failed, if it was tried.
    NeedsCanvas(Option<String>),
    /// Opening on the fresh canvas; why the same one failed, if it was tried.
    Fresh(Attempt, Option<String>),
}

/// A renderer being opened again.
pub struct Reopening {
    stage: Stage,
}

fn attempt(canvas: Canvas) -> Attempt {
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

impl Reopening {
    /// Starts opening a renderer for `canvas`; with `fresh`, asks for a fresh canvas at once.
    pub fn start(canvas: Canvas, fresh: bool) -> Self {
        Self {
            stage: if fresh {
                Stage::NeedsCanvas(None)
            } else {
                Stage::Same(attempt(canvas))
            },
        }
    }

    /// Whether it waits for a fresh canvas ([`Self::give_canvas`]).
    pub fn needs_canvas(&self) -> bool {
        matches!(self.stage, Stage::NeedsCanvas(_))
    }

    /// The fresh canvas asked for: the renderer is opened on it.
    pub fn give_canvas(&mut self, canvas: Canvas) {
        if let Stage::NeedsCanvas(first) = &mut self.stage {
            self.stage = Stage::Fresh(attempt(canvas), first.take());
        }
    }

    /// The renderer, or why none could be opened, once the browser has answered (a failure on
    /// the same canvas asks for a fresh one instead).
    pub fn take(&mut self) -> Option<Result<Reopened, String>> {
        match &mut self.stage {
            Stage::Same(slot) => {
                let opened = slot.borrow_mut().take()?;
                match opened {
                    Ok(reopened) => Some(Ok(reopened)),
                    Err(e) => {
                        self.stage = Stage::NeedsCanvas(Some(e));
                        None
                    }
                }
            }
            Stage::NeedsCanvas(_) => None,
            Stage::Fresh(slot, first) => {
                let opened = slot.borrow_mut().take()?;
                Some(opened.map_err(|e| match first.take() {
                    Some(first) => format!("{first} On a fresh canvas: {e}"),
                    None => e,
                }))
            }
        }
    }
}
