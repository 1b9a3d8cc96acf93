//! The papers' figures beside ours, a section of the gallery: paper by paper, each figure's
//! number and caption in our words, with the presets that reproduce it (a place for their
//! pictures, drawn with the gallery's cards) and the stories' steps that show it, or why none
//! does. Built from the core's join of species/papers.json with the presets and stories
//! ([`crate::papers`]).

use super::element::Element;
use crate::papers::{Shown, papers};
use crate::share::link;

/// One section per paper.
pub fn figures() -> Vec<Element> {
    papers()
        .iter()
        .map(|paper| {
            let mut heading = Element::new("h3", "").text(&paper.source);
            if !paper.source.contains(&paper.title) {
                heading = heading.with([Element::new("i", "").text(format!(", {}", paper.title))]);
            }
            let list = Element::new("ol", "figure-list").with(paper.shown().iter().map(figure));
            Element::new("section", "paper").with([heading, list])
        })
        .collect()
}

/// A figure of a paper and what of ours shows it.
fn figure(shown: &Shown) -> Element {
    let figure = shown.figure;
    let shells = shown.presets.iter().map(|preset| {
        Element::new("a", "ours-shell")
            .attr("href", format!("#{}", link::encode(preset, &preset.spec)))
            .with([
                Element::new("img", "")
                    .attr("data-picture", preset.id)
                    .attr("alt", "")
                    .attr("width", "96")
                    .attr("height", "96"),
                Element::new("span", "").text(&preset.name),
            ])
    });
    let steps = shown.steps.iter().map(|(story, index)| {
        Element::new("a", "ours-step")
            .text(format!("{}, step {}", story.title, index + 1))
            .attr("href", format!("#story={}&step={}", story.id, index + 1))
    });
    let why_not = (figure.why_not.iter())
        .map(|why| Element::new("p", "why-not").text(format!("Not reproduced. {why}")));
    Element::new("li", "figure")
        .attr("data-figure", figure.number.to_string())
        .with([
            Element::new("span", "figure-number").text(format!("Fig. {}", figure.number)),
            Element::new("p", "figure-caption").text(&figure.caption),
            Element::new("div", "ours").with(shells.chain(steps).chain(why_not)),
        ])
}
