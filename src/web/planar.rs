//! The planar representation beside the shell (the left halves of Fowler et al.'s figures
//! 11–14): a 2D canvas one pixel per cell and row, written a few rows at a time.

use wasm_bindgen::{Clamped, JsCast};
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement, ImageData};

pub struct Planar {
    context: CanvasRenderingContext2d,
    cells: u32,
}

impl Planar {
    /// Sizes the canvas for a cells × rows pattern, or hides it when there is none.
    pub fn new(canvas: HtmlCanvasElement, pattern: Option<(u32, u32)>) -> Option<Self> {
        let figure = canvas.parent_element();
        let Some((cells, rows)) = pattern else {
            if let Some(f) = figure {
                // Hiding an element cannot fail.
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
        Some(Self { context, cells })
    }

    /// Draws rows `first..` from `rgba` (`cells × 4` bytes a row).
    pub fn draw_rows(&self, first: u32, rgba: &[u8]) {
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
}
