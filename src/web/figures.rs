//! The papers' figures beside ours, a section of the gallery: paper by paper, each figure's
//! number and caption in our words, with the presets that reproduce it (their pictures, drawn
//! with the gallery's cards) and the stories' steps that show it, or why none does. Built from
//! the core's join of species/papers.json with the presets and stories ([`crate::papers`]).

use super::dom::{append, attr, create, typed};
use crate::papers::papers;
use crate::share::link;
use web_sys::{Element, HtmlImageElement};

/// Fills `container` with one section per paper.
pub fn build(container: &Element) {
    for paper in papers() {
        let section = create("section", "paper", None);
        let heading = create("h3", "", Some(&paper.source));
        if !paper.source.contains(&paper.title) {
            append(
                &heading,
                &[&create("i", "", Some(&format!(", {}", paper.title)))],
            );
        }
        let list = create("ol", "figure-list", None);
        append(&section, &[&heading, &list]);
        for shown in paper.shown() {
            let figure = shown.figure;
            let item = create("li", "figure", None);
            attr(&item, "data-figure", &figure.number.to_string());
            let number = create(
                "span",
                "figure-number",
                Some(&format!("Fig. {}", figure.number)),
            );
            let caption = create("p", "figure-caption", Some(&figure.caption));
            append(&item, &[&number, &caption]);
            let ours = create("div", "ours", None);
            for preset in &shown.presets {
                let a = create("a", "ours-shell", None);
                attr(
                    &a,
                    "href",
                    &format!("#{}", link::encode(preset, &preset.spec)),
                );
                let picture: HtmlImageElement = typed("img", "");
                attr(&picture, "data-picture", preset.id);
                picture.set_alt("");
                picture.set_width(96);
                picture.set_height(96);
                append(&a, &[&picture, &create("span", "", Some(&preset.name))]);
                append(&ours, &[&a]);
            }
            for (story, index) in &shown.steps {
                let a = create(
                    "a",
                    "ours-step",
                    Some(&format!("{}, step {}", story.title, index + 1)),
                );
                attr(
                    &a,
                    "href",
                    &format!("#story={}&step={}", story.id, index + 1),
                );
                append(&ours, &[&a]);
            }
            if let Some(why) = &figure.why_not {
                append(
                    &ours,
                    &[&create(
                        "p",
                        "why-not",
                        Some(&format!("Not reproduced. {why}")),
                    )],
                );
            }
            append(&item, &[&ours]);
            append(&list, &[&item]);
        }
        append(container, &[&section]);
    }
}
