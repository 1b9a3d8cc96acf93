//! What the page shows of a viewer, read once a frame: where the shell being grown stands (rows,
//! grown whole, settled, at rest, stopped, hashes, the counts its downloads are estimated from)
//! and the preview of a pattern being dragged. Plain data copied out of the viewer, so that the
//! page reads nothing else of it: a viewer drawing elsewhere than on the page's thread (a
//! worker) can send the same.

use super::file_writer::FileStage;
use super::planar_update::PlanarUpdate;
use crate::export::estimate::Counts;
use crate::view::preview::PreviewState;
use serde::{Deserialize, Serialize};

/// Where the shell being grown stands, once its worker has built it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ShellStatus {
    /// The session it grows in: each load starts another.
    pub session: u32,
    pub rows_done: usize,
    /// Rows from apex to opening.
    pub rows: usize,
    /// Growth has ended (grown whole, or stopped by a failure).
    pub done: bool,
    /// Every answer asked of its worker is in: paused, it stands still.
    pub settled: bool,
    /// The view rests on what has grown (or where the user left it).
    pub at_rest: bool,
    /// Why growth stopped early, in words.
    pub failure: Option<String>,
    pub pattern_hash: Option<u64>,
    /// The whole mesh's hash, once growth has ended.
    pub mesh_hash: Option<u64>,
    /// What its files' sizes are estimated from (vertices and triangles as they stand, edge
    /// included; the pattern's cells and rows; the drawing's pixels).
    pub counts: Counts,
}

impl ShellStatus {
    /// Grown whole with every answer in, and the view at rest on it: what the page calls
    /// `grown`.
    pub fn finished(&self) -> bool {
        self.done && self.settled && self.at_rest
    }
}

/// A viewer as the page sees it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ViewStatus {
    /// The shell being grown, once built (`None` before its worker has answered, or without a
    /// shell).
    pub shell: Option<ShellStatus>,
    /// The preview of a pattern slider being dragged, if one is shown.
    pub preview: Option<PreviewState>,
}

impl ViewStatus {
    /// The page's `data-preview` signal: "filling", "whole", "stopped", or "" for none.
    pub fn preview_signal(&self) -> &'static str {
        self.preview.map_or("", PreviewState::signal)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grown_only_when_done_settled_and_at_rest() {
        let whole = ShellStatus {
            done: true,
            settled: true,
            at_rest: true,
            ..ShellStatus::default()
        };
        assert!(whole.finished());
        for unfinished in [
            ShellStatus {
                done: false,
                ..whole.clone()
            },
            ShellStatus {
                settled: false,
                ..whole.clone()
            },
            ShellStatus {
                at_rest: false,
                ..whole.clone()
            },
        ] {
            assert!(!unfinished.finished(), "{unfinished:?}");
        }
    }

    #[test]
    fn the_preview_signal_names_its_state_or_nothing() {
        assert_eq!(ViewStatus::default().preview_signal(), "");
        let filling = ViewStatus {
            preview: Some(PreviewState::Filling),
            ..ViewStatus::default()
        };
        assert_eq!(filling.preview_signal(), "filling");
    }
}

/// What a frame of the viewer gives the page: where a file asked for stands, whether the shell
/// was drawn, the status, words to show, and what the planar view is to show.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FrameReport {
    /// How many shells the page had asked the viewer to load ([`ViewCommand::Load`]) when it
    /// made this frame. A viewer in a worker may send a frame before the page's last load
    /// reaches it: the page takes status and drawing only from a frame that counts every load
    /// it sent, or it would show the shell it left as the one it asked for.
    ///
    /// [`ViewCommand::Load`]: super::viewer_command::ViewCommand::Load
    pub loads: u32,
    /// Where the file asked for stands (`None`: none is asked for).
    pub file: Option<FileStage>,
    pub drawn: bool,
    pub status: ViewStatus,
    /// Words to show (why a preview stopped).
    pub notice: Option<String>,
    pub planar: Vec<PlanarUpdate>,
}

/// The state of a viewer's graphics device.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Device {
    /// Drawing.
    Ready,
    /// Lost (why, in words), and being opened again.
    Reopening(String),
    /// Lost (why, in words), and to be opened again on a fresh canvas, which the page makes in
    /// its canvas's place and gives the viewer.
    NeedsCanvas(String),
    /// Opened again just now, with this backend ("WebGPU" or "WebGL2").
    Reopened(String),
    /// Lost for good: no device could be opened again (why, in words).
    Gone(String),
}
