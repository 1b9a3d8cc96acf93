//! The gallery: every preset in species/, grouped by where it comes from, each a card with its
//! name, the figure it reproduces, a line of description and a picture of the shell. The cards
//! are plain links to the preset's fragment, so the browser's history does the navigation; the
//! shells are grown whole by the pool of workers and drawn by a second viewer on a small canvas
//! laid out off the screen as they come, each card's picture a PNG read back from it.

use super::clock::now;
use super::debug::Loss;
use super::dom::{append, attr, create, typed};
use super::view_canvas::{object_url, replace};
use super::viewer::Viewer;
use super::workers::Workers;
use crate::presets::{Preset, presets};
use crate::render::Canvas;
use crate::share::link;
use crate::spec::ShellSpec;
use crate::work::message::{Request, WholeShell};
use crate::work::view_command::ViewCommand;
use crate::work::view_status::Device;
use std::collections::VecDeque;
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

/// Draws the cards' pictures: each shell is grown whole by a worker of the pool (all at once,
/// shared among them), and drawn here by a viewer of its own as its answer comes.
pub struct Pictures {
    viewer: Viewer,
    /// The presets whose pictures are not drawn yet, each with the link its shell is grown from.
    left: Vec<(&'static Preset, String)>,
    /// Whether the pool has been asked for them since the gallery was last shown.
    asked: bool,
    /// Shells grown and not drawn yet.
    waiting: Vec<(&'static Preset, WholeShell)>,
    /// Pictures drawn within [`LOSS_NOTICE_MS`], and when: the browser tells of a lost device a
    /// little after the fact, so these may be blank, and are grown and drawn again after a loss.
    lately: VecDeque<(&'static Preset, f64)>,
}

/// Milliseconds within which the browser is taken to report a lost device.
const LOSS_NOTICE_MS: f64 = 2000.0;

/// The spec of a preset's picture: its mesh as fine as a picture shows.
fn picture_spec(preset: &Preset) -> ShellSpec {
    crate::view::picture::picture_spec(&preset.spec)
}

/// The link a preset's picture is grown from.
fn picture_link(preset: &Preset) -> String {
    link::encode(preset, &picture_spec(preset))
}

impl Pictures {
    /// Pictures drawn by `viewer` (none where it draws nothing).
    pub fn new(viewer: Viewer) -> Self {
        let left = if viewer.backend().is_some() {
            presets().iter().map(|p| (p, picture_link(p))).collect()
        } else {
            Vec::new()
        };
        Self {
            viewer,
            left,
            asked: false,
            waiting: Vec::new(),
            lately: VecDeque::new(),
        }
    }

    /// Asks the pool for the pictures not drawn yet (once while the gallery is shown).
    pub fn ask(&mut self, workers: &mut Workers) {
        if self.asked {
            return;
        }
        self.asked = true;
        for (job, (_, link)) in self.left.iter().enumerate() {
            workers.submit(Request::Whole {
                job: job as u32,
                link: link.clone(),
            });
        }
    }

    /// Asks the pool again for a picture that may have been drawn blank by a lost device.
    fn ask_again(&mut self, preset: &'static Preset, workers: &mut Workers) {
        let link = picture_link(preset);
        workers.submit(Request::Whole {
            job: self.left.len() as u32,
            link: link.clone(),
        });
        self.left.push((preset, link));
    }

    /// The gallery was left: the pictures not yet sent to a worker wait until it is shown
    /// again.
    pub fn pause(&mut self, workers: &mut Workers) {
        workers.cancel(|r| matches!(r, Request::Whole { .. }));
        self.asked = false;
    }

    /// A worker grew the shell of `link`: it waits to be drawn onto its card ([`Self::work`]).
    pub fn take(&mut self, link: &str, result: Result<WholeShell, String>) {
        let Some(at) = self.left.iter().position(|(_, l)| l == link) else {
            return;
        };
        let (preset, _) = self.left.remove(at);
        if let Ok(whole) = result {
            self.waiting.push((preset, whole));
        }
    }

    /// Keeps the pictures' graphics device and draws the next shell waiting for it. After a
    /// loss, the pictures drawn just before it are grown and drawn again on the next device.
    pub fn work(&mut self, workers: &mut Workers) {
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
            while let Some((preset, _)) = self.lately.pop_front() {
                self.ask_again(preset, workers);
            }
            return;
        }
        let noticed = now() - LOSS_NOTICE_MS;
        while self.lately.front().is_some_and(|(_, at)| *at < noticed) {
            self.lately.pop_front();
        }
        // One picture a frame: reading a picture back waits for the GPU to draw it, and the
        // page answers the user between two.
        let Some((preset, whole)) = self.waiting.pop() else {
            return;
        };
        self.viewer.show_whole(preset, &picture_spec(preset), whole);
        let picture = self.viewer.picture();
        if self.viewer.survive() != Device::Ready {
            // Lost while drawing: the picture may be blank; it is drawn on the next device.
            self.ask_again(preset, workers);
            return;
        }
        let Ok(blob) = picture else {
            return;
        };
        self.lately.push_back((preset, now()));
        let selector = format!("a.card[data-preset=\"{}\"] img", preset.id);
        let image = super::page::document()
            .query_selector(&selector)
            .ok()
            .flatten()
            .and_then(|e| wasm_bindgen::JsCast::dyn_into::<HtmlImageElement>(e).ok());
        if let Some(img) = image {
            wasm_bindgen_futures::spawn_local(async move {
                // A picture the browser could not read leaves the card as it was.
                if let Ok(url) = object_url(blob).await {
                    img.set_src(&url);
                }
            });
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

    /// Whether every picture is drawn, and the last of them long enough ago that a lost
    /// device would have been reported.
    pub fn finished(&self) -> bool {
        self.left.is_empty() && self.waiting.is_empty() && self.lately.is_empty()
    }
}
