//! The share panel's link, embed code and QR code, and the interface a link asks for
//! (`ui=controls` or `ui=none` hide the page around the shell, by classes on <body> that
//! style.css reads).

use super::page::{self, element_as, set_text, signal};
use crate::share::embed;
use crate::share::presentation::{Presentation, Ui};
use crate::share::qr;
use web_sys::{HtmlImageElement, HtmlSelectElement, HtmlTextAreaElement};

/// The QR code's size in CSS pixels.
const QR_SIZE: u32 = 160;

/// The page's address without its fragment.
pub fn page_url() -> String {
    let Some(location) = web_sys::window().map(|w| w.location()) else {
        return String::new();
    };
    format!(
        "{}{}{}",
        location.origin().unwrap_or_default(),
        location.pathname().unwrap_or_default(),
        location.search().unwrap_or_default()
    )
}

/// Shows the QR code of `url`, or why there is none.
pub fn show_qr(url: &str) {
    let Some(img) = element_as::<HtmlImageElement>("qr") else {
        return;
    };
    match qr::svg(url, QR_SIZE) {
        Ok(svg) => {
            img.set_src(&format!(
                "data:image/svg+xml;charset=utf-8,{}",
                js_sys::encode_uri_component(&svg)
            ));
            img.set_hidden(false);
            set_text("qr-caption", "Scan to open this shell on a phone.");
        }
        Err(e) => {
            img.set_hidden(true);
            img.set_src("");
            set_text("qr-caption", &format!("No QR code: {e}."));
        }
    }
}

/// The interface chosen for the embed code.
pub fn chosen_ui() -> Ui {
    element_as::<HtmlSelectElement>("embed-ui").map_or(Ui::None, |s| Ui::parse(&s.value()).0)
}

/// Shows `snippet` in the panel, selectable, and copies it, saying whether it was copied.
pub fn copy_embed(snippet: String) {
    if let Some(area) = element_as::<HtmlTextAreaElement>("embed-code") {
        area.set_value(&snippet);
        area.set_hidden(false);
    }
    copy(
        snippet,
        "Embed code copied",
        "Copy the embed code above".into(),
    );
}

/// Copies `text` to the clipboard; the status says `done`, or `refused` when the browser
/// does not allow it or has no clipboard to write to (a page served over plain HTTP from
/// another host than this one, say).
pub fn copy(text: String, done: &'static str, refused: String) {
    let Some(window) = web_sys::window() else {
        return;
    };
    let navigator = window.navigator();
    let has_clipboard =
        js_sys::Reflect::get(&navigator, &"clipboard".into()).is_ok_and(|c| c.is_object());
    if !has_clipboard {
        set_text("copy-status", &refused);
        return;
    }
    let promise = navigator.clipboard().write_text(&text);
    wasm_bindgen_futures::spawn_local(async move {
        let copied = wasm_bindgen_futures::JsFuture::from(promise).await.is_ok();
        set_text("copy-status", if copied { done } else { &refused });
    });
}

/// Shows the page with interface `ui`: the whole page, the shell and its play controls, or the
/// shell alone.
pub fn apply_ui(ui: Ui) {
    if let Some(body) = page::document().body() {
        for u in Ui::ALL {
            let _ = body
                .class_list()
                .toggle_with_force(&format!("ui-{}", u.name()), u == ui && ui.embedded());
        }
    }
    signal("ui", ui.name());
}

/// Whether the reader asked for reduced motion.
pub fn reduced_motion() -> bool {
    super::page::matches("(prefers-reduced-motion: reduce)")
}

/// The embed code of the link `fragment` (without '#') titled `name`, presented as
/// `presentation` asks.
pub fn snippet(fragment: &str, presentation: Presentation, name: &str) -> String {
    embed::snippet(
        &page_url(),
        fragment,
        presentation,
        &format!("{name} — Seashells"),
    )
}
