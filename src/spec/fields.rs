//! The spec's description of its own fields: for every key of a [`ShellSpec`](super::ShellSpec)
//! (its dotted path in the serialised form), the paper's symbol and name, the section it belongs
//! to, and the range a value may take. Links are checked against it, and the editing panel is
//! generated from it.

/// The sections of the editing panel, one per concept of a form or of the pattern.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Section {
    Shape,
    Mouth,
    Chamber,
    Trunk,
    Knot,
    Branches,
    Spiral,
    Whorls,
    Generator,
    Varices,
    CanalSpines,
    Opening,
    Textures,
    Polygonization,
    Curve,
    Orientation,
    Sculpture,
    Wall,
    Pattern,
    Colours,
    Material,
    Growth,
    Seed,
    /// Raup's coiling parameters: coordinates a parameter map may span, not keys of a spec.
    Raup,
}

impl Section {
    pub fn title(self) -> &'static str {
        match self {
            Section::Shape => "Shape",
            Section::Mouth => "Mouth polygon",
            Section::Chamber => "Chamber to chamber",
            Section::Trunk => "Trunks",
            Section::Knot => "Knots and tendrils",
            Section::Branches => "Branches",
            Section::Spiral => "Helico-spiral",
            Section::Whorls => "Whorls and sections",
            Section::Generator => "Generating surface",
            Section::Varices => "Varices, spines and bumps",
            Section::CanalSpines => "Canal spines",
            Section::Opening => "Opening",
            Section::Textures => "Textures of the parts",
            Section::Polygonization => "Polygonization",
            Section::Curve => "Generating curve",
            Section::Orientation => "Orientation",
            Section::Sculpture => "Sculpture",
            Section::Wall => "Wall and lip",
            Section::Pattern => "Pattern model",
            Section::Colours => "Colours",
            Section::Material => "Material and light",
            Section::Growth => "Growth",
            Section::Seed => "Seed",
            Section::Raup => "Raup's coiling parameters",
        }
    }
}

/// What kind of value a field holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A real number in [min, max]; `log` when a slider should move on a logarithmic scale.
    Real {
        min: f64,
        max: f64,
        log: bool,
    },
    /// A whole number in [min, max].
    Integer {
        min: u64,
        max: u64,
    },
    Flag,
    /// One of a fixed set of names.
    Choice(&'static [&'static str]),
    /// Six hexadecimal digits.
    Colour,
    /// A list of numbers (`width` > 1: a list of tuples of that many, written "a,b;c,d").
    List {
        width: usize,
        integer: bool,
    },
    /// Rows of whole numbers of any length, written "0,1,1;0,0,1".
    Table,
    /// Free text, checked by the model that reads it.
    Text,
}

/// Positions of a slider over a real range.
const SLIDER_STEPS: f64 = 1000.0;

impl Kind {
    /// The slider position (0 to 1000 for reals, the offset from `min` for whole numbers) of
    /// a value; logarithmic ranges move by equal ratios.
    pub fn slider_position(self, x: f64) -> f64 {
        match self {
            Kind::Real {
                min,
                max,
                log: true,
            } => SLIDER_STEPS * (x / min).ln() / (max / min).ln(),
            Kind::Real { min, max, .. } => SLIDER_STEPS * (x - min) / (max - min),
            Kind::Integer { min, .. } => x - min as f64,
            _ => 0.0,
        }
    }

    /// The value at a slider position.
    pub fn slider_value(self, position: f64) -> f64 {
        match self {
            Kind::Real {
                min,
                max,
                log: true,
            } => min * (max / min).powf(position / SLIDER_STEPS),
            Kind::Real { min, max, .. } => min + (max - min) * position / SLIDER_STEPS,
            Kind::Integer { min, .. } => min as f64 + position,
            _ => position,
        }
    }
}

/// A number shown with four significant digits, for a slider's live readout.
pub fn display(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// One field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Field {
    /// Dotted path in the serialised spec. Keys under `pattern.model.` apply to every model
    /// that has that parameter.
    pub key: &'static str,
    pub section: Section,
    /// The paper's symbol, or "" where the paper has none.
    pub symbol: &'static str,
    pub name: &'static str,
    pub kind: Kind,
}

