//! The page's elements as the core builds them (`seashells_core::markup`): every card and
//! every link of the gallery and of the papers' figures leads where it says, and every field
//! of the panel has one labelled control of its kind, read here without a browser.

use seashells_core::markup::{
    Element, Shows, field_id, field_options, figures, gallery, map_tile, panel, tile,
};
use seashells_core::papers::papers;
use seashells_core::presets::presets;
use seashells_core::share::link;
use seashells_core::stories::{stories, story};
use seashells_core::variation::map_plan::Label;
use seashells_core::variation::parameter_map::parameters;
use seashells_core::work::panel_controls::{Control, control, panel_fields};
use std::collections::HashSet;

/// Every element of `sections` of `class`.
fn of_class<'a>(sections: &'a [Element], class: &str) -> Vec<&'a Element> {
    (sections.iter())
        .flat_map(Element::all)
        .filter(|e| e.class == class)
        .collect()
}

/// Asserts that no heading of `place`'s groups heads two of them.
fn each_once<T: PartialEq + std::fmt::Debug>(headings: &[T], place: &str) {
    for (i, heading) in headings.iter().enumerate() {
        assert!(
            !headings[..i].contains(heading),
            "{heading:?} twice in {place}"
        );
    }
}

/// The fragment a link element leads to.
fn href(e: &Element) -> &str {
    e.get("href").expect("a link has an address")
}

/// Asserts that `a` leads to `id`'s preset as it stands in species/, read as a link is.
fn leads_to_preset(a: &Element, id: &str) {
    let decoded = link::decode(href(a));
    assert!(decoded.problems.is_empty(), "{id}: {:?}", decoded.problems);
    assert_eq!(decoded.preset.id, id);
    assert_eq!(
        decoded.spec, decoded.preset.spec,
        "{id}: the preset's own values"
    );
}

#[test]
fn every_preset_has_one_card_leading_to_it_under_its_group() {
    let sections = gallery();
    let cards = of_class(&sections, "card");
    assert_eq!(cards.len(), presets().len());
    for preset in presets() {
        let card = (cards.iter())
            .find(|c| c.get("data-preset") == Some(preset.id))
            .unwrap_or_else(|| panic!("no card for {}", preset.id));
        leads_to_preset(card, preset.id);
        let picture = &card.children[0];
        assert_eq!(picture.tag, "img");
        assert_eq!(picture.get("data-picture"), Some(preset.id));
        assert!(picture.get("alt").is_some_and(|a| a.contains(&preset.name)));
        let texts: Vec<&String> = card
            .children
            .iter()
            .filter_map(|c| c.text.as_ref())
            .collect();
        assert_eq!(
            texts,
            [&preset.name, &preset.source, &preset.description],
            "{}",
            preset.id
        );
        let section = (sections.iter())
            .find(|s| s.all().iter().any(|e| std::ptr::eq(*e, *card)))
            .expect("a card is in a section");
        assert_eq!(
            section.children[0].text.as_deref(),
            Some(preset.group.title())
        );
    }
    let titles: Vec<_> = sections.iter().map(|s| &s.children[0].text).collect();
    each_once(&titles, "the gallery");
}

#[test]
fn every_story_has_a_card_that_opens_it() {
    let sections = gallery();
    assert_eq!(sections[0].children[0].text.as_deref(), Some("Stories"));
    let cards = of_class(&sections, "story-card");
    assert_eq!(cards.len(), stories().len());
    for card in cards {
        let id = href(card).strip_prefix("#story=").expect("a story's link");
        let found = story(id).expect("the story exists");
        assert_eq!(card.get("data-story"), Some(found.id));
        assert_eq!(card.children[0].text.as_deref(), Some(found.title.as_str()));
    }
}

#[test]
fn every_figure_of_every_paper_is_listed_once_with_what_shows_it_or_why_not() {
    let sections = figures();
    assert_eq!(sections.len(), papers().len());
    for (section, paper) in sections.iter().zip(papers()) {
        assert_eq!(
            section.children[0].text.as_deref(),
            Some(paper.source.as_str())
        );
        let listed = of_class(std::slice::from_ref(section), "figure");
        assert_eq!(listed.len(), paper.shown().len(), "{}", paper.source);
        for (item, shown) in listed.iter().zip(paper.shown()) {
            let number = shown.figure.number.to_string();
            assert_eq!(item.get("data-figure"), Some(number.as_str()));
            let ours = &item.children[2];
            let shells: Vec<_> = (ours.children.iter())
                .filter(|e| e.class == "ours-shell")
                .collect();
            assert_eq!(shells.len(), shown.presets.len());
            for (a, preset) in shells.iter().zip(&shown.presets) {
                leads_to_preset(a, preset.id);
            }
            let steps: Vec<_> = (ours.children.iter())
                .filter(|e| e.class == "ours-step")
                .collect();
            assert_eq!(steps.len(), shown.steps.len(), "fig. {number}");
            for (a, (story, index)) in steps.iter().zip(&shown.steps) {
                let step = format!("#story={}&step={}", story.id, index + 1);
                assert_eq!(href(a), step);
            }
            let why_not = ours.children.iter().any(|e| e.class == "why-not");
            assert_eq!(why_not, shown.figure.why_not.is_some(), "fig. {number}");
            assert!(
                !ours.children.is_empty(),
                "fig. {number} shows something or says why not"
            );
        }
    }
}

