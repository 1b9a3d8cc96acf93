//! Where the page's main view is drawn, and where it goes when it cannot be drawn there: in
//! the drawing worker where the browser lets a module worker hold an `OffscreenCanvas` (unless
//! the link's query asks for the page's thread, `view=page`), else on the page's own thread,
//! else nowhere: the shell still grows, its pattern shows and its files are written, and the
//! page's no-3D notice says why. A drawing worker that fails, at start or later, gives way to
//! the page's thread; a renderer that fails there gives way to nothing. Each move is said in
//! words once: a move off the worker on the status or the message line, its cause on the
//! console; a move to nothing in the no-3D notice, with its cause.

/// Where the main view is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawnIn {
    Worker,
    Page,
    Nowhere,
}

/// A move of the view, and what the page says of it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Move {
    pub to: DrawnIn,
    /// For the console: why, as the browser said it.
    pub log: Option<String>,
    /// Added to the workers' status line (a move at start, before any shell was shown).
    pub status: Option<&'static str>,
    /// For the message line (a move once a shell may have been shown: it grows again).
    pub say: Option<&'static str>,
    /// For the no-3D notice's details: why nothing can be drawn.
    pub no_3d: Option<String>,
}

impl DrawnIn {
    /// Where the view is drawn first: in a worker where one can draw (`worker_draws`: module
    /// workers and `OffscreenCanvas` both there), unless the link asks for the page's thread.
    pub fn first(worker_draws: bool, asked_page: bool) -> Self {
        if worker_draws && !asked_page {
            DrawnIn::Worker
        } else {
            DrawnIn::Page
        }
    }

    /// The page's `data-drawn-in` signal.
    pub fn signal(self) -> &'static str {
        match self {
            DrawnIn::Worker => "worker",
            DrawnIn::Page => "page",
            DrawnIn::Nowhere => "nowhere",
        }
    }

    /// The view cannot be drawn here (`why`), at start (`running` false) or once the page
    /// runs: where it goes, and what the page says.
    pub fn fall_back(self, why: &str, running: bool) -> Move {
        match (self, running) {
            (DrawnIn::Worker, false) => Move {
                to: DrawnIn::Page,
                log: Some(format!("The view is drawn on the page's thread: {why}")),
                status: Some("Drawn on the page's thread: this browser cannot draw in a worker."),
                say: None,
                no_3d: None,
            },
            (DrawnIn::Worker, true) => Move {
                to: DrawnIn::Page,
                log: Some(format!("The view moves to the page's thread: {why}")),
                status: None,
                say: Some(
                    "The shell could not be drawn in a worker here, so the page draws it on its \
                     own thread; it grows again from its apex.",
                ),
                no_3d: None,
            },
            (DrawnIn::Page | DrawnIn::Nowhere, _) => Move {
                to: DrawnIn::Nowhere,
                log: None,
                status: None,
                say: None,
                no_3d: Some(why.to_string()),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_worker_first_where_one_draws_unless_the_link_asks_for_the_page() {
        assert_eq!(DrawnIn::first(true, false), DrawnIn::Worker);
        assert_eq!(DrawnIn::first(true, true), DrawnIn::Page);
        assert_eq!(DrawnIn::first(false, false), DrawnIn::Page);
        let signals = [DrawnIn::Worker, DrawnIn::Page, DrawnIn::Nowhere].map(DrawnIn::signal);
        assert_eq!(signals, ["worker", "page", "nowhere"]);
    }

    #[test]
    fn a_failing_worker_gives_way_to_the_page_and_the_page_to_nothing_each_said_once() {
        let at_start = DrawnIn::Worker.fall_back("no WebGL2 on an OffscreenCanvas", false);
        assert_eq!(at_start.to, DrawnIn::Page);
        assert!(
            at_start.say.is_none(),
            "no shell was shown yet: the status line says it"
        );
        assert!(
            at_start
                .status
                .is_some_and(|s| s.contains("cannot draw in a worker"))
        );
        assert!(
            at_start
                .log
                .is_some_and(|l| l.ends_with("no WebGL2 on an OffscreenCanvas"))
        );
        let later = DrawnIn::Worker.fall_back("it fell silent", true);
        assert_eq!(later.to, DrawnIn::Page);
        assert!(
            later
                .say
                .is_some_and(|s| s.contains("grows again from its apex"))
        );
        assert!(later.status.is_none());
        let page = DrawnIn::Page.fall_back("no adapter", true);
        assert_eq!(page.to, DrawnIn::Nowhere);
        assert_eq!(page.no_3d.as_deref(), Some("no adapter"));
        assert!(
            page.say.is_none() && page.log.is_none(),
            "the no-3D notice says it"
        );
        assert_eq!(
            DrawnIn::Nowhere.fall_back("again", true).to,
            DrawnIn::Nowhere
        );
    }
}
