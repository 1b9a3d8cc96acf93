//! The gallery: every preset in species/, grouped by where it comes from, each a card with its
//! name, the figure it reproduces, a line of description and a picture of the shell. The cards
//! are plain links to the preset's fragment, so the browser's history does the navigation; the
//! shells are grown whole by the pool of workers and drawn by a second viewer on a small canvas
//! laid out off the screen as they come, each card's picture a PNG read back from it.

use super::canvases::{object_url, replace};
use super::clock::now;
use super::debug::Loss;
use super::dom::{append, attr, create, typed};
use super::viewer::Viewer;
use super::workers::Workers;
use crate::presets::{Preset, presets};
use crate::render::Canvas;
use crate::share::link;
use crate::spec::ShellSpec;
use crate::view::picture::{CARD_PIXELS, TILE_PIXELS, picture_spec};
use crate::work::message::{Request, WholeShell};
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_status::Device;
use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::Rc;
use web_sys::{Element, HtmlImageElement};

/// Fills `container` with one section per group and one card per preset.
pub fn build(container: &Element) {
    let mut group = None;
    let mut grid: Option<Element> = None;
    for preset in presets() {
        if group != Some(preset.group) {
            group = Some(preset.group);
            let section = create("section", "group", None);
            let heading = create("h2", "", Some(preset.group.title()));
            let cards = create("div", "cards", None);
            append(&section, &[&heading, &cards]);
            append(container, &[&section]);
            grid = Some(cards.into());
        }
        let card = create("a", "card", None);
        attr(
            &card,
            "href",
            &format!("#{}", link::encode(preset, &preset.spec)),
        );
        attr(&card, "data-preset", preset.id);
        let picture: HtmlImageElement = typed("img", "picture");
        picture.set_alt(&format!("{}, grown from the model", preset.name));
        picture.set_width(256);
        picture.set_height(256);
        let name = create("h3", "", Some(&preset.name));
        let source = create("p", "source", Some(&preset.source));
        let description = create("p", "description", Some(&preset.description));
        append(&card, &[&picture, &name, &source, &description]);
        if let Some(g) = &grid {
            append(g, &[&card]);
        }
    }
}

/// Where a picture goes: a gallery card's, or a tile of a grid of shells (the parameter map
/// over a shape's parameters, or breeding), by the tile's job number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Place {
    Card,
    /// A tile by its job number, `small` where the grid shows many (the map's 64) rather
    /// than a few large (breeding's nine).
    Tile {
        job: u32,
        small: bool,
    },
}

impl Place {
    /// Pixels across the picture as drawn.
    fn pixels(self) -> u32 {
        match self {
            Place::Card => CARD_PIXELS,
            Place::Tile { .. } => TILE_PIXELS,
        }
    }

    /// Whether the picture is drawn multisampled. A small tile is not: drawn at 128 pixels
    /// and shown at about 100 among 63 others, it is smoothed about as much by the browser's
    /// scaling, and one sample a pixel draws it in a third of the time on a software
    /// rasterizer. Breeding's tiles are shown larger than drawn, and multisampled.
    fn multisampled(self) -> bool {
        !matches!(self, Place::Tile { small: true, .. })
    }
}

/// A picture asked of the pool: where it goes, the shell and the link it is grown from, and
/// the job number it was asked with.
#[derive(Clone)]
struct Wanted {
    job: u32,
    place: Place,
    preset: &'static Preset,
    spec: ShellSpec,
    link: String,
}

impl Place {
    /// The `img` a picture of `preset` is shown in here.
    fn selector(self, preset: &Preset) -> String {
        match self {
            Place::Card => format!("a.card[data-preset=\"{}\"] img", preset.id),
            Place::Tile { job, .. } => format!("a.tile[data-job=\"{job}\"] img"),
        }
    }
}

/// The `img` the selector finds on the page.
fn image(selector: &str) -> Option<HtmlImageElement> {
    super::page::document()
        .query_selector(selector)
        .ok()
        .flatten()
        .and_then(|e| wasm_bindgen::JsCast::dyn_into::<HtmlImageElement>(e).ok())
}

/// Keeps the address of a tile's picture by its link, letting the oldest go past [`KEPT`].
fn keep(drawn: &mut VecDeque<(String, String)>, link: String, url: String) {
    if drawn.len() >= KEPT
        && let Some((_, old)) = drawn.pop_front()
    {
        // The address of a picture no longer kept; a tile showing it keeps its image.
        let _ = web_sys::Url::revoke_object_url(&old);
    }
    drawn.push_back((link, url));
}

