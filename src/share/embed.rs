//! Embedding a shell in another page: the interface a link asks for (`ui=full`, `ui=controls`
//! or `ui=none`, carried in the link beside the shell's values) and the `<iframe>` snippet that
//! shows a link with one of them.

use crate::spec::problem::Problem;

/// The link's key for the interface.
pub const KEY: &str = "ui";

/// How much of the page a link shows around the shell.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Ui {
    /// The whole page: caption, controls, panel, planar view.
    #[default]
    Full,
    /// The canvas and the play controls.
    Controls,
    /// The canvas alone, growing on load; orbit and zoom still work.
    None,
}

impl Ui {
    pub const ALL: [Ui; 3] = [Ui::Full, Ui::Controls, Ui::None];

    /// The value written in a link.
    pub fn name(self) -> &'static str {
        match self {
            Ui::Full => "full",
            Ui::Controls => "controls",
            Ui::None => "none",
        }
    }

    /// Reads a link's value; anything else is the full interface, with a problem that says so.
    pub fn parse(text: &str) -> (Self, Option<Problem>) {
        match Self::ALL.into_iter().find(|u| u.name() == text) {
            Some(ui) => (ui, None),
            None => {
                let names: Vec<&str> = Self::ALL.iter().map(|u| u.name()).collect();
                let problem = Problem::new(
                    KEY,
                    format!(
                        "'{text}' is not one of {}; opened the full interface",
                        names.join(", ")
                    ),
                );
                (Ui::Full, Some(problem))
            }
        }
    }

    /// Whether the page is embedded (anything but the full interface).
    pub fn embedded(self) -> bool {
        self != Ui::Full
    }

    /// The iframe's size in CSS pixels that suits this interface: room for the panel beside
    /// the shell in the full page, a 4:3 frame otherwise.
    pub fn frame_size(self) -> (u32, u32) {
        match self {
            Ui::Full => (960, 720),
            Ui::Controls | Ui::None => (640, 480),
        }
    }
}

/// `fragment` (a link's fragment without '#') showing interface `ui`: the key is left out for
/// the full interface, which is what a link without it opens.
pub fn with_ui(fragment: &str, ui: Ui) -> String {
    match ui {
        Ui::Full => fragment.to_string(),
        _ => format!("{fragment}&{KEY}={}", ui.name()),
    }
}

/// Text as an HTML attribute's value between double quotes.
fn attribute(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            c => out.push(c),
        }
    }
    out
}

/// The `<iframe>` that shows the page at `page_url` (without fragment) with the link
/// `fragment` in interface `ui`, titled `title` for screen readers. It loads lazily and may go
/// full screen; it takes no focus (the page inside never asks for it).
pub fn snippet(page_url: &str, fragment: &str, ui: Ui, title: &str) -> String {
    let (width, height) = ui.frame_size();
    let src = format!("{page_url}#{}", with_ui(fragment, ui));
    format!(
        "<iframe src=\"{}\" title=\"{}\" width=\"{width}\" height=\"{height}\" style=\"border:0\" loading=\"lazy\" allow=\"fullscreen\"></iframe>",
        attribute(&src),
        attribute(title)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_interface_reads_back_and_others_open_the_full_page_with_a_problem() {
        for ui in Ui::ALL {
            assert_eq!(Ui::parse(ui.name()), (ui, None));
        }
        let (ui, problem) = Ui::parse("sidebar");
        assert_eq!(ui, Ui::Full);
        let problem = problem.expect("an unknown interface is reported");
        assert_eq!(problem.key, "ui");
        assert!(problem.message.contains("'sidebar'"), "{problem}");
        assert!(
            problem.message.contains("full, controls, none"),
            "{problem}"
        );
    }

    #[test]
    fn the_snippet_escapes_what_would_break_out_of_its_attributes() {
        let s = snippet(
            "https://example.org/shells/",
            "v=1&preset=murex-cabritii",
            Ui::None,
            "Murex \"cabritii\" <b> — Seashells",
        );
        assert_eq!(
            s,
            "<iframe src=\"https://example.org/shells/#v=1&amp;preset=murex-cabritii&amp;ui=none\" \
             title=\"Murex &quot;cabritii&quot; &lt;b&gt; — Seashells\" width=\"640\" height=\"480\" \
             style=\"border:0\" loading=\"lazy\" allow=\"fullscreen\"></iframe>"
        );
        assert!(snippet("u", "v=1&preset=x", Ui::Full, "t").contains("#v=1&amp;preset=x\""));
    }
}