impl Field {
    /// What the field is called where room is short (the map's axes, a change of breeding):
    /// the paper's symbol, or its name.
    pub fn short_name(&self) -> &'static str {
        if self.symbol.is_empty() {
            self.name
        } else {
            self.symbol
        }
    }

    /// The field's name with the paper's symbol before it, where it has one.
    pub fn label(&self) -> String {
        if self.symbol.is_empty() {
            self.name.to_string()
        } else {
            format!("{} — {}", self.symbol, self.name)
        }
    }
}

const fn real(min: f64, max: f64) -> Kind {
    Kind::Real {
        min,
        max,
        log: false,
    }
}

const fn log(min: f64, max: f64) -> Kind {
    Kind::Real {
        min,
        max,
        log: true,
    }
}

const fn int(min: u64, max: u64) -> Kind {
    Kind::Integer { min, max }
}

const fn f(
    key: &'static str,
    section: Section,
    symbol: &'static str,
    name: &'static str,
    kind: Kind,
) -> Field {
    Field {
        key,
        section,
        symbol,
        name,
        kind,
    }
}

use super::form::textures::{ImageOf, SHADE_RANGE};
use Section::*;

/// The largest diffusion per iteration that explicit Euler with Δt = Δx = 1 integrates
/// stably: above it the discrete Laplacian amplifies the shortest wave.
pub const MAX_DIFFUSION: f64 = 0.5;

/// The kinds of form, as `form.kind` names them.
pub const FORM_KINDS: &[&str] = &["sweep", "chambers", "branching", "implicit"];

/// The field that chooses the form: first in every shell's panel.
const FORM_KIND: Field = f(
    "form.kind",
    Shape,
    "",
    "surface model",
    Kind::Choice(FORM_KINDS),
);

/// The swept shell's fields (Fowler, Meinhardt & Prusinkiewicz 1992, §2).
#[rustfmt::skip]
pub const SWEEP: &[Field] = &[
    f("form.spiral.delta_theta", Shape, "Δθ", "angular step (degrees)", real(0.5, 90.0)),
    f("form.spiral.lambda_r", Shape, "λᵣ", "radial growth per step", log(0.8, 3.0)),
    f("form.spiral.lambda_z", Shape, "λ_z", "axial growth per step", log(0.8, 3.0)),
    f("form.spiral.r0", Shape, "r₀", "distance from the axis at the apex", real(0.0, 10.0)),
    f("form.spiral.z0", Shape, "z₀", "height along the axis at the apex", real(-10.0, 10.0)),
    f("form.spiral.whorls", Shape, "t_max/2π", "whorls", real(0.05, 30.0)),
    f("form.spiral.subdivisions", Shape, "", "rims per step", int(1, 16)),
    f("form.spiral.handedness", Shape, "", "coiling", Kind::Choice(&["dextral", "sinistral"])),
    f("form.curve.points", Curve, "𝓒", "Bézier control points (u,v,w)", Kind::List { width: 3, integer: false }),
    f("form.curve.closed", Curve, "", "closed curve", Kind::Flag),
    f("form.curve.lambda_c", Curve, "λ_c", "growth of the curve per step", log(0.8, 3.0)),
    f("form.curve.segments", Curve, "n", "segments per rim", int(3, 512)),
    f("form.curve.reparametrize", Curve, "", "equal arc lengths (eqs 4–7)", Kind::Flag),
    f("form.orientation.frame", Orientation, "", "reference frame", Kind::Choice(&["axis_aligned", "frenet"])),
    f("form.orientation.rotate_e1", Orientation, "e₁", "rotation about the tangent (degrees)", real(-180.0, 180.0)),
    f("form.orientation.rotate_e2", Orientation, "e₂", "rotation about the normal (degrees)", real(-180.0, 180.0)),
    f("form.orientation.rotate_e3", Orientation, "e₃", "rotation about the binormal (degrees)", real(-180.0, 180.0)),
    f("form.sculpture.growth_ribs.amplitude", Sculpture, "d", "ribs along growth: height", real(-0.5, 0.5)),
    f("form.sculpture.growth_ribs.count", Sculpture, "", "ribs along growth: number across the curve", real(0.0, 200.0)),
    f("form.sculpture.growth_ribs.sharpness", Sculpture, "", "ribs along growth: sharpness", log(0.25, 64.0)),
    f("form.sculpture.growth_ribs.drift", Sculpture, "", "ribs along growth: phase drift per whorl (oblique ribs)", real(-20.0, 20.0)),
    f("form.sculpture.growth_ribs.frequency_change", Sculpture, "", "ribs along growth: frequency factor per whorl", log(0.2, 5.0)),
    f("form.sculpture.curve_ribs.amplitude", Sculpture, "d", "ribs along the curve: height", real(-0.5, 0.5)),
    f("form.sculpture.curve_ribs.count", Sculpture, "", "ribs along the curve: number per whorl", real(0.0, 400.0)),
    f("form.sculpture.curve_ribs.sharpness", Sculpture, "", "ribs along the curve: sharpness", log(0.25, 64.0)),
    f("form.sculpture.curve_ribs.drift", Sculpture, "", "ribs along the curve: phase drift per whorl", real(-20.0, 20.0)),
    f("form.sculpture.curve_ribs.frequency_change", Sculpture, "", "ribs along the curve: frequency factor per whorl", log(0.2, 5.0)),
    f("form.wall.thickness", Wall, "", "wall thickness (relative to the curve)", real(0.0, 0.5)),
    f("form.wall.lip_length", Wall, "", "lip length (degrees before the opening)", real(0.0, 720.0)),
    f("form.wall.lip_flare", Wall, "", "lip flare (extra size at the opening)", real(-0.5, 2.0)),
    f("form.wall.lip_thickening", Wall, "", "lip thickening (factor at the opening)", log(0.5, 10.0)),
];

