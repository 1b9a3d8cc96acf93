//! The plan of a frame-exact video of a shell's growth: one video frame per growth frame at a
//! fixed rate, however long each takes to grow, draw and encode, then optionally a turntable.
//!
//! How many rows a video frame grows: as many as the link's speed grows in the same time on a
//! 60 Hz display (`growth.speed` rows per display frame), so the video shows the growth at the
//! pace the page shows it — 2 to 22 seconds for the presets. That pace is bounded so that the
//! growth lasts at least [`MIN_GROWTH_S`] (a shell grown at 200 rows a frame would otherwise be
//! over in a few frames) and at most [`MAX_GROWTH_S`] (a slow speed would make a file nobody
//! watches). Frame i of the growth shows the shell at row 1 + (i + 1)(rows − 1)/n of its n
//! growth frames, so the last one shows it whole; the turntable then turns the camera once
//! around the grown shell and ends where it began.

use serde::{Deserialize, Serialize};
use std::f32::consts::TAU;

/// The display rate the link's speed is counted in (rows per frame at 60 Hz).
pub const DISPLAY_HZ: f64 = 60.0;
/// The shortest growth a video shows, in seconds.
pub const MIN_GROWTH_S: f64 = 1.0;
/// The longest growth a video shows, in seconds.
pub const MAX_GROWTH_S: f64 = 60.0;
/// Seconds between key frames (each starts a cluster the player can seek to).
pub const KEYFRAME_S: u32 = 2;

/// The video's size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VideoSize {
    /// A quick, small preview (and what the page tests record).
    P360,
    P720,
    P1080,
}

impl VideoSize {
    /// Width and height in pixels (16:9).
    pub fn pixels(self) -> (u32, u32) {
        match self {
            VideoSize::P360 => (640, 360),
            VideoSize::P720 => (1280, 720),
            VideoSize::P1080 => (1920, 1080),
        }
    }

    /// Reads "360", "720" or "1080".
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "360" => Some(VideoSize::P360),
            "720" => Some(VideoSize::P720),
            "1080" => Some(VideoSize::P1080),
            _ => None,
        }
    }
}

/// What the person recording chose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecordingOptions {
    pub size: VideoSize,
    /// 30 or 60 frames a second.
    pub fps: u32,
    /// Seconds of turntable after the growth (0: none).
    pub turntable_s: u32,
}

/// The longest turntable offered, seconds.
const LONGEST_TURNTABLE_S: u32 = 6;

impl RecordingOptions {
    /// The options as the page's choices read them (size "360", "720" or "1080"; "30" or "60"
    /// frames a second; seconds of turntable): anything else is read as 720p, 30 frames a
    /// second and no turntable, and a turntable is at most six seconds.
    pub fn from_choices(size: &str, fps: &str, turntable_s: &str) -> Self {
        Self {
            size: VideoSize::parse(size).unwrap_or(VideoSize::P720),
            fps: if fps == "60" { 60 } else { 30 },
            turntable_s: turntable_s.parse().unwrap_or(0).min(LONGEST_TURNTABLE_S),
        }
    }
}

/// One video frame a recording asks of the viewer: the shell grown to `row`, the camera eased
/// by `dt` seconds of video (not of the clock) and turned by `turn` radians about the vertical,
/// drawn, and read as the frame shown at `timestamp_us` for `duration_us`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameAsk {
    pub row: usize,
    pub dt: f32,
    pub turn: f32,
    pub timestamp_us: u64,
    pub duration_us: u64,
}

/// The frames of one recording.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordingPlan {
    pub width: u32,
    pub height: u32,
    pub fps: u32,
    /// Rows from apex to opening.
    rows: usize,
    /// Frames of growth (the last shows the whole shell).
    pub growth_frames: usize,
    /// Frames of turntable after it.
    pub turntable_frames: usize,
}

impl RecordingPlan {
    /// The plan for a shell of `rows` rows whose link grows `speed` rows per display frame.
    pub fn new(rows: usize, speed: f64, options: RecordingOptions) -> Self {
        let (width, height) = options.size.pixels();
        let fps = options.fps.max(1);
        let seconds = (rows.saturating_sub(1) as f64 / (speed.max(1e-6) * DISPLAY_HZ))
            .clamp(MIN_GROWTH_S, MAX_GROWTH_S);
        Self {
            width,
            height,
            fps,
            rows: rows.max(1),
            growth_frames: ((seconds * f64::from(fps)).round() as usize).max(1),
            turntable_frames: (options.turntable_s * fps) as usize,
        }
    }

    /// All the video's frames.
    pub fn frames(&self) -> usize {
        self.growth_frames + self.turntable_frames
    }

    /// Rows grown in the video frame `frame` (0-based).
    pub fn rows_at(&self, frame: usize) -> usize {
        let i = frame.min(self.growth_frames - 1);
        1 + (i + 1) * (self.rows - 1) / self.growth_frames
    }

