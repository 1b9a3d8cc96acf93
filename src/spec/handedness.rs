//! Which way a shell coils. Every form builds the dextral shell and shows a sinistral one
//! through the same mirror.

use glam::DVec3;
use serde::{Deserialize, Serialize};

/// Coiling direction, seen with the apex up and the aperture facing the viewer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Handedness {
    /// Right-handed: the aperture opens on the right.
    Dextral,
    /// Left-handed: the mirror image.
    Sinistral,
}

impl Handedness {
    /// A point or direction of shell space as this handedness shows it: the sinistral shell is
    /// the dextral one mirrored in the plane of the axis and x (y negated).
    pub fn mirror(self, p: DVec3) -> DVec3 {
        match self {
            Handedness::Dextral => p,
            Handedness::Sinistral => DVec3::new(p.x, -p.y, p.z),
        }
    }

    /// Whether the mirror turns the shell inside out, so triangles must be wound the other way.
    pub fn is_sinistral(self) -> bool {
        self == Handedness::Sinistral
    }
}
