//! The parameters of Kawaguchi's growth by branching (*A morphological study of the form of
//! nature*, SIGGRAPH 1982, "Growth model by branching", rules 1–8, "Tendril plants and their
//! modification" and "Extension of generating model", steps 1–6): trunks joined by knots,
//! branches that start at knots, tendrils that correct their own rolling.

use super::chambers::Look;
use serde::{Deserialize, Serialize};

/// A plant, coral or cluster of tentacles grown from one trunk.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BranchingSpec {
    pub trunk: TrunkSpec,
    pub knot: KnotSpec,
    pub branches: BranchesSpec,
    /// Most trunks one branch may have (a branch that never thins must still end).
    pub knots: u32,
    /// Most generations of branches on branches.
    pub depth: u32,
    /// Rule 8, "when the height of a branch or knot becomes smaller than one pixel, the branch
    /// stops growing": the size of the picture the form is grown for, in pixels across. A
    /// branch stops when its next trunk would be lower than [`BranchingSpec::pixel`]. A
    /// picture of more pixels (an export, `seashells mesh --resolution`) grows finer tips.
    pub pixels: u32,
    /// Random turn of every knot's roll and every branch's angle, up to ± this many degrees,
    /// drawn from the spec's seed (0: none).
    pub jitter: f64,
    /// Flat facets, a crease at every knot, as Kawaguchi drew his polyhedral trunks; or round
    /// tubes bending smoothly through their knots.
    pub look: Look,
    /// What stands upright: the first trunk, or the axis of the coil its knots wind.
    #[serde(default)]
    pub stand: Stand,
}

impl BranchingSpec {
    /// One pixel of a picture [`pixels`](Self::pixels) across that frames the whole form. The
    /// form's size is not known before it grows; its first branch's reach stands for it (its
    /// trunks' heights summed, as if it grew every knot: bent, the stem spans less, and
    /// branches on branches may stand out a little further). In heights of the first trunk the
    /// pixel depends on the parameters only, so a form keeps its look at any size.
    pub fn pixel(&self) -> f64 {
        let first = self.trunk.slenderness * self.trunk.diameter;
        first * reach_in_first_heights(self.knots, self.trunk.taper) / f64::from(self.pixels)
    }
}

/// The reach of a branch of `knots` trunks, each `taper` times the one before, in heights of
/// its first trunk: 1 + t + t² + … + t^(knots−1) (libm's power, the same bits in wasm).
pub fn reach_in_first_heights(knots: u32, taper: f64) -> f64 {
    if taper == 1.0 {
        f64::from(knots)
    } else {
        (1.0 - libm::pow(taper, f64::from(knots))) / (1.0 - taper)
    }
}

/// What of a branching form stands upright (along the display's up).
///
/// Knots that bend by α and turn their bending side by the twist, the same at every knot, are
/// a screw motion scaled by the taper: they wind a branch into a conical helix about a fixed
/// axis, which leans from the first trunk by about atan(α/twist). A spiral is seen standing on
/// that axis, as a shell is; a first trunk set upright lays a wide coil on its side.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stand {
    /// The first trunk upright: a bush, a coral, a tuft of tentacles.
    #[default]
    Trunk,
    /// The coil's axis upright, the first trunk leaning along the helix as a climbing stem
    /// leans along its support: a spiral plant. Without twist the coil is flat, and lies flat.
    Coil,
}

/// Rule 1: trunks of diameter D and height H with H/D = S.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrunkSpec {
    /// D₀: the first trunk's diameter.
    pub diameter: f64,
    /// S = H/D, the same for every trunk and branch.
    pub slenderness: f64,
    /// Ratio of a trunk's diameter to the one before it along the same branch.
    pub taper: f64,
    /// Sides of the polygon that stands for a trunk's round section.
    pub sides: u32,
}

/// Rules 3–5 and the tendril's self-adjustment (steps 2–5): the knot angle α between the bases
/// of a knot, which touch at one point K.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KnotSpec {
    /// α at a branch's first knot, degrees (its sign: which side the branch bends to).
    pub angle: f64,
    /// θ: the change of α from one knot to the next, degrees (step 2).
    pub roll: f64,
    /// k₀: the lower limit of α, degrees (step 4).
    pub k0: f64,
    /// k₁: the upper limit of α, degrees.
    pub k1: f64,
    /// β: the self-adjusting force that pushes α back inside (k₀, k₁), degrees (step 3); 0: no
    /// force, and α rolls on.
    pub beta: f64,
    /// Turn of the bending side about the trunk's axis per knot, degrees: 0 keeps a branch in
    /// one plane, other values coil it in space.
    pub twist: f64,
}

/// Rules 6–7 and the spiral plant's series: where branches start and how big they are.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BranchesSpec {
    /// A knot bears branches every this many knots; 0: only where the self-adjusting force
    /// turns the tendril (step 5).
    pub every: u32,
    /// Branches at a branching knot, spread evenly around the trunk.
    pub count: u32,
    /// Added to the count at each later branching knot of the same branch (the spiral plant's
    /// series).
    pub count_step: f64,
    /// Angle of a branch to its parent's axis, degrees.
    pub angle: f64,
    /// Added to that angle at each later branching knot, degrees.
    pub angle_step: f64,
    /// Rule 7: a branch's diameter is this multiple of the height of its knot.
    pub scale: f64,
    /// Factor on that multiple at each later branching knot (the series of lengths).
    pub scale_growth: f64,
}
