//! How the page presents a shell, carried in its link beside the spec: not part of the shell
//! (the same shell has the same mesh and pattern however it is shown), so it is written after
//! the spec's values and never changes a hash. Today: the layout of the view, one perspective
//! view or Kawaguchi's four (`view=four`).

use crate::spec::problem::Problem;

/// The link key of the layout.
pub const VIEW_KEY: &str = "view";

/// How the viewer lays out its canvas.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
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

/// Everything about the page's presentation that a link carries.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Presentation {
    pub layout: Layout,
}

impl Presentation {
    /// Reads the presentation's own `key=value`, when `key` is one of its keys: `None` leaves
    /// the pair to the spec. A value it cannot read keeps the default and says so.
    pub(crate) fn read(&mut self, key: &str, value: &str, problems: &mut Vec<Problem>) -> bool {
        if key != VIEW_KEY {
            return false;
        }
        match [Layout::Single, Layout::Four]
            .into_iter()
            .find(|l| l.name() == value)
        {
            Some(layout) => self.layout = layout,
            None => problems.push(Problem::new(
                VIEW_KEY,
                format!("'{value}' is not one of single, four; used single"),
            )),
        }
        true
    }

    /// Appends what differs from the default to a link fragment (`&view=four`).
    pub fn write(&self, link: &mut String) {
        if self.layout != Layout::default() {
            link.push_str(&format!("&{VIEW_KEY}={}", self.layout.name()));
        }
    }
}