    /// The camera's turn about the vertical in frame `frame`, radians: none during growth,
    /// then a whole turn over the turntable, its last frame back where the growth ended.
    pub fn turn_at(&self, frame: usize) -> f32 {
        match frame.checked_sub(self.growth_frames) {
            Some(j) if self.turntable_frames > 0 => {
                TAU * (j + 1) as f32 / self.turntable_frames as f32
            }
            _ => 0.0,
        }
    }

    /// Seconds from one frame to the next, for the camera's easing.
    pub fn frame_s(&self) -> f32 {
        1.0 / self.fps as f32
    }

    /// When frame `frame` is shown, in microseconds.
    pub fn timestamp_us(&self, frame: usize) -> u64 {
        frame as u64 * 1_000_000 / u64::from(self.fps)
    }

    /// The video's length in microseconds.
    pub fn duration_us(&self) -> u64 {
        self.timestamp_us(self.frames())
    }

    /// What frame `frame` asks of the viewer, the camera having turned `turned` radians so far.
    pub fn ask(&self, frame: usize, turned: f32) -> FrameAsk {
        let at = self.timestamp_us(frame);
        FrameAsk {
            row: self.rows_at(frame),
            dt: self.frame_s(),
            turn: self.turn_at(frame) - turned,
            timestamp_us: at,
            duration_us: self.timestamp_us(frame + 1) - at,
        }
    }

    /// Whether frame `frame` is encoded as a key frame.
    pub fn is_keyframe(&self, frame: usize) -> bool {
        frame.is_multiple_of((KEYFRAME_S * self.fps) as usize)
    }

    /// The encoder's target in bits a second: 0.12 bits a pixel, so about 3.3 Mbit/s at 720p
    /// and 30 fps (a shell on a plain background compresses well).
    pub fn bitrate(&self) -> u32 {
        (f64::from(self.width) * f64::from(self.height) * f64::from(self.fps) * 0.12) as u32
    }

    /// The file's name: the preset, the size, and the rate.
    pub fn file_name(&self, preset: &str) -> String {
        format!("{preset}-{}p{}.webm", self.height, self.fps)
    }
}

/// Frames waiting in the encoder before the recording waits for it.
pub const MAX_QUEUE: u32 = 4;

/// What paces a recording's frames.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pace {
    /// An encoder that takes frames as fast as they come: `queued` wait in it now.
    Encoder { queued: u32 },
    /// A recorder of the canvas in real time, started at `started` and read at `now`
    /// (milliseconds): a frame is drawn when the clock reaches its timestamp.
    RealTime { started: f64, now: f64 },
}

/// Where a recording stands: the next frame to capture, the turntable's turn so far, whether
/// a frame is asked of the viewer and not yet drawn, and whether every frame is in.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Progress {
    next: usize,
    turned: f32,
    asked: bool,
    flushing: bool,
}

impl Progress {
    /// Frames captured so far.
    pub fn frames_done(&self) -> usize {
        self.next
    }

    /// Whether every frame is captured (the encoder is finishing).
    pub fn flushing(&self) -> bool {
        self.flushing
    }

    /// The next frame of `plan` to ask of the viewer, when it is time to: none is asked and
    /// not yet drawn, every frame is not yet in, and `pace` lets it (the encoder has room, or
    /// the clock has reached its timestamp).
    pub fn ask(&mut self, plan: &RecordingPlan, pace: Pace) -> Option<FrameAsk> {
        if self.flushing || self.asked {
            return None;
        }
        let waiting = match pace {
            Pace::Encoder { queued } => queued > MAX_QUEUE,
            Pace::RealTime { started, now } => {
                now < started + plan.timestamp_us(self.next) as f64 / 1000.0
            }
        };
        if waiting {
            return None;
        }
        self.asked = true;
        Some(plan.ask(self.next, self.turned))
    }

    /// The frame asked was drawn and captured; returns whether it was the last (the encoder
    /// is to finish).
    pub fn captured(&mut self, plan: &RecordingPlan) -> bool {
        self.asked = false;
        self.turned = plan.turn_at(self.next);
        self.next += 1;
        self.flushing = self.next == plan.frames();
        self.flushing
    }

