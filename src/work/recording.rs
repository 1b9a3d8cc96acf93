//! A video recording as the page runs it: what the browser can record with, whether Record
//! may start, and what the page says at every turn of a recording (under way, saved, failed,
//! cancelled). The page asks the browser and drives its encoder; the words and the rules are
//! here, tested natively. The plan and the pacing of the frames are
//! [`crate::view::recording`]'s.

use crate::export::webm::VideoCodec;
use crate::view::recording::{Progress, RecordingPlan};

/// What this browser can record with. The browser is asked when Record is first pressed, not
/// when the page opens: asking wakes the browser's media stack, which costs every visitor
/// time, and WebKitGTK 2.50 on Debian 12 crashes the page's process as soon as it is asked.
#[derive(Clone, Debug, PartialEq)]
pub enum Support {
    /// Not asked yet.
    Unasked,
    /// Not known yet (the encoders are being asked).
    Checking,
    /// WebCodecs with this codec, frame-exact.
    WebCodecs(VideoCodec),
    /// `MediaRecorder` writing this type, in real time.
    MediaRecorder(String),
    /// Nothing: why.
    Nothing(String),
}

impl Support {
    /// The page's signal (`data-encoder`).
    pub fn signal(&self) -> &str {
        match self {
            Support::Unasked => "unasked",
            Support::Checking => "checking",
            Support::WebCodecs(codec) => codec.name(),
            Support::MediaRecorder(_) => "MediaRecorder",
            Support::Nothing(_) => "none",
        }
    }

    /// Whether Record can start a recording now (the browser has answered, with something).
    pub fn may_record(&self) -> bool {
        matches!(self, Support::WebCodecs(_) | Support::MediaRecorder(_))
    }

    /// Whether the Record button is refused (the browser can record nothing).
    pub fn refused(&self) -> bool {
        matches!(self, Support::Nothing(_))
    }

    /// What the page says about recording here, before anything is recorded.
    pub fn note(&self) -> String {
        match self {
            Support::Unasked => {
                "Records every frame of the growth; Record first asks the browser for a video \
                 encoder."
                    .into()
            }
            Support::Checking => "Asking the browser for a video encoder…".into(),
            Support::WebCodecs(codec) => format!(
                "Records every frame of the growth, however slow this machine: {} in WebM.",
                codec.name()
            ),
            Support::MediaRecorder(mime) => format!(
                "This browser has no WebCodecs video encoder, so the video is recorded in real \
                 time with MediaRecorder ({mime}): on a slow machine it is uneven."
            ),
            Support::Nothing(why) => format!("This browser cannot record video: {why}."),
        }
    }

    /// What the browser answered when asked: the first codec of [`VideoCodec::PREFERENCE`]
    /// its encoder takes (`encoder` is `None` without WebCodecs' `VideoEncoder`), else the
    /// first type `MediaRecorder` writes, else why neither.
    pub fn answered(encoder: Option<Option<VideoCodec>>, recorder: Option<&str>) -> Self {
        if let Some(Some(codec)) = encoder {
            return Support::WebCodecs(codec);
        }
        if let Some(mime) = recorder {
            return Support::MediaRecorder(mime.to_string());
        }
        Support::Nothing(if encoder.is_some() {
            "its VideoEncoder takes none of VP9, VP8 and AV1, and it has no MediaRecorder".into()
        } else {
            "it has neither WebCodecs' VideoEncoder nor MediaRecorder".into()
        })
    }
}

/// The status line of a recording under way at `progress` of `plan`, `real_time` when
/// `MediaRecorder` records it (and the page says what that costs).
pub fn under_way(plan: &RecordingPlan, progress: &Progress, real_time: bool) -> String {
    let frames = plan.frames();
    if progress.flushing() {
        return format!("Finishing the file ({frames} frames)…");
    }
    format!(
        "Recording frame {} of {frames} ({}×{}, {} a second{})…",
        progress.frames_done() + 1,
        plan.width,
        plan.height,
        plan.fps,
        if real_time {
            ", in real time with MediaRecorder: this browser has no WebCodecs video encoder, so \
             on a slow machine the video is uneven"
        } else {
            ""
        }
    )
}

/// How a recording ended, or why it never began.
#[derive(Clone, Debug, PartialEq)]
pub enum Ended {
    /// The file `name` was offered: `frames` frames, `seconds` long.
    Saved {
        name: String,
        frames: usize,
        seconds: f64,
    },
    /// It could not start: why.
    NotStarted(String),
    /// It failed on the way: why.
    Failed(String),
    /// It was stopped: why (the user, a hidden tab, growth moved by hand…).
    Cancelled(String),
}