/// Draws the gallery's and the shape map's pictures: each shell is grown whole by a worker of
/// the pool (all at once, shared among them), and drawn here by a viewer of its own as its
/// answer comes.
pub struct Pictures {
    viewer: Viewer,
    /// The pictures not drawn yet.
    left: Vec<Wanted>,
    /// Whether the pool has been asked for the cards' since the gallery was last shown.
    asked: bool,
    /// Shells grown and not drawn yet.
    waiting: Vec<(Wanted, WholeShell)>,
    /// Pictures drawn within [`LOSS_NOTICE_MS`], and when: the browser tells of a lost device a
    /// little after the fact, so these may be blank, and are grown and drawn again after a loss.
    lately: VecDeque<(Wanted, f64)>,
    /// The job number of the next picture asked.
    next_job: u32,
    /// The addresses of tiles' pictures drawn lately, by the link they were grown from: a tile
    /// asked again (a parent that was an offspring, a generation gone back to, a map drawn
    /// again) is shown at once.
    drawn: Rc<RefCell<VecDeque<(String, String)>>>,
}

/// Tiles' pictures kept by [`Pictures::drawn`] (the oldest are let go).
const KEPT: usize = 256;

/// Milliseconds within which the browser is taken to report a lost device.
const LOSS_NOTICE_MS: f64 = 2000.0;

impl Pictures {
    /// Pictures drawn by `viewer` (none where it draws nothing).
    pub fn new(viewer: Viewer) -> Self {
        let mut pictures = Self {
            viewer,
            left: Vec::new(),
            asked: false,
            waiting: Vec::new(),
            lately: VecDeque::new(),
            next_job: 0,
            drawn: Rc::default(),
        };
        if pictures.draws() {
            for preset in presets() {
                pictures.want(Place::Card, preset, &preset.spec);
            }
        }
        pictures
    }

    /// Adds the picture of `spec` (a variant of `preset`) to those to draw, its mesh as fine as
    /// a picture shows; returns it to be asked of the pool.
    fn want(&mut self, place: Place, preset: &'static Preset, spec: &ShellSpec) -> &Wanted {
        let spec = picture_spec(spec, place.pixels());
        let link = link::encode(preset, &spec);
        self.push(place, preset, spec, link)
    }

    /// Adds a picture to draw of `spec`, already as fine as a picture shows, whose link is
    /// `link`.
    fn push(
        &mut self,
        place: Place,
        preset: &'static Preset,
        spec: ShellSpec,
        link: String,
    ) -> &Wanted {
        let wanted = Wanted {
            job: self.next_job,
            place,
            preset,
            link,
            spec,
        };
        self.next_job = self.next_job.wrapping_add(1);
        self.left.push(wanted);
        self.left.last().expect("just pushed")
    }

    fn submit(workers: &mut Workers, wanted: &Wanted) {
        workers.submit(Request::Whole {
            job: wanted.job,
            link: wanted.link.clone(),
        });
    }

    /// Asks the pool for the cards' pictures not drawn yet (once while the gallery is shown).
    pub fn ask(&mut self, workers: &mut Workers) {
        if self.asked {
            return;
        }
        self.asked = true;
        for wanted in self.left.iter().filter(|w| w.place == Place::Card) {
            Self::submit(workers, wanted);
        }
    }

    /// Asks the pool for the picture of tile `job` (`small`: one of many, [`Place::Tile`]),
    /// the shell `spec`; true if it was drawn lately, and is shown at once instead.
    pub fn ask_tile(
        &mut self,
        job: u32,
        small: bool,
        preset: &'static Preset,
        spec: &ShellSpec,
        workers: &mut Workers,
    ) -> bool {
        let spec = picture_spec(spec, TILE_PIXELS);
        let link = link::encode(preset, &spec);
        let drawn = self.drawn.borrow();
        if let Some((_, url)) = drawn.iter().find(|(l, _)| *l == link)
            && let Some(img) = image(&Place::Tile { job, small }.selector(preset))
        {
            img.set_src(url);
            return true;
        }
        drop(drawn);
        let wanted = self.push(Place::Tile { job, small }, preset, spec, link);
        Self::submit(workers, wanted);
        false
    }

    /// Asks the pool again for a picture that may have been drawn blank by a lost device.
    fn ask_again(&mut self, wanted: Wanted, workers: &mut Workers) {
        self.drawn
            .borrow_mut()
            .retain(|(link, _)| *link != wanted.link);
        let again = self.want(wanted.place, wanted.preset, &wanted.spec);
        Self::submit(workers, again);
    }

    /// Whether the pool's job `job` is a picture for `place`.
    fn job_for(&self, job: u32, place: impl Fn(Place) -> bool) -> bool {
        self.left.iter().any(|w| w.job == job && place(w.place))
    }

