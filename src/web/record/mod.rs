//! Recording a video of the growth, frame-exact: each video frame grows the shell to the row
//! the plan gives it (`view::recording`), draws it at the video's size and hands the canvas to
//! the encoder, however long that takes — "grow k rows, draw, capture", spread over as many
//! animation frames as the growth budget needs, so the tab stays responsive. WebCodecs'
//! `VideoEncoder` encodes (VP9, VP8 or AV1, the first the browser takes) and the core's WebM
//! muxer writes the file, which downloads only when whole. Where WebCodecs is missing,
//! `MediaRecorder` records the canvas in real time instead, and the page says so: its video
//! follows the clock, so a slow machine gives an uneven one. A cancelled or interrupted
//! recording drops everything it collected.

mod sink;

use sink::{Collected, Sink, codec_sink, stream_sink};

use super::clock::now;
use super::download;
use super::page::{element, element_as, set_text, signal};
use super::webcodecs::{self, VideoEncoder, VideoFrame, describe};
use crate::export::webm::VideoCodec;
use crate::view::recording::{
    FrameAsk, Pace, Progress, RecordingOptions, RecordingPlan, VideoSize,
};
use crate::work::recording::{self, Support};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen_futures::JsFuture;
use web_sys::{HtmlProgressElement, HtmlSelectElement};

/// What `MediaRecorder` may write, in order of preference.
const RECORDER_TYPES: [&str; 4] = [
    "video/webm;codecs=vp9",
    "video/webm;codecs=vp8",
    "video/webm",
    "video/mp4",
];

/// Asks the browser what it can record with: the first codec of [`VideoCodec::PREFERENCE`]
/// its `VideoEncoder` takes at the largest size and rate offered, else `MediaRecorder`.
pub async fn probe() -> Support {
    let has_encoder = webcodecs::has("VideoEncoder");
    if has_encoder {
        for codec in VideoCodec::PREFERENCE {
            let (width, height) = VideoSize::P1080.pixels();
            let config = webcodecs::object(&[
                ("codec", codec.codec_string().into()),
                ("width", width.into()),
                ("height", height.into()),
                ("bitrate", 10_000_000.into()),
                ("framerate", 60.into()),
            ]);
            let answer = JsFuture::from(VideoEncoder::is_config_supported(&config)).await;
            let supported = answer
                .ok()
                .and_then(|a| js_sys::Reflect::get(&a, &"supported".into()).ok())
                .is_some_and(|s| s.is_truthy());
            if supported {
                // The media stack is asked no more than it must be (see `Support`).
                return Support::answered(Some(Some(codec)), None);
            }
        }
    }
    let recorder = webcodecs::has("MediaRecorder")
        .then(|| {
            RECORDER_TYPES
                .iter()
                .find(|t| web_sys::MediaRecorder::is_type_supported(t))
        })
        .flatten();
    Support::answered(has_encoder.then_some(None), recorder.copied())
}

/// The options chosen on the page.
pub fn options() -> RecordingOptions {
    let choice = |id: &str| {
        element_as::<HtmlSelectElement>(id)
            .map(|s| s.value())
            .unwrap_or_default()
    };
    RecordingOptions::from_choices(
        &choice("record-size"),
        &choice("record-fps"),
        &choice("record-turntable"),
    )
}

/// How a step of the recording went.
pub enum Step {
    Working,
    /// Every frame is in: [`Recording::save`] makes the file.
    Done,
    Failed(String),
}

/// A recording under way.
pub struct Recording {
    plan: RecordingPlan,
    preset: &'static str,
    sink: Sink,
    collected: Rc<RefCell<Collected>>,
    /// Where it stands: the frames asked and captured (the core paces them).
    progress: Progress,
    /// When it started, for `MediaRecorder`'s real-time pace.
    started: f64,
}

impl Recording {
    /// Starts recording the shell the viewer has just started growing, with what `support`
    /// offers, as `plan` says.
    pub fn start(
        plan: RecordingPlan,
        preset: &'static str,
        support: &Support,
    ) -> Result<Self, String> {
        let collected = Rc::new(RefCell::new(Collected::default()));
        let sink = match support {
            Support::WebCodecs(codec) => codec_sink(&plan, *codec, &collected)?,
            Support::MediaRecorder(mime) => stream_sink(&plan, mime, &collected)?,
            other => return Err(other.note()),
        };
        Ok(Self {
            plan,
            preset,
            sink,
            collected,
            progress: Progress::default(),
            started: now(),
        })
    }

    /// The plan being recorded.
    pub fn plan(&self) -> &RecordingPlan {
        &self.plan
    }

    /// Frames captured so far.
    pub fn frames_done(&self) -> usize {
        self.progress.frames_done()
    }

    /// Where the recording stands, once a frame: failed, working, or every frame encoded.
    pub fn step(&self) -> Step {
        if let Some(e) = self.collected.borrow_mut().error.take() {
            return Step::Failed(e);
        }
        if self.progress.flushing() && self.collected.borrow().finished {
            Step::Done
        } else {
            Step::Working
        }
    }

    /// The next video frame to ask of the viewer, when it is time to, as the core's
    /// [`Progress`] paces it: by the encoder's queue, or `MediaRecorder`'s real time.
    pub fn ask(&mut self) -> Option<FrameAsk> {
        let pace = match &self.sink {
            Sink::Codec { encoder, .. } => Pace::Encoder {
                queued: encoder.encode_queue_size(),
            },
            Sink::Stream { .. } => Pace::RealTime {
                started: self.started,
                now: now(),
            },
        };
        self.progress.ask(&self.plan, pace)
    }

