//! The parameter panel, generated from the spec's own description of its fields
//! (`spec::fields`): for every field the current spec has, grouped as the table groups them, a
//! control with the paper's symbol and name, its range, and a number beside each slider. Every
//! change is handed back as `key=value` text and read exactly as a link's value would be, and a
//! slider also hands back every value it passes while it is dragged.

use super::dom::{append, attr, clear, create, typed};
use crate::share::link::{format_value, leaves};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Kind, Section, display, fields};
use crate::work::session::Edit;
use serde_json::Value;
use std::collections::BTreeMap;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{Element, Event, HtmlInputElement, HtmlOptionElement, HtmlSelectElement};

/// Fields with a control of their own elsewhere on the page.
const ELSEWHERE: &[&str] = &["growth.speed"];

/// What the panel calls when a value changes: (key, value as link text, which change).
pub type OnChange = Rc<dyn Fn(&str, String, Edit)>;

/// The controls that show one field.
enum Control {
    Slider {
        range: HtmlInputElement,
        number: HtmlInputElement,
    },
    Input(HtmlInputElement),
    Check(HtmlInputElement),
    Select(HtmlSelectElement),
}

pub struct Panel {
    controls: Vec<(&'static Field, Control)>,
}

/// The fields the spec has, in table order.
fn present(spec: &ShellSpec) -> (Vec<&'static Field>, BTreeMap<String, Value>) {
    let leaves = leaves(spec);
    let fields = fields(spec.form.kind())
        .filter(|f| leaves.contains_key(f.key) && !ELSEWHERE.contains(&f.key))
        .collect();
    (fields, leaves)
}

fn listen(target: &web_sys::EventTarget, kind: &str, f: impl FnMut(Event) + 'static) {
    let closure = Closure::<dyn FnMut(Event)>::new(f);
    // Adding a listener to an element of the page cannot fail.
    let _ = target.add_event_listener_with_callback(kind, closure.as_ref().unchecked_ref());
    closure.forget();
}

/// The input element an event came from.
fn input(e: &Event) -> Option<HtmlInputElement> {
    e.target()
        .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
}

/// Hands `key` and the value `read` takes from a change event to `on_change`.
fn report(
    target: &web_sys::EventTarget,
    key: &'static str,
    on_change: &OnChange,
    read: fn(&Event) -> Option<String>,
) {
    let on_change = Rc::clone(on_change);
    listen(target, "change", move |e| {
        if let Some(v) = read(&e) {
            on_change(key, v, Edit::Set);
        }
    });
}

/// Whether a field gets a slider (whole numbers only over a short range).
fn has_slider(kind: Kind) -> bool {
    match kind {
        Kind::Real { .. } => true,
        Kind::Integer { min, max } => max - min <= 5000,
        _ => false,
    }
}

/// A slider over [lo, hi] with a number field beside it: the number follows the slider while
/// it moves, every value passed is reported as moving, and either reports its value when set.
fn slider(
    field: &'static Field,
    id: &str,
    row: &Element,
    on_change: &OnChange,
    lo: f64,
    hi: f64,
) -> Control {
    let range: HtmlInputElement = typed("input", "slider");
    range.set_type("range");
    range.set_min("0");
    range.set_max(&(field.kind.slider_position(hi) as u64).to_string());
    attr(&range, "aria-label", &label(field));
    attr(
        row,
        "title",
        &format!("from {} to {}", display(lo), display(hi)),
    );
    let number: HtmlInputElement = typed("input", "number");
    number.set_type("number");
    number.set_id(id);
    number.set_min(&lo.to_string());
    number.set_max(&hi.to_string());
    number.set_step("any");
    let (shown, kind, key) = (number.clone(), field.kind, field.key);
    let moving = Rc::clone(on_change);
    listen(&range, "input", move |e| {
        if let Some(p) = input(&e).and_then(|i| i.value().parse::<f64>().ok()) {
            let value = display(kind.slider_value(p));
            shown.set_value(&value);
            moving(key, value, Edit::Moving);
        }
    });
    let (value, slid) = (number.clone(), Rc::clone(on_change));
    listen(&range, "change", move |_| {
        slid(key, value.value(), Edit::Set)
    });
    report(&number, field.key, on_change, |e| {
        input(e).map(|i| i.value())
    });
    Control::Slider { range, number }
}

/// A field's name with the paper's symbol before it, where it has one.
pub(super) fn label(field: &Field) -> String {
    if field.symbol.is_empty() {
        field.name.to_string()
    } else {
        format!("{} — {}", field.symbol, field.name)
    }
}

impl Panel {
    /// Builds the panel for `spec` inside `container`.
    pub fn build(container: &Element, spec: &ShellSpec, on_change: &OnChange) -> Self {
        clear(container);
        let (fields, leaves) = present(spec);
        let mut controls = Vec::new();
        let mut group: Option<(Section, Element)> = None;
        for field in fields {
            if group.as_ref().map(|g| g.0) != Some(field.section) {
                let details = create("details", "params", None);
                attr(&details, "open", "");
                append(
                    &details,
                    &[&create("summary", "", Some(field.section.title()))],
                );
                append(container, &[&details]);
                group = Some((field.section, details.into()));
            }
            let row = create("div", "field", None);
            attr(&row, "data-key", field.key);
            let id = format!("field-{}", field.key);
            let name = create("label", "", Some(&label(field)));
            attr(&name, "for", &id);
            let control = Self::control(field, &id, &row, on_change);
            append(&row, &[&name]);
            match &control {
                Control::Slider { range, number } => append(&row, &[range, number]),
                Control::Input(i) | Control::Check(i) => append(&row, &[i]),
                Control::Select(s) => append(&row, &[s]),
            }
            if let Some((_, g)) = &group {
                append(g, &[&row]);
            }
            controls.push((field, control));
        }
        let panel = Self { controls };
        panel.refresh_with(&leaves);
        panel
    }

