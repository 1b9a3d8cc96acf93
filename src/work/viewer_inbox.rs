//! What the page takes from its viewer in a frame, sorted out of the news a drawing worker
//! sent since the page's last ([`ViewerNews`], each with the video frame posted beside it, of
//! the platform's type `F`): the viewer's frames with their recorded video frames matched,
//! the shells it refused, what its pool said last, whether it opened and whether it panicked.
//! A viewer on the page's own thread gives one frame of the same kind. [`Inbox`] is what the
//! page holds of a drawing worker between its frames: `web/viewer_handle.rs` hands it the
//! worker's messages as they come, and so does the simulator.

use super::drawing_link::DrawingLink;
use super::viewer_message::{PoolNews, ViewerNews, decode_news};
use super::viewer_status::{Device, FrameReport};

/// Why the page takes nothing more from its drawing worker: the view then moves to the page's
/// thread.
#[derive(Clone, Debug, PartialEq)]
pub enum Unheard {
    /// It said nothing for [`super::drawing_link::SILENT_MS`] of frames sent to it (in words).
    Silent(String),
    /// Its renderer failed (why).
    Failed(String),
}

impl std::fmt::Display for Unheard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unheard::Silent(words) | Unheard::Failed(words) => f.write_str(words),
        }
    }
}

/// What the page has heard of its drawing worker since it last looked: the worker's news, in
/// order, what they say of its device and its silences ([`DrawingLink`]), and a failure of the
/// worker itself (it could not load, it threw outside the viewer, its news could not be read).
#[derive(Debug)]
pub struct Inbox<F> {
    news: Vec<(ViewerNews, Option<F>)>,
    link: DrawingLink,
    error: Option<String>,
}

impl<F> Default for Inbox<F> {
    fn default() -> Self {
        Self {
            news: Vec::new(),
            link: DrawingLink::default(),
            error: None,
        }
    }
}

impl<F> Inbox<F> {
    /// A message of the worker at `now`: its news as the bytes it posted, and the video frame
    /// posted beside them. Says whether it is the worker's answer to opening its renderer;
    /// fails, and keeps the failure for [`Inbox::device`], when the news cannot be read.
    pub fn heard(&mut self, bytes: &[u8], video: Option<F>, now: f64) -> Result<bool, String> {
        match decode_news(bytes) {
            Ok(news) => {
                let device = match &news {
                    ViewerNews::Frame { device, .. } => Some(device),
                    _ => None,
                };
                self.link.heard(now, device);
                let opened = matches!(news, ViewerNews::Opened(_));
                self.news.push((news, video));
                Ok(opened)
            }
            Err(e) => {
                self.link.heard(now, None);
                let why = format!("the drawing worker's news was misread: {e}");
                self.error.get_or_insert(why.clone());
                Err(why)
            }
        }
    }

    /// The worker failed outside its viewer (`why`: it could not load, or threw); the first
    /// failure is kept.
    pub fn failed(&mut self, why: String) {
        self.error.get_or_insert(why);
    }

    /// Whether the worker opened its renderer: the backend, or why not (its own failure
    /// first), or that it said nothing in `waited_s` seconds.
    pub fn opened(&mut self, waited_s: i32) -> Result<String, String> {
        match self.error.take() {
            Some(why) => Err(why),
            None => opened(&mut self.news, waited_s),
        }
    }

    /// The state of the worker's device as the page goes through it this frame (see
    /// [`DrawingLink::device`]); a failure of the worker itself is its device gone.
    pub fn device(&mut self) -> Device {
        if let Some(why) = self.error.take() {
            self.link.failed(why);
        }
        self.link.device()
    }

    /// The first panic among the news not yet taken: the message the page shows as its own.
    pub fn crash(&self) -> Option<&str> {
        crash(&self.news)
    }

    /// The page sent the worker a frame at `now`.
    pub fn ticked(&mut self, now: f64) {
        self.link.ticked(now);
    }

    /// What the page takes at `now` of the news since its last frame (see [`take`]); fails
    /// when the worker has gone silent or its renderer failed.
    pub fn take(&mut self, now: f64) -> Result<Taken<F>, Unheard> {
        (self.link)
            .took(!self.news.is_empty(), now)
            .map_err(Unheard::Silent)?;
        take(self.news.drain(..)).map_err(Unheard::Failed)
    }

    /// Fails when the worker's renderer failed or the worker fell silent, at `now`, its news
    /// left for [`Inbox::take`]: a page whose device is not ready takes nothing in, and a
    /// worker that fails or hangs while its device is lost says nothing more of the device
    /// (the page would wait for it for ever).
    pub fn answering(&self, now: f64) -> Result<(), Unheard> {
        let failed = self.news.iter().find_map(|(n, _)| match n {
            ViewerNews::Failed(why) => Some(why.clone()),
            _ => None,
        });
        if let Some(why) = failed {
            return Err(Unheard::Failed(why));
        }
        self.link.silent(now).map_err(Unheard::Silent)
    }
}

