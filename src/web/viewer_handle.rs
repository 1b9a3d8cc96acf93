//! The page's main viewer, wherever it runs: in a worker that draws on the canvas the page
//! handed over (`drawing_worker.rs`), so that the page's thread only handles input and the page,
//! or, where a module worker cannot draw (no `OffscreenCanvas`, no WebGL2 on one, as in WebKit
//! before Safari 17; `view=page` in the address's query), the same [`Viewer`] on the page's own
//! thread, drawing on the canvas element itself. The page talks to both the same way: commands
//! in, the device's state and each frame's report out.

use super::canvases::hand_over;
use super::clock::now;
use super::debug::Loss;
use super::scope;
use super::viewer::Viewer;
use super::webcodecs::VideoFrame;
use crate::render::Canvas;
use crate::view::drawn_in::DrawnIn;
use crate::work::message::{Reply, Request};
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_inbox::{Inbox, Taken};
use crate::work::viewer_message::encode_command;
use crate::work::viewer_status::Device;
use js_sys::{Array, Promise, Reflect, Uint8Array};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;
use web_sys::{
    ErrorEvent, HtmlCanvasElement, MessageEvent, OffscreenCanvas, Worker, WorkerOptions, WorkerType,
};

/// Milliseconds the drawing worker is given to open its renderer (it loads the WebAssembly
/// module first) before the page draws on its own thread.
const START_MS: i32 = 20_000;

/// The main viewer in a worker, as the page sees it.
pub struct DrawingWorker {
    worker: Worker,
    inbox: Rc<RefCell<Inbox<VideoFrame>>>,
    backend: String,
    /// It panicked (and the page shows so).
    crashed: bool,
    _on_message: Closure<dyn FnMut(MessageEvent)>,
    _on_error: Closure<dyn FnMut(ErrorEvent)>,
}

/// The page's main viewer.
pub enum ViewerHandle {
    /// On the page's own thread.
    Here(Box<Viewer>),
    /// In a worker.
    Worker(DrawingWorker),
}

/// Whether a worker can draw here: module workers can hold an `OffscreenCanvas`.
pub fn worker_draws() -> bool {
    let has = |name: &str| Reflect::has(&js_sys::global(), &name.into()).unwrap_or(false);
    has("OffscreenCanvas") && has("Worker")
}

impl DrawingWorker {
    /// Starts the drawing worker on `canvas` (transferred to it) and waits until it has opened
    /// its renderer: the backend, or why it could not.
    pub async fn start(
        canvas: OffscreenCanvas,
        planar: bool,
        background: [u8; 3],
    ) -> Result<Self, String> {
        let options = WorkerOptions::new();
        options.set_type(WorkerType::Module);
        options.set_name("seashells-drawing");
        // The page's query goes with it: the worker's pool reads its switches (`workers=N`).
        let url = format!("./drawing-worker.js{}", scope::search());
        let worker = Worker::new_with_options(&url, &options)
            .map_err(|_| "the drawing worker could not start".to_string())?;
        let inbox: Rc<RefCell<Inbox<VideoFrame>>> = Rc::default();
        let opened: Rc<RefCell<Option<js_sys::Function>>> = Rc::default();
        let wait = Promise::new(&mut |resolve, _| *opened.borrow_mut() = Some(resolve));
        let (to, wake) = (Rc::clone(&inbox), Rc::clone(&opened));
        let on_message = Closure::<dyn FnMut(MessageEvent)>::new(move |e: MessageEvent| {
            let data = e.data();
            let bytes = Reflect::get(&data, &"news".into()).unwrap_or(JsValue::UNDEFINED);
            let frame = Reflect::get(&data, &"frame".into())
                .ok()
                .filter(|f| !f.is_undefined())
                .map(JsCast::unchecked_into::<VideoFrame>);
            let heard = (to.borrow_mut()).heard(&Uint8Array::new(&bytes).to_vec(), frame, now());
            // The answer to opening, or a message misread (the worker's failure, which the
            // start or the next frame goes through), ends the wait.
            if heard != Ok(false)
                && let Some(resolve) = wake.borrow_mut().take()
            {
                let _ = resolve.call0(&JsValue::NULL);
            }
        });
        let wake = Rc::clone(&opened);
        scope::after(START_MS, move || {
            if let Some(resolve) = wake.borrow_mut().take() {
                let _ = resolve.call0(&JsValue::NULL);
            }
        });
        let (to, wake) = (Rc::clone(&inbox), Rc::clone(&opened));
        let on_error = Closure::<dyn FnMut(ErrorEvent)>::new(move |e: ErrorEvent| {
            e.prevent_default();
            (to.borrow_mut()).failed(format!("the drawing worker failed: {}", e.message()));
            if let Some(resolve) = wake.borrow_mut().take() {
                let _ = resolve.call0(&JsValue::NULL);
            }
        });
        worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
        worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
        let init = js_sys::Object::new();
        let _ = Reflect::set(&init, &"canvas".into(), &canvas);
        let _ = Reflect::set(&init, &"planar".into(), &planar.into());
        let _ = Reflect::set(
            &init,
            &"background".into(),
            &Uint8Array::from(&background[..]),
        );
        let message = js_sys::Object::new();
        let _ = Reflect::set(&message, &"init".into(), &init);
        worker
            .post_message_with_transfer(&message, &Array::of1(&canvas))
            .map_err(|_| "the canvas could not be handed to the drawing worker".to_string())?;
        let _ = JsFuture::from(wait).await;
        let mut this = Self {
            worker,
            inbox,
            backend: String::new(),
            crashed: false,
            _on_message: on_message,
            _on_error: on_error,
        };
        let opened = this.inbox.borrow_mut().opened(START_MS / 1000);
        this.backend = opened?;
        Ok(this)
    }

