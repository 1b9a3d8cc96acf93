//! The size an element (a canvas, the box it scrolls in) is shown at on the page, as a
//! `ResizeObserver` last reported it. The observer's callback runs after the browser has laid
//! the page out, so reading the size there costs nothing; read in each animation frame
//! instead, it is a call out of wasm that lays the page out first whenever anything on it
//! changed since. A frame that needs a size (to keep the drawing buffer at the canvas's, to
//! turn the camera by a drag's share of it, to scroll the planar pattern) takes the last one
//! observed.

use std::cell::Cell;
use std::rc::Rc;
use wasm_bindgen::prelude::*;
use web_sys::{Element, ResizeObserver};

/// Keeps the size an element is shown at, in CSS pixels, while it lives.
pub(crate) struct ShownSize {
    size: Rc<Cell<(u32, u32)>>,
    observer: ResizeObserver,
    _on_resize: Closure<dyn FnMut()>,
}

/// The element's width and height in CSS pixels (whole ones, as the browser rounds them).
fn css_size(element: &Element) -> (u32, u32) {
    let (w, h) = (element.client_width(), element.client_height());
    (w.max(0) as u32, h.max(0) as u32)
}

impl ShownSize {
    /// Observes `element`, starting from its size now (read once here: the observer first
    /// reports after the next layout, after the first frame has been drawn).
    pub(crate) fn observe(element: &Element) -> Result<Self, String> {
        let size = Rc::new(Cell::new(css_size(element)));
        let (to, seen) = (Rc::clone(&size), element.clone());
        let on_resize = Closure::<dyn FnMut()>::new(move || to.set(css_size(&seen)));
        let observer = ResizeObserver::new(on_resize.as_ref().unchecked_ref())
            .map_err(|_| "this browser cannot observe the size of what it shows".to_string())?;
        observer.observe(element);
        Ok(Self {
            size,
            observer,
            _on_resize: on_resize,
        })
    }

    /// The element's width and height in CSS pixels, as last laid out.
    pub(crate) fn css(&self) -> (u32, u32) {
        self.size.get()
    }
}

impl Drop for ShownSize {
    fn drop(&mut self) {
        self.observer.disconnect();
    }
}
