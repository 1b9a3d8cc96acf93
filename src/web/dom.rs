//! A few helpers for building the page's elements from Rust (text only, never HTML).

use super::page::document;
use crate::markup;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlElement};

/// A new element with a class (may be empty) and optional text.
pub fn create(tag: &str, class: &str, text: Option<&str>) -> HtmlElement {
    let e: HtmlElement = document()
        .create_element(tag)
        .expect("creating an element of a known tag cannot fail")
        .dyn_into()
        .expect("a created HTML element is an HtmlElement");
    if !class.is_empty() {
        e.set_class_name(class);
    }
    if let Some(t) = text {
        e.set_text_content(Some(t));
    }
    e
}

/// Sets an attribute; attributes with valid names cannot fail to be set.
pub fn attr(e: &Element, name: &str, value: &str) {
    let _ = e.set_attribute(name, value);
}

/// Appends children in order.
pub fn append(parent: &Element, children: &[&Element]) {
    for c in children {
        // Appending a fresh element to an element cannot fail.
        let _ = parent.append_child(c);
    }
}

/// Removes every child.
pub fn clear(e: &Element) {
    e.set_text_content(None);
}

/// The element `markup` describes, with its children.
pub fn make(markup: &markup::Element) -> HtmlElement {
    let e = create(markup.tag, markup.class, markup.text.as_deref());
    for (name, value) in &markup.attributes {
        attr(&e, name, value);
    }
    for (name, value) in &markup.style {
        // A known property with a valid value cannot fail to be set.
        let _ = e.style().set_property(name, value);
    }
    build(&e, &markup.children);
    e
}

/// Appends the elements `markup` describes to `parent`.
pub fn build(parent: &Element, markup: &[markup::Element]) {
    for m in markup {
        append(parent, &[&make(m)]);
    }
}
