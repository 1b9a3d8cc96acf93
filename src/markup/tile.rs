//! A tile of the parameter map or of breeding: a link to its shell (none: it cannot be
//! chosen), named by its label, holding its picture (an image the pictures' viewer fills, or a
//! canvas a pattern is painted into), and on the map the presets nearest it, as words and as
//! markers where their own values fall.

use super::element::Element;
use crate::variation::map_plan::Label;

/// What a tile shows: the shell, as a picture drawn by the page; or a pattern, painted into a
/// canvas from its pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shows {
    Shell,
    Pattern,
}

/// Tile `job` of `class` ("tile" and any more) linking to `href`, named `label`; `current`
/// marks the shell shown (or the parent bred from).
pub fn tile(
    job: u32,
    href: Option<&str>,
    label: &str,
    class: &'static str,
    current: bool,
    shows: Shows,
) -> Element {
    let mut a = Element::new("a", class);
    if let Some(href) = href {
        a = a.attr("href", href);
    }
    a = a
        .attr("data-job", job.to_string())
        .attr("title", label)
        .attr("aria-label", label);
    if current {
        a = a.attr("aria-current", "true");
    }
    a.with([match shows {
        Shows::Shell => Element::new("img", "").attr("alt", ""),
        Shows::Pattern => Element::new("canvas", ""),
    }])
}

/// Tile `job` of the parameter map, as `label` describes it, linking to `link`.
pub fn map_tile(job: u32, link: &str, label: &Label, shows: Shows) -> Element {
    let class = match (label.apart, label.current) {
        (true, true) => "tile apart current",
        (true, false) => "tile apart",
        (false, true) => "tile current",
        (false, false) => "tile",
    };
    let href = format!("#{link}");
    let mut a = tile(job, Some(&href), &label.text, class, label.current, shows);
    if !label.landmarks.is_empty() {
        a.children
            .push(Element::new("span", "landmark").text(&label.landmarks));
    }
    // Each gallery shell marked where its own values fall; the names are in the label.
    a.with(label.marks.iter().map(|&(left, top, name)| {
        Element::new("span", "marker")
            .attr("data-name", name)
            .attr("aria-hidden", "true")
            .style("left", format!("{left:.1}%"))
            .style("top", format!("{top:.1}%"))
    }))
}
