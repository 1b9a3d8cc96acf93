//! How the page presents a shell, carried in its link beside the spec: not part of the shell
//! (the same shell has the same mesh and pattern however it is shown), so it is written after
//! the spec's values and never changes a hash: the layout of the view, one perspective view or
//! Kawaguchi's four (`view=four`), and how much of the page shows around it (`ui=`, for
//! embeds).

use crate::spec::problem::Problem;
use serde::{Deserialize, Serialize};

/// The link key of the layout.
pub const VIEW_KEY: &str = "view";

/// How the viewer lays out its canvas.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Layout {
    /// One perspective view the pointer orbits.
    #[default]
    Single,
    /// Kawaguchi's views for checking a shell's twist while entering its data (*A morphological
    /// study of the form of nature*, figs 2–4): front, side and top in orthographic projection,
    /// with the perspective view.
    Four,
}

impl Layout {
    pub const ALL: [Layout; 2] = [Layout::Single, Layout::Four];

    /// Reads a link's value; anything else is one view, with a problem that says so.
    pub fn parse(text: &str) -> (Self, Option<Problem>) {
        match Self::ALL.into_iter().find(|l| l.name() == text) {
            Some(layout) => (layout, None),
            None => (
                Layout::Single,
                Some(Problem::new(
                    VIEW_KEY,
                    format!("'{text}' is not one of single, four; used single"),
                )),
            ),
        }
    }

    /// The name a link writes.
    pub fn name(self) -> &'static str {
        match self {
            Layout::Single => "single",
            Layout::Four => "four",
        }
    }

    /// The other layout: what the page's toggle switches to.
    pub fn toggled(self) -> Layout {
        match self {
            Layout::Single => Layout::Four,
            Layout::Four => Layout::Single,
        }
    }
}

/// The link key of the interface.
pub const UI_KEY: &str = "ui";

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
                    UI_KEY,
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
}

/// Everything about the page's presentation that a link carries.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Presentation {
    pub layout: Layout,
    pub ui: Ui,
}

impl Presentation {
    /// Reads the presentation's own `key=value`, when `key` is one of its keys (false leaves
    /// the pair to the spec). A value it cannot read keeps the default and says so.
    pub(crate) fn read(&mut self, key: &str, value: &str, problems: &mut Vec<Problem>) -> bool {
        match key {
            VIEW_KEY => {
                let (layout, problem) = Layout::parse(value);
                self.layout = layout;
                problems.extend(problem);
            }
            UI_KEY => {
                let (ui, problem) = Ui::parse(value);
                self.ui = ui;
                problems.extend(problem);
            }
            _ => return false,
        }
        true
    }

    /// Appends what differs from the default to a link fragment (`&view=four&ui=none`).
    pub fn write(&self, link: &mut String) {
        if self.layout != Layout::default() {
            link.push_str(&format!("&{VIEW_KEY}={}", self.layout.name()));
        }
        if self.ui != Ui::default() {
            link.push_str(&format!("&{UI_KEY}={}", self.ui.name()));
        }
    }
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
}