    fn post(&self, message: &js_sys::Object, transfer: &Array) {
        // A worker that cannot take a message has failed: its error event says so.
        let _ = self.worker.post_message_with_transfer(message, transfer);
    }

    fn command(&mut self, command: &ViewCommand) {
        let bytes = Uint8Array::from(&encode_command(command)[..]).buffer();
        let message = js_sys::Object::new();
        let _ = Reflect::set(&message, &"command".into(), &bytes);
        self.post(&message, &Array::of1(&bytes));
    }

    fn debug(&self, ask: &str, ms: Option<i32>) {
        let message = js_sys::Object::new();
        let _ = Reflect::set(&message, &"debug".into(), &ask.into());
        if let Some(ms) = ms {
            let _ = Reflect::set(&message, &"ms".into(), &ms.into());
        }
        self.post(&message, &Array::new());
    }
}

impl Drop for DrawingWorker {
    fn drop(&mut self) {
        self.worker.set_onmessage(None);
        self.worker.set_onerror(None);
        self.worker.terminate();
    }
}

impl ViewerHandle {
    /// "WebGPU" or "WebGL2", or `None` where the viewer draws nothing.
    pub fn backend(&self) -> Option<String> {
        match self {
            ViewerHandle::Here(viewer) => viewer.backend().map(str::to_string),
            ViewerHandle::Worker(w) => Some(w.backend.clone()),
        }
    }

    /// Where it draws.
    pub fn drawn_in(&self) -> DrawnIn {
        match self {
            ViewerHandle::Worker(_) => DrawnIn::Worker,
            ViewerHandle::Here(viewer) if viewer.backend().is_some() => DrawnIn::Page,
            ViewerHandle::Here(_) => DrawnIn::Nowhere,
        }
    }

    /// Asks the viewer `command`.
    pub fn command(&mut self, command: ViewCommand) {
        match self {
            ViewerHandle::Here(viewer) => viewer.command(command),
            ViewerHandle::Worker(w) => w.command(&command),
        }
    }

    /// The state of the viewer's device (in a worker, as it said last; a panic there is
    /// shown as the page's own).
    pub fn survive(&mut self) -> Device {
        match self {
            ViewerHandle::Here(viewer) => viewer.survive(),
            ViewerHandle::Worker(w) => {
                let device = w.inbox.borrow_mut().device();
                if let Device::Reopened(backend) = &device {
                    w.backend.clone_from(backend);
                }
                device
            }
        }
    }

