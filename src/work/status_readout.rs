//! What the page shows of the viewer's status, frame by frame: the `data-*` signals its tests
//! and embedders read (rows, settled, growth, state, hashes, preview), the progress bar, and
//! why growth stopped, said once per shell; and, before that, what it says of the graphics
//! device (lost, opened again, gone). The page applies what [`Readout::frame`] and
//! [`Readout::device`] return and decides nothing itself (the pure part returns data, the
//! runner applies it), so every rule here is tested natively.

use super::viewer_status::{Device, ShellStatus, ViewStatus};

/// Least time between two moves of the progress bar and its text while the shell grows
/// (milliseconds): a bar that moves ten times a second looks as smooth as one moved every
/// frame, without an element written and laid out in each of the frames between.
const PROGRESS_EVERY_MS: f64 = 100.0;

/// What the page last showed, to show only what changed.
#[derive(Debug)]
pub struct Readout {
    /// The session whose failure was said: said once, so that a message said since (a refused
    /// download) stays.
    stop_said: Option<u32>,
    /// The rows done and in all the progress bar shows, and when it was set.
    progress: (usize, usize, f64),
    /// How many times the graphics device was lost and opened again.
    recoveries: u32,
}

impl Default for Readout {
    fn default() -> Self {
        Self {
            stop_said: None,
            progress: (0, 0, f64::NEG_INFINITY),
            recoveries: 0,
        }
    }
}

/// Words the page shows in its message line, after a frame.
#[derive(Debug, Default, PartialEq)]
pub enum Say {
    /// Leave the line as it is.
    #[default]
    Nothing,
    Show(String),
    /// Clear it.
    Hide,
}

/// What the page is to show of the graphics device, before a frame.
#[derive(Debug, PartialEq)]
pub struct DeviceShown {
    /// Whether the frame may draw.
    pub draws: bool,
    /// `data-*` signals to set, by name.
    pub signals: Vec<(&'static str, String)>,
    pub say: Say,
    /// The backend a device was opened again with, to show in place of the old one.
    pub backend: Option<String>,
}

/// What the page is to show after one frame.
#[derive(Debug, Default, PartialEq)]
pub struct FrameShown {
    /// `data-*` signals to set, by name.
    pub signals: Vec<(&'static str, String)>,
    /// The progress bar's rows done and rows in all, when it is to move.
    pub progress: Option<(usize, usize)>,
    /// Words to show the user (why growth stopped).
    pub say: Say,
    /// Whether the downloads' estimated sizes are to be shown again, from the shell's counts.
    pub sizes: bool,
}

impl FrameShown {
    fn signal(&mut self, name: &'static str, value: impl Into<String>) {
        self.signals.push((name, value.into()));
    }
}

impl Readout {
    /// Another viewer took the old one's place: its sessions are numbered afresh, so that a
    /// stop said of the old one's shell numbered as the new one's must not keep the new one's
    /// from being said; the progress bar starts again too. The device's recoveries still count.
    pub fn viewer_replaced(&mut self) {
        *self = Self {
            recoveries: self.recoveries,
            ..Self::default()
        };
    }

    /// What to show of `status` after a frame that drew the shell (`drawn`) or did not, at
    /// time `now` (milliseconds). Settled is said false at once, but true only with the rows it
    /// settled on, in a frame that shows them: a test reading the rows once settled reads the
    /// last. The state is `grown` only when the shell is grown whole, settled and at rest
    /// ([`ShellStatus::finished`]), with its hashes and counts beside it.
    pub fn frame(&mut self, status: &ViewStatus, drawn: bool, now: f64) -> FrameShown {
        let mut shown = FrameShown::default();
        shown.signal("preview", status.preview_signal());
        let Some(shell) = &status.shell else {
            shown.signal("settled", "false");
            return shown;
        };
        if !shell.settled {
            shown.signal("settled", "false");
        }
        shown.progress = self.progress(shell, now);
        if drawn {
            self.drawn(shell, &mut shown);
        }
        shown
    }

    /// The progress bar's new rows, when they have changed, at most every
    /// [`PROGRESS_EVERY_MS`] while the shell grows (asked every frame, drawn or not, so that
    /// the last rows of a growth paused or finished are shown too).
    fn progress(&mut self, shell: &ShellStatus, now: f64) -> Option<(usize, usize)> {
        let (done, total) = (shell.rows_done, shell.rows);
        let (shown_done, shown_total, shown_at) = self.progress;
        if (shown_done, shown_total) == (done, total)
            || (done < total && now - shown_at < PROGRESS_EVERY_MS)
        {
            return None;
        }
        self.progress = (done, total, now);
        Some((done, total))
    }

