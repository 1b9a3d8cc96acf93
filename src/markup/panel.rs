//! The parameter panel's elements: for every field the spec has (in table order,
//! [`panel_fields`]), a row in its section's group with its label and the control the core
//! chooses for it ([`control`]): a slider with a number beside it, a check box, a choice, a
//! colour, a text. The page wires each control (found by [`field_id`]) to hand changes back as
//! link text.
//!
//! [`panel_fields`]: crate::work::panel_controls::panel_fields

use super::element::Element;
use crate::spec::fields::{Field, Section};
use crate::work::panel_controls::{Control, choice_text, control};

/// The id of the control that holds `key`'s value (a slider's number field).
pub fn field_id(key: &str) -> String {
    format!("field-{key}")
}

/// The panel's groups of rows, one group per section, for `fields` in table order.
pub fn panel(fields: &[&'static Field]) -> Vec<Element> {
    let mut groups: Vec<(Section, Vec<Element>)> = Vec::new();
    for field in fields {
        if groups.last().map(|(s, _)| *s) != Some(field.section) {
            groups.push((field.section, Vec::new()));
        }
        if let Some((_, rows)) = groups.last_mut() {
            rows.push(row(field));
        }
    }
    (groups.into_iter())
        .map(|(section, rows)| {
            Element::new("details", "params")
                .attr("open", "")
                .with([Element::new("summary", "").text(section.title())])
                .with(rows)
        })
        .collect()
}

/// The options of a choice among `fields` (the parameter map's axes), grouped by the panel's
/// sections, each a field's key shown by its label.
pub fn field_options<'a>(fields: impl IntoIterator<Item = &'a Field>) -> Vec<Element> {
    let mut groups: Vec<(Section, Element)> = Vec::new();
    for field in fields {
        if groups.last().map(|(s, _)| *s) != Some(field.section) {
            let group = Element::new("optgroup", "").attr("label", field.section.title());
            groups.push((field.section, group));
        }
        if let Some((_, group)) = groups.last_mut() {
            let option = Element::new("option", "").attr("value", field.key);
            group.children.push(option.text(field.label()));
        }
    }
    groups.into_iter().map(|(_, group)| group).collect()
}

/// A field's row: its label and its control.
fn row(field: &Field) -> Element {
    let id = field_id(field.key);
    let row = Element::new("div", "field").attr("data-key", field.key);
    let label = Element::new("label", "")
        .text(field.label())
        .attr("for", id.clone());
    let input = |class, kind| {
        Element::new("input", class)
            .attr("type", kind)
            .attr("id", id.clone())
    };
    match control(field) {
        Control::Slider {
            lo,
            hi,
            positions,
            title,
        } => row.attr("title", title).with([
            label,
            Element::new("input", "slider")
                .attr("type", "range")
                .attr("min", "0")
                .attr("max", positions.to_string())
                .attr("aria-label", field.label()),
            input("number", "number")
                .attr("min", lo.to_string())
                .attr("max", hi.to_string())
                .attr("step", "any"),
        ]),
        Control::Check => row.with([label, input("check", "checkbox")]),
        Control::Choice(options) => row.with([
            label,
            Element::new("select", "choice")
                .attr("id", id.clone())
                .with((options.iter()).map(|o| {
                    Element::new("option", "")
                        .attr("value", *o)
                        .text(choice_text(o))
                })),
        ]),
        Control::Colour => row.with([label, input("colour", "color")]),
        Control::Text => row.with([label, input("text", "text").attr("spellcheck", "false")]),
    }
}
