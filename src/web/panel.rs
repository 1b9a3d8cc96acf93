//! The parameter panel on the page: the controls the core chooses for the spec's fields
//! ([`crate::work::panel_controls`]), grouped as the table groups them. Every change is handed
//! back as `key=value` text and read exactly as a link's value would be, and a slider also
//! hands back every value it passes while it is dragged.

use super::dom::{append, attr, clear, create, typed};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Section, display};
use crate::work::panel_controls::{self, Shown, choice_text, colour_text, panel_fields};
use crate::work::session::Edit;
use serde_json::Value;
use std::collections::BTreeMap;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{Element, Event, HtmlInputElement, HtmlOptionElement, HtmlSelectElement};

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

/// A slider over [lo, hi] with a number field beside it: the number follows the slider while
/// it moves, every value passed is reported as moving, and either reports its value when set.
fn slider(
    field: &'static Field,
    id: &str,
    row: &Element,
    on_change: &OnChange,
    (lo, hi, positions, title): (f64, f64, u64, &str),
) -> Control {
    let range: HtmlInputElement = typed("input", "slider");
    range.set_type("range");
    range.set_min("0");
    range.set_max(&positions.to_string());
    attr(&range, "aria-label", &field.label());
    attr(row, "title", title);
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

impl Panel {
    /// Builds the panel for `spec` inside `container`.
    pub fn build(container: &Element, spec: &ShellSpec, on_change: &OnChange) -> Self {
        clear(container);
        let (fields, leaves) = panel_fields(spec);
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
            let name = create("label", "", Some(&field.label()));
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
        match panel_controls::control(field) {
            panel_controls::Control::Slider {
                lo,
                hi,
                positions,
                title,
            } => slider(field, id, row, on_change, (lo, hi, positions, &title)),
            panel_controls::Control::Check => {
                let check: HtmlInputElement = typed("input", "check");
                check.set_type("checkbox");
                check.set_id(id);
                report(&check, field.key, on_change, |e| {
                    input(e).map(|i| i.checked().to_string())
                });
                Control::Check(check)
            }
            panel_controls::Control::Choice(options) => {
                let select: HtmlSelectElement = typed("select", "choice");
                select.set_id(id);
                for o in options {
                    let option: HtmlOptionElement = typed("option", "");
                    option.set_value(o);
                    option.set_text(&choice_text(o));
                    append(&select, &[&option]);
                }
                report(&select, field.key, on_change, |e| {
                    e.target()
                        .and_then(|t| t.dyn_into::<HtmlSelectElement>().ok())
                        .map(|s| s.value())
                });
                Control::Select(select)
            }
            panel_controls::Control::Colour => {
                let colour: HtmlInputElement = typed("input", "colour");
                colour.set_type("color");
                colour.set_id(id);
                report(&colour, field.key, on_change, |e| {
                    input(e).map(|i| colour_text(&i.value()))
                });
                Control::Input(colour)
            }
            panel_controls::Control::Text => {
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
        let (fields, _) = panel_fields(spec);
        fields.len() == self.controls.len()
            && fields
                .iter()
                .zip(&self.controls)
                .all(|(a, (b, _))| a.key == b.key)
    }

    /// Shows the values of `spec`.
    pub fn refresh(&self, spec: &ShellSpec) {
        self.refresh_with(&panel_fields(spec).1);
    }

    fn refresh_with(&self, leaves: &BTreeMap<String, Value>) {
        for (field, control) in &self.controls {
            let Some(value) = leaves.get(field.key) else {
                continue;
            };
            match (control, panel_controls::shown(field, value)) {
                (
                    Control::Slider { range, number },
                    Shown::Slider {
                        position,
                        number: text,
                    },
                ) => {
                    range.set_value(&position);
                    number.set_value(&text);
                }
                (Control::Check(c), Shown::Check(checked)) => c.set_checked(checked),
                (Control::Select(s), Shown::Text(text)) => s.set_value(&text),
                (Control::Input(i), Shown::Text(text)) => i.set_value(&text),
                _ => {}
            }
        }
    }
}
