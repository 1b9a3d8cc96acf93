//! The page around the canvas: status text, messages in words, and the data attributes on
//! <body> that tests and scripts read (`data-state`, `data-backend`, `data-rows`).

use std::cell::RefCell;
use std::collections::HashMap;
use std::thread::LocalKey;
use wasm_bindgen::JsCast;
use web_sys::{Document, HtmlElement};

thread_local! {
    /// The document, looked up once: the page's frame finds a handful of elements and writes
    /// its signals, and each lookup of the window and its document is a call out of wasm.
    static DOCUMENT: Document = web_sys::window()
        .and_then(|w| w.document())
        .expect("a browser page has a document");
    /// What each `data-<key>` was last set to by [`signal`] (only it writes them).
    static SIGNALLED: RefCell<HashMap<String, String>> = RefCell::default();
    /// What each element's text was last set to by [`set_text`] (only it writes those).
    static TEXTS: RefCell<HashMap<String, String>> = RefCell::default();
}

/// Writes `value` under `key` with `write` unless `memory` says it was the last written there;
/// `write` says whether it could write (its element is on the page).
fn write_once(
    memory: &'static LocalKey<RefCell<HashMap<String, String>>>,
    key: &str,
    value: &str,
    write: impl FnOnce() -> bool,
) {
    if memory.with_borrow(|m| m.get(key).is_some_and(|v| v == value)) {
        return;
    }
    if write() {
        memory.with_borrow_mut(|m| m.insert(key.to_string(), value.to_string()));
    }
}

/// The document, which a page served to a browser always has.
pub fn document() -> Document {
    DOCUMENT.with(Document::clone)
}

/// The element with this id, as an `HtmlElement`.
pub fn element(id: &str) -> Option<HtmlElement> {
    DOCUMENT.with(|d| d.get_element_by_id(id))?.dyn_into().ok()
}

/// The element with this id, as a `T` (an input, a select, …).
pub fn element_as<T: JsCast>(id: &str) -> Option<T> {
    DOCUMENT.with(|d| d.get_element_by_id(id))?.dyn_into().ok()
}

/// Sets `data-<key>` on <body>; `key` is in the dataset's camelCase (`patternHash` sets
/// `data-pattern-hash`). A value the attribute has already is not written again: most are set
/// every frame, and each write is a call into the page and a change of the document.
pub fn signal(key: &str, value: &str) {
    write_once(&SIGNALLED, key, value, || {
        DOCUMENT.with(Document::body).is_some_and(|body| {
            // A dataset write fails only for keys with a hyphen, which this page never uses.
            body.dataset().set(key, value).is_ok()
        })
    });
}

/// Sets the text (never HTML) of the element with this id. A text the element shows already
/// is not written again: some are set as often as every frame (the growth's progress, the
/// files' sizes), and each write is a lookup, a call into the page and a layout.
pub fn set_text(id: &str, text: &str) {
    write_once(&TEXTS, id, text, || {
        element(id).is_some_and(|e| {
            e.set_text_content(Some(text));
            true
        })
    });
}

/// Shows a message in words in the page's alert area.
pub fn show_message(text: &str) {
    if let Some(e) = element("message") {
        e.set_text_content(Some(text));
        e.set_hidden(false);
    }
}

/// Hides the alert area.
pub fn hide_message() {
    if let Some(e) = element("message") {
        e.set_hidden(true);
        e.set_text_content(None);
    }
}

/// Shows an error that stops the shell from being drawn, and marks the page as failed.
pub fn show_error(text: &str) {
    show_message(text);
    signal("state", "error");
}

/// Says, in the words of the page's `#no-3d` notice, that this browser draws no 3D here and
/// what still works; the technical cause (`details`) is folded away under it. The gallery's
/// cards then show no pictures and the viewer no canvas.
pub fn show_no_3d(details: &str) {
    set_text("no-3d-details", details);
    if let Some(notice) = element("no-3d") {
        notice.set_hidden(false);
    }
    if let Some(body) = DOCUMENT.with(Document::body) {
        let _ = body.class_list().add_1("no-3d");
    }
    signal("backend", "none");
    set_text("backend", "Not drawn in 3D");
}

/// Puts the `#no-3d` notice where it is read: over the viewer's empty stage while a shell is
/// shown, above the gallery otherwise.
pub fn place_no_3d(in_viewer: bool) {
    let Some(notice) = element("no-3d") else {
        return;
    };
    let document = document();
    let place = if in_viewer {
        document.query_selector(".stage").ok().flatten()
    } else {
        document.body().map(Into::into)
    };
    if let Some(place) = place {
        // Moving an element of the page within it cannot fail.
        let _ = place.prepend_with_node_1(&notice);
    }
}

/// Shows what a panic left: what was being done and what went wrong, above a button that
/// reloads the link (wired in main.js, which works without the wasm). The first panic's message
/// stays: later ones are what the first left broken.
pub fn show_crash(text: &str) {
    let Some(crash) = element("crash") else {
        return show_error(text);
    };
    if !crash.hidden() {
        return;
    }
    set_text("crash-text", text);
    crash.set_hidden(false);
    signal("state", "error");
    signal("crashed", "true");
}

/// The media query of a dark colour scheme.
pub const DARK: &str = "(prefers-color-scheme: dark)";

/// The page's media query `query` (`None` where the browser has none).
pub fn media(query: &str) -> Option<web_sys::MediaQueryList> {
    web_sys::window()?.match_media(query).ok().flatten()
}

/// Whether the page's media query `query` holds.
pub fn matches(query: &str) -> bool {
    media(query).is_some_and(|m| m.matches())
}

/// The page's background colour as sRGB bytes, following the light or dark theme (the same
/// values as --bg in style.css).
pub fn background() -> [u8; 3] {
    let dark = matches(DARK);
    if dark {
        [0x16, 0x17, 0x19]
    } else {
        [0xf4, 0xf1, 0xea]
    }
}