/// One frame of the viewer: what a worker posts of it, and a recording's video frame asked
/// for, drawn (or why it could not be).
#[derive(Debug)]
pub struct ViewFrame<F> {
    pub report: FrameReport,
    pub recorded: Option<Result<F, String>>,
}

/// What the page takes from its viewer in a frame.
#[derive(Debug)]
pub struct Taken<F> {
    /// The viewer's frames since the page's last (one on the page's thread; as many as the
    /// worker ran, or none, in a worker).
    pub frames: Vec<ViewFrame<F>>,
    /// Shells that could not be built or grown: the loads the viewer had taken when it said
    /// so (none: whatever shell it held), and why.
    pub refused: Vec<(Option<u32>, String)>,
    /// What the drawing worker's pool said of itself last.
    pub pool: Option<PoolNews>,
}

impl<F> Default for Taken<F> {
    fn default() -> Self {
        Self {
            frames: Vec::new(),
            refused: Vec::new(),
            pool: None,
        }
    }
}

/// Sorts `news` into what the page takes: a frame's video frame is the one posted beside it
/// when the frame says it drew one (else why not, or that it never arrived). Fails with the
/// words to show when the viewer's renderer failed.
fn take<F>(news: impl IntoIterator<Item = (ViewerNews, Option<F>)>) -> Result<Taken<F>, String> {
    let mut taken = Taken::default();
    for (news, video) in news {
        match news {
            ViewerNews::Frame {
                report: Some(report),
                recorded,
                ..
            } => taken.frames.push(ViewFrame {
                report: *report,
                recorded: match (recorded, video) {
                    (Some(Ok(())), Some(frame)) => Some(Ok(frame)),
                    (Some(Ok(())), None) => Some(Err("the video frame did not arrive".into())),
                    (Some(Err(e)), _) => Some(Err(e)),
                    (None, _) => None,
                },
            }),
            ViewerNews::Refused { loads, why } => taken.refused.push((loads, why)),
            ViewerNews::Failed(why) => return Err(why),
            ViewerNews::Pool(pool) => taken.pool = Some(pool),
            ViewerNews::Frame { report: None, .. }
            | ViewerNews::Opened(_)
            | ViewerNews::Crashed(_) => {}
        }
    }
    Ok(taken)
}

/// The first panic among `news`: the message the page shows as its own.
fn crash<F>(news: &[(ViewerNews, F)]) -> Option<&str> {
    news.iter().find_map(|(n, _)| match n {
        ViewerNews::Crashed(message) => Some(message.as_str()),
        _ => None,
    })
}