impl Ended {
    /// The page's signal (`data-record`).
    pub fn signal(&self) -> &'static str {
        match self {
            Ended::Saved { .. } => "saved",
            Ended::NotStarted(_) | Ended::Failed(_) => "failed",
            Ended::Cancelled(_) => "cancelled",
        }
    }

    /// What the page says, in a sentence.
    pub fn words(&self) -> String {
        match self {
            Ended::Saved {
                name,
                frames,
                seconds,
            } => format!("Saved {name}: {frames} frames, {seconds:.2} s."),
            Ended::NotStarted(why) => format!("The recording could not start: {why}."),
            Ended::Failed(why) => format!("The recording failed: {why}. Nothing was saved."),
            Ended::Cancelled(why) => format!("Recording cancelled: {why}. Nothing was saved."),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::recording::{Pace, RecordingOptions, VideoSize};

    #[test]
    fn record_starts_only_once_the_browser_has_answered_with_an_encoder() {
        assert!(!Support::Unasked.may_record());
        assert!(!Support::Checking.may_record());
        assert!(Support::WebCodecs(VideoCodec::Vp9).may_record());
        assert!(Support::MediaRecorder("video/webm".into()).may_record());
        let nothing = Support::Nothing("no encoder".into());
        assert!(!nothing.may_record() && nothing.refused());
        assert!(!Support::Checking.refused());
        assert_eq!(
            nothing.note(),
            "This browser cannot record video: no encoder."
        );
        assert_eq!(Support::WebCodecs(VideoCodec::Vp8).signal(), "VP8");
    }

    #[test]
    fn the_browsers_answer_prefers_webcodecs_then_mediarecorder_and_says_why_not() {
        let vp9 = Support::answered(Some(Some(VideoCodec::Vp9)), Some("video/webm"));
        assert_eq!(vp9, Support::WebCodecs(VideoCodec::Vp9));
        let stream = Support::answered(Some(None), Some("video/mp4"));
        assert_eq!(stream, Support::MediaRecorder("video/mp4".into()));
        assert!(stream.note().contains("MediaRecorder (video/mp4)"));
        let Support::Nothing(why) = Support::answered(Some(None), None) else {
            panic!("an encoder that takes no codec and no recorder records nothing");
        };
        assert!(why.contains("none of VP9, VP8 and AV1"), "{why}");
        let Support::Nothing(why) = Support::answered(None, None) else {
            panic!("a browser without either records nothing");
        };
        assert!(why.contains("neither"), "{why}");
    }

    #[test]
    fn the_status_line_counts_frames_and_says_what_real_time_costs() {
        let options = RecordingOptions {
            size: VideoSize::P360,
            fps: 30,
            turntable_s: 0,
        };
        let plan = RecordingPlan::new(31, 1.0, options);
        let mut progress = Progress::default();
        let first = under_way(&plan, &progress, false);
        assert!(
            first.starts_with(&format!("Recording frame 1 of {}", plan.frames())),
            "{first}"
        );
        assert!(!first.contains("MediaRecorder"));
        assert!(under_way(&plan, &progress, true).contains("in real time with MediaRecorder"));
        for _ in 0..plan.frames() {
            progress
                .ask(&plan, Pace::Encoder { queued: 0 })
                .expect("the encoder has room");
            progress.captured(&plan);
        }
        assert_eq!(
            under_way(&plan, &progress, false),
            format!("Finishing the file ({} frames)…", plan.frames())
        );
    }

    #[test]
    fn each_end_is_said_with_its_signal() {
        let saved = Ended::Saved {
            name: "turbinate-360p30.webm".into(),
            frames: 61,
            seconds: 2.0333,
        };
        assert_eq!(saved.signal(), "saved");
        assert_eq!(
            saved.words(),
            "Saved turbinate-360p30.webm: 61 frames, 2.03 s."
        );
        let cancelled = Ended::Cancelled("the tab was hidden".into());
        assert_eq!(cancelled.signal(), "cancelled");
        assert_eq!(
            cancelled.words(),
            "Recording cancelled: the tab was hidden. Nothing was saved."
        );
        assert_eq!(Ended::Failed("x".into()).signal(), "failed");
        assert_eq!(
            Ended::NotStarted("no canvas".into()).words(),
            "The recording could not start: no canvas."
        );
    }
}
