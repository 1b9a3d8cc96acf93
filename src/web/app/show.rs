//! What the page shows around the viewer, as the app applies it: which backend draws and
//! where, the message line, the speed box, the presentation (the interface, one view or
//! Kawaguchi's four with their names), the story's step beside the shell, the canvas held at
//! a recording's size.

use crate::share::presentation::{Layout, Presentation};
use crate::stories::StoryAt;
use crate::view::panes::arrangement;
use crate::web::dom;
use crate::web::page::{self, element, element_as, set_text, show_message, signal};
use crate::web::share_panel;
use crate::web::viewer_handle::ViewerHandle;
use crate::work::status_readout::Say;
use web_sys::HtmlInputElement;

/// Shows which backend the main view is drawn with (none: no 3D).
pub(super) fn show_backend(backend: Option<String>) {
    if let Some(backend) = backend {
        signal("backend", &backend);
        set_text("backend", &format!("Drawn with {backend}"));
    }
}

/// Signals where the main view is drawn (`data-drawn-in`): in the drawing worker, on the
/// page's thread, or nowhere.
pub(super) fn show_drawn_in(viewer: &ViewerHandle) {
    signal("drawnIn", viewer.drawn_in().signal());
}

/// Shows or hides the message line as the session said.
pub(super) fn say(say: Say) {
    match say {
        Say::Nothing => {}
        Say::Show(words) => show_message(&words),
        Say::Hide => page::hide_message(),
    }
}

/// The speed box shows `speed` rows per frame.
pub(super) fn show_speed(speed: f64) {
    if let Some(input) = element_as::<HtmlInputElement>("speed") {
        input.set_value(&crate::spec::fields::display(speed));
    }
}

/// Shows the shell as `presentation` asks: the interface, one view, or Kawaguchi's four with
/// each pane named over the canvas.
pub(super) fn present(presentation: Presentation) {
    share_panel::apply_ui(presentation.ui);
    let layout = presentation.layout;
    if let Some(button) = element("views") {
        let pressed = if layout == Layout::Four {
            "true"
        } else {
            "false"
        };
        dom::attr(&button, "aria-pressed", pressed);
    }
    if let Some(viewer) = element("viewer") {
        let _ = viewer
            .class_list()
            .toggle_with_force("four", layout == Layout::Four);
    }
    if let Some(labels) = element("panes") {
        dom::clear(&labels);
        labels.set_hidden(layout == Layout::Single);
        for place in arrangement(layout) {
            let label = dom::create("span", "pane", Some(place.name));
            let style = label.style();
            for (property, fraction) in ["left", "top", "width", "height"]
                .into_iter()
                .zip(place.viewport)
            {
                let _ = style.set_property(property, &format!("{}%", fraction * 100.0));
            }
            dom::append(&labels, &[&label]);
        }
    }
}

/// Marks the main canvas as drawn at a recording's size, which the page shows scaled to fit
/// (or, with `false`, at its own size again).
pub(super) fn fix_canvas(fixed: bool) {
    if let Some(canvas) = element("shell") {
        let _ = canvas.class_list().toggle_with_force("fixed", fixed);
    }
}

pub(super) fn location_hash() -> String {
    web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default()
}

/// Shows the story's step `at` beside the shell (its story's title, where it is, its words, the
/// paper's figure, the links to the steps before and after), or hides the story.
pub(super) fn show_story(at: Option<&StoryAt>) {
    signal("story", &at.map_or(String::new(), |at| at.link()));
    let Some(section) = element("story") else {
        return;
    };
    section.set_hidden(at.is_none());
    let Some(at) = at else { return };
    let step = at.step();
    set_text("story-title", &at.story.title);
    set_text("story-count", &at.count());
    set_text("story-step-title", &step.title);
    set_text("story-text", &step.text);
    let cites = step.cites();
    set_text("story-cites", cites.as_deref().unwrap_or(""));
    if let Some(e) = element("story-cites") {
        e.set_hidden(cites.is_none());
    }
    for (id, to) in [("story-back", at.previous()), ("story-next", at.next())] {
        let Some(a) = element(id) else { continue };
        match to {
            Some(fragment) => {
                dom::attr(&a, "href", &format!("#{fragment}"));
                a.remove_attribute("aria-disabled").ok();
            }
            None => {
                a.remove_attribute("href").ok();
                dom::attr(&a, "aria-disabled", "true");
            }
        }
    }
}
