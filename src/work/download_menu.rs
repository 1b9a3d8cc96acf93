//! The download menu's rules: every file the page offers for the shell shown (GLB first, then
//! PLY, 3MF, OBJ, STL, the picture and the pattern), each with its size, one file at a time. The
//! viewer writes a file where its copy of the shell is ([`super::file_writer`]), a frame's
//! budget at a time; the menu says where it stands (a progress bar while it takes longer than a
//! frame), then has the page offer it. What cannot be exported (nothing grown yet, a shell that
//! stopped, an open surface as 3MF, a size out of bounds) is said in words. The page's
//! `data-download`: finishing (an implicit shell still growing is grown whole first), writing,
//! offered, refused (empty before any).
//!
//! The menu returns what the page is to show ([`MenuShown`]); the page applies it and offers
//! the file's bytes, and tells the menu how the offer went.

use super::file_writer::{Body, File, FileStage};
use super::viewer_command::ViewCommand;
use super::viewer_status::ShellStatus;
use crate::export::Download;
use crate::export::estimate::{Counts, Size};
use crate::export::print_size::PrintSize;

/// Least time between two updates of the sizes shown while the shell grows, milliseconds.
const SIZES_EVERY_MS: f64 = 500.0;
/// What the size field is called in messages.
const SIZE: &str = "Size";

/// The page's message line.
#[derive(Clone, Debug, PartialEq)]
pub enum Message {
    Show(String),
    Hide,
}

/// What the page shows of the menu after a change; `None` leaves a part as it is.
#[derive(Debug, Default, PartialEq)]
pub struct MenuShown {
    /// The page's `data-download`.
    pub signal: Option<&'static str>,
    pub message: Option<Message>,
    /// The progress bar's value and the status line beside it; `Some(None)` hides both.
    pub progress: Option<Option<(f64, String)>>,
    /// Whether the download buttons are enabled.
    pub buttons: Option<bool>,
    /// Sizes to show beside the files.
    pub sizes: Vec<(Download, String)>,
    /// A file written whole, for the page to offer; it then calls [`DownloadMenu::offered`].
    pub offer: Option<File>,
}

/// The menu: whether a file is under way, and the counts the sizes shown were estimated from
/// (and when).
#[derive(Debug, Default)]
pub struct DownloadMenu {
    busy: bool,
    shown: Option<(Counts, f64)>,
}

impl DownloadMenu {
    /// Download `what` was pressed, with the size field reading `size_mm`: what to ask the
    /// viewer for (none while a file is under way, or when the size is out of bounds, said
    /// by name).
    pub fn start(&mut self, what: Download, size_mm: f64) -> (Option<ViewCommand>, MenuShown) {
        if self.busy {
            return (None, MenuShown::default());
        }
        let size = match what {
            Download::Mesh(format) if format.sized() => {
                PrintSize::new(size_mm, SIZE).map_err(|e| e.to_string())
            }
            _ => Ok(PrintSize::default()),
        };
        match size {
            Ok(size) => {
                self.busy = true;
                let shown = MenuShown {
                    buttons: Some(false),
                    ..MenuShown::default()
                };
                (Some(ViewCommand::WriteFile { what, size }), shown)
            }
            Err(e) => (None, refused(&e)),
        }
    }

    /// Where the file asked for stands now.
    pub fn stage(&mut self, stage: FileStage) -> MenuShown {
        match stage {
            FileStage::Finishing => MenuShown {
                signal: Some("finishing"),
                message: Some(Message::Hide),
                ..MenuShown::default()
            },
            FileStage::Writing { name, done } => MenuShown {
                signal: Some("writing"),
                message: Some(Message::Hide),
                progress: Some(Some((
                    done,
                    format!("Writing {name}… {:.0} %", done * 100.0),
                ))),
                ..MenuShown::default()
            },
            FileStage::Written(file) => {
                let sizes = match &file.body {
                    Body::Bytes(bytes) => {
                        vec![(file.what, format!("{} MB", megabytes(bytes.len() as f64)))]
                    }
                    Body::Url(_) => Vec::new(),
                };
                MenuShown {
                    sizes,
                    offer: Some(file),
                    ..MenuShown::default()
                }
            }
            FileStage::Refused(e) => self.offered(Err(e)),
        }
    }

    /// The page offered the file written (or could not: why); the menu takes the next.
    pub fn offered(&mut self, offered: Result<(), String>) -> MenuShown {
        self.busy = false;
        let done = MenuShown {
            progress: Some(None),
            buttons: Some(true),
            ..MenuShown::default()
        };
        match offered {
            Ok(()) => MenuShown {
                signal: Some("offered"),
                message: Some(Message::Hide),
                ..done
            },
            Err(e) => MenuShown {
                progress: done.progress,
                buttons: done.buttons,
                ..refused(&e)
            },
        }
    }

    /// The viewer that was writing a file is gone (it moved to another thread): the file is
    /// refused with `why`, and may be asked again.
    pub fn abandon(&mut self, why: &str) -> MenuShown {
        if self.busy {
            self.offered(Err(why.to_string()))
        } else {
            MenuShown::default()
        }
    }

