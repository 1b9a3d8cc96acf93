//! The presets: one JSON file per shell in species/, compiled in by build.rs, each naming the
//! figure and paper it reproduces.

use crate::spec::ShellSpec;
use serde::{Deserialize, Serialize};
use std::sync::OnceLock;

include!(concat!(env!("OUT_DIR"), "/species.rs"));

/// The preset shown when a link names none.
pub const DEFAULT_PRESET: &str = "turbinate";

/// Where a preset comes from, which groups the gallery.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Group {
    /// Shell shapes of Fowler, Meinhardt & Prusinkiewicz 1992, §2.
    Shapes,
    /// Reaction-diffusion pigmentation of the same paper, §3.
    Pigmentation,
    /// Pigmentation by the vector cellular automaton.
    Automaton,
    /// Kawaguchi's GROWTH (1982): accumulated chambers, later branching.
    Kawaguchi,
    /// Implicit surfaces of Galbraith, Prusinkiewicz & Wyvill: BlobTree whorls.
    Implicit,
}

impl Group {
    /// Heading of the group in the gallery.
    pub fn title(self) -> &'static str {
        match self {
            Group::Shapes => "Shell shapes",
            Group::Pigmentation => "Pigmentation patterns",
            Group::Automaton => "Cellular automaton",
            Group::Kawaguchi => "Kawaguchi's GROWTH",
            Group::Implicit => "Implicit surfaces",
        }
    }
}

/// One preset file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    /// The file name without extension: the preset's id in links and on the command line.
    #[serde(skip)]
    pub id: &'static str,
    /// Common or scientific name, as shown in the gallery.
    pub name: String,
    /// The paper and figure reproduced.
    pub source: String,
    pub group: Group,
    /// One line about what it shows.
    pub description: String,
    /// Where the camera starts, when the view from the opening is not the telling one.
    #[serde(default)]
    pub view: View,
    pub spec: ShellSpec,
}

/// The first view of a preset, relative to looking into its opening.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct View {
    /// Turn about the vertical, degrees.
    pub yaw: f32,
    /// Extra height above the horizon, degrees.
    pub pitch: f32,
}

/// The figure a source names ("…, fig. 12" gives 12), for ordering; none sorts last.
fn figure(source: &str) -> u32 {
    source
        .rsplit_once("fig. ")
        .and_then(|(_, rest)| rest.split(|c: char| !c.is_ascii_digit()).next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(u32::MAX)
}

/// Every preset, in gallery order (by group, then the figure it reproduces, then file name). A preset file that does not
/// parse is a build defect, caught by the native tests; here it panics with the file's name.
pub fn presets() -> &'static [Preset] {
    static PRESETS: OnceLock<Vec<Preset>> = OnceLock::new();
    PRESETS.get_or_init(|| {
        let mut all: Vec<Preset> = PRESET_FILES
            .iter()
            .map(|&(id, json)| {
                let mut preset: Preset = serde_json::from_str(json)
                    .unwrap_or_else(|e| panic!("species/{id}.json does not parse: {e}"));
                preset.id = id;
                preset
            })
            .collect();
        all.sort_by_key(|p| (p.group, figure(&p.source), p.id));
        all
    })
}

/// The preset with this id.
pub fn preset(id: &str) -> Option<&'static Preset> {
    presets().iter().find(|p| p.id == id)
}