/// The fields of Kawaguchi's accumulated chambers.
#[rustfmt::skip]
pub const CHAMBERS: &[Field] = &[
    f("form.chambers", Shape, "", "chambers (the age of the shell)", int(1, 2000)),
    f("form.handedness", Shape, "", "twist", Kind::Choice(&["dextral", "sinistral"])),
    f("form.look", Shape, "", "look", Kind::Choice(&["faceted", "smooth"])),
    f("form.septa", Shape, "", "mark the septa (suture lines)", Kind::Flag),
    f("form.wall", Shape, "", "wall and septa thickness (relative to each chamber's radius; 0: solid)", real(0.0, 0.4)),
    f("form.mouth.apexes", Mouth, "N", "apexes of the polygon", int(3, 256)),
    f("form.mouth.radius_a", Mouth, "D₀/2", "long radius", log(0.01, 100.0)),
    f("form.mouth.radius_b", Mouth, "", "short radius", log(0.01, 100.0)),
    f("form.mouth.protuberances", Mouth, "", "protuberances: radial offsets around the ellipse (fractions)", Kind::List { width: 1, integer: false }),
    f("form.chamber.ratio", Chamber, "r", "growth ratio D₀′/D₀ per chamber", log(0.5, 2.0)),
    f("form.chamber.width", Chamber, "H", "width between bottom and top base (Tz)", log(0.001, 100.0)),
    f("form.chamber.inclination.x", Chamber, "Qx", "inclination about x (degrees)", real(-90.0, 90.0)),
    f("form.chamber.inclination.y", Chamber, "Qy", "inclination about y (degrees)", real(-90.0, 90.0)),
    f("form.chamber.inclination.z", Chamber, "Qz", "inclination about z (degrees)", real(-90.0, 90.0)),
    f("form.chamber.shift.x", Chamber, "Tx", "position: top base moved sideways along x", real(-10.0, 10.0)),
    f("form.chamber.shift.y", Chamber, "Ty", "position: top base moved sideways along y", real(-10.0, 10.0)),
];

