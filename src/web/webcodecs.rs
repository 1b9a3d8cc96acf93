//! The few parts of WebCodecs the recording uses (web-sys has them only behind an unstable
//! flag): a `VideoEncoder`, a `VideoFrame` taken from the viewer's canvas, the
//! `EncodedVideoChunk`s that come out; and, for `MediaRecorder` where WebCodecs is missing, a
//! 2D canvas that draws those frames and its stream's `requestFrame`.

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// WebCodecs' video encoder.
    pub type VideoEncoder;

    #[wasm_bindgen(constructor, catch)]
    pub fn new(init: &js_sys::Object) -> Result<VideoEncoder, JsValue>;

    #[wasm_bindgen(method, catch)]
    pub fn configure(this: &VideoEncoder, config: &js_sys::Object) -> Result<(), JsValue>;

    #[wasm_bindgen(method, catch)]
    pub fn encode(
        this: &VideoEncoder,
        frame: &VideoFrame,
        options: &js_sys::Object,
    ) -> Result<(), JsValue>;

    #[wasm_bindgen(method)]
    pub fn flush(this: &VideoEncoder) -> js_sys::Promise;

    #[wasm_bindgen(method, catch)]
    pub fn close(this: &VideoEncoder) -> Result<(), JsValue>;

    #[wasm_bindgen(method, getter, js_name = encodeQueueSize)]
    pub fn encode_queue_size(this: &VideoEncoder) -> u32;

    #[wasm_bindgen(static_method_of = VideoEncoder, js_name = isConfigSupported)]
    pub fn is_config_supported(config: &js_sys::Object) -> js_sys::Promise;

    /// A frame of video: here, the canvas as just drawn.
    pub type VideoFrame;

    /// A frame of `canvas` (an element or an offscreen canvas).
    #[wasm_bindgen(constructor, catch)]
    pub fn new(canvas: &JsValue, init: &js_sys::Object) -> Result<VideoFrame, JsValue>;

    #[wasm_bindgen(method)]
    pub fn close(this: &VideoFrame);

    /// One encoded frame.
    pub type EncodedVideoChunk;

    #[wasm_bindgen(method, getter, js_name = type)]
    pub fn kind(this: &EncodedVideoChunk) -> String;

    #[wasm_bindgen(method, getter)]
    pub fn timestamp(this: &EncodedVideoChunk) -> f64;

    #[wasm_bindgen(method, getter, js_name = byteLength)]
    pub fn byte_length(this: &EncodedVideoChunk) -> u32;

    #[wasm_bindgen(method, js_name = copyTo)]
    pub fn copy_to(this: &EncodedVideoChunk, destination: &js_sys::Uint8Array);

    /// A canvas's 2D drawing, which draws a video frame (web-sys's `drawImage` takes none).
    pub type Context2d;

    #[wasm_bindgen(method, catch, js_name = drawImage)]
    pub fn draw_frame(this: &Context2d, frame: &VideoFrame, x: f64, y: f64) -> Result<(), JsValue>;

    /// The track of a canvas's capture stream, which sends a frame when asked.
    pub type CanvasCaptureTrack;

    #[wasm_bindgen(method, js_name = requestFrame)]
    pub fn request_frame(this: &CanvasCaptureTrack);

    #[wasm_bindgen(method)]
    pub fn stop(this: &CanvasCaptureTrack);
}

/// Whether the window has a global named `name` (`VideoEncoder`, `MediaRecorder`).
pub fn has(name: &str) -> bool {
    web_sys::window().is_some_and(|w| {
        js_sys::Reflect::get(&w, &JsValue::from_str(name)).is_ok_and(|v| v.is_function())
    })
}

/// A plain object with these properties.
pub fn object(properties: &[(&str, JsValue)]) -> js_sys::Object {
    let o = js_sys::Object::new();
    for (key, value) in properties {
        // Setting a property on a fresh plain object cannot fail.
        let _ = js_sys::Reflect::set(&o, &JsValue::from_str(key), value);
    }
    o
}

/// A JavaScript error (or whatever was thrown) in words.
pub fn describe(e: &JsValue) -> String {
    e.as_string()
        .or_else(|| {
            e.dyn_ref::<js_sys::Error>()
                .map(|e| String::from(e.message()))
        })
        .unwrap_or_else(|| format!("{e:?}"))
}
