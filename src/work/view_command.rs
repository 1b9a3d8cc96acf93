//! What the page asks of its viewer: every change the page makes to what is grown and how it
//! is shown, as plain data. The page sends these and reads back a [`ViewStatus`]
//! (`view_status.rs`), so that the viewer can run where the page's thread is not (a worker
//! holding the canvas) and be driven exactly as it is on the page's own thread.
//!
//! [`ViewStatus`]: super::view_status::ViewStatus

use crate::export::Download;
use crate::export::print_size::PrintSize;
use crate::presets::Preset;
use crate::share::presentation::Layout;
use crate::spec::ShellSpec;
use crate::view::recording::FrameAsk;
use serde::{Deserialize, Serialize};

/// One thing the page asks of its viewer.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub enum ViewCommand {
    /// Grow `spec` of `preset` from its apex, dropping the shell grown before; with `finish`,
    /// to its end at once (an implicit shell remeshed whole, an embed for a reader who asked
    /// for less motion).
    Load {
        #[serde(with = "preset_by_id")]
        preset: &'static Preset,
        #[serde(with = "spec_as_json")]
        spec: Box<ShellSpec>,
        finish: bool,
    },
    /// Draw the shell grown so far in the material of `spec`, which grows it as the loaded spec
    /// does ([`ShellSpec::grows_like`]): nothing grows again.
    Restyle(#[serde(with = "spec_as_json")] Box<ShellSpec>),
    /// Show the whole pattern of `spec` in the planar view while growth waits (a slider of
    /// the pattern being dragged).
    Preview(#[serde(with = "spec_as_json")] Box<ShellSpec>),
    /// Back from a preview to the growing shell's own pattern.
    EndPreview,
    /// Grow this many rows (a step, paused).
    Grow(usize),
    /// Grow the rest of the shell at once.
    Finish,
    /// Whether growth advances each frame.
    Play(bool),
    /// Whether the page shows something else over the shell (the gallery, the map): growth
    /// waits.
    Hold(bool),
    /// Rows grown per frame while playing.
    Speed(f64),
    /// One view, or Kawaguchi's four.
    Layout(Layout),
    /// Back to the first view (following the growth again on the main view).
    ResetCamera,
    /// A pointer pressed, moved, or let go over the canvas.
    Pointer(PointerChange),
    /// A wheel turned by this many pixels.
    Wheel(f64),
    /// The size the canvas is shown at on the page, in CSS pixels, and the device pixels in
    /// each: the drawing is kept at that size in device pixels, and a drag turns the camera by
    /// its share of the height.
    Shown {
        width: u32,
        height: u32,
        pixel_ratio: f64,
    },
    /// The clear colour, as sRGB bytes (the page's theme changed).
    Background([u8; 3]),
    /// Record at this size (`None`: back to the canvas's own size and the playback).
    RecordAt(Option<(u32, u32)>),
    /// A recording's next video frame.
    AskFrame(FrameAsk),
    /// Write this file of the shell shown (GLB and 3MF at `size`).
    WriteFile { what: Download, size: PrintSize },
}

/// A pointer over the canvas, at CSS pixels from the page's top left.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum PointerChange {
    Down { id: i32, x: f32, y: f32 },
    Move { id: i32, x: f32, y: f32 },
    Up { id: i32 },
}

/// A preset crosses as its id, and is read back only when it names one of [`presets::presets`].
mod preset_by_id {
    use crate::presets::{self, Preset};
    use serde::de::Error;
    use serde::{Deserialize, Deserializer, Serializer};

    pub(super) fn serialize<S: Serializer>(
        preset: &&'static Preset,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        s.serialize_str(preset.id)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<&'static Preset, D::Error> {
        let id = String::deserialize(d)?;
        presets::preset(&id).ok_or_else(|| D::Error::custom(format!("there is no preset '{id}'")))
    }
}

/// A spec crosses as the JSON of its species files: its forms and patterns are told apart by a
/// `kind` field inside them, which only a self-describing format can read back.
mod spec_as_json {
    use crate::spec::ShellSpec;
    use serde::de::Error;
    use serde::{Deserialize, Deserializer, Serializer};

    pub(super) fn serialize<S: Serializer>(spec: &ShellSpec, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&serde_json::to_string(spec).expect("a spec is always written as JSON"))
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Box<ShellSpec>, D::Error> {
        serde_json::from_str(&String::deserialize(d)?).map_err(D::Error::custom)
    }
}
