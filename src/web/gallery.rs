//! The gallery's pictures (its cards are the core's, [`crate::markup::gallery`]): the
//! shells are grown whole by the pool of workers and drawn by a second viewer on a small
//! canvas laid out off the screen as they come, each card's picture a PNG read back from it.

use super::canvases::{object_url, replace};
use super::clock::now;
use super::debug::Loss;
use super::viewer::WebScreen;
use super::workers::Workers;
use crate::presets::Preset;
use crate::render::Canvas;
use crate::spec::ShellSpec;
use crate::work::message::WholeShell;
use crate::work::picture_drawer::PictureDrawer;
use crate::work::picture_queue::{PictureQueue, Place};
use crate::work::recent_pictures::RecentPictures;
use crate::work::screen::Screen;
use crate::work::viewer_driver::PoolWorkers;
use std::cell::RefCell;
use std::rc::Rc;
use web_sys::HtmlImageElement;

/// The `img`s a picture of `preset` for `place` is shown in: a card's, and the figures'
/// section's beside it.
fn selector(place: Place, preset: &Preset) -> String {
    match place {
        Place::Card => format!("img[data-picture=\"{}\"]", preset.id),
        Place::Tile { job, .. } => format!("a.tile[data-job=\"{job}\"] img"),
    }
}

/// The first `img` the selector finds on the page.
fn image(selector: &str) -> Option<HtmlImageElement> {
    images(selector).into_iter().next()
}

/// Every `img` the selector finds on the page.
fn images(selector: &str) -> Vec<HtmlImageElement> {
    let Ok(found) = super::page::document().query_selector_all(selector) else {
        return Vec::new();
    };
    (0..found.length())
        .filter_map(|i| found.item(i))
        .filter_map(|e| wasm_bindgen::JsCast::dyn_into::<HtmlImageElement>(e).ok())
        .collect()
}

/// Releases the address of a picture no longer kept; a tile showing it keeps its image.
fn release(url: Option<String>) {
    if let Some(url) = url {
        let _ = web_sys::Url::revoke_object_url(&url);
    }
}

/// Draws the gallery's and the shape map's pictures as the core's [`PictureDrawer`] decides,
/// and shows each in the images that wait for it.
pub struct Pictures {
    drawer: PictureDrawer<WebScreen>,
    /// The object URLs of tiles' pictures drawn lately, by link.
    drawn: Rc<RefCell<RecentPictures<String>>>,
}

impl Pictures {
    /// Pictures drawn on `screen` (none where it draws nothing).
    pub fn new(screen: WebScreen) -> Self {
        Self {
            drawer: PictureDrawer::new(screen, now()),
            drawn: Rc::default(),
        }
    }

    /// Asks the pool for the cards' pictures not drawn yet (once while the gallery is shown).
    pub fn ask(&mut self, workers: &mut Workers) {
        self.drawer.queue_mut().ask_cards(workers.pool());
    }

    /// Asks the pool for the picture of tile `job` (`small`: one of many), the shell `spec`;
    /// true if it was drawn lately, and is shown at once instead.
    pub fn ask_tile(
        &mut self,
        job: u32,
        small: bool,
        preset: &'static Preset,
        spec: &ShellSpec,
        workers: &mut Workers,
    ) -> bool {
        let picture = PictureQueue::tile_picture(preset, spec);
        let drawn = self.drawn.borrow();
        if let Some(url) = drawn.get(&picture.1)
            && let Some(img) = image(&selector(Place::Tile { job, small }, preset))
        {
            img.set_src(url);
            return true;
        }
        drop(drawn);
        (self.drawer.queue_mut()).ask_tile(job, small, preset, picture, workers.pool(), now());
        false
    }

    /// Seconds a tile's picture (`small`: a map's) took over the last set of such tiles drawn
    /// whole: how slow this machine draws shells ([`PictureQueue::pace`]).
    pub fn pace(&self, small: bool) -> Option<f64> {
        self.drawer.queue().pace(small)
    }

    /// Whether the picture of a tile of `spec` (a variant of `preset`) was drawn lately, and
    /// would be shown at once.
    pub fn drawn_lately(&self, preset: &'static Preset, spec: &ShellSpec) -> bool {
        let link = PictureQueue::tile_picture(preset, spec).1;
        self.drawn.borrow().get(&link).is_some()
    }

    /// Takes `seconds` as the pace of this machine (a test's slow machine).
    pub fn assume_pace(&mut self, seconds: f64) {
        self.drawer.queue_mut().assume_pace(seconds);
    }

    /// The gallery was left: the cards' pictures not yet sent to a worker wait until it is
    /// shown again.
    pub fn pause(&mut self, workers: &mut Workers) {
        self.drawer.queue_mut().pause(workers.pool());
    }

    /// The shape map was closed or drawn anew: its tiles' pictures are drawn no more.
    pub fn drop_tiles(&mut self, workers: &mut Workers) {
        self.drawer.queue_mut().drop_tiles(workers.pool());
    }

    /// A worker grew the shell of picture `job`: it waits to be drawn ([`Self::work`]). A
    /// map's tile whose shell could not be grown is returned with the reason.
    pub fn take(&mut self, job: u32, result: Result<WholeShell, String>) -> Option<(u32, String)> {
        self.drawer.queue_mut().take(job, result)
    }

    /// Draws the next picture ([`PictureDrawer::work`]; a canvas that cannot be drawn on again
    /// is replaced by a fresh copy) and shows it; returns the map's tile it drew, if it was
    /// one.
    pub fn work(&mut self, workers: &mut Workers) -> Option<u32> {
        let fresh = || replace("picture-canvas").ok().map(Canvas::Element);
        let drew = self.drawer.work(now(), workers.pool(), fresh);
        for wanted in drew.forgotten {
            release(self.drawn.borrow_mut().forget(&wanted.link));
        }
        let (wanted, blob) = drew.drawn?;
        let imgs = images(&selector(wanted.place, wanted.preset));
        let kept = matches!(wanted.place, Place::Tile { .. })
            .then(|| (wanted.link.clone(), Rc::clone(&self.drawn)));
        if !imgs.is_empty() {
            wasm_bindgen_futures::spawn_local(async move {
                // A picture the browser could not read leaves the card as it was.
                if let Ok(url) = object_url(blob).await {
                    for img in &imgs {
                        img.set_src(&url);
                    }
                    if let Some((link, drawn)) = kept {
                        release(drawn.borrow_mut().keep(link, url));
                    }
                }
            });
        }
        match wanted.place {
            Place::Tile { job, .. } => Some(job),
            Place::Card => None,
        }
    }

    /// Follows a change of the page's theme (pictures already drawn keep theirs).
    pub fn set_background(&mut self, srgb: [u8; 3]) {
        self.drawer.screen_mut().set_background(srgb);
    }

    /// Test-only (see `debug.rs`): takes the pictures' graphics device away.
    pub fn take_device(&self, loss: Loss) -> Result<(), String> {
        self.drawer.screen().take_device(loss)
    }

    /// Whether it draws pictures at all (not where the browser draws no 3D).
    pub fn draws(&self) -> bool {
        self.drawer.draws()
    }

    /// The page's signal of the gallery's pictures (`data-pictures`).
    pub fn signal(&self) -> &'static str {
        self.drawer.queue().signal(self.draws())
    }
}
