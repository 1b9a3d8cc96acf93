//! The parameters of an implicit shell (Galbraith, Prusinkiewicz & Wyvill, §2.1 and §3.1): a
//! generating surface of skeletal primitives, placed again and again along a helico-spiral
//! and blended into whorls, then polygonized at a chosen resolution.

use super::form::Handedness;
use serde::{Deserialize, Serialize};

/// A whorl built of generating surfaces on a helico-spiral.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImplicitSpec {
    pub spiral: HelixSpec,
    /// Whorls from the apex to the opening.
    pub whorls: u32,
    /// Degrees of rotation about the axis per whorl (348° in the Murex: three sections of 116°
    /// between varices).
    pub whorl_angle: f64,
    /// Sections per whorl (eq 10's Blobtrees, between varices).
    pub sections: u32,
    /// Generating surfaces placed per section (eq 9's b − a + 1).
    pub surfaces: u32,
    /// Which sections blend together.
    pub blending: Blending,
    /// The generating surface, in its own coordinates scaled by the size D(θ) of eq 3: u
    /// points towards the shell axis, v along it towards the apex, w along the growth.
    pub generator: GeneratorSpec,
    /// Voxels along the longest side of the grown shell when it is polygonized.
    pub resolution: u32,
}

/// The helico-spiral of eqs 1–3.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HelixSpec {
    /// β in degrees: the angle between the shell axis and the line through successive whorls.
    pub beta: f64,
    /// λ: the ratio of radii one turn (360°) apart.
    pub lambda: f64,
    /// R₀: the distance from the axis at θ = 0.
    pub r0: f64,
    pub handedness: Handedness,
}

/// How the generating surfaces of different sections combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Blending {
    /// All blend with all (the sum of their fields): touching whorls fuse (fig 5, left).
    All,
    /// Controlled blending (eq 10): a section blends only with its two neighbours along the
    /// spiral, and whorls meet as in a union (fig 5, right).
    Neighbours,
}

/// The primitives of the generating surface, each a row of numbers. Sizes are surface radii:
/// the radius a lone primitive's surface would have.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GeneratorSpec {
    /// (u, v, w, radius).
    pub points: Vec<[f64; 4]>,
    /// (u₀, v₀, w₀, u₁, v₁, w₁, radius₀, radius₁, bend, from whorl): a tapered segment, bent by
    /// `bend` degrees about w (positive turns from u towards v), present from the given whorl
    /// (counted from 0 at the apex; fractions allowed) to the opening.
    pub cones: Vec<[f64; 10]>,
    /// (u, v, w, major radius, radius): a ring in the generating surface's uv plane.
    pub tori: Vec<[f64; 5]>,
    /// n of eq 4 for blending the parts together: 1 sums their fields, larger values approach
    /// their union.
    pub exponent: f64,
    /// Controlled blending of the parts (eq 6): when not empty, only these pairs of parts blend
    /// and the others meet as in a union. Parts are numbered from 0: the points, then the
    /// cones, then the tori.
    pub pairs: Vec<[u32; 2]>,
}

impl Default for GeneratorSpec {
    /// No parts, blended by summing.
    fn default() -> Self {
        Self {
            points: Vec::new(),
            cones: Vec::new(),
            tori: Vec::new(),
            exponent: 1.0,
            pairs: Vec::new(),
        }
    }
}