/// The fields of Kawaguchi's branching forms.
#[rustfmt::skip]
pub const BRANCHING: &[Field] = &[
    f("form.knots", Shape, "", "most trunks per branch", int(1, 400)),
    f("form.depth", Shape, "", "most generations of branches on branches", int(0, 12)),
    f("form.pixels", Shape, "px", "picture size in pixels: a branch stops under one (rule 8)", int(64, 4096)),
    f("form.jitter", Shape, "", "random turn of rolls and branch angles (degrees)", real(0.0, 90.0)),
    f("form.look", Shape, "", "look", Kind::Choice(&["faceted", "smooth"])),
    f("form.stand", Shape, "", "upright: the first trunk or the coil's axis", Kind::Choice(&["trunk", "coil"])),
    f("form.trunk.diameter", Trunk, "D₀", "diameter of the first trunk", log(0.01, 100.0)),
    f("form.trunk.slenderness", Trunk, "S", "H/D of every trunk (rule 1)", log(0.05, 20.0)),
    f("form.trunk.taper", Trunk, "", "diameter ratio from trunk to trunk", log(0.5, 1.0)),
    f("form.trunk.sides", Trunk, "", "sides of a trunk's section", int(3, 32)),
    f("form.knot.angle", Knot, "α", "knot angle at a branch's first knot (degrees)", real(-90.0, 90.0)),
    f("form.knot.roll", Knot, "θ", "change of α per knot (degrees)", real(-45.0, 45.0)),
    f("form.knot.k0", Knot, "k₀", "lower limit of α (degrees)", real(-90.0, 90.0)),
    f("form.knot.k1", Knot, "k₁", "upper limit of α (degrees)", real(-90.0, 90.0)),
    f("form.knot.beta", Knot, "β", "self-adjusting force (degrees)", real(0.0, 90.0)),
    f("form.knot.twist", Knot, "", "turn of the bending side per knot (degrees)", real(-180.0, 180.0)),
    f("form.branches.every", Branches, "", "branches every n knots (0: where the tendril turns)", int(0, 50)),
    f("form.branches.count", Branches, "", "branches at a branching knot", int(1, 24)),
    f("form.branches.count_step", Branches, "", "added to the count at each later branching knot", real(-4.0, 4.0)),
    f("form.branches.angle", Branches, "", "angle of a branch to its parent (degrees)", real(-90.0, 90.0)),
    f("form.branches.angle_step", Branches, "", "added to the angle at each later branching knot (degrees)", real(-30.0, 30.0)),
    f("form.branches.scale", Branches, "", "branch diameter / knot height (rule 7)", log(0.05, 20.0)),
    f("form.branches.scale_growth", Branches, "", "factor on that at each later branching knot", log(0.5, 2.0)),
];