    /// What to show of the graphics device as the viewer found it (`device`; a device that
    /// needs a fresh canvas, which the page has given, is being opened again) while the page
    /// shows the gallery (`in_gallery`) or the viewer; an error with the words to show when no
    /// device can be opened again.
    pub fn device(
        &mut self,
        device: Device,
        status: &ViewStatus,
        in_gallery: bool,
    ) -> Result<DeviceShown, String> {
        let mut shown = DeviceShown {
            draws: true,
            signals: Vec::new(),
            say: Say::Nothing,
            backend: None,
        };
        match device {
            Device::Ready => {}
            Device::Reopening(reason) | Device::NeedsCanvas(reason) => {
                shown.draws = false;
                shown.say = Say::Show(format!(
                    "The graphics device was lost ({reason}); opening it again…"
                ));
                if !in_gallery {
                    shown.signals.push(("state", "recovering".to_string()));
                }
            }
            Device::Reopened(backend) => {
                self.recoveries += 1;
                shown
                    .signals
                    .push(("recoveries", self.recoveries.to_string()));
                shown.say = if in_gallery {
                    Say::Hide
                } else {
                    let rows = status.shell.as_ref().map_or(0, |s| s.rows_done);
                    Say::Show(format!(
                        "The graphics device was lost and has been opened again, with \
                         {backend}: the shell goes on from row {rows}."
                    ))
                };
                shown.backend = Some(backend);
            }
            Device::Gone(message) => return Err(message),
        }
        Ok(shown)
    }