    /// The gallery was left: the cards' pictures not yet sent to a worker wait until it is
    /// shown again.
    pub fn pause(&mut self, workers: &mut Workers) {
        workers.cancel(
            |r| matches!(r, Request::Whole { job, .. } if self.job_for(*job, |p| p == Place::Card)),
        );
        self.asked = false;
    }

    /// The shape map was closed or drawn anew: its tiles' pictures are drawn no more.
    pub fn drop_tiles(&mut self, workers: &mut Workers) {
        let tile = |p: Place| matches!(p, Place::Tile { .. });
        workers.cancel(|r| matches!(r, Request::Whole { job, .. } if self.job_for(*job, tile)));
        self.left.retain(|w| !tile(w.place));
        self.waiting.retain(|(w, _)| !tile(w.place));
        self.lately.retain(|(w, _)| !tile(w.place));
    }

    /// A worker grew the shell of picture `job`: it waits to be drawn ([`Self::work`]). A
    /// map's tile whose shell could not be grown is returned with the reason.
    pub fn take(&mut self, job: u32, result: Result<WholeShell, String>) -> Option<(u32, String)> {
        let at = self.left.iter().position(|w| w.job == job)?;
        let wanted = self.left.remove(at);
        match (result, wanted.place) {
            (Ok(whole), _) => {
                self.waiting.push((wanted, whole));
                None
            }
            (Err(why), Place::Tile { job, .. }) => Some((job, why)),
            (Err(_), Place::Card) => None,
        }
    }

    /// Keeps the pictures' graphics device and draws the next shell waiting for it; returns
    /// the map's tile it drew, if it was one. After a loss, the pictures drawn just before it
    /// are grown and drawn again on the next device.
    pub fn work(&mut self, workers: &mut Workers) -> Option<u32> {
        let mut device = self.viewer.survive();
        if matches!(device, Device::NeedsCanvas(_)) {
            // The canvas cannot be drawn on again: a fresh copy takes its place (or, failing
            // that, the pictures are drawn no more).
            match replace("picture-canvas") {
                Ok(fresh) => self.viewer.give_canvas(Canvas::Element(fresh)),
                Err(e) => device = Device::Gone(e),
            }
        }
        if device != Device::Ready {
            while let Some((wanted, _)) = self.lately.pop_front() {
                self.ask_again(wanted, workers);
            }
            return None;
        }
        let noticed = now() - LOSS_NOTICE_MS;
        while self.lately.front().is_some_and(|(_, at)| *at < noticed) {
            self.lately.pop_front();
        }
        // One picture a frame: reading a picture back waits for the GPU to draw it, and the
        // page answers the user between two.
        let (wanted, whole) = self.waiting.pop()?;
        self.viewer.show_whole(wanted.preset, &wanted.spec, whole);
        let place = wanted.place;
        let picture = self.viewer.picture_at(place.pixels(), place.multisampled());
        if self.viewer.survive() != Device::Ready {
            // Lost while drawing: the picture may be blank; it is drawn on the next device.
            self.ask_again(wanted, workers);
            return None;
        }
        let blob = picture.ok()?;
        let img = image(&wanted.place.selector(wanted.preset));
        let kept = matches!(place, Place::Tile { .. })
            .then(|| (wanted.link.clone(), Rc::clone(&self.drawn)));
        self.lately.push_back((wanted, now()));
        if let Some(img) = img {
            wasm_bindgen_futures::spawn_local(async move {
                // A picture the browser could not read leaves the card as it was.
                if let Ok(url) = object_url(blob).await {
                    img.set_src(&url);
                    if let Some((link, drawn)) = kept {
                        keep(&mut drawn.borrow_mut(), link, url);
                    }
                }
            });
        }
        match place {
            Place::Tile { job, .. } => Some(job),
            Place::Card => None,
        }
    }

    /// Follows a change of the page's theme (pictures already drawn keep theirs).
    pub fn set_background(&mut self, srgb: [u8; 3]) {
        self.viewer.command(ViewCommand::Background(srgb));
    }

    /// Test-only (see `debug.rs`): takes the pictures' graphics device away.
    pub fn take_device(&self, loss: Loss) -> Result<(), String> {
        self.viewer.take_device(loss)
    }

    /// Whether it draws pictures at all (not where the browser draws no 3D).
    pub fn draws(&self) -> bool {
        self.viewer.backend().is_some()
    }

    /// Whether every card's picture is drawn, and the last of them long enough ago that a
    /// lost device would have been reported.
    pub fn finished(&self) -> bool {
        let card = |w: &Wanted| w.place == Place::Card;
        !self.left.iter().any(card)
            && !self.waiting.iter().any(|(w, _)| card(w))
            && !self.lately.iter().any(|(w, _)| card(w))
    }
}