/// Whether the drawing worker opened its renderer, taking its answer out of `news`: the
/// backend, or why it could not, or (no answer after `waited_s` seconds) that it said nothing.
fn opened<F>(news: &mut Vec<(ViewerNews, F)>, waited_s: i32) -> Result<String, String> {
    let at = news
        .iter()
        .position(|(n, _)| matches!(n, ViewerNews::Opened(_)));
    match at.map(|at| news.remove(at).0) {
        Some(ViewerNews::Opened(answer)) => answer,
        _ => Err(format!("the drawing worker said nothing in {waited_s} s")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(loads: u32, recorded: Option<Result<(), String>>) -> ViewerNews {
        ViewerNews::Frame {
            device: Device::Ready,
            report: Some(Box::new(FrameReport {
                loads,
                ..FrameReport::default()
            })),
            recorded,
        }
    }

    #[test]
    fn each_frame_takes_the_video_frame_posted_beside_it_or_says_it_is_missing() {
        let news = vec![
            (frame(1, Some(Ok(()))), Some("first picture")),
            (frame(1, Some(Ok(()))), None),
            (frame(2, Some(Err("too big".into()))), None),
            (frame(2, None), Some("stray")),
            (
                ViewerNews::Frame {
                    device: Device::Reopening("lost".into()),
                    report: None,
                    recorded: None,
                },
                None,
            ),
        ];
        let taken = take(news).expect("no failure");
        let recorded: Vec<_> = taken.frames.iter().map(|f| f.recorded.clone()).collect();
        assert_eq!(
            recorded,
            [
                Some(Ok("first picture")),
                Some(Err("the video frame did not arrive".into())),
                Some(Err("too big".into())),
                None,
            ],
            "a frame without a report (its device lost) is no frame"
        );
        let loads: Vec<u32> = taken.frames.iter().map(|f| f.report.loads).collect();
        assert_eq!(loads, [1, 1, 2, 2], "in the order sent");
    }

    #[test]
    fn refusals_are_kept_the_last_pool_news_wins_and_a_failure_ends_the_frame() {
        let pool = |count| PoolNews {
            count,
            ..PoolNews::default()
        };
        let news: Vec<(ViewerNews, Option<()>)> = vec![
            (ViewerNews::Pool(pool(1)), None),
            (
                ViewerNews::Refused {
                    loads: Some(3),
                    why: "no such shell".into(),
                },
                None,
            ),
            (ViewerNews::Pool(pool(2)), None),
        ];
        let taken = take(news).expect("no failure");
        assert_eq!(taken.refused, [(Some(3), "no such shell".to_string())]);
        assert_eq!(taken.pool.map(|p| p.count), Some(2));
        let failed: Vec<(ViewerNews, Option<()>)> = vec![
            (frame(1, None), None),
            (ViewerNews::Failed("the GPU went away".into()), None),
        ];
        assert_eq!(take(failed).err().as_deref(), Some("the GPU went away"));
    }

    #[test]
    fn the_answer_to_opening_is_taken_out_and_a_panic_is_found_among_frames() {
        let mut news = vec![
            (frame(0, None), ()),
            (ViewerNews::Opened(Ok("WebGL2".into())), ()),
        ];
        assert_eq!(opened(&mut news, 20), Ok("WebGL2".to_string()));
        assert_eq!(news.len(), 1, "the frame stays");
        assert_eq!(
            opened(&mut news, 20),
            Err("the drawing worker said nothing in 20 s".to_string())
        );
        assert_eq!(crash(&news), None);
        news.push((ViewerNews::Crashed("panicked at growth".into()), ()));
        news.push((ViewerNews::Crashed("a second panic".into()), ()));
        assert_eq!(crash(&news), Some("panicked at growth"));
    }

    #[test]
    fn the_inbox_hears_the_worker_and_its_failures_and_its_silence() {
        use crate::work::drawing_link::SILENT_MS;
        use crate::work::viewer_message::encode_news;
        let mut inbox: Inbox<()> = Inbox::default();
        let opening = encode_news(&ViewerNews::Opened(Ok("WebGPU".into())));
        assert_eq!(
            inbox.heard(&encode_news(&frame(1, None)), None, 0.0),
            Ok(false)
        );
        assert_eq!(
            inbox.heard(&opening, None, 0.0),
            Ok(true),
            "the answer to opening"
        );
        assert_eq!(inbox.opened(20), Ok("WebGPU".to_string()));
        assert_eq!(inbox.take(0.0).map(|t| t.frames.len()), Ok(1));
        // Frames sent and nothing heard: taken for hung only after SILENT_MS.
        inbox.ticked(1.0);
        assert!(inbox.take(SILENT_MS).is_ok());
        let silent = inbox.take(SILENT_MS + 2.0).err();
        let answered = "the drawing worker has not answered";
        assert!(
            matches!(&silent, Some(Unheard::Silent(words)) if words.starts_with(answered)),
            "{silent:?}"
        );
        // News that cannot be read is the worker's failure: its device is gone.
        let misread = inbox.heard(&[0xff, 0xff, 0xff], None, 3.0);
        assert!(misread.is_err_and(|e| e.contains("misread")));
        assert_eq!(
            inbox.device(),
            Device::Ready,
            "first the change heard before it"
        );
        assert!(matches!(inbox.device(), Device::Gone(why) if why.contains("misread")));
        // A worker that failed to load answers opening with its failure, kept once.
        let mut failed: Inbox<()> = Inbox::default();
        failed.failed("the drawing worker failed: no module".into());
        failed.failed("a second failure".into());
        assert_eq!(
            failed.opened(20),
            Err("the drawing worker failed: no module".into())
        );
        assert_eq!(
            failed.opened(20),
            Err("the drawing worker said nothing in 20 s".into())
        );
    }

    #[test]
    fn a_worker_that_fails_or_falls_silent_while_its_device_is_lost_is_found_out() {
        use crate::work::drawing_link::SILENT_MS;
        use crate::work::viewer_message::encode_news;
        let lost = ViewerNews::Frame {
            device: Device::Reopening("the context was lost".into()),
            report: None,
            recorded: None,
        };
        let mut inbox: Inbox<()> = Inbox::default();
        inbox.heard(&encode_news(&lost), None, 0.0).unwrap();
        assert!(matches!(inbox.device(), Device::Reopening(_)));
        assert_eq!(inbox.answering(0.0), Ok(()));
        // It fails while the page takes nothing in: found, and its news still there to take.
        let failed = ViewerNews::Failed("Nothing drawn reaches the screen".into());
        inbox.heard(&encode_news(&failed), None, 1.0).unwrap();
        assert!(
            matches!(inbox.device(), Device::Reopening(_)),
            "nothing more of the device"
        );
        let why = Unheard::Failed("Nothing drawn reaches the screen".into());
        assert_eq!(inbox.answering(1.0), Err(why.clone()));
        assert_eq!(inbox.take(1.0).err(), Some(why));
        // One that answered the page's last frame is not silent after a pause in the page's
        // frames (a hidden tab).
        let mut paused: Inbox<()> = Inbox::default();
        paused.ticked(0.0);
        paused.heard(&encode_news(&lost), None, 1.0).unwrap();
        assert_eq!(paused.answering(SILENT_MS + 5_000.0), Ok(()));
        // It hangs while the page sends it frames: found after SILENT_MS.
        let mut hung: Inbox<()> = Inbox::default();
        hung.heard(&encode_news(&lost), None, 0.0).unwrap();
        hung.ticked(1.0);
        assert_eq!(hung.answering(SILENT_MS), Ok(()));
        assert!(matches!(
            hung.answering(SILENT_MS + 2.0),
            Err(Unheard::Silent(_))
        ));
    }
}
