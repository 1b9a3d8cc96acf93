//! What the page takes from its viewer in a frame, sorted out of the news a drawing worker
//! sent since the page's last ([`ViewerNews`], each with the video frame posted beside it, of
//! the platform's type `F`): the viewer's frames with their recorded video frames matched,
//! the shells it refused, what its pool said last, whether it opened and whether it panicked.
//! A viewer on the page's own thread gives one frame of the same kind. `web/viewer_handle.rs`
//! feeds it the worker's messages; the simulator feeds it what its drawing worker posts.

use super::viewer_message::{PoolNews, ViewerNews};
use super::viewer_status::FrameReport;

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
pub fn take<F>(
    news: impl IntoIterator<Item = (ViewerNews, Option<F>)>,
) -> Result<Taken<F>, String> {
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
pub fn crash<F>(news: &[(ViewerNews, F)]) -> Option<&str> {
    news.iter().find_map(|(n, _)| match n {
        ViewerNews::Crashed(message) => Some(message.as_str()),
        _ => None,
    })
}

/// Whether the drawing worker opened its renderer, taking its answer out of `news`: the
/// backend, or why it could not, or (no answer after `waited_s` seconds) that it said nothing.
pub fn opened<F>(news: &mut Vec<(ViewerNews, F)>, waited_s: i32) -> Result<String, String> {
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
    use crate::work::viewer_status::Device;

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
}