/// The implicit shell's fields (Galbraith, Prusinkiewicz & Wyvill): its helico-spiral, its whorls,
/// its generating surface, varices, canal spines and opening, and its polygonization.
#[rustfmt::skip]
pub const IMPLICIT: &[Field] = &[
    f("form.spiral.beta", Spiral, "β", "angle between the axis and the line through the whorls (degrees)", real(1.0, 89.0)),
    f("form.spiral.lambda", Spiral, "λ", "ratio of radii one turn apart (eq 1)", log(1.01, 10.0)),
    f("form.spiral.r0", Spiral, "R₀", "distance from the axis at θ = 0 (eq 1)", log(0.001, 10.0)),
    f("form.spiral.handedness", Spiral, "", "coiling", Kind::Choice(&["dextral", "sinistral"])),
    f("form.whorls", Whorls, "", "whorls", int(1, 40)),
    f("form.whorl_angle", Whorls, "", "rotation per whorl (degrees)", real(30.0, 720.0)),
    f("form.sections", Whorls, "", "sections per whorl (between varices)", int(1, 12)),
    f("form.surfaces", Whorls, "", "generating surfaces per section (eq 9)", int(1, 64)),
    f("form.blending", Whorls, "", "sections blend with", Kind::Choice(&["all", "neighbours"])),
    f("form.generator.points", Generator, "", "points (u,v,w,radius)", Kind::List { width: 4, integer: false }),
    f("form.generator.cones", Generator, "", "cones (u₀,v₀,w₀,u₁,v₁,w₁,radius₀,radius₁,bend°,from whorl)", Kind::List { width: 10, integer: false }),
    f("form.generator.tori", Generator, "", "tori in the uv plane (u,v,w,major radius,radius)", Kind::List { width: 5, integer: false }),
    f("form.generator.exponent", Generator, "n", "blending exponent of the parts (eq 4)", log(1.0, 400.0)),
    f("form.generator.pairs", Generator, "", "only these pairs of parts blend (eq 6)", Kind::List { width: 2, integer: true }),
    f("form.varices.placement", Varices, "", "spines stand where", Kind::Choice(&["table", "pattern"])),
    f("form.varices.spines", Varices, "σ", "spines (whorl, angle°, relative size σ; table 1)", Kind::List { width: 3, integer: false }),
    f("form.varices.length", Varices, "", "length of a spine of σ = 1 (units of D)", log(0.05, 5.0)),
    f("form.varices.radius", Varices, "", "radius at a spine's base", log(0.005, 1.0)),
    f("form.varices.tip", Varices, "", "radius at the largest spine's tip (eq 12)", log(0.002, 1.0)),
    f("form.varices.bend", Varices, "", "curve of a spine (degrees)", real(-90.0, 90.0)),
    f("form.varices.ridge", Varices, "", "radius of the ridge joining the spines", real(0.0, 0.5)),
    f("form.varices.bump_sets", Varices, "", "sets of bumps between two varices", int(0, 16)),
    f("form.varices.bump_size", Varices, "s", "size of a bump", log(0.01, 1.0)),
    f("form.varices.bump_spread", Varices, "σ", "deviation of a bump's random scale", real(0.0, 1.0)),
    f("form.varices.spine_level", Varices, "", "pattern: activator peak (of the edge's highest) that grows a spine", real(0.05, 1.0)),
    f("form.varices.bump_level", Varices, "", "pattern: lower peak that bears bumps", real(0.0, 1.0)),
    f("form.varices.peak_sigma", Varices, "σ", "pattern: relative size of a spine on the highest peak", real(0.1, 5.0)),
    f("form.canal_spines.spines", CanalSpines, "", "canal spines (varix 1–3, σ; table 2)", Kind::List { width: 2, integer: false }),
    f("form.canal_spines.length", CanalSpines, "", "length of a canal spine of σ = 1", log(0.05, 5.0)),
    f("form.canal_spines.radius", CanalSpines, "", "radius at a canal spine's base", log(0.005, 1.0)),
    f("form.opening.inside.points", Opening, "", "hollow: points (u,v,w,radius)", Kind::List { width: 4, integer: false }),
    f("form.opening.inside.cones", Opening, "", "hollow: cones (u₀,v₀,w₀,u₁,v₁,w₁,radius₀,radius₁,bend°,from whorl)", Kind::List { width: 10, integer: false }),
    f("form.opening.inside.tori", Opening, "", "hollow: tori (u,v,w,major radius,radius)", Kind::List { width: 5, integer: false }),
    f("form.opening.inside.exponent", Opening, "n", "hollow: blending exponent (eq 4)", log(1.0, 400.0)),
    f("form.opening.inside.pairs", Opening, "", "hollow: only these pairs blend (eq 6)", Kind::List { width: 2, integer: true }),
    f("form.opening.extension", Opening, "", "hollow: cones extending its inner edge to the previous whorl (eq 14)", Kind::List { width: 10, integer: false }),
    f("form.opening.wall", Opening, "", "generating surfaces of inside wall at the aperture (eq 15)", int(0, 64)),
    f("form.opening.ahead", Opening, "", "generating surfaces the hollow reaches beyond the edge", int(0, 16)),
    f("form.opening.shows", Opening, "", "solid drawn (fig 10)", Kind::Choice(&["shell", "inside", "opening"])),
    f("form.textures.body.look", Textures, "", "body whorl: texture", Kind::Choice(&["pattern", "ramp", "image"])),
    f("form.textures.body.image", Textures, "", "body whorl: species whose pattern is the image", Kind::Choice(ImageOf::IDS)),
    f("form.textures.body.base", Textures, "", "body whorl: ramp colour at the base", Kind::Colour),
    f("form.textures.body.tip", Textures, "", "body whorl: ramp colour at the tip", Kind::Colour),
    f("form.textures.body.shade", Textures, "", "body whorl: ramp exponent (above 1: darker toward the tip)", log(SHADE_RANGE[0], SHADE_RANGE[1])),
    f("form.textures.spines.look", Textures, "", "spines in the varices: texture", Kind::Choice(&["pattern", "ramp", "image"])),
    f("form.textures.spines.image", Textures, "", "spines in the varices: species whose pattern is the image", Kind::Choice(ImageOf::IDS)),
    f("form.textures.spines.base", Textures, "", "spines in the varices: ramp colour at the base", Kind::Colour),
    f("form.textures.spines.tip", Textures, "", "spines in the varices: ramp colour at the tip", Kind::Colour),
    f("form.textures.spines.shade", Textures, "", "spines in the varices: ramp exponent (above 1: darker toward the tip)", log(SHADE_RANGE[0], SHADE_RANGE[1])),
    f("form.textures.canal_spines.look", Textures, "", "spines on the canal: texture", Kind::Choice(&["pattern", "ramp", "image"])),
    f("form.textures.canal_spines.image", Textures, "", "spines on the canal: species whose pattern is the image", Kind::Choice(ImageOf::IDS)),
    f("form.textures.canal_spines.base", Textures, "", "spines on the canal: ramp colour at the base", Kind::Colour),
    f("form.textures.canal_spines.tip", Textures, "", "spines on the canal: ramp colour at the tip", Kind::Colour),
    f("form.textures.canal_spines.shade", Textures, "", "spines on the canal: ramp exponent (above 1: darker toward the tip)", log(SHADE_RANGE[0], SHADE_RANGE[1])),
    f("form.textures.bumps.look", Textures, "", "bumps: texture", Kind::Choice(&["pattern", "ramp", "image"])),
    f("form.textures.bumps.image", Textures, "", "bumps: species whose pattern is the image", Kind::Choice(ImageOf::IDS)),
    f("form.textures.bumps.base", Textures, "", "bumps: ramp colour at the base", Kind::Colour),
    f("form.textures.bumps.tip", Textures, "", "bumps: ramp colour at the tip", Kind::Colour),
    f("form.textures.bumps.shade", Textures, "", "bumps: ramp exponent (above 1: darker toward the tip)", log(SHADE_RANGE[0], SHADE_RANGE[1])),
    f("form.resolution", Polygonization, "", "voxels along the longest side (polygonization)", int(16, 384)),
];