    /// What a frame that drew `shell` shows of it.
    fn drawn(&mut self, shell: &ShellStatus, shown: &mut FrameShown) {
        shown.signal("rows", shell.rows_done.to_string());
        shown.signal("settled", if shell.settled { "true" } else { "false" });
        let whole = shell.done && shell.settled;
        shown.signal("growth", if whole { "done" } else { "growing" });
        shown.sizes = true;
        if let Some(failure) = &shell.failure {
            if self.stop_said != Some(shell.session) {
                shown.say = Say::Show(failure.clone());
                self.stop_said = Some(shell.session);
            }
            shown.signal("state", "stopped");
        } else if shell.finished() {
            if let Some(hash) = shell.pattern_hash {
                shown.signal("patternHash", format!("{hash:016x}"));
            }
            let counts = &shell.counts;
            shown.signal(
                "mesh",
                format!(
                    "{} vertices, {} triangles",
                    counts.vertices, counts.triangles
                ),
            );
            if let Some(hash) = shell.mesh_hash {
                shown.signal("meshHash", format!("{hash:016x}"));
            }
            shown.signal("state", "grown");
        } else {
            shown.signal("state", "growing");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::preview::PreviewState;

    impl FrameShown {
        /// The value of signal `name` if this frame sets it (the last, if set twice).
        fn signal_of(&self, name: &str) -> Option<&str> {
            (self.signals.iter().rev())
                .find(|(n, _)| *n == name)
                .map(|(_, v)| v.as_str())
        }
    }

    fn growing(rows_done: usize) -> ViewStatus {
        ViewStatus {
            shell: Some(ShellStatus {
                session: 1,
                rows_done,
                rows: 100,
                ..ShellStatus::default()
            }),
            preview: None,
        }
    }

    fn whole() -> ViewStatus {
        let mut status = growing(100);
        let shell = status.shell.as_mut().unwrap();
        (shell.done, shell.settled, shell.at_rest) = (true, true, true);
        (shell.pattern_hash, shell.mesh_hash) = (Some(0xab), Some(0xcd));
        shell.counts.vertices = 12;
        shell.counts.triangles = 20;
        status
    }

    #[test]
    fn before_the_worker_has_built_the_shell_it_is_not_settled_and_shows_no_rows() {
        let shown = Readout::default().frame(&ViewStatus::default(), true, 0.0);
        assert_eq!(shown.signal_of("settled"), Some("false"));
        assert_eq!(shown.signal_of("preview"), Some(""));
        assert_eq!((shown.signal_of("rows"), shown.progress), (None, None));
    }

    #[test]
    fn rows_and_state_are_said_only_with_a_frame_that_draws_them() {
        let mut readout = Readout::default();
        let unseen = readout.frame(&growing(10), false, 0.0);
        assert_eq!(unseen.signal_of("settled"), Some("false"));
        assert_eq!(unseen.signal_of("rows"), None);
        assert_eq!(unseen.signal_of("state"), None);
        assert!(!unseen.sizes);
        let drawn = readout.frame(&growing(10), true, 1.0);
        assert_eq!(drawn.signal_of("rows"), Some("10"));
        assert_eq!(drawn.signal_of("state"), Some("growing"));
        assert_eq!(drawn.signal_of("growth"), Some("growing"));
        assert!(drawn.sizes);
    }

    #[test]
    fn grown_comes_with_its_hashes_and_counts_and_only_when_at_rest() {
        let mut readout = Readout::default();
        let shown = readout.frame(&whole(), true, 0.0);
        assert_eq!(shown.signal_of("state"), Some("grown"));
        assert_eq!(shown.signal_of("settled"), Some("true"));
        assert_eq!(shown.signal_of("growth"), Some("done"));
        assert_eq!(shown.signal_of("patternHash"), Some("00000000000000ab"));
        assert_eq!(shown.signal_of("meshHash"), Some("00000000000000cd"));
        assert_eq!(shown.signal_of("mesh"), Some("12 vertices, 20 triangles"));
        let mut turning = whole();
        turning.shell.as_mut().unwrap().at_rest = false;
        let shown = readout.frame(&turning, true, 1.0);
        assert_eq!(shown.signal_of("state"), Some("growing"));
        assert_eq!(shown.signal_of("growth"), Some("done"));
        assert_eq!(shown.signal_of("meshHash"), None);
    }

    #[test]
    fn why_growth_stopped_is_said_once_per_shell() {
        let mut readout = Readout::default();
        let mut stopped = growing(40);
        let shell = stopped.shell.as_mut().unwrap();
        shell.failure = Some("the whorls pass through one another".to_string());
        shell.done = true;
        let first = readout.frame(&stopped, true, 0.0);
        assert_eq!(
            first.say,
            Say::Show("the whorls pass through one another".to_string())
        );
        assert_eq!(first.signal_of("state"), Some("stopped"));
        let again = readout.frame(&stopped, true, 1.0);
        assert_eq!(again.say, Say::Nothing);
        assert_eq!(again.signal_of("state"), Some("stopped"));
        stopped.shell.as_mut().unwrap().session = 2;
        let next_shell = readout.frame(&stopped, true, 2.0);
        assert_ne!(
            next_shell.say,
            Say::Nothing,
            "another shell's failure is said"
        );
    }

    #[test]
    fn the_progress_bar_moves_at_most_every_100_ms_but_always_to_the_last_row() {
        let mut readout = Readout::default();
        assert_eq!(
            readout.frame(&growing(1), false, 0.0).progress,
            Some((1, 100))
        );
        assert_eq!(readout.frame(&growing(2), false, 50.0).progress, None);
        assert_eq!(readout.frame(&growing(3), false, 99.0).progress, None);
        assert_eq!(
            readout.frame(&growing(4), false, 100.0).progress,
            Some((4, 100))
        );
        assert_eq!(
            readout.frame(&growing(4), false, 500.0).progress,
            None,
            "unchanged"
        );
        // The last row is shown at once, however soon after the one before.
        assert_eq!(
            readout.frame(&whole(), false, 501.0).progress,
            Some((100, 100))
        );
    }

    #[test]
    fn a_lost_device_holds_the_drawing_and_one_opened_again_is_counted_and_said() {
        let mut readout = Readout::default();
        let lost = Device::Reopening("the driver was reset".to_string());
        let shown = readout.device(lost.clone(), &growing(30), false).unwrap();
        assert!(!shown.draws);
        assert_eq!(shown.signals, [("state", "recovering".to_string())]);
        assert_eq!(
            shown.say,
            Say::Show(
                "The graphics device was lost (the driver was reset); opening it again…".into()
            )
        );
        // Over the gallery, the viewer's state is not the page's.
        let shown = readout.device(lost, &growing(30), true).unwrap();
        assert!(shown.signals.is_empty());
        for (k, in_gallery) in [(1, false), (2, true)] {
            let shown =
                (readout.device(Device::Reopened("WebGL2".into()), &growing(30), in_gallery))
                    .unwrap();
            assert!(shown.draws);
            assert_eq!(shown.signals, [("recoveries", k.to_string())]);
            assert_eq!(shown.backend.as_deref(), Some("WebGL2"));
            if in_gallery {
                assert_eq!(shown.say, Say::Hide);
            } else {
                assert_eq!(
                    shown.say,
                    Say::Show("The graphics device was lost and has been opened again, with WebGL2: the shell goes on from row 30.".into())
                );
            }
        }
        let ready = readout.device(Device::Ready, &growing(30), false).unwrap();
        assert!(ready.draws && ready.signals.is_empty() && ready.say == Say::Nothing);
        assert_eq!(
            readout.device(Device::Gone("no device".into()), &growing(30), false),
            Err("no device".to_string())
        );
    }

    #[test]
    fn the_preview_of_a_dragged_slider_is_signalled() {
        let mut status = growing(5);
        status.preview = Some(PreviewState::Filling);
        let shown = Readout::default().frame(&status, false, 0.0);
        assert_eq!(shown.signal_of("preview"), Some("filling"));
    }
}
