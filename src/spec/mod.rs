//! The whole shareable parameter set of a shell: one type, [`ShellSpec`], read from preset files
//! and links, validated before anything is built from it.

pub(crate) mod colour;
pub mod fields;
pub mod form;
pub mod handedness;
pub mod material;
pub mod pattern;
pub(crate) mod problem;
pub use problem::{Problem, Said};

use colour::Rgb;
use form::Form;
use material::MaterialSpec;
use pattern::PatternSpec;
use serde::{Deserialize, Serialize};

/// Everything needed to grow one shell, exactly.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShellSpec {
    /// The shape and the model that builds it.
    pub form: Form,
    /// The pigmentation model computed on the growing edge.
    #[serde(default)]
    pub pattern: PatternSpec,
    pub colours: Colours,
    /// How the surface meets the light.
    #[serde(default)]
    pub material: MaterialSpec,
    pub growth: GrowthSpec,
    /// Seed of every random choice (the pattern's fluctuations and starting cells).
    pub seed: u64,
}

impl ShellSpec {
    /// Whether `other` grows the very shell this one grows: the two differ at most in their
    /// material, which only the drawing reads. A change of material redraws the grown shell and
    /// grows nothing again.
    pub fn grows_like(&self, other: &ShellSpec) -> bool {
        let mut restyled = self.clone();
        restyled.material = other.material.clone();
        restyled == *other
    }
}

/// How the shell is painted.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Colours {
    /// The shell where there is no pigment.
    pub ground: Rgb,
    /// The pigment at full concentration.
    pub pigment: Rgb,
    /// The inside of the wall and the lip.
    pub interior: Rgb,
}

/// The growth clock: how long the shell grows, and how fast it is shown.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GrowthSpec {
    /// Length of the growth in pattern rows (time steps of the growing edge), apex to opening.
    pub rows: u32,
    /// Rows grown per animation frame.
    pub speed: f64,
}

impl GrowthSpec {
    /// The rows the shell grows in: [`GrowthSpec::rows`], but at least two, an apex and an
    /// opening, however few a spec asks for.
    pub fn rows_grown(&self) -> usize {
        self.rows.max(2) as usize
    }
}
