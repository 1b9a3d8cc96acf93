//! Embedding a shell in another page: the `<iframe>` snippet that shows a link with the
//! interface it asks for (`ui=full`, `ui=controls` or `ui=none`, part of the link's
//! [`Presentation`]), sized for it.

use super::presentation::{Presentation, Ui};

/// The iframe's size in CSS pixels that suits interface `ui`: room for the panel beside the
/// shell in the full page, a 4:3 frame otherwise.
fn frame_size(ui: Ui) -> (u32, u32) {
    match ui {
        Ui::Full => (960, 720),
        Ui::Controls | Ui::None => (640, 480),
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
/// `fragment` (a shell's link, without '#') presented as `presentation` asks, titled `title` for
/// screen readers, sized for its interface. It loads lazily and may go full screen; it takes no
/// focus (the page inside never asks for it).
pub fn snippet(page_url: &str, fragment: &str, presentation: Presentation, title: &str) -> String {
    let (width, height) = frame_size(presentation.ui);
    let mut src = format!("{page_url}#{fragment}");
    presentation.write(&mut src);
    format!(
        "<iframe src=\"{}\" title=\"{}\" width=\"{width}\" height=\"{height}\" style=\"border:0\" loading=\"lazy\" allow=\"fullscreen\"></iframe>",
        attribute(&src),
        attribute(title)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::share::presentation::Layout;

    #[test]
    fn the_snippet_escapes_what_would_break_out_of_its_attributes() {
        let s = snippet(
            "https://example.org/shells/",
            "v=1&preset=murex-cabritii",
            Presentation {
                ui: Ui::None,
                layout: Layout::Single,
            },
            "Murex \"cabritii\" <b> — Seashells",
        );
        assert_eq!(
            s,
            "<iframe src=\"https://example.org/shells/#v=1&amp;preset=murex-cabritii&amp;ui=none\" \
             title=\"Murex &quot;cabritii&quot; &lt;b&gt; — Seashells\" width=\"640\" height=\"480\" \
             style=\"border:0\" loading=\"lazy\" allow=\"fullscreen\"></iframe>"
        );
        assert!(
            snippet("u", "v=1&preset=x", Presentation::default(), "t")
                .contains("#v=1&amp;preset=x\"")
        );
        let four = Presentation {
            ui: Ui::Controls,
            layout: Layout::Four,
        };
        assert!(
            snippet("u", "v=1&preset=x", four, "t")
                .contains("#v=1&amp;preset=x&amp;view=four&amp;ui=controls\"")
        );
    }
}
