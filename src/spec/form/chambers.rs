//! The parameters of Kawaguchi's accumulated chambers (*A morphological study of the form of
//! nature*, SIGGRAPH 1982, "Algorithm of three-dimensional small chambers" and "Relationship
//! between two flat surfaces"): a mouth polygon, and the one similarity that relates each
//! chamber to the next.

use crate::spec::handedness::Handedness;
use serde::{Deserialize, Serialize};

/// A shell, horn, tusk or claw as a stack of similar chambers.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChambersSpec {
    /// The bottom base of the first chamber.
    pub mouth: MouthSpec,
    /// How each chamber's top base follows from its bottom base, and the next chamber from it.
    pub chamber: ChamberSpec,
    /// Number of chambers: the age of the shell.
    pub chambers: u32,
    pub handedness: Handedness,
    /// Flat facets, as Kawaguchi drew his polyhedra, or smooth shading across them.
    pub look: Look,
    /// Mark each septum where it meets the wall (the suture line), in the interior colour.
    pub septa: bool,
    /// The wall's thickness as a fraction of each chamber's radius: above 0 every chamber is
    /// hollow, closed from the next by a septum as thick as the wall and pierced by a
    /// siphuncle, and the last chamber opens at the mouth. 0: solid chambers.
    #[serde(default)]
    pub wall: f64,
}

/// How the chamber polyhedra are shaded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Look {
    /// Every facet flat, with its own normal.
    Faceted,
    /// Normals averaged across facets and chambers.
    Smooth,
}

/// The mouth polygon (Kawaguchi's figure 1): N apexes on an ellipse, optionally pushed in and
/// out by protuberances.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MouthSpec {
    /// N: apexes of the polygon.
    pub apexes: u32,
    /// The long radius D₀/2, along the base's x axis.
    pub radius_a: f64,
    /// The short radius, along the base's y axis.
    pub radius_b: f64,
    /// Radial offsets, as fractions of the ellipse's radius, at equally spaced angles around
    /// it (the first at the end of the long radius), interpolated smoothly between: positive
    /// values are convex protuberances, negative ones concave. Empty: a plain ellipse.
    #[serde(default)]
    pub protuberances: Vec<f64>,
}

/// The relation between the bottom and the top base of a chamber, and between one chamber
/// and the next. Lengths are those of the first chamber; every later chamber is scaled by r.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChamberSpec {
    /// r = D₀′ / D₀: the growth ratio from a chamber's bottom base to its top base.
    pub ratio: f64,
    /// H: the width (distance) between the bottom and top bases, along the bottom base's
    /// normal; the height component T_z of the position T.
    pub width: f64,
    /// Q: the inclination of the top base against the bottom base, degrees about x, y, z.
    pub inclination: Triple,
    /// (T_x, T_y): the position of the top base, moved sideways from straight above the
    /// bottom base along its x and y axes (an oblique chamber). With T_z = H it is the whole
    /// position T. Zero: the top base's centre lies straight above the bottom base's.
    pub shift: Pair,
}

/// Two components along x and y.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pair {
    pub x: f64,
    pub y: f64,
}

/// Three components along x, y and z.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Triple {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl Triple {
    pub fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}
