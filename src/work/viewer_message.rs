//! What the page and a viewer drawing in a worker send each other, in [`super::wire`]: the
//! page's [`ViewCommand`]s, and the viewer's [`ViewerNews`] (its renderer opened, each
//! frame's device and report, a shell refused, its pool of workers, a panic). What is not data
//! (a recording's `VideoFrame`, a fresh `OffscreenCanvas`) crosses beside the bytes,
//! transferred.

use super::viewer_command::ViewCommand;
use super::viewer_status::{Device, FrameReport};
use super::wire::{self, WireError};
use serde::{Deserialize, Serialize};

/// What a viewer drawing in a worker tells the page.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ViewerNews {
    /// Its renderer opened with this backend ("WebGPU" or "WebGL2"), or why none could be.
    Opened(Result<String, String>),
    /// A frame: the device's state and, when it was ready, the frame's report; and whether
    /// a recording's video frame was drawn (sent beside) or why not.
    Frame {
        device: Device,
        report: Option<Box<FrameReport>>,
        recorded: Option<Result<(), String>>,
    },
    /// The shell could not be built or grown: why, in words, and how many loads the viewer had
    /// taken then ([`FrameReport::loads`]): the page ignores the refusal of a shell it has
    /// already left. `None` for a command the worker could not read, said whatever was loaded.
    Refused { loads: Option<u32>, why: String },
    /// What its pool of workers says of itself.
    Pool(PoolNews),
    /// Its renderer failed: the viewer draws no more (why, in words).
    Failed(String),
    /// It panicked: the message to show.
    Crashed(String),
}

/// What the drawing worker's pool of workers says of itself: how many, where the shells grow in
/// words, workers replaced so far and what the page should say of it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PoolNews {
    pub count: u32,
    pub status: String,
    pub deaths: u32,
    pub words: Option<String>,
}

/// `command` as bytes.
pub fn encode_command(command: &ViewCommand) -> Vec<u8> {
    wire::write(command)
}

/// The command written by [`encode_command`], or why its bytes could not be read.
pub fn decode_command(bytes: &[u8]) -> Result<ViewCommand, WireError> {
    wire::read(bytes, "command")
}

/// `news` as bytes.
pub fn encode_news(news: &ViewerNews) -> Vec<u8> {
    wire::write(news)
}

/// The news written by [`encode_news`], or why its bytes could not be read.
pub fn decode_news(bytes: &[u8]) -> Result<ViewerNews, WireError> {
    wire::read(bytes, "news")
}