    /// Whether the viewer panicked in its worker: the page then shows the panic's message, as
    /// its own panic would, and does nothing more (the page's thread cannot panic with it).
    pub fn crashed(&mut self) -> bool {
        let ViewerHandle::Worker(w) = self else {
            return false;
        };
        if w.crashed {
            return true;
        }
        let Some(message) = w.inbox.borrow().crash().map(str::to_string) else {
            return false;
        };
        w.crashed = true;
        web_sys::console::error_1(&message.clone().into());
        super::page::show_crash(&message);
        true
    }

    /// Ends the page's frame: a viewer in a worker runs its own on it, after the commands the
    /// page's frame sent.
    pub fn tick(&mut self) {
        if let ViewerHandle::Worker(w) = self {
            w.inbox.borrow_mut().ticked(now());
            let message = js_sys::Object::new();
            let _ = Reflect::set(&message, &"tick".into(), &JsValue::TRUE);
            w.post(&message, &Array::new());
        }
    }

    /// The fresh canvas element the viewer asked for ([`Device::NeedsCanvas`]): drawn on as
    /// it is on the page's thread, handed over to a drawing worker.
    pub fn give_canvas(&mut self, element: HtmlCanvasElement) -> Result<(), String> {
        match self {
            ViewerHandle::Here(viewer) => viewer.give_canvas(Canvas::Element(element)),
            ViewerHandle::Worker(w) => {
                let canvas = hand_over(&element)?;
                let message = js_sys::Object::new();
                let _ = Reflect::set(&message, &"canvas".into(), &canvas);
                w.post(&message, &Array::of1(&canvas));
            }
        }
        Ok(())
    }

    /// Fails, in words, when the drawing worker's renderer failed or the worker fell silent
    /// ([`crate::work::viewer_inbox::Inbox::answering`]), its news left for [`Self::frames`].
    pub fn answering(&self) -> Result<(), String> {
        match self {
            ViewerHandle::Here(_) => Ok(()),
            ViewerHandle::Worker(w) => {
                (w.inbox.borrow().answering(now())).map_err(|e| e.to_string())
            }
        }
    }

    /// The viewer's frames since the page's last: on the page's thread, runs one (after the
    /// page took in the pool's replies); in a worker, what it sent. Fails with the words to
    /// show when its renderer failed.
    pub fn frames(&mut self) -> Result<Taken<VideoFrame>, String> {
        match self {
            ViewerHandle::Here(viewer) => Ok(Taken {
                frames: vec![viewer.run_frame()?],
                ..Taken::default()
            }),
            ViewerHandle::Worker(w) => {
                (w.inbox.borrow_mut().take(now())).map_err(|e| e.to_string())
            }
        }
    }

    /// Takes in the replies of the page's pool about the viewer's shell, and resumes it when
    /// the worker holding it was replaced (on the page's thread; a viewer in a worker has a
    /// pool of its own). Fails with the words to show.
    pub fn take_all(
        &mut self,
        replies: Vec<(Request, Reply)>,
        sessions_lost: Option<Vec<Request>>,
    ) -> Result<(), String> {
        match self {
            ViewerHandle::Here(viewer) => viewer.take_all(replies, sessions_lost),
            ViewerHandle::Worker(_) => Ok(()),
        }
    }

    /// Test-only (see `debug.rs`): takes the viewer's graphics device away.
    pub fn take_device(&self, loss: Loss) -> Result<(), String> {
        match self {
            ViewerHandle::Here(viewer) => viewer.take_device(loss),
            ViewerHandle::Worker(w) => {
                match loss {
                    Loss::Destroy => w.debug("destroy", None),
                    Loss::Context { restore_after_ms } => w.debug("lose", restore_after_ms),
                }
                Ok(())
            }
        }
    }

    /// Test-only (see `debug.rs`): passes a hook that acts where the viewer grows (a panic
    /// while growing, a worker that throws on a preview's rows) to a drawing worker; on the
    /// page's thread the hook has acted already.
    pub fn forward_debug(&self, ask: &str) {
        if let ViewerHandle::Worker(w) = self {
            w.debug(ask, None);
        }
    }
}
