//! The parameters of an implicit shell (Galbraith, Prusinkiewicz & Wyvill, §2.1 and §3.1): a
//! generating surface of skeletal primitives, placed again and again along a helico-spiral
//! and blended into whorls, then polygonized at a chosen resolution.

use crate::spec::form::textures::TexturesSpec;
use crate::spec::handedness::Handedness;
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
    /// The varices at the end of every section, with their spines and the bumps between them
    /// (§3.2); none when no spines are given.
    #[serde(default)]
    pub varices: VaricesSpec,
    /// The axial rows of spines on the canal below the last three varices (§3.2, table 2).
    #[serde(default)]
    pub canal_spines: CanalSpinesSpec,
    /// The hollow inside carved out of the shell and the inside wall at the aperture (§3.3,
    /// eqs 14–15); none when its generating surface is empty. Boxed, as the form's variants
    /// should stay near one size.
    #[serde(default)]
    pub opening: Box<OpeningSpec>,
    /// How the four parts are coloured and blended (§3.4, fig 12); boxed, as the form's
    /// variants should stay near one size.
    #[serde(default)]
    pub textures: Box<TexturesSpec>,
}

impl ImplicitSpec {
    /// Turns about the axis from the apex to the opening.
    pub fn turns(&self) -> f64 {
        f64::from(self.whorls) * self.whorl_angle / 360.0
    }
}

/// Where a varix's spines stand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Placement {
    /// As the table of spines says (table 1 of the paper).
    Table,
    /// By the reaction-diffusion pattern on the growing edge, over the whole edge: its high
    /// activator peaks grow spines when a varix forms, its lower peaks bumps between the
    /// varices (the paper's proposed extension; the table is not read).
    Pattern,
}

/// Varices (eqs 11–13): a row of curving spines in the plane of the generating curve, joined
/// near the surface by a ridge, placed at the end of every section; and bumps between them.
/// Lengths are in units of the generating surface's size D(θ).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct VaricesSpec {
    pub placement: Placement,
    /// (whorl from 1 at the apex, angle in degrees, relative size σ): the spines of every varix
    /// of that whorl (table 1). The angle turns in the plane of the generating curve from the
    /// horizontal, pointing away from the axis, towards the apex (positive) or the canal.
    pub spines: Vec<[f64; 3]>,
    /// Length of a spine of σ = 1.
    pub length: f64,
    /// Radius at the base of a spine of σ = 1.
    pub radius: f64,
    /// Radius at the tip of the largest spine; smaller spines have wider tips (eq 12).
    pub tip: f64,
    /// Degrees each spine curves, towards the growth direction.
    pub bend: f64,
    /// Radius of the ridge that joins the spines near the surface (the paper's two tori).
    pub ridge: f64,
    /// Sets of bumps (beaded riblets) between two varices.
    pub bump_sets: u32,
    /// Radius s of a bump.
    pub bump_size: f64,
    /// Standard deviation of the normal random factors that scale each bump.
    pub bump_spread: f64,
    /// Spines placed by the pattern: a peak of the activator at least this fraction of the
    /// edge's highest concentration grows a spine when a varix forms.
    pub spine_level: f64,
    /// Spines placed by the pattern: lower peaks, down to this fraction, bear bumps between
    /// the varices.
    pub bump_level: f64,
    /// Spines placed by the pattern: the relative size σ of a spine on the edge's highest
    /// peak; a spine on a peak just at `spine_level` is the smallest.
    pub peak_sigma: f64,
}

impl Default for VaricesSpec {
    /// No spines, so no varices.
    fn default() -> Self {
        Self {
            placement: Placement::Table,
            spines: Vec::new(),
            length: 1.0,
            radius: 0.08,
            tip: 0.03,
            bend: 30.0,
            ridge: 0.07,
            bump_sets: 0,
            bump_size: 0.1,
            bump_spread: 0.2,
            spine_level: 0.8,
            bump_level: 0.55,
            peak_sigma: 1.9,
        }
    }
}

/// The axial rows of spines on the canal, one below each of the last three varices (table 2).
/// They stand on the canal: the generator's first cone present at the varix's whorl.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CanalSpinesSpec {
    /// (varix 1–3, from the earliest to the one at the opening; relative size σ), in order
    /// down the canal.
    pub spines: Vec<[f64; 2]>,
    /// Length of a spine of σ = 1, in units of D(θ).
    pub length: f64,
    /// Radius at the base of a spine of σ = 1.
    pub radius: f64,
}

impl Default for CanalSpinesSpec {
    /// No canal spines.
    fn default() -> Self {
        Self {
            spines: Vec::new(),
            length: 0.8,
            radius: 0.07,
        }
    }
}

/// The opening (eqs 14–15): B_murex = (B_shell − B_opening) ∪ B_inside_wall, where
/// B_opening = B_inside − B_{w−1} is a whorl of a smaller generating surface, its inner edge
/// extended to the previous whorl, less that previous whorl.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OpeningSpec {
    /// The generating surface of the hollow inside: slightly smaller than the body's, with
    /// its inner canal; empty for a solid shell.
    pub inside: GeneratorSpec,
    /// Cones (as the generating surface's) blended into the inside generating surface that
    /// extend its inner edge to the edge of the previous whorl (§3.3): the previous whorl,
    /// subtracted from the hollow (eq 14), then bounds it, so the wall between two whorls is
    /// the previous whorl's own.
    pub extension: Vec<[f64; 10]>,
    /// Generating surfaces at the growing edge over which the inside wall of eq 15 stands:
    /// the body's own inner wall, put back where the extension carved it, so that the
    /// opening is roughly round; 0 for none.
    pub wall: u32,
    /// Generating surfaces the hollow reaches beyond the growing edge, so the aperture stays
    /// open at every stage.
    pub ahead: u32,
    /// Which solid of eqs 14–15 is drawn: the Murex, or one of the two its opening is carved
    /// with (the paper's fig 10).
    pub shows: Shows,
}

/// A solid of eqs 14–15, as the paper's figs 10 and 11 show them apart.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shows {
    /// B_murex = (B_shell − B_opening) ∪ B_inside_wall: the shell.
    #[default]
    Shell,
    /// B_inside: the whorl the inside generating surface sweeps (fig 10, centre).
    Inside,
    /// B_opening = B_inside − B_{w−1}: what is carved out of the shell (fig 10, right).
    Opening,
}

impl Default for OpeningSpec {
    /// A solid shell.
    fn default() -> Self {
        Self {
            inside: GeneratorSpec::default(),
            extension: Vec::new(),
            wall: 0,
            ahead: 3,
            shows: Shows::Shell,
        }
    }
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

impl GeneratorSpec {
    /// Whether it has no parts (an opening's inside surface that carves nothing).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty() && self.cones.is_empty() && self.tori.is_empty()
    }
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
