//! Where a recording's frames go: WebCodecs' `VideoEncoder`, its chunks muxed into WebM by the
//! core's writer, or `MediaRecorder` recording a canvas of the page's own in real time; and
//! what the browser's callbacks hand back meanwhile.

use crate::export::webm::{VideoCodec, WebmWriter};
use crate::view::recording::RecordingPlan;
use crate::web::page;
use crate::web::webcodecs::{
    self, CanvasCaptureTrack, Context2d, EncodedVideoChunk, VideoEncoder, describe,
};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

/// Milliseconds of video in each piece `MediaRecorder` hands over.
const RECORDER_SLICE_MS: i32 = 1000;
/// What the browser's callbacks hand back while the recording runs.
#[derive(Default)]
pub(super) struct Collected {
    pub(super) muxer: Option<WebmWriter>,
    pub(super) pieces: Vec<web_sys::Blob>,
    pub(super) error: Option<String>,
    /// The encoder has flushed, or the recorder stopped: the file can be made.
    pub(super) finished: bool,
}

/// Where the frames go.
pub(super) enum Sink {
    Codec {
        encoder: VideoEncoder,
        _output: Closure<dyn FnMut(EncodedVideoChunk, JsValue)>,
        _error: Closure<dyn FnMut(JsValue)>,
    },
    /// `MediaRecorder` records a canvas of the page's own, on which each frame is drawn.
    Stream {
        recorder: web_sys::MediaRecorder,
        canvas: Context2d,
        track: CanvasCaptureTrack,
        mime: String,
        _data: Closure<dyn FnMut(web_sys::BlobEvent)>,
        _stop: Closure<dyn FnMut()>,
    },
}

pub(super) fn codec_sink(
    plan: &RecordingPlan,
    codec: VideoCodec,
    collected: &Rc<RefCell<Collected>>,
) -> Result<Sink, String> {
    collected.borrow_mut().muxer = Some(WebmWriter::new(codec, plan.width, plan.height, plan.fps));
    let into = Rc::clone(collected);
    let output = Closure::new(move |chunk: EncodedVideoChunk, metadata: JsValue| {
        let bytes = js_sys::Uint8Array::new_with_length(chunk.byte_length());
        chunk.copy_to(&bytes);
        let mut collected = into.borrow_mut();
        let collected = &mut *collected;
        let Some(muxer) = &mut collected.muxer else {
            return;
        };
        let description = js_sys::Reflect::get(&metadata, &"decoderConfig".into())
            .and_then(|c| js_sys::Reflect::get(&c, &"description".into()));
        if let Some(d) = description.ok().filter(|d| !d.is_undefined()) {
            muxer.set_codec_private(&js_sys::Uint8Array::new(&d).to_vec());
        }
        let pushed = muxer.push(
            &bytes.to_vec(),
            chunk.timestamp().max(0.0) as u64,
            chunk.kind() == "key",
        );
        if let Err(e) = pushed {
            collected
                .error
                .get_or_insert(format!("the muxer refused a frame ({e})"));
        }
    });
    let errors = Rc::clone(collected);
    let error = Closure::new(move |e: JsValue| {
        errors
            .borrow_mut()
            .error
            .get_or_insert(format!("the video encoder failed ({})", describe(&e)));
    });
    let init = webcodecs::object(&[
        ("output", output.as_ref().clone()),
        ("error", error.as_ref().clone()),
    ]);
    let encoder = VideoEncoder::new(&init)
        .map_err(|e| format!("the video encoder could not be made ({})", describe(&e)))?;
    let config = webcodecs::object(&[
        ("codec", codec.codec_string().into()),
        ("width", plan.width.into()),
        ("height", plan.height.into()),
        ("bitrate", plan.bitrate().into()),
        ("framerate", plan.fps.into()),
    ]);
    encoder
        .configure(&config)
        .map_err(|e| format!("the video encoder refused its settings ({})", describe(&e)))?;
    Ok(Sink::Codec {
        encoder,
        _output: output,
        _error: error,
    })
}

pub(super) fn stream_sink(
    plan: &RecordingPlan,
    mime: &str,
    collected: &Rc<RefCell<Collected>>,
) -> Result<Sink, String> {
    let canvas: HtmlCanvasElement = page::document()
        .create_element("canvas")
        .ok()
        .and_then(|e| e.dyn_into().ok())
        .ok_or("the page could not make a canvas to record")?;
    canvas.set_width(plan.width);
    canvas.set_height(plan.height);
    let context: Context2d = canvas
        .get_context("2d")
        .ok()
        .flatten()
        .ok_or("the canvas to record has no 2D drawing")?
        .unchecked_into();
    let stream = canvas
        .capture_stream_with_frame_request_rate(0.0)
        .map_err(|e| format!("the canvas cannot be captured ({})", describe(&e)))?;
    let track: CanvasCaptureTrack = stream
        .get_video_tracks()
        .get(0)
        .dyn_into::<web_sys::MediaStreamTrack>()
        .map_err(|_| "the canvas's stream has no video".to_string())?
        .unchecked_into();
    let options = web_sys::MediaRecorderOptions::new();
    options.set_mime_type(mime);
    options.set_video_bits_per_second(plan.bitrate());
    let recorder =
        web_sys::MediaRecorder::new_with_media_stream_and_media_recorder_options(&stream, &options)
            .map_err(|e| format!("MediaRecorder could not start ({})", describe(&e)))?;
    let into = Rc::clone(collected);
    let data = Closure::new(move |e: web_sys::BlobEvent| {
        if let Some(blob) = e.data().filter(|b| b.size() > 0.0) {
            into.borrow_mut().pieces.push(blob);
        }
    });
    let done = Rc::clone(collected);
    let stop = Closure::new(move || done.borrow_mut().finished = true);
    recorder.set_ondataavailable(Some(data.as_ref().unchecked_ref()));
    recorder.set_onstop(Some(stop.as_ref().unchecked_ref()));
    recorder
        .start_with_time_slice(RECORDER_SLICE_MS)
        .map_err(|e| format!("MediaRecorder could not start ({})", describe(&e)))?;
    Ok(Sink::Stream {
        recorder,
        canvas: context,
        track,
        mime: mime.to_string(),
        _data: data,
        _stop: stop,
    })
}