#[test]
fn every_field_of_every_preset_has_one_labelled_control_of_its_kind() {
    for preset in presets() {
        let (fields, _) = panel_fields(&preset.spec);
        let groups = panel(&fields);
        let rows = of_class(&groups, "field");
        assert_eq!(rows.len(), fields.len(), "{}", preset.id);
        let mut ids = HashSet::new();
        for (row, field) in rows.iter().zip(&fields) {
            assert_eq!(row.get("data-key"), Some(field.key));
            let id = field_id(field.key);
            let label = &row.children[0];
            assert_eq!(label.tag, "label");
            assert_eq!(label.get("for"), Some(id.as_str()));
            assert_eq!(label.text.as_deref(), Some(field.label().as_str()));
            let with_id: Vec<_> = (row.all().into_iter())
                .filter(|e| e.get("id").is_some())
                .collect();
            assert_eq!(
                with_id.len(),
                1,
                "{}: one control holds the value",
                field.key
            );
            let held = with_id[0];
            assert_eq!(held.get("id"), Some(id.as_str()));
            assert!(
                ids.insert(id.clone()),
                "{id} twice in {}'s panel",
                preset.id
            );
            match control(field) {
                Control::Slider {
                    lo, hi, positions, ..
                } => {
                    let range = &row.children[1];
                    assert_eq!(range.get("type"), Some("range"));
                    // The page finds the slider as the number field's previous sibling.
                    assert_eq!(&row.children[2], held);
                    assert_eq!(range.get("max"), Some(positions.to_string().as_str()));
                    assert_eq!(held.get("type"), Some("number"));
                    let bound = |k| held.get(k).and_then(|v| v.parse::<f64>().ok());
                    assert_eq!((bound("min"), bound("max")), (Some(lo), Some(hi)));
                }
                Control::Check => assert_eq!(held.get("type"), Some("checkbox")),
                Control::Colour => assert_eq!(held.get("type"), Some("color")),
                Control::Text => assert_eq!(held.get("type"), Some("text")),
                Control::Choice(options) => {
                    assert_eq!(held.tag, "select");
                    let offered: Vec<_> = held
                        .children
                        .iter()
                        .filter_map(|o| o.get("value"))
                        .collect();
                    assert_eq!(offered, options, "{}", field.key);
                }
            }
        }
        let sections: Vec<_> = groups.iter().map(|g| g.children[0].text.clone()).collect();
        each_once(&sections, preset.id);
    }
}

#[test]
fn the_map_offers_every_parameter_once_under_its_section() {
    for preset in presets() {
        let fields: Vec<_> = parameters(&preset.spec)
            .into_iter()
            .map(|(f, _)| f)
            .collect();
        let groups = field_options(fields.iter().copied());
        let offered: Vec<(&str, &str)> = (groups.iter())
            .flat_map(|g| {
                let section = g.get("label").expect("a group is labelled");
                g.children
                    .iter()
                    .map(move |o| (section, o.get("value").expect("a value")))
            })
            .collect();
        let expected: Vec<_> = (fields.iter())
            .map(|f| (f.section.title(), f.key))
            .collect();
        assert_eq!(offered, expected, "{}", preset.id);
        let sections: Vec<_> = groups.iter().map(|g| g.get("label")).collect();
        each_once(&sections, preset.id);
    }
}

#[test]
fn a_map_tile_links_to_its_shell_and_marks_the_presets_near_it() {
    let label = Label {
        text: "W 2.0, T 1.5".into(),
        apart: true,
        current: true,
        landmarks: "Turbinate shell".into(),
        marks: vec![(25.0, 75.04, "turbinate")],
    };
    let a = map_tile(7, "v=1&preset=turbinate", &label, Shows::Shell);
    assert_eq!(a.class, "tile apart current");
    assert_eq!(href(&a), "#v=1&preset=turbinate");
    assert_eq!(a.get("data-job"), Some("7"));
    assert_eq!(a.get("aria-label"), Some("W 2.0, T 1.5"));
    assert_eq!(a.get("aria-current"), Some("true"));
    assert_eq!(a.children[0].tag, "img");
    assert_eq!(a.children[1].text.as_deref(), Some("Turbinate shell"));
    let marker = &a.children[2];
    assert_eq!(marker.get("data-name"), Some("turbinate"));
    assert_eq!(
        marker.get("style"),
        None,
        "the page's policy refuses inline styles"
    );
    let at = |(name, value): &(&str, String)| (name.to_string(), value.clone());
    let style: Vec<_> = marker.style.iter().map(at).collect();
    assert_eq!(
        style,
        [
            ("left".into(), "25.0%".into()),
            ("top".into(), "75.0%".into())
        ]
    );
    let plain = Label {
        apart: false,
        current: false,
        landmarks: String::new(),
        marks: Vec::new(),
        ..label
    };
    let a = map_tile(8, "x", &plain, Shows::Pattern);
    assert_eq!(a.class, "tile");
    assert_eq!(a.get("aria-current"), None);
    assert_eq!(a.children.len(), 1, "a pattern's canvas alone");
    assert_eq!(a.children[0].tag, "canvas");
    let offspring = tile(9, None, "the parent", "tile parent", true, Shows::Shell);
    assert_eq!(
        offspring.get("href"),
        None,
        "a tile that cannot be chosen links nowhere"
    );
    assert_eq!(offspring.get("aria-current"), Some("true"));
}
