//! Breeding on the page: over the shell's view, the current shell among its eight offspring
//! (the core's `Breeding`), each grown by the pool and drawn by the pictures' viewer as the
//! map's shells are. Choosing an offspring follows its link, the lineage with that choice, so
//! the browser's history steps through the generations and a shared link replays them; Back,
//! the mutation rate and leaving with the parent are links too.

use super::debug;
use super::gallery::Pictures;
use super::page::{element, element_as, set_text, signal};
use super::tile_grid::{TileGrid, signal_filled};
use super::workers::Workers;
use crate::markup::{self, Shows};
use crate::variation::breeding::{Breeding, PARENT};
use web_sys::HtmlInputElement;

/// Tiles along each side of the breeding grid: the parent in the middle of its offspring.
const SIDE: usize = 3;

/// The breeding view: the generation shown and its tiles.
pub struct BreedView {
    breeding: Option<Breeding>,
    grid: TileGrid,
}

impl Default for BreedView {
    fn default() -> Self {
        Self {
            breeding: None,
            grid: TileGrid::new("breed-grid"),
        }
    }
}

/// Follows a link of this page (`#…`): with `replace`, in place of the page's current entry
/// of the history, as a change of the rate is.
fn go(fragment: &str, replace: bool) {
    let Some(location) = web_sys::window().map(|w| w.location()) else {
        return;
    };
    let _ = if replace {
        location.replace(&format!("#{fragment}"))
    } else {
        location.set_hash(fragment)
    };
}

impl BreedView {
    /// Whether the breeding view is shown.
    pub fn is_open(&self) -> bool {
        self.breeding.is_some()
    }

    /// Shows the generation `breeding` has come to (the session replayed its lineage; its
    /// parent is the shell shown behind it) and starts drawing it.
    pub fn open(&mut self, mut breeding: Breeding, workers: &mut Workers, pictures: &mut Pictures) {
        self.stop(workers, pictures);
        if let Some(section) = element("breed") {
            section.set_hidden(false);
        }
        if let Some(rate) = element_as::<HtmlInputElement>("breed-rate") {
            rate.set_value(&breeding.lineage.rate.to_string());
        }
        set_text("breed-rate-value", &breeding.lineage.rate.to_string());
        if let Some(back) = element("breed-back") {
            back.toggle_attribute_with_force("disabled", breeding.lineage.back().is_none())
                .ok();
        }
        if !pictures.draws() {
            set_text(
                "breed-status",
                "This browser draws no 3D here, so there are no shells to choose among.",
            );
            signal("breed", "refused");
            self.breeding = Some(breeding);
            return;
        }
        // A machine that drew the last shells slowly draws fewer offspring.
        if let Some(pace) = debug::forced_pace() {
            pictures.assume_pace(pace);
        }
        breeding.pace(pictures.pace(false), |tile| {
            pictures.drawn_lately(tile.preset, &tile.spec)
        });
        let mut drawn = Vec::new();
        for (index, tile) in breeding.tiles().iter().enumerate() {
            let (label, href) = breeding.label(index);
            let class = if index == PARENT {
                "tile parent"
            } else {
                "tile"
            };
            let href = href.map(|h| format!("#{h}"));
            let current = index == PARENT;
            (self.grid).add(|job| {
                markup::tile(job, href.as_deref(), &label, class, current, Shows::Shell)
            });
            if tile.failure.is_some() || tile.note.is_some() {
                self.grid.show(index, tile);
            }
            if tile.failure.is_none()
                && pictures.ask_tile(
                    self.grid.job(index),
                    false,
                    tile.preset,
                    &tile.spec,
                    workers,
                )
            {
                drawn.push(index);
            }
        }
        for index in drawn {
            breeding.shown(index, Ok(()));
        }
        set_text("breed-status", &breeding.status());
        signal_filled("breed", breeding.finished());
        self.breeding = Some(breeding);
    }

    /// Hides the view and stops drawing its tiles.
    pub fn close(&mut self, workers: &mut Workers, pictures: &mut Pictures) {
        if self.breeding.is_none() {
            return;
        }
        self.stop(workers, pictures);
        self.breeding = None;
        if let Some(section) = element("breed") {
            section.set_hidden(true);
        }
        signal("breed", "");
    }

    fn stop(&mut self, workers: &mut Workers, pictures: &mut Pictures) {
        pictures.drop_tiles(workers);
        self.grid.clear();
    }

    /// The link of the lineage shown (without '#').
    pub fn link(&self) -> Option<String> {
        let breeding = self.breeding.as_ref()?;
        Some(breeding.link(&breeding.lineage))
    }

    /// Goes to the generation before.
    pub fn back(&self) {
        if let Some(breeding) = &self.breeding
            && let Some(before) = breeding.lineage.back()
        {
            go(&breeding.link(&before), false);
        }
    }

    /// Leaves breeding with the parent: the shell shown, by its own link.
    pub fn keep(&self) {
        if let Some(breeding) = &self.breeding {
            go(&breeding.parent().link, false);
        }
    }

    /// Breeds the generation shown again at `rate`.
    pub fn set_rate(&self, rate: f64) {
        if let Some(breeding) = &self.breeding {
            go(&breeding.link(&breeding.lineage.at_rate(rate)), true);
        }
    }

    /// Moves the keyboard's focus among the tiles (from the parent).
    pub fn step(&self, dx: i32, dy: i32) {
        self.grid.step(dx, dy, SIDE, Some(PARENT));
    }

    /// The shell of tile `job` was drawn as a picture, or could not be grown.
    pub fn shown(&mut self, job: u32, result: Result<(), String>) {
        let (Some(breeding), Some(index)) = (&mut self.breeding, self.grid.index(job)) else {
            return;
        };
        breeding.shown(index, result);
        self.grid.show(index, &breeding.tiles()[index]);
        signal_filled("breed", breeding.finished());
    }
}
