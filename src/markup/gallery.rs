//! The gallery: the stories of species/stories/, each a card with its title, its steps and a
//! line about it; then every preset in species/, grouped by where it comes from, each a card
//! with its name, the figure it reproduces, a line of description and a place for a picture
//! of the shell (`img[data-picture]`, filled as the workers grow it). The cards are plain
//! links to the preset's or the story's fragment, so the browser's history does the
//! navigation.

use super::element::Element;
use crate::presets::presets;
use crate::share::link;
use crate::stories::stories;

/// The gallery's sections: the stories, then one per group of presets.
pub fn gallery() -> Vec<Element> {
    let story_cards = stories().iter().map(|story| {
        Element::new("a", "story-card")
            .attr("href", format!("#story={}", story.id))
            .attr("data-story", story.id)
            .with([
                Element::new("h3", "").text(&story.title),
                Element::new("p", "source").text(format!("{} steps", story.steps.len())),
                Element::new("p", "description").text(&story.summary),
            ])
    });
    let mut groups: Vec<(&str, Vec<Element>)> = Vec::new();
    for preset in presets() {
        let title = preset.group.title();
        if groups.last().map(|(t, _)| *t) != Some(title) {
            groups.push((title, Vec::new()));
        }
        let card = Element::new("a", "card")
            .attr("href", format!("#{}", link::encode(preset, &preset.spec)))
            .attr("data-preset", preset.id)
            .with([
                Element::new("img", "picture")
                    .attr("data-picture", preset.id)
                    .attr("alt", format!("{}, grown from the model", preset.name))
                    .attr("width", "256")
                    .attr("height", "256"),
                Element::new("h3", "").text(&preset.name),
                Element::new("p", "source").text(&preset.source),
                Element::new("p", "description").text(&preset.description),
            ]);
        if let Some((_, cards)) = groups.last_mut() {
            cards.push(card);
        }
    }
    let presets = groups
        .into_iter()
        .map(|(title, cards)| section("group", title, cards));
    std::iter::once(section("group stories", "Stories", story_cards.collect()))
        .chain(presets)
        .collect()
}

/// A section of `class` headed `title`, with a grid of `cards`.
fn section(class: &'static str, title: &str, cards: Vec<Element>) -> Element {
    Element::new("section", class).with([
        Element::new("h2", "").text(title),
        Element::new("div", "cards").with(cards),
    ])
}