    /// Takes the frame asked for, as the viewer drew it (or why it could not), and hands it to
    /// the encoder.
    pub fn took(&mut self, frame: Result<VideoFrame, String>) -> Result<(), String> {
        let captured = frame.and_then(|frame| {
            let captured = self.capture(&frame);
            frame.close();
            captured
        });
        if let Err(e) = captured {
            self.progress.missed();
            return Err(e);
        }
        if self.progress.captured(&self.plan) {
            self.end();
        }
        Ok(())
    }

    /// Hands the next frame, just drawn, to the encoder (or draws it on the canvas
    /// `MediaRecorder` records).
    fn capture(&self, frame: &VideoFrame) -> Result<(), String> {
        match &self.sink {
            Sink::Codec { encoder, .. } => {
                let options = webcodecs::object(&[(
                    "keyFrame",
                    self.plan.is_keyframe(self.progress.frames_done()).into(),
                )]);
                encoder
                    .encode(frame, &options)
                    .map_err(|e| format!("the frame could not be encoded ({})", describe(&e)))
            }
            Sink::Stream { canvas, track, .. } => {
                canvas
                    .draw_frame(frame, 0.0, 0.0)
                    .map_err(|e| format!("the frame could not be drawn ({})", describe(&e)))?;
                track.request_frame();
                Ok(())
            }
        }
    }

    /// Every frame is captured: lets the encoder finish.
    fn end(&mut self) {
        match &self.sink {
            Sink::Codec { encoder, .. } => {
                let flushed = JsFuture::from(encoder.flush());
                let collected = Rc::clone(&self.collected);
                wasm_bindgen_futures::spawn_local(async move {
                    let result = flushed.await;
                    let mut c = collected.borrow_mut();
                    match result {
                        Ok(_) => c.finished = true,
                        Err(e) => {
                            c.error.get_or_insert(format!(
                                "the video encoder could not finish ({})",
                                describe(&e)
                            ));
                        }
                    }
                });
            }
            Sink::Stream { recorder, .. } => {
                // Stopping hands over the last piece, then says it stopped.
                let _ = recorder.stop();
            }
        }
    }

    /// Stops the encoder and lets go of the canvas, keeping nothing.
    fn close(&self) {
        match &self.sink {
            Sink::Codec { encoder, .. } => {
                // Closing an encoder that failed or closed already changes nothing.
                let _ = encoder.close();
            }
            Sink::Stream {
                recorder, track, ..
            } => {
                recorder.set_ondataavailable(None);
                recorder.set_onstop(None);
                if recorder.state() != web_sys::RecordingState::Inactive {
                    let _ = recorder.stop();
                }
                track.stop();
            }
        }
        let mut c = self.collected.borrow_mut();
        c.muxer = None;
        c.pieces.clear();
    }

    /// Drops the recording: nothing collected is kept, no file is made.
    pub fn cancel(self) {
        self.close();
    }

    /// Makes the file of a finished recording and offers it; returns its name.
    pub fn save(self) -> Result<String, String> {
        let made = match &self.sink {
            Sink::Codec { .. } => {
                let muxer = self.collected.borrow_mut().muxer.take();
                let muxer = muxer.ok_or("the recording has no frames")?;
                if muxer.frames() != self.plan.frames() {
                    Err(format!(
                        "the encoder returned {} frames of {}",
                        muxer.frames(),
                        self.plan.frames()
                    ))
                } else {
                    let name = self.plan.file_name(self.preset);
                    download::offer(&name, "video/webm", &muxer.finish()).map(|()| name)
                }
            }
            Sink::Stream { mime, .. } => self.save_pieces(mime),
        };
        self.close();
        made
    }

    /// `MediaRecorder`'s pieces as one file.
    fn save_pieces(&self, mime: &str) -> Result<String, String> {
        let pieces: js_sys::Array = self.collected.borrow().pieces.iter().collect();
        let options = web_sys::BlobPropertyBag::new();
        let kind = mime.split(';').next().unwrap_or(mime);
        options.set_type(kind);
        let blob = web_sys::Blob::new_with_blob_sequence_and_options(&pieces, &options)
            .map_err(|_| "the browser refused to make the file".to_string())?;
        let extension = if kind == "video/mp4" { "mp4" } else { "webm" };
        let name = self
            .plan
            .file_name(self.preset)
            .replace(".webm", &format!(".{extension}"));
        download::offer_blob(&name, &blob).map(|()| name)
    }
}

/// The share panel's recording controls: while recording, the progress bar and Cancel; else
/// the options and Record.
pub fn show_recording(recording: Option<&Recording>) {
    let active = recording.is_some();
    for (id, hidden) in [
        ("record", active),
        ("record-cancel", !active),
        ("record-progress", !active),
    ] {
        if let Some(e) = element(id) {
            e.set_hidden(hidden);
        }
    }
    for id in ["record-size", "record-fps", "record-turntable"] {
        if let Some(select) = element_as::<HtmlSelectElement>(id) {
            select.set_disabled(active);
        }
    }
    let Some(r) = recording else { return };
    let frames = r.plan.frames();
    if let Some(bar) = element_as::<HtmlProgressElement>("record-progress") {
        bar.set_max(frames as f64);
        bar.set_value(r.progress.frames_done() as f64);
    }
    signal("recordFrames", &r.progress.frames_done().to_string());
    set_text(
        "record-status",
        &recording::under_way(&r.plan, &r.progress, matches!(r.sink, Sink::Stream { .. })),
    );
}
