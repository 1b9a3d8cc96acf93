//! The canvas a renderer draws on: a canvas element of the page, drawn on from the page's
//! thread, or an `OffscreenCanvas` an element handed its drawing to, which a worker may hold.
//! Browsers differ in which of the two gives a WebGL2 context: WebKit before Safari 17 gives
//! none on an `OffscreenCanvas`, so the page falls back to its elements there.

use wasm_bindgen::JsValue;
use web_sys::{EventTarget, HtmlCanvasElement, OffscreenCanvas};

/// A canvas to draw on.
#[derive(Clone, Debug)]
pub enum Canvas {
    /// A canvas element, on the page's thread.
    Element(HtmlCanvasElement),
    /// An offscreen canvas, on the page's thread or in a worker.
    Offscreen(OffscreenCanvas),
}

impl Canvas {
    /// The drawing buffer's size in pixels.
    pub fn size(&self) -> (u32, u32) {
        match self {
            Canvas::Element(c) => (c.width(), c.height()),
            Canvas::Offscreen(c) => (c.width(), c.height()),
        }
    }

    /// Sets the drawing buffer's size in pixels.
    pub fn set_size(&self, (width, height): (u32, u32)) {
        match self {
            Canvas::Element(c) => {
                c.set_width(width);
                c.set_height(height);
            }
            Canvas::Offscreen(c) => {
                c.set_width(width);
                c.set_height(height);
            }
        }
    }

    /// Where its context's events (a WebGL context lost, given back) arrive.
    pub fn events(&self) -> &EventTarget {
        match self {
            Canvas::Element(c) => c,
            Canvas::Offscreen(c) => c,
        }
    }

    /// The canvas as a JavaScript value (an image source a video frame is made from).
    pub fn as_js(&self) -> &JsValue {
        match self {
            Canvas::Element(c) => c,
            Canvas::Offscreen(c) => c,
        }
    }

    /// What wgpu opens a surface on.
    pub(super) fn surface_target(&self) -> wgpu::SurfaceTarget<'static> {
        match self.clone() {
            Canvas::Element(c) => wgpu::SurfaceTarget::Canvas(c),
            Canvas::Offscreen(c) => wgpu::SurfaceTarget::OffscreenCanvas(c),
        }
    }
}
