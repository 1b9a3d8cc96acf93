//! Where the main view is drawn, and keeping it drawn: a lost graphics device kept (a fresh
//! canvas where the old cannot be drawn on again), the drawing worker giving way to the page's
//! thread, and a viewer that draws nothing where none can; the size the canvas is shown at.

use super::{App, Moving, show_backend, show_drawn_in};
use crate::render::Canvas;
use crate::view::drawn_in::DrawnIn;
use crate::web::canvases::replace;
use crate::web::debug::Loss;
use crate::web::page::{self, show_message};
use crate::web::shown_size::ShownSize;
use crate::web::viewer::Viewer;
use crate::web::viewer_handle::ViewerHandle;
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_status::Device;
use std::cell::RefCell;
use std::rc::Rc;
use web_sys::HtmlCanvasElement;

impl App {
    /// Test-only (see `debug.rs`): takes both graphics devices away, the main viewer's and the
    /// gallery pictures', as a driver reset or the browser would.
    pub fn take_devices(&self, loss: Loss) -> Result<(), String> {
        self.viewer.take_device(loss)?;
        self.pictures.take_device(loss)
    }

    /// Test-only (see `debug.rs`): passes a hook that acts where the viewer grows on to a
    /// viewer drawing in a worker.
    pub fn forward_debug(&self, ask: &str) {
        self.viewer.forward_debug(ask);
    }

    /// Keeps the main viewer's graphics device, saying in words when it was lost and when it
    /// is back; returns whether the frame may draw.
    pub(super) fn survive(&mut self) -> Result<bool, String> {
        let device = match self.viewer.survive() {
            Device::NeedsCanvas(reason) => {
                // The canvas cannot be drawn on again: a fresh copy takes its place.
                let fresh = replace("shell")?;
                self.viewer.give_canvas(fresh.clone())?;
                self.canvas_replaced(&fresh);
                self.replaced_canvas = Some(fresh);
                Device::Reopening(reason)
            }
            device => device,
        };
        let draws = self.session.device(device);
        self.apply();
        draws
    }

    /// The main viewer cannot draw where it is (`why`): the drawing worker gives way to the
    /// page's thread, on a fresh canvas, and a viewer on the page's thread to none that draws
    /// (the shell grows, its pattern shows and its files are written all the same). Said in
    /// words; growth starts again from the apex.
    pub(super) fn fall_back(&mut self, why: String) {
        let moved = self.viewer.drawn_in().fall_back(&why, true);
        if let Some(log) = &moved.log {
            web_sys::console::info_1(&log.into());
        }
        if moved.to == DrawnIn::Nowhere {
            self.without_3d(moved.no_3d.as_deref().unwrap_or(&why));
            return;
        }
        if let Some(words) = moved.say {
            show_message(words);
        }
        let element = match replace("shell") {
            Ok(element) => element,
            Err(e) => {
                self.without_3d(&format!("{why}; {e}"));
                return;
            }
        };
        let opened: Rc<RefCell<Option<Result<Viewer, String>>>> = Rc::default();
        let (slot, canvas, workers) = (
            Rc::clone(&opened),
            Canvas::Element(element.clone()),
            Rc::clone(&self.workers),
        );
        wasm_bindgen_futures::spawn_local(async move {
            let viewer = Viewer::new(canvas, true, page::background(), true, workers).await;
            *slot.borrow_mut() = Some(viewer);
        });
        self.moving = Some(Moving { element, opened });
    }

    /// No viewer can draw here (`why`): one that draws nothing takes the main viewer's place,
    /// and the page says so in the words of its `#no-3d` notice.
    fn without_3d(&mut self, why: &str) {
        page::show_no_3d(why);
        let viewer = Viewer::without_drawing(true, page::background(), Rc::clone(&self.workers));
        self.install(ViewerHandle::Here(Box::new(viewer)), None);
    }

    /// Takes the viewer opened on the page's thread once the browser has answered (or, when it
    /// could not be opened, one that draws nothing).
    pub(super) fn take_moved(&mut self) {
        let Some(moving) = &self.moving else { return };
        let Some(opened) = moving.opened.borrow_mut().take() else {
            return;
        };
        let Some(Moving { element, .. }) = self.moving.take() else {
            return;
        };
        match opened {
            Ok(viewer) => self.install(ViewerHandle::Here(Box::new(viewer)), Some(element)),
            Err(why) => {
                self.without_3d(&why);
            }
        }
    }

    /// Puts `viewer` in the old one's place (drawing on `element`, a fresh canvas of the page,
    /// if it draws) and tells it what the page told the old one: the layout, the background,
    /// the shell shown, grown again from its apex. A recording or a file under way is dropped.
    fn install(&mut self, viewer: ViewerHandle, element: Option<HtmlCanvasElement>) {
        self.stop_recording("the view moved to another thread");
        self.downloads
            .abandon("the view moved to another thread; ask for the file again");
        self.viewer = viewer;
        show_backend(self.viewer.backend());
        show_drawn_in(&self.viewer);
        if let Some(element) = element {
            self.canvas_replaced(&element);
            self.replaced_canvas = Some(element);
        }
        self.session.viewer_replaced(page::background());
        self.apply();
    }

    /// Tells the viewer the size its canvas is shown at, when the page's layout or the pixel
    /// ratio changed it.
    pub(super) fn tell_shown(&mut self) {
        let Some(shown) = &self.shown else { return };
        let (width, height) = shown.css();
        let pixel_ratio = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        if (width, height, pixel_ratio) != self.told_shown {
            self.told_shown = (width, height, pixel_ratio);
            self.viewer.command(ViewCommand::Shown {
                width,
                height,
                pixel_ratio,
            });
        }
    }

    /// A fresh canvas that took the main viewer's old one's place since the last call: the
    /// page listens to it instead.
    pub fn take_replaced_canvas(&mut self) -> Option<HtmlCanvasElement> {
        self.replaced_canvas.take()
    }

    /// A fresh canvas took the main viewer's place (a lost device opened again): its size is
    /// observed instead.
    fn canvas_replaced(&mut self, canvas: &HtmlCanvasElement) {
        self.shown = ShownSize::observe(canvas).ok();
        self.told_shown = (0, 0, 0.0);
    }
}
