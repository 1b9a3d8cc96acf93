//! What the page asks of its viewer: every change the page makes to what is grown and how it
//! is shown, as plain data. The page sends these and reads back a [`ViewStatus`]
//! (`viewer_status.rs`), so that the viewer can run where the page's thread is not (a worker
//! holding the canvas) and be driven exactly as it is on the page's own thread.
//!
//! [`ViewStatus`]: super::viewer_status::ViewStatus

use crate::export::Download;
use crate::export::print_size::PrintSize;
use crate::presets::{Preset, View};
use crate::share::link;
use crate::share::presentation::Layout;
use crate::spec::ShellSpec;
use crate::spec::problem::Said;
use crate::view::recording::FrameAsk;
use serde::{Deserialize, Serialize};

/// One thing the page asks of its viewer.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub enum ViewCommand {
    /// Grow the shell from its apex, dropping the shell grown before; with `finish`,
    /// to its end at once (an implicit shell remeshed whole, an embed for a reader who asked
    /// for less motion).
    Load { shell: PresetSpec, finish: bool },
    /// Draw the shell grown so far in the material of this one, which grows as the loaded one
    /// does ([`ShellSpec::grows_like`]): nothing grows again.
    Restyle(PresetSpec),
    /// Show the whole pattern of the shell of this link in the planar view while growth waits
    /// (a slider of the pattern being dragged). The viewer only hands the link to a worker, so
    /// it crosses as the text, not as a spec read and written again on every move.
    Preview(String),
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
    /// The shell's first view is this one, relative to its opening (a story's step turns
    /// the camera): the view goes there, now or once the shell is built.
    Turn(View),
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

/// A spec and the preset it was made from: a shell as the page names it. It crosses between
/// threads as its link, the one text every thread reads the same spec from, bit for bit (the
/// workers are sent the same). One that would not read back as it was written (a value of it
/// not used as given) is refused; one shown as asked but not to be written to a file (whorls
/// that overlap) is read.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(into = "String", try_from = "String")]
pub struct PresetSpec {
    pub preset: &'static Preset,
    pub spec: Box<ShellSpec>,
}

impl PresetSpec {
    pub fn new(preset: &'static Preset, spec: ShellSpec) -> Self {
        Self {
            preset,
            spec: Box::new(spec),
        }
    }
}

impl From<PresetSpec> for String {
    fn from(shell: PresetSpec) -> Self {
        link::encode(shell.preset, &shell.spec)
    }
}

impl TryFrom<String> for PresetSpec {
    type Error = String;

    fn try_from(text: String) -> Result<Self, String> {
        let decoded = link::decode(&text);
        match decoded.problems.iter().find(|p| p.said == Said::Changed) {
            Some(problem) => Err(format!("{text}: {problem}")),
            None => Ok(Self::new(decoded.preset, decoded.spec)),
        }
    }
}