/// The fields every shell has, whatever its form: the pattern model, the colours, the material,
/// the growth and the seed.
#[rustfmt::skip]
pub const SHELL: &[Field] = &[
    f("pattern.cells", Pattern, "", "cells along the growing edge", int(8, 2048)),
    f("pattern.iterations", Pattern, "", "iterations per row", int(1, 5000)),
    f("pattern.refinement", Pattern, "k", "refinement (k cells per cell, Δt = 1/k²)", int(1, 4)),
    f("pattern.boundary", Pattern, "", "ends of the edge", Kind::Choice(&["zero_flux", "periodic"])),
    f("pattern.edge_growth", Pattern, "", "cells divide as the rim lengthens (beyond the paper)", Kind::Choice(&["off", "uniform"])),
    f("pattern.apex_cells", Pattern, "", "fewest cells of a growing edge (at the apex)", int(1, 2048)),
    f("pattern.low", Pattern, "", "value shown as no pigment", real(-1000.0, 1000.0)),
    f("pattern.high", Pattern, "", "value shown as full pigment", real(-1000.0, 1000.0)),
    f("pattern.model.kind", Pattern, "", "model", Kind::Choice(&["none", "activator_substrate", "activator_inhibitor", "coupled", "automaton"])),
    f("pattern.model.rho", Pattern, "ρ", "autocatalysis rate", log(1e-4, 10.0)),
    f("pattern.model.rho_noise", Pattern, "", "random fluctuation of ρ (fraction)", real(0.0, 0.5)),
    f("pattern.model.rho0", Pattern, "ρ₀", "base production of the activator", log(1e-6, 1.0)),
    f("pattern.model.mu", Pattern, "μ", "decay of the activator", log(1e-5, 1.0)),
    f("pattern.model.d_a", Pattern, "D_a", "activator diffusion", real(0.0, MAX_DIFFUSION)),
    f("pattern.model.sigma", Pattern, "σ", "substrate (inhibitor) production", log(1e-6, 1.0)),
    f("pattern.model.sigma_depth", Pattern, "", "depth of the modulation of σ(x)", real(0.0, 1.0)),
    f("pattern.model.sigma_period", Pattern, "", "period of σ(x) (cells)", real(2.0, 4096.0)),
    f("pattern.model.nu", Pattern, "ν", "decay of the substrate (inhibitor)", log(1e-6, 1.0)),
    f("pattern.model.d_s", Pattern, "D_s", "substrate diffusion", real(0.0, MAX_DIFFUSION)),
    f("pattern.model.d_h", Pattern, "D_h", "inhibitor diffusion", real(0.0, MAX_DIFFUSION)),
    f("pattern.model.rho_c", Pattern, "ρ′", "hormone production", log(1e-4, 10.0)),
    f("pattern.model.eta", Pattern, "η", "hormone decay", log(1e-5, 1.0)),
    f("pattern.model.h0", Pattern, "h₀", "inhibitor offset", log(1e-4, 10.0)),
    f("pattern.model.kappa", Pattern, "κ", "saturation of the autocatalysis", real(0.0, 100.0)),
    f("pattern.model.a_init", Pattern, "a(0)", "activator at the start", real(0.0, 100.0)),
    f("pattern.model.s_init", Pattern, "s(0)", "substrate at the start", real(0.0, 100.0)),
    f("pattern.model.h_init", Pattern, "h(0)", "inhibitor at the start", real(0.0, 100.0)),
    f("pattern.model.c_init", Pattern, "c(0)", "hormone at the start", real(0.0, 100.0)),
    f("pattern.model.starts", Pattern, "", "activated cells at the start", int(0, 2048)),
    f("pattern.model.start_level", Pattern, "", "activator of the starting cells", real(0.0, 100.0)),
    f("pattern.model.start_width", Pattern, "", "width of each start (cells)", int(1, 64)),
    f("pattern.model.rho_e", Pattern, "ρₑ", "autocatalysis of the extinguisher", log(1e-4, 10.0)),
    f("pattern.model.rho_e0", Pattern, "ρₑ₀", "base production of the extinguisher (its clock)", log(1e-5, 1.0)),
    f("pattern.model.mu_e", Pattern, "μₑ", "decay of the extinguisher", log(1e-5, 1.0)),
    f("pattern.model.d_e", Pattern, "Dₑ", "extinguisher diffusion", real(0.0, MAX_DIFFUSION)),
    f("pattern.model.k_a", Pattern, "kₐ", "reaction level that half-enables the extinguisher", log(1e-4, 10.0)),
    f("pattern.model.gamma", Pattern, "γ", "strength of the extinction", log(1e-4, 10.0)),
    f("pattern.model.theta", Pattern, "θ", "extinguisher level of half extinction", log(1e-3, 10.0)),
    f("pattern.model.nu_f", Pattern, "ν_f", "recovery of the extinguisher's substrate", log(1e-6, 1.0)),
    f("pattern.model.eps_f", Pattern, "ε_f", "use of that substrate by the extinguisher", log(1e-5, 10.0)),
    f("pattern.model.rule", Pattern, "", "automaton rule a/b-c/d, or custom", Kind::Text),
    f("pattern.model.f", Pattern, "f", "custom prepigment table (p = 0; p = 1)", Kind::Table),
    f("pattern.model.g", Pattern, "g", "custom activity table (p = 0; p = 1)", Kind::Table),
    f("pattern.model.start_cells", Pattern, "", "starting cells, by position", Kind::List { width: 1, integer: true }),
    f("pattern.model.random_starts", Pattern, "", "starting cells placed by the seed", int(0, 2048)),
    f("pattern.model.start_value", Pattern, "x(j,0)", "prepigment of a starting cell", int(1, 255)),
    f("pattern.model.start_activity", Pattern, "p(j,0)", "activity of a starting cell", int(0, 1)),
    f("pattern.model.colour_by", Pattern, "", "colour by", Kind::Choice(&["prepigment", "activity", "both"])),
    f("colours.ground", Colours, "", "shell ground", Kind::Colour),
    f("colours.pigment", Colours, "", "pigment", Kind::Colour),
    f("colours.interior", Colours, "", "inside of the wall", Kind::Colour),
    f("material.drawing", Material, "", "drawn as", Kind::Choice(&["shaded", "lines"])),
    f("material.gloss", Material, "", "polished reflections", real(0.0, 1.0)),
    f("material.anisotropy", Material, "", "highlights along the growth lines", real(0.0, 1.0)),
    f("material.translucency", Material, "", "light through the wall", real(0.0, 1.0)),
    f("material.occlusion", Material, "", "darkness inside the opening", real(0.0, 1.0)),
    f("material.shadow", Material, "", "shadow on the ground", real(0.0, 1.0)),
    f("growth.rows", Growth, "", "rows from apex to opening", int(2, 20_000)),
    f("growth.speed", Growth, "", "rows per frame", log(0.05, 200.0)),
    f("seed", Seed, "", "seed of the random choices", int(0, u64::MAX)),
];

