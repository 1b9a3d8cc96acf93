//! A grid of tiles on the page, as the parameter map and breeding lay them out: each tile a
//! link with its picture, drawn as the pool's answers come. Its numbering, focus and marks are
//! the core's [`TileSet`] and [`crate::variation::tile_grid::TileMarks`].

use super::dom::{self, append, attr, clear};
use super::page::{element, signal};
use crate::markup;
use crate::variation::tile::{Picture, Tile};
use crate::variation::tile_grid::{self, TileSet};
use std::cell::Cell;
use wasm_bindgen::{Clamped, JsCast};
use web_sys::{CanvasRenderingContext2d, Element, HtmlCanvasElement, ImageData};

thread_local! {
    /// The number of the next set of tiles, over all grids of the page.
    static NEXT_SET: Cell<u32> = const { Cell::new(0) };
}

/// The tiles of one grid element of the page, and the set they belong to.
pub struct TileGrid {
    id: &'static str,
    tiles: Vec<Element>,
    set: TileSet,
}

impl TileGrid {
    /// The grid in the element of this id.
    pub fn new(id: &'static str) -> Self {
        Self {
            id,
            tiles: Vec::new(),
            set: TileSet::new(u32::MAX),
        }
    }

    /// Removes the tiles, and starts a new set: pictures of the old ones are dropped.
    pub fn clear(&mut self) {
        if let Some(grid) = element(self.id) {
            clear(&grid);
        }
        self.tiles.clear();
        self.set = TileSet::new(NEXT_SET.with(|next| next.replace(TileSet::after(next.get()))));
    }

    /// Adds the tile `make` makes of its job number (the core's [`crate::markup::tile`]).
    pub fn add(&mut self, make: impl FnOnce(u32) -> markup::Element) {
        let tile = dom::make(&make(self.set.add()));
        if let Some(grid) = element(self.id) {
            append(&grid, &[&tile]);
        }
        self.tiles.push(tile.into());
    }

    /// The job number of tile `index` of this set.
    pub fn job(&self, index: usize) -> u32 {
        self.set.job(index)
    }

    /// The tile of this set a job number is for.
    pub fn index(&self, job: u32) -> Option<usize> {
        self.set.index(job)
    }

    /// Draws tile `index`'s picture, or hatches it and says why it has none; a tile whose
    /// link repaired another value is marked, and says what.
    pub fn show(&self, index: usize, tile: &Tile) {
        let Some(element) = self.tiles.get(index) else {
            return;
        };
        let marks = tile.marks(&element.get_attribute("aria-label").unwrap_or_default());
        for (class, marked) in [("failed", marks.failed), ("repaired", marks.repaired)] {
            if marked {
                let _ = element.class_list().add_1(class);
            }
        }
        attr(element, "title", &marks.title);
        if let (Some(picture), None) = (&tile.picture, &tile.failure) {
            paint(element, picture);
        }
    }

    /// Moves the keyboard's focus `dx` tiles across and `dy` down a grid `side` tiles wide
    /// (from the focused tile, or from `from`, or the first); Enter then follows that tile.
    pub fn step(&self, dx: i32, dy: i32, side: usize, from: Option<usize>) {
        let focused = super::page::document().active_element();
        let at = self
            .tiles
            .iter()
            .position(|t| Some(t) == focused.as_ref())
            .or(from);
        if let Some(tile) = self
            .tiles
            .get(self.set.step(at, dx, dy, side))
            .and_then(|t| t.dyn_ref::<web_sys::HtmlElement>())
        {
            let _ = tile.focus();
        }
    }
}

/// Tells the page tests whether the tiles of a grid are all drawn (`data-<key>`: whole, or
/// filling).
pub fn signal_filled(key: &str, finished: bool) {
    signal(key, tile_grid::filled(finished));
}

/// Draws a pattern's picture into its tile's canvas.
fn paint(tile: &Element, picture: &Picture) {
    let Some(canvas) = tile
        .first_element_child()
        .and_then(|c| c.dyn_into::<HtmlCanvasElement>().ok())
    else {
        return;
    };
    canvas.set_width(picture.width as u32);
    canvas.set_height(picture.height as u32);
    let context = canvas
        .get_context("2d")
        .ok()
        .flatten()
        .and_then(|c| c.dyn_into::<CanvasRenderingContext2d>().ok());
    if let (Some(context), Ok(image)) = (
        context,
        ImageData::new_with_u8_clamped_array_and_sh(
            Clamped(&picture.rgba),
            picture.width as u32,
            picture.height as u32,
        ),
    ) {
        // Drawing into our own canvas cannot fail for in-range coordinates.
        let _ = context.put_image_data(&image, 0.0, 0.0);
    }
}
