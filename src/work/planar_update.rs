//! What the planar view beside the shell (the left halves of Fowler et al.'s figures 11–14) is
//! told to show, as plain data: the viewer that grows the shell says which pattern is shown and
//! which of its rows are new, and the page draws them. The page's thread draws the planar view
//! wherever the viewer runs.

use serde::{Deserialize, Serialize};

/// One change to the planar view.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum PlanarUpdate {
    /// From now on, a blank pattern of `cells × rows` (`None`: no pattern, the view hidden).
    Open(Option<(u32, u32)>),
    /// Rows `first..` of the pattern, RGBA, `cells × 4` bytes a row.
    Rows {
        first: u32,
        #[serde(with = "crate::pod_bytes")]
        rgba: Vec<u8>,
    },
    /// Keep row `row` in sight (the newest grown).
    Follow(u32),
}
