//! What the parameter panel shows, from the spec's own description of its fields
//! (`spec::fields`): for every field the current spec has, in table order, a control of the
//! kind its values take (a slider with a number beside it over a range, a check box, a choice,
//! a colour, a text), labelled with the paper's symbol and name, and the value it shows. The
//! page builds the elements and hands every change back as link text.

use crate::share::link::{format_value, leaves};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Kind, display, fields};
use serde_json::Value;
use std::collections::BTreeMap;

/// Fields with a control of their own elsewhere on the page.
const ELSEWHERE: &[&str] = &["growth.speed"];
/// The widest range of whole numbers a slider steps through one by one.
const MOST_SLIDER_STEPS: u64 = 5000;

/// The fields of `spec` the panel shows, in table order, and the spec's values by key.
pub fn panel_fields(spec: &ShellSpec) -> (Vec<&'static Field>, BTreeMap<String, Value>) {
    let leaves = leaves(spec);
    let fields = fields(spec.form.kind())
        .filter(|f| leaves.contains_key(f.key) && !ELSEWHERE.contains(&f.key))
        .collect();
    (fields, leaves)
}

/// The control a field gets.
#[derive(Clone, Debug, PartialEq)]
pub enum Control {
    /// A slider over `lo..=hi` in `positions` steps, a number field beside it, and the range
    /// in words for its title.
    Slider {
        lo: f64,
        hi: f64,
        positions: u64,
        title: String,
    },
    Check,
    /// A choice among these values, each shown by [`choice_text`].
    Choice(&'static [&'static str]),
    /// A colour picker; its value reaches the link without its '#'.
    Colour,
    Text,
}

/// The control `field` gets: a slider for real numbers and for whole numbers over a short
/// range.
pub fn control(field: &Field) -> Control {
    let slider = |lo: f64, hi: f64| Control::Slider {
        lo,
        hi,
        positions: field.kind.slider_position(hi) as u64,
        title: format!("from {} to {}", display(lo), display(hi)),
    };
    match field.kind {
        Kind::Real { min, max, .. } => slider(min, max),
        Kind::Integer { min, max } if max - min <= MOST_SLIDER_STEPS => {
            slider(min as f64, max as f64)
        }
        Kind::Flag => Control::Check,
        Kind::Choice(options) => Control::Choice(options),
        Kind::Colour => Control::Colour,
        _ => Control::Text,
    }
}

/// How a choice's value is shown in its list.
pub fn choice_text(value: &str) -> String {
    value.replace('_', " ")
}

/// A colour picker's value (`#rrggbb`) as link text.
pub fn colour_text(picked: &str) -> String {
    picked.trim_start_matches('#').to_string()
}

/// What a field's control shows for `value`.
#[derive(Clone, Debug, PartialEq)]
pub enum Shown {
    /// The slider's position (a whole step) and the number beside it.
    Slider {
        position: String,
        number: String,
    },
    Check(bool),
    /// A choice's, a colour's (with its '#') or a text's value.
    Text(String),
}

/// What `field`'s control shows for `value`.
pub fn shown(field: &Field, value: &Value) -> Shown {
    let text = format_value(value);
    match control(field) {
        Control::Slider { .. } => Shown::Slider {
            position: field
                .kind
                .slider_position(value.as_f64().unwrap_or_default())
                .round()
                .to_string(),
            number: text,
        },
        Control::Check => Shown::Check(value.as_bool().unwrap_or_default()),
        Control::Colour => Shown::Text(format!("#{text}")),
        Control::Choice(_) | Control::Text => Shown::Text(text),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::preset;

    fn field(spec: &ShellSpec, key: &str) -> &'static Field {
        panel_fields(spec)
            .0
            .into_iter()
            .find(|f| f.key == key)
            .unwrap_or_else(|| panic!("no field {key}"))
    }

    #[test]
    fn the_panel_shows_the_specs_fields_but_the_speed_which_has_its_own_control() {
        let spec = &preset("oliva-porphyria").expect("a preset").spec;
        let (fields, leaves) = panel_fields(spec);
        assert!(fields.iter().all(|f| leaves.contains_key(f.key)));
        assert!(fields.iter().any(|f| f.key == "pattern.model.d_a"));
        assert!(!fields.iter().any(|f| f.key == "growth.speed"));
    }

    #[test]
    fn real_numbers_get_a_slider_whose_number_is_the_links_value() {
        let spec = &preset("oliva-porphyria").expect("a preset").spec;
        let d_a = field(spec, "pattern.model.d_a");
        let Control::Slider { lo, hi, title, .. } = control(d_a) else {
            panic!("a real number gets a slider");
        };
        assert_eq!((lo, hi), (0.0, 0.5), "the table's range");
        assert_eq!(title, "from 0 to 0.5");
        let Shown::Slider { number, position } = shown(d_a, &Value::from(0.15)) else {
            panic!("a slider shows a position and a number");
        };
        assert_eq!(number, "0.15");
        assert!(position.parse::<u64>().is_ok(), "a whole step: {position}");
    }

    #[test]
    fn flags_choices_and_colours_get_their_own_controls() {
        let flag = Field {
            key: "k",
            section: crate::spec::fields::Section::Growth,
            symbol: "",
            name: "a flag",
            kind: Kind::Flag,
        };
        assert_eq!(control(&flag), Control::Check);
        assert_eq!(shown(&flag, &Value::Bool(true)), Shown::Check(true));
        let colour = Field {
            kind: Kind::Colour,
            ..flag
        };
        assert_eq!(
            shown(&colour, &Value::from("a0522d")),
            Shown::Text("#a0522d".into())
        );
        assert_eq!(colour_text("#a0522d"), "a0522d");
        assert_eq!(choice_text("growing_edge"), "growing edge");
        let wide = Field {
            kind: Kind::Integer {
                min: 0,
                max: 100_000,
            },
            ..flag
        };
        assert_eq!(control(&wide), Control::Text, "too many steps for a slider");
    }
}