    /// The frame asked could not be drawn or captured (the recording fails).
    pub fn missed(&mut self) {
        self.asked = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pages_choices_are_read_with_their_defaults_and_bounds() {
        let chosen = RecordingOptions::from_choices("1080", "60", "4");
        assert_eq!(
            chosen,
            RecordingOptions {
                size: VideoSize::P1080,
                fps: 60,
                turntable_s: 4
            }
        );
        let odd = RecordingOptions::from_choices("4k", "25", "many");
        assert_eq!(
            (odd.size, odd.fps, odd.turntable_s),
            (VideoSize::P720, 30, 0)
        );
        assert_eq!(
            RecordingOptions::from_choices("360", "30", "60").turntable_s,
            6
        );
    }

    fn options(fps: u32, turntable_s: u32) -> RecordingOptions {
        RecordingOptions {
            size: VideoSize::P720,
            fps,
            turntable_s,
        }
    }

    #[test]
    fn growth_goes_at_the_pages_pace_and_ends_on_the_whole_shell() {
        // 577 rows at 2 rows a display frame: 4.8 s, at either rate.
        for fps in [30, 60] {
            let plan = RecordingPlan::new(577, 2.0, options(fps, 0));
            assert_eq!(plan.growth_frames, (4.8 * fps as f64).round() as usize);
            assert_eq!(plan.frames(), plan.growth_frames);
            assert_eq!(plan.rows_at(plan.growth_frames - 1), 577);
            let rows: Vec<usize> = (0..plan.frames()).map(|i| plan.rows_at(i)).collect();
            assert!(rows.windows(2).all(|w| w[0] <= w[1]), "rows never go back");
            assert!(rows[0] > 1, "the first frame has grown");
            // Every frame grows (rows − 1)/n rows, to one row.
            let per = 576.0 / plan.growth_frames as f64;
            assert!(
                rows.windows(2)
                    .all(|w| ((w[1] - w[0]) as f64 - per).abs() < 1.0)
            );
        }
    }

    #[test]
    fn very_fast_and_very_slow_speeds_are_bounded() {
        let fast = RecordingPlan::new(577, 200.0, options(30, 0));
        assert_eq!(fast.growth_frames, 30, "at least a second");
        let slow = RecordingPlan::new(3900, 0.05, options(60, 0));
        assert_eq!(slow.growth_frames, 3600, "at most a minute");
        let tiny = RecordingPlan::new(1, 1.0, options(30, 0));
        assert_eq!(tiny.rows_at(0), 1);
    }

    #[test]
    fn the_turntable_turns_once_and_ends_where_it_began() {
        let plan = RecordingPlan::new(577, 200.0, options(30, 3));
        assert_eq!(plan.turntable_frames, 90);
        assert_eq!(plan.frames(), 120);
        assert_eq!(plan.turn_at(29), 0.0);
        assert!((plan.turn_at(30) - TAU / 90.0).abs() < 1e-6);
        assert!((plan.turn_at(119) - TAU).abs() < 1e-5);
        assert_eq!(
            plan.rows_at(119),
            577,
            "the turntable shows the whole shell"
        );
    }

    #[test]
    fn the_frames_asked_add_up_to_the_plan() {
        let plan = RecordingPlan::new(577, 200.0, options(30, 3));
        let mut turned = 0.0;
        let mut shown = 0;
        for frame in 0..plan.frames() {
            let ask = plan.ask(frame, turned);
            assert_eq!(ask.row, plan.rows_at(frame));
            assert_eq!(
                ask.timestamp_us, shown,
                "each frame starts where the last ended"
            );
            assert!(ask.duration_us > 0);
            assert_eq!(ask.dt, plan.frame_s());
            turned += ask.turn;
            shown += ask.duration_us;
        }
        assert!((turned - TAU).abs() < 1e-5, "one whole turn");
        assert_eq!(shown, plan.duration_us());
    }

    #[test]
    fn timestamps_duration_and_key_frames_follow_the_rate() {
        let plan = RecordingPlan::new(577, 200.0, options(30, 3));
        assert_eq!(plan.timestamp_us(1), 33_333);
        assert_eq!(plan.timestamp_us(30), 1_000_000);
        assert_eq!(plan.duration_us(), 4_000_000);
        let keys: Vec<usize> = (0..plan.frames())
            .filter(|&i| plan.is_keyframe(i))
            .collect();
        assert_eq!(keys, [0, 60]);
        assert_eq!(plan.file_name("turbinate"), "turbinate-720p30.webm");
        assert_eq!(plan.bitrate(), 3_317_760);
    }

    #[test]
    fn a_frame_is_asked_once_at_the_pace_of_the_encoder_or_the_clock_until_the_last() {
        let plan = RecordingPlan::new(
            3,
            200.0,
            RecordingOptions {
                size: VideoSize::P360,
                fps: 30,
                turntable_s: 0,
            },
        );
        let mut progress = Progress::default();
        let room = Pace::Encoder { queued: 0 };
        assert_eq!(
            progress.ask(
                &plan,
                Pace::Encoder {
                    queued: MAX_QUEUE + 1
                }
            ),
            None
        );
        let first = progress.ask(&plan, room).expect("room in the encoder");
        assert_eq!(first.timestamp_us, 0);
        assert_eq!(progress.ask(&plan, room), None, "asked once until drawn");
        progress.missed();
        assert!(
            progress.ask(&plan, room).is_some(),
            "asked again after a miss"
        );
        let mut last = false;
        for _ in 0..plan.frames() {
            last = progress.captured(&plan);
            if !last {
                let early = Pace::RealTime {
                    started: 0.0,
                    now: plan.timestamp_us(progress.frames_done()) as f64 / 1000.0 - 1.0,
                };
                assert_eq!(progress.ask(&plan, early), None, "not before its time");
                let due = Pace::RealTime {
                    started: 0.0,
                    now: plan.timestamp_us(progress.frames_done()) as f64 / 1000.0,
                };
                assert!(progress.ask(&plan, due).is_some());
            }
        }
        assert!(last && progress.flushing());
        assert_eq!(progress.frames_done(), plan.frames());
        assert_eq!(progress.ask(&plan, room), None, "every frame is in");
    }
}