/// Raup's coordinates of a swept shell (`forms::sweep::raup`): no keys of its spec, but what a
/// parameter map may span, each written into the spiral's and the curve's values. W, the
/// expansion per whorl, from barely growing to Raup's million; D, from a curve that touches the
/// axis to one as thin as a twentieth of its distance; T, the height over the distance of the
/// curve's centre, either way along the axis.
#[rustfmt::skip]
pub const RAUP: &[Field] = &[
    f("raup.w", Raup, "W", "whorl expansion rate (growth per whorl)", log(1.01, 1e6)),
    f("raup.d", Raup, "D", "distance from the axis (inner edge over outer edge)", real(0.0, 0.95)),
    f("raup.t", Raup, "T", "translation along the axis (height over distance)", real(-20.0, 20.0)),
];

/// Each form's own fields, by the form's kind; a new form adds its block here.
const FORMS: &[(&str, &[Field])] = &[
    ("sweep", SWEEP),
    ("chambers", CHAMBERS),
    ("branching", BRANCHING),
    ("implicit", IMPLICIT),
];

/// The fields of a shell whose form is of `kind`, in the panel's order: the choice of form,
/// the form's own fields, then those every shell has.
pub fn fields(kind: &str) -> impl Iterator<Item = &'static Field> {
    let own = FORMS
        .iter()
        .find(|(k, _)| *k == kind)
        .map_or(&[][..], |(_, fields)| fields);
    std::iter::once(&FORM_KIND).chain(own).chain(SHELL)
}