    /// Each file's size for `shell` at `now` (milliseconds), when the counts have changed: at
    /// most every half second while the shell grows, never while a file is written.
    pub fn sizes(&mut self, shell: &ShellStatus, now: f64) -> Vec<(Download, String)> {
        let counts = shell.counts;
        if self.busy
            || self
                .shown
                .is_some_and(|(c, at)| c == counts || (!shell.done && now - at < SIZES_EVERY_MS))
        {
            return Vec::new();
        }
        self.shown = Some((counts, now));
        Download::ALL
            .into_iter()
            .map(|what| {
                let text = match what.estimate(&counts) {
                    Some(Size::Bytes(bytes)) => format!("≈ {} MB", megabytes(bytes as f64)),
                    Some(Size::Pixels(w, h)) => format!("{w} × {h}"),
                    None => "none".to_string(),
                };
                (what, text)
            })
            .collect()
    }
}

/// What the page shows when the download could not be made, and why.
fn refused(why: &str) -> MenuShown {
    MenuShown {
        signal: Some("refused"),
        message: Some(Message::Show(format!(
            "The download could not be made: {why}."
        ))),
        ..MenuShown::default()
    }
}

/// Bytes in megabytes, to two significant figures (three from 10 MB).
fn megabytes(bytes: f64) -> String {
    let mb = bytes / 1e6;
    if mb >= 10.0 {
        format!("{mb:.0}")
    } else if mb >= 0.1 {
        format!("{mb:.1}")
    } else {
        format!("{mb:.2}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::MeshFormat;

    fn status(done: bool, vertices: usize) -> ShellStatus {
        let mut status = ShellStatus {
            done,
            ..ShellStatus::default()
        };
        status.counts.vertices = vertices;
        status.counts.triangles = 2 * vertices;
        status
    }

    #[test]
    fn one_file_at_a_time_and_the_buttons_wait_for_it() {
        let mut menu = DownloadMenu::default();
        let (asked, shown) = menu.start(Download::Mesh(MeshFormat::Obj), f64::NAN);
        assert!(matches!(asked, Some(ViewCommand::WriteFile { .. })));
        assert_eq!(shown.buttons, Some(false));
        let (again, _) = menu.start(Download::Mesh(MeshFormat::Stl), f64::NAN);
        assert!(again.is_none(), "a second file waits for the first");
        let writing = menu.stage(FileStage::Writing {
            name: "turbinate.obj".into(),
            done: 0.25,
        });
        assert_eq!(writing.signal, Some("writing"));
        assert_eq!(
            writing.progress,
            Some(Some((0.25, "Writing turbinate.obj… 25 %".into())))
        );
        let offered = menu.offered(Ok(()));
        assert_eq!(offered.signal, Some("offered"));
        assert_eq!(
            (offered.progress, offered.buttons),
            (Some(None), Some(true))
        );
        let (next, _) = menu.start(Download::Mesh(MeshFormat::Stl), f64::NAN);
        assert!(
            next.is_some(),
            "the next file may be asked once one is offered"
        );
    }

    #[test]
    fn a_size_out_of_bounds_is_refused_by_name_and_only_for_sized_files() {
        let mut menu = DownloadMenu::default();
        let (asked, shown) = menu.start(Download::Mesh(MeshFormat::Glb), -3.0);
        assert!(asked.is_none());
        assert_eq!(shown.signal, Some("refused"));
        let Some(Message::Show(words)) = shown.message else {
            panic!("the refusal is said");
        };
        assert!(
            words.starts_with("The download could not be made: Size"),
            "{words}"
        );
        let (obj, _) = menu.start(Download::Mesh(MeshFormat::Obj), -3.0);
        assert!(obj.is_some(), "an OBJ has no size to refuse");
    }

    #[test]
    fn a_written_file_is_offered_with_its_size_and_a_refusal_frees_the_menu() {
        let mut menu = DownloadMenu::default();
        menu.start(Download::Mesh(MeshFormat::Obj), f64::NAN);
        let what = Download::Mesh(MeshFormat::Obj);
        let shown = menu.stage(FileStage::Written(File {
            name: "turbinate.obj".into(),
            what,
            body: Body::Bytes(vec![0; 1_234_567]),
        }));
        assert_eq!(shown.sizes, vec![(what, "1.2 MB".to_string())]);
        assert!(shown.offer.is_some());
        let refused = menu.offered(Err("the browser refused to make the file".into()));
        assert_eq!(refused.signal, Some("refused"));
        assert_eq!(refused.buttons, Some(true));
        assert_eq!(
            menu.abandon("the view moved"),
            MenuShown::default(),
            "nothing under way"
        );
        menu.start(what, f64::NAN);
        assert_eq!(menu.abandon("the view moved").signal, Some("refused"));
    }

    #[test]
    fn sizes_follow_a_growing_shell_at_most_every_half_second() {
        let mut menu = DownloadMenu::default();
        let first = menu.sizes(&status(false, 1000), 0.0);
        assert_eq!(first.len(), Download::ALL.len());
        assert!(
            menu.sizes(&status(false, 2000), 100.0).is_empty(),
            "too soon"
        );
        assert!(!menu.sizes(&status(false, 2000), 600.0).is_empty());
        assert!(
            menu.sizes(&status(false, 2000), 2000.0).is_empty(),
            "unchanged"
        );
        assert!(
            !menu.sizes(&status(true, 3000), 2100.0).is_empty(),
            "the grown shell's sizes at once"
        );
    }

    #[test]
    fn megabytes_keep_two_figures_and_three_from_ten() {
        assert_eq!(megabytes(12_345.0), "0.01");
        assert_eq!(megabytes(456_000.0), "0.5");
        assert_eq!(megabytes(38_320_338.0), "38");
    }
}
