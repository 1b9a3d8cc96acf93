//! The parameter panel on the page: the rows the core builds for the spec's fields
//! ([`crate::markup::panel`]), wired here. Every change is handed back as `key=value` text and
//! read exactly as a link's value would be, and a slider also hands back every value it passes
//! while it is dragged.

use super::dom::{build, clear};
use super::page::element_as;
use crate::markup;
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, display};
use crate::work::panel_controls::{self, Shown, colour_text, panel_fields};
use crate::work::session::Edit;
use serde_json::Value;
use std::collections::BTreeMap;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{Element, Event, HtmlInputElement, HtmlSelectElement};

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

/// Wires a slider and the number field beside it: the number follows the slider while it
/// moves, every value passed is reported as moving, and either reports its value when set.
fn slider(
    field: &'static Field,
    number: HtmlInputElement,
    on_change: &OnChange,
) -> Option<Control> {
    let range: HtmlInputElement = number.previous_element_sibling()?.dyn_into().ok()?;
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
    Some(Control::Slider { range, number })
}

impl Panel {
    /// Builds the panel for `spec` inside `container` (the core's [`markup::panel`]) and wires
    /// its controls to `on_change`.
    pub fn build(container: &Element, spec: &ShellSpec, on_change: &OnChange) -> Self {
        clear(container);
        let (fields, leaves) = panel_fields(spec);
        build(container, &markup::panel(&fields));
        let controls = (fields.into_iter())
            .filter_map(|field| match Self::wire(field, on_change) {
                Some(control) => Some((field, control)),
                None => {
                    let missing = format!("the panel's control of {} is missing", field.key);
                    web_sys::console::error_1(&missing.into());
                    None
                }
            })
            .collect();
        let panel = Self { controls };
        panel.refresh_with(&leaves);
        panel
    }

    /// Hands the changes of `field`'s control to `on_change`.
    fn wire(field: &'static Field, on_change: &OnChange) -> Option<Control> {
        let id = markup::field_id(field.key);
        let key = field.key;
        Some(match panel_controls::control(field) {
            panel_controls::Control::Slider { .. } => slider(field, element_as(&id)?, on_change)?,
            panel_controls::Control::Check => {
                let check: HtmlInputElement = element_as(&id)?;
                report(&check, key, on_change, |e| {
                    input(e).map(|i| i.checked().to_string())
                });
                Control::Check(check)
            }
            panel_controls::Control::Choice(_) => {
                let select: HtmlSelectElement = element_as(&id)?;
                report(&select, key, on_change, |e| {
                    e.target()
                        .and_then(|t| t.dyn_into::<HtmlSelectElement>().ok())
                        .map(|s| s.value())
                });
                Control::Select(select)
            }
            panel_controls::Control::Colour => {
                let colour: HtmlInputElement = element_as(&id)?;
                report(&colour, key, on_change, |e| {
                    input(e).map(|i| colour_text(&i.value()))
                });
                Control::Input(colour)
            }
            panel_controls::Control::Text => {
                let text: HtmlInputElement = element_as(&id)?;
                report(&text, key, on_change, |e| input(e).map(|i| i.value()));
                Control::Input(text)
            }
        })
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
