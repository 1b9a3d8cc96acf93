//! The parameters of the swept shell of Fowler, Meinhardt & Prusinkiewicz 1992, §2: the
//! helico-spiral, the generating curve and its frame, sculpture, and the wall and lip.

use crate::spec::handedness::Handedness;
use serde::{Deserialize, Serialize};

/// Parameters of the swept surface.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSpec {
    pub spiral: SpiralSpec,
    pub curve: CurveSpec,
    #[serde(default)]
    pub orientation: OrientationSpec,
    #[serde(default)]
    pub sculpture: SculptureSpec,
    #[serde(default)]
    pub wall: WallSpec,
}

/// The helico-spiral 𝓗 (eqs 1–2).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpiralSpec {
    /// Δθ in degrees: the angular step for which λᵣ, λ_z and λ_c are given.
    pub delta_theta: f64,
    /// λᵣ = ξᵣ^Δθ: growth of the distance from the axis per step.
    pub lambda_r: f64,
    /// λ_z = ξ_z^Δθ: growth of the height along the axis per step.
    pub lambda_z: f64,
    /// r₀: distance from the axis at the apex.
    pub r0: f64,
    /// z₀: height along the axis at the apex.
    pub z0: f64,
    /// Number of whorls, t_max / 2π.
    pub whorls: f64,
    /// Rims per step Δθ: the mesh's resolution along the spiral.
    pub subdivisions: u32,
    pub handedness: Handedness,
}

/// The generating curve 𝓒 (§2.2) and how it is sampled (§2.4).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveSpec {
    /// Cubic Bézier control points (u, v, w): 3k + 1 for k open segments, 3k for a closed curve.
    /// u points towards the shell axis, v along it, w along the direction of growth.
    pub points: Vec<[f64; 3]>,
    /// Whether the last segment returns to the first point.
    pub closed: bool,
    /// λ_c = ξ_c^Δθ: growth of the curve's size per step.
    pub lambda_c: f64,
    /// n: the curve is sampled at n + 1 points (one rim of the mesh).
    pub segments: u32,
    /// Space the n + 1 points equally by arc length (eqs 4–7) rather than by parameter.
    pub reparametrize: bool,
}

/// Which reference frame the generating curve is laid on (§2.3): the axis-aligned frame, or
/// the Frenet frame of the helico-spiral.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FrameMode {
    AxisAligned,
    Frenet,
}

/// Orientation of the curve's uvw axes (§2.3).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OrientationSpec {
    pub frame: FrameMode,
    /// Rotation of uvw about e₁ (the direction of growth), degrees.
    pub rotate_e1: f64,
    /// Rotation of uvw about e₂, degrees.
    pub rotate_e2: f64,
    /// Rotation of uvw about e₃, degrees.
    pub rotate_e3: f64,
}

/// Sculpture by displacement along the surface normal (§2.5).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SculptureSpec {
    /// Ribs parallel to the direction of growth: periodic along the generating curve.
    pub growth_ribs: RibSpec,
    /// Ribs parallel to the generating curve: periodic along the helico-spiral.
    pub curve_ribs: RibSpec,
}

/// One family of ribs. The displacement is amplitude × size of the curve × a periodic profile
/// ((1 + cos 2πx) / 2)^sharpness.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RibSpec {
    /// Height of a rib relative to the current size of the curve; 0 turns the family off.
    pub amplitude: f64,
    /// Ribs along the whole curve (growth ribs) or per whorl (curve ribs).
    pub count: f64,
    /// Exponent of the profile: 1 is a sine, larger values give narrow crests.
    pub sharpness: f64,
    /// Phase drift in rib periods per whorl: oblique ribs (growth ribs only).
    pub drift: f64,
    /// Factor by which the frequency changes per whorl (1: constant).
    pub frequency_change: f64,
}

/// The wall's thickness and the lip at the opening (the paper's open problems, §4).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WallSpec {
    /// Thickness relative to the current size of the curve; 0 gives a single surface.
    pub thickness: f64,
    /// Angle, in degrees, over which the lip departs from self-similarity before the opening.
    pub lip_length: f64,
    /// Extra relative size of the curve at the opening (0: none).
    pub lip_flare: f64,
    /// Factor by which the wall thickens towards the opening (1: none).
    pub lip_thickening: f64,
}

impl RibSpec {
    /// No ribs.
    pub const NONE: RibSpec = RibSpec {
        amplitude: 0.0,
        count: 0.0,
        sharpness: 1.0,
        drift: 0.0,
        frequency_change: 1.0,
    };
}

impl Default for RibSpec {
    fn default() -> Self {
        Self::NONE
    }
}

impl Default for SculptureSpec {
    fn default() -> Self {
        Self {
            growth_ribs: RibSpec::NONE,
            curve_ribs: RibSpec::NONE,
        }
    }
}

impl Default for OrientationSpec {
    /// Axis-aligned, unrotated.
    fn default() -> Self {
        Self {
            frame: FrameMode::AxisAligned,
            rotate_e1: 0.0,
            rotate_e2: 0.0,
            rotate_e3: 0.0,
        }
    }
}

impl Default for WallSpec {
    /// A single surface, self-similar to the end.
    fn default() -> Self {
        Self {
            thickness: 0.0,
            lip_length: 0.0,
            lip_flare: 0.0,
            lip_thickening: 1.0,
        }
    }
}
