//! The planar representation beside the shell (the left halves of Fowler et al.'s figures
//! 11–14): a 2D canvas one pixel per cell and row, written a few rows at a time, scrolled so
//! that the newest rows stay in sight. It draws what the viewer tells it
//! ([`PlanarUpdate`]), on the page's thread wherever the viewer runs.

use super::shown_size::ShownSize;
use crate::work::planar_update::PlanarUpdate;
use wasm_bindgen::{Clamped, JsCast};
use web_sys::{CanvasRenderingContext2d, Element, HtmlCanvasElement, ImageData};

/// The planar view's canvas, and the pattern it shows (none: hidden).
pub struct PlanarView {
    canvas: HtmlCanvasElement,
    shown: Option<Planar>,
}

impl PlanarView {
    pub fn new(canvas: HtmlCanvasElement) -> Self {
        Self {
            canvas,
            shown: None,
        }
    }

    /// Shows what the viewer says.
    pub fn apply(&mut self, update: PlanarUpdate) {
        match update {
            PlanarUpdate::Open(pattern) => self.shown = Planar::new(self.canvas.clone(), pattern),
            PlanarUpdate::Rows { first, rgba } => {
                if let Some(planar) = &self.shown {
                    planar.draw_rows(first, &rgba);
                }
            }
            PlanarUpdate::Follow(row) => {
                if let Some(planar) = &self.shown {
                    planar.follow(row);
                }
            }
        }
    }
}

/// A pattern shown in the planar view.
struct Planar {
    canvas: HtmlCanvasElement,
    context: CanvasRenderingContext2d,
    cells: u32,
    /// The box the canvas scrolls in, and the sizes both are shown at.
    scroller: Option<(Element, ShownSize, ShownSize)>,
}

impl Planar {
    /// Sizes the canvas for a cells × rows pattern, or hides its figure when there is none.
    fn new(canvas: HtmlCanvasElement, pattern: Option<(u32, u32)>) -> Option<Self> {
        let figure = canvas.closest("figure").ok().flatten();
        let Some((cells, rows)) = pattern else {
            if let Some(f) = figure {
                // Setting a plain attribute cannot fail.
                let _ = f.set_attribute("hidden", "");
            }
            return None;
        };
        if let Some(f) = figure {
            let _ = f.remove_attribute("hidden");
        }
        canvas.set_width(cells);
        canvas.set_height(rows);
        let context = canvas.get_context("2d").ok()??.dyn_into().ok()?;
        let scroller = canvas.parent_element().and_then(|scroller| {
            scroller.set_scroll_top(0);
            let shown = ShownSize::observe(&canvas).ok()?;
            let view = ShownSize::observe(&scroller).ok()?;
            Some((scroller, shown, view))
        });
        Some(Self {
            canvas,
            context,
            cells,
            scroller,
        })
    }

    /// Draws rows `first..` from `rgba` (`cells × 4` bytes a row).
    fn draw_rows(&self, first: u32, rgba: &[u8]) {
        let rows = (rgba.len() / (self.cells as usize * 4)) as u32;
        if rows == 0 {
            return;
        }
        if let Ok(image) =
            ImageData::new_with_u8_clamped_array_and_sh(Clamped(rgba), self.cells, rows)
        {
            // Drawing into our own canvas cannot fail for in-range coordinates.
            let _ = self.context.put_image_data(&image, 0.0, f64::from(first));
        }
    }

    /// Scrolls the view so that row `row` stays in sight.
    fn follow(&self, row: u32) {
        let Some((scroller, shown, view)) = &self.scroller else {
            return;
        };
        let scale = f64::from(shown.css().1) / f64::from(self.canvas.height().max(1));
        let bottom = f64::from(row) * scale;
        let view = f64::from(view.css().1);
        if bottom > f64::from(scroller.scroll_top()) + view {
            scroller.set_scroll_top((bottom - view * 0.8).max(0.0) as i32);
        }
    }
}