/// The description of `key` in a shell whose form is of `kind`.
pub fn field(kind: &str, key: &str) -> Option<&'static Field> {
    fields(kind).find(|f| f.key == key)
}

/// The panel's range of the numeric field `key` of a shell whose form is of `kind`: the one
/// source of that value's limits, which links are held to and the forms' checks read.
pub fn range(kind: &str, key: &str) -> (f64, f64) {
    match field(kind, key).map(|f| f.kind) {
        Some(Kind::Real { min, max, .. }) => (min, max),
        Some(Kind::Integer { min, max }) => (min as f64, max as f64),
        _ => panic!("{key} is no numeric field of a {kind} shell"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sliders_map_both_ways() {
        for kind in [log(0.001, 10.0), real(-2.0, 3.0), int(8, 2048)] {
            for x in [0.002, 0.5, 1.0, 9.0, 100.0] {
                let back = kind.slider_value(kind.slider_position(x));
                assert!(
                    (back - x).abs() < 1e-9 * x.abs().max(1.0),
                    "{kind:?}: {x} → {back}"
                );
            }
        }
        assert_eq!(display(0.0150004), "0.015");
        assert_eq!(display(1234.6), "1235");
        assert_eq!(display(-0.5), "-0.5");
    }

    #[test]
    fn every_range_is_sound() {
        for f in FORM_KINDS.iter().flat_map(|k| fields(k)) {
            match f.kind {
                Kind::Real { min, max, log } => {
                    assert!(min < max && (!log || min > 0.0), "{}", f.key)
                }
                Kind::Integer { min, max } => assert!(min < max, "{}", f.key),
                _ => {}
            }
        }
    }
}