    fn control(field: &'static Field, id: &str, row: &Element, on_change: &OnChange) -> Control {
        match field.kind {
            Kind::Real { min, max, .. } if has_slider(field.kind) => {
                slider(field, id, row, on_change, min, max)
            }
            Kind::Integer { min, max } if has_slider(field.kind) => {
                slider(field, id, row, on_change, min as f64, max as f64)
            }
            Kind::Flag => {
                let check: HtmlInputElement = typed("input", "check");
                check.set_type("checkbox");
                check.set_id(id);
                report(&check, field.key, on_change, |e| {
                    input(e).map(|i| i.checked().to_string())
                });
                Control::Check(check)
            }
            Kind::Choice(options) => {
                let select: HtmlSelectElement = typed("select", "choice");
                select.set_id(id);
                for o in options {
                    let option: HtmlOptionElement = typed("option", "");
                    option.set_value(o);
                    option.set_text(&o.replace('_', " "));
                    append(&select, &[&option]);
                }
                report(&select, field.key, on_change, |e| {
                    e.target()
                        .and_then(|t| t.dyn_into::<HtmlSelectElement>().ok())
                        .map(|s| s.value())
                });
                Control::Select(select)
            }
            Kind::Colour => {
                let colour: HtmlInputElement = typed("input", "colour");
                colour.set_type("color");
                colour.set_id(id);
                report(&colour, field.key, on_change, |e| {
                    input(e).map(|i| i.value().trim_start_matches('#').to_string())
                });
                Control::Input(colour)
            }
            _ => {
                let text: HtmlInputElement = typed("input", "text");
                text.set_type("text");
                text.set_id(id);
                attr(&text, "spellcheck", "false");
                report(&text, field.key, on_change, |e| input(e).map(|i| i.value()));
                Control::Input(text)
            }
        }
    }

    /// Whether `spec` has exactly the fields this panel shows (else it must be rebuilt).
    pub fn fits(&self, spec: &ShellSpec) -> bool {
        let (fields, _) = present(spec);
        fields.len() == self.controls.len()
            && fields
                .iter()
                .zip(&self.controls)
                .all(|(a, (b, _))| a.key == b.key)
    }

    /// Shows the values of `spec`.
    pub fn refresh(&self, spec: &ShellSpec) {
        self.refresh_with(&present(spec).1);
    }

    fn refresh_with(&self, leaves: &BTreeMap<String, Value>) {
        for (field, control) in &self.controls {
            let Some(value) = leaves.get(field.key) else {
                continue;
            };
            let text = format_value(value);
            match control {
                Control::Slider { range, number } => {
                    let x = value.as_f64().unwrap_or_default();
                    range.set_value(&field.kind.slider_position(x).round().to_string());
                    number.set_value(&text);
                }
                Control::Check(c) => c.set_checked(value.as_bool().unwrap_or_default()),
                Control::Select(s) => s.set_value(&text),
                Control::Input(i) if field.kind == Kind::Colour => i.set_value(&format!("#{text}")),
                Control::Input(i) => i.set_value(&text),
            }
        }
    }
}
