//! The gallery: every preset in species/, grouped by where it comes from, each a card with its
//! name, the figure it reproduces, a line of description and a picture of the shell. The cards
//! are plain links to the preset's fragment, so the browser's history does the navigation; the
//! pictures are drawn one by one by a second viewer on a small off-screen canvas.

use super::dom::{append, attr, create, typed};
use super::viewer::{Device, Viewer, now};
use crate::presets::{Preset, presets};
use crate::share::link;
use crate::spec::form::Form;
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

/// Draws the cards' pictures, a few milliseconds a frame.
pub struct Pictures {
    viewer: Viewer,
    queue: VecDeque<&'static Preset>,
    current: Option<&'static Preset>,
    /// Pictures finished within [`LOSS_NOTICE_MS`], and when: the browser tells of a lost
    /// device a little after the fact, so these may be blank and are drawn again after a loss.
    lately: VecDeque<(&'static Preset, f64)>,
}

/// Milliseconds within which the browser is taken to report a lost device.
const LOSS_NOTICE_MS: f64 = 2000.0;

/// Voxels along the longest side of an implicit shell in a gallery picture: enough for its
/// size, and quick to grow.
const PICTURE_RESOLUTION: u32 = 64;

impl Pictures {
    pub fn new(viewer: Viewer) -> Self {
        Self {
            viewer,
            queue: presets().iter().collect(),
            current: None,
            lately: VecDeque::new(),
        }
    }

    /// Works on the pictures for at most `budget_ms`.
    pub fn work(&mut self, budget_ms: f64) {
        if self.viewer.survive() != Device::Ready {
            // The device was lost: the picture under way, and those finished just before, are
            // drawn once another is open.
            for (preset, _) in self.lately.drain(..).rev() {
                self.queue.push_front(preset);
            }
            return;
        }
        let noticed = now() - LOSS_NOTICE_MS;
        while self.lately.front().is_some_and(|(_, at)| *at < noticed) {
            self.lately.pop_front();
        }
        let preset = match self.current {
            Some(p) => p,
            None => {
                let Some(next) = self.queue.pop_front() else {
                    return;
                };
                let mut spec = next.spec.clone();
                if let Form::Implicit(implicit) = &mut spec.form {
                    implicit.resolution = implicit.resolution.min(PICTURE_RESOLUTION);
                }
                if self.viewer.load(next, &spec).is_err() {
                    return;
                }
                self.current = Some(next);
                next
            }
        };
        let done = self.viewer.growing().is_none_or(|g| g.generator.is_done());
        if !done {
            self.viewer.grow(usize::MAX, budget_ms);
            return;
        }
        let picture = self.viewer.picture();
        if self.viewer.survive() != Device::Ready {
            // Lost while drawing: the picture may be blank; it is drawn again on the next device.
            return;
        }
        self.current = None;
        let Ok(url) = picture else {
            return;
        };
        let selector = format!("a.card[data-preset=\"{}\"] img", preset.id);
        let image = super::page::document()
            .query_selector(&selector)
            .ok()
            .flatten()
            .and_then(|e| wasm_bindgen::JsCast::dyn_into::<HtmlImageElement>(e).ok());
        if let Some(img) = image {
            img.set_src(&url);
        }
        self.lately.push_back((preset, now()));
    }

    /// Follows a change of the page's theme (pictures already drawn keep theirs).
    pub fn set_background(&mut self, srgb: [u8; 3]) {
        self.viewer.set_background(srgb);
    }

    /// Test-only (see `debug.rs`): destroys the pictures' graphics device.
    pub fn destroy_device(&self) {
        self.viewer.destroy_device();
    }

    /// Whether every picture is drawn, and the last of them long enough ago that a lost
    /// device would have been reported.
    pub fn finished(&self) -> bool {
        self.queue.is_empty() && self.current.is_none() && self.lately.is_empty()
    }
}
