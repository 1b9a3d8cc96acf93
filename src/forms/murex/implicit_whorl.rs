//! A shell whorl as a BlobTree (Galbraith, Prusinkiewicz & Wyvill §2.1 and §3.1): the generating
//! surface is placed along the helico-spiral by P(B, θ) (eq 8), its instances blend into
//! sections (eq 9), and the sections combine by blending or by controlled blending with their
//! neighbours only (eq 10). Each instance is one growth step.
//!
//! The paper's equations 1–3, as we read them: R(θ) = R₀ λ^(θ/2π); H(θ) = R(θ) cot β; and, for
//! circles of consecutive whorls that touch, D(θ) = R(θ)(λ − 1) / ((λ + 1) sin β), which gives
//! the paper's D = 0.341 R for β = 22.5°, λ = 1.3. The paper's y axis is our z: as for all our
//! shells, the apex points towards −z and growth goes towards +z (the display turns it apex up).

use super::bumps::{BUMP_EXPONENT, BUMP_STREAM, bump_set};
use super::canal_spines::{CANAL_STREAM, CANAL_VARICES, canal_row};
use super::varix::{
    Standing, edge_distance, outward, pattern_spines, pigment_at, standing, table_spines, varix,
};
use crate::blobtree::bend::{Bend, MAX_BEND_DEGREES};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::{ISO, support_of};
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::Texture;
use crate::mesh::Bounds;
use crate::pattern::noise::Noise;
use crate::shape::ShapeError;
use crate::spec::handedness::Handedness;
use crate::spec::implicit::{Blending, GeneratorSpec, HelixSpec, ImplicitSpec, Placement};
use crate::spec::pattern::PatternSpec;
use glam::{DAffine3, DMat3, DVec3};
use std::f64::consts::TAU;

/// Most generating surfaces (growth steps) in one shell.
pub const MAX_INSTANCES: u64 = 5_000;
/// Most voxels along the longest side: 384³ samples at most.
pub const MAX_RESOLUTION: u32 = 384;
/// Fewest voxels along the longest side that still show a whorl.
pub const MIN_RESOLUTION: u32 = 16;

/// The helico-spiral of eqs 1–3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Helix {
    r0: f64,
    lambda: f64,
    cot_beta: f64,
    /// D / R (eq 3).
    size: f64,
    handedness: Handedness,
}

impl Helix {
    pub fn new(spec: &HelixSpec) -> Self {
        let beta = spec.beta.to_radians();
        Self {
            r0: spec.r0,
            lambda: spec.lambda,
            cot_beta: libm::cos(beta) / libm::sin(beta),
            size: (spec.lambda - 1.0) / ((spec.lambda + 1.0) * libm::sin(beta)),
            handedness: spec.handedness,
        }
    }

    /// R(θ), eq 1.
    pub fn radius(&self, theta: f64) -> f64 {
        self.r0 * libm::pow(self.lambda, theta / TAU)
    }

    /// H(θ), eq 2.
    pub fn height(&self, theta: f64) -> f64 {
        self.radius(theta) * self.cot_beta
    }

    /// D(θ), eq 3.
    pub fn size(&self, theta: f64) -> f64 {
        self.radius(theta) * self.size
    }

    /// The growth direction at θ: the w axis of the generating surface.
    pub fn growth_direction(&self, theta: f64) -> DVec3 {
        self.handedness
            .mirror(DVec3::new(-libm::sin(theta), libm::cos(theta), 0.0))
    }

    /// P(·, θ) of eq 8: scale by D(θ), then carry the generating surface's u (towards the
    /// axis), v (along the axis, towards the apex: −z) and w (along the growth) to the point
    /// (R(θ), H(θ)) of the half plane at angle θ about the axis.
    pub fn placement(&self, theta: f64) -> DAffine3 {
        let (s, c) = (libm::sin(theta), libm::cos(theta));
        let d = self.size(theta);
        let r = self.radius(theta);
        let u = self.handedness.mirror(DVec3::new(-c, -s, 0.0));
        let w = self.growth_direction(theta);
        DAffine3 {
            matrix3: DMat3::from_cols(u * d, DVec3::NEG_Z * d, w * d),
            translation: self
                .handedness
                .mirror(DVec3::new(r * c, r * s, self.height(theta))),
        }
    }
}

/// The BlobTree of a whole shell, with what growing it needs.
pub struct Whorl {
    pub tree: Node,
    /// Generating surfaces placed: one growth step each.
    pub instances: u32,
    /// The box of each instance's field, by growth step: where adding it changes the shell.
    pub reach: Vec<Bounds>,
    /// The direction the opening faces.
    pub front: DVec3,
    /// What stands on each varix, from the apex to the opening.
    pub varices: Vec<Varix>,
}

/// One varix as built: where it stands and its spines.
#[derive(Clone, Debug, PartialEq)]
pub struct Varix {
    /// The instance (growth step) it closes.
    pub instance: u32,
    /// Its spines, each where its angle meets the surface.
    pub spines: Vec<Standing>,
    /// Spines in the canal row below it.
    pub canal_spines: usize,
}

/// Checks what the numbers must satisfy for the tree to be built.
pub fn check(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let h = &spec.spiral;
    if h.lambda <= 1.0 || h.lambda.is_nan() {
        return Err(ShapeError::new(
            "form.spiral.lambda",
            format!("λ must exceed 1 (whorls grow), not {}", h.lambda),
        ));
    }
    if !(h.beta > 0.0 && h.beta < 90.0) {
        return Err(ShapeError::new(
            "form.spiral.beta",
            format!("β must lie strictly between 0° and 90°, not {}°", h.beta),
        ));
    }
    if h.r0 <= 0.0 || h.r0.is_nan() {
        return Err(ShapeError::new(
            "form.spiral.r0",
            format!("R₀ must be positive, not {}", h.r0),
        ));
    }
    if spec.whorls == 0 || spec.sections == 0 || spec.surfaces == 0 {
        return Err(ShapeError::new(
            "form.whorls",
            "whorls, sections and surfaces must each be at least 1",
        ));
    }
    let instances = u64::from(spec.whorls) * u64::from(spec.sections) * u64::from(spec.surfaces);
    if instances > MAX_INSTANCES {
        return Err(ShapeError::new(
            "form.surfaces",
            format!(
                "{} whorls × {} sections × {} surfaces make {instances} generating surfaces, more than the cap of {MAX_INSTANCES}",
                spec.whorls, spec.sections, spec.surfaces
            ),
        ));
    }
    if spec.whorl_angle <= 0.0 || spec.whorl_angle.is_nan() {
        return Err(ShapeError::new(
            "form.whorl_angle",
            format!(
                "the angle of a whorl must be positive, not {}°",
                spec.whorl_angle
            ),
        ));
    }
    if !(MIN_RESOLUTION..=MAX_RESOLUTION).contains(&spec.resolution) {
        return Err(ShapeError::new(
            "form.resolution",
            format!(
                "the resolution must lie from {MIN_RESOLUTION} to the cap of {MAX_RESOLUTION} voxels, not {}",
                spec.resolution
            ),
        ));
    }
    check_generator(&spec.generator, "form.generator")?;
    check_varices(spec)?;
    check_canal_spines(spec)?;
    let o = &spec.opening;
    if o.ahead > MAX_AHEAD {
        return Err(ShapeError::new(
            "form.opening.ahead",
            format!(
                "the hollow may reach at most {MAX_AHEAD} generating surfaces ahead, not {}",
                o.ahead
            ),
        ));
    }
    if parts(&o.inside) > 0 {
        check_generator(&o.inside, "form.opening.inside")?;
    }
    Ok(())
}

/// Most spines in the table of a varix's spines, and in the canal spines' table.
pub const MAX_SPINES: usize = 1024;
/// Most sets of bumps between two varices.
pub const MAX_BUMP_SETS: u32 = 16;
/// Most generating surfaces the hollow reaches ahead of the growing edge.
pub const MAX_AHEAD: u32 = 16;

fn parts(g: &GeneratorSpec) -> usize {
    g.points.len() + g.cones.len() + g.tori.len()
}

fn positive(key: &str, x: f64, what: &str) -> Result<(), ShapeError> {
    if x > 0.0 && x.is_finite() {
        Ok(())
    } else {
        Err(ShapeError::new(
            key,
            format!("{what} must be positive, not {x}"),
        ))
    }
}

fn check_varices(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let v = &spec.varices;
    if v.spines.len() > MAX_SPINES {
        return Err(ShapeError::new(
            "form.varices.spines",
            format!(
                "{} spines are more than the cap of {MAX_SPINES}",
                v.spines.len()
            ),
        ));
    }
    for &[whorl, angle, sigma] in &v.spines {
        if !(whorl >= 1.0 && whorl <= f64::from(spec.whorls) && whorl.fract() == 0.0) {
            return Err(ShapeError::new(
                "form.varices.spines",
                format!(
                    "a spine's whorl must be a whole number from 1 to {}, not {whorl}",
                    spec.whorls
                ),
            ));
        }
        if !(-180.0..=180.0).contains(&angle) {
            return Err(ShapeError::new(
                "form.varices.spines",
                format!("a spine's angle must lie from −180° to 180°, not {angle}°"),
            ));
        }
        if !(sigma > 0.0 && sigma <= 10.0) {
            return Err(ShapeError::new(
                "form.varices.spines",
                format!("a spine's relative size σ must lie in (0, 10], not {sigma}"),
            ));
        }
    }
    positive("form.varices.length", v.length, "the spines' length")?;
    positive("form.varices.radius", v.radius, "the spines' radius")?;
    positive("form.varices.tip", v.tip, "the spines' tip radius")?;
    positive("form.varices.bump_size", v.bump_size, "the bumps' size")?;
    if v.bend.is_nan() || v.bend.abs() > MAX_BEND_DEGREES {
        return Err(ShapeError::new(
            "form.varices.bend",
            format!(
                "a spine may curve by at most {MAX_BEND_DEGREES}°, not {}°",
                v.bend
            ),
        ));
    }
    if !(v.ridge >= 0.0 && v.ridge.is_finite()) {
        return Err(ShapeError::new(
            "form.varices.ridge",
            format!(
                "the ridge's radius must be 0 (none) or positive, not {}",
                v.ridge
            ),
        ));
    }
    if v.bump_sets > MAX_BUMP_SETS {
        return Err(ShapeError::new(
            "form.varices.bump_sets",
            format!(
                "at most {MAX_BUMP_SETS} sets of bumps fit between two varices, not {}",
                v.bump_sets
            ),
        ));
    }
    if !(0.0..=1.0).contains(&v.bump_spread) {
        return Err(ShapeError::new(
            "form.varices.bump_spread",
            format!(
                "the bumps' spread must lie from 0 to 1, not {}",
                v.bump_spread
            ),
        ));
    }
    Ok(())
}

fn check_canal_spines(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let c = &spec.canal_spines;
    if c.spines.len() > MAX_SPINES {
        return Err(ShapeError::new(
            "form.canal_spines.spines",
            format!(
                "{} canal spines are more than the cap of {MAX_SPINES}",
                c.spines.len()
            ),
        ));
    }
    for &[varix, sigma] in &c.spines {
        if ![1.0, 2.0, 3.0].contains(&varix) {
            return Err(ShapeError::new(
                "form.canal_spines.spines",
                format!(
                    "a canal spine stands below varix 1, 2 or 3 (the last three, 3 at the opening), not {varix}"
                ),
            ));
        }
        if !(sigma > 0.0 && sigma <= 10.0) {
            return Err(ShapeError::new(
                "form.canal_spines.spines",
                format!("a canal spine's relative size σ must lie in (0, 10], not {sigma}"),
            ));
        }
    }
    if !c.spines.is_empty() && spec.generator.cones.is_empty() {
        return Err(ShapeError::new(
            "form.canal_spines.spines",
            "canal spines stand on the canal: the generating surface needs a cone for it",
        ));
    }
    if !c.spines.is_empty() && spec.varices.spines.is_empty() {
        return Err(ShapeError::new(
            "form.canal_spines.spines",
            "canal spines stand below varices: give the varices spines",
        ));
    }
    positive(
        "form.canal_spines.length",
        c.length,
        "the canal spines' length",
    )?;
    positive(
        "form.canal_spines.radius",
        c.radius,
        "the canal spines' radius",
    )
}

/// Checks the generating surface `g`, whose keys start with `prefix`.
fn check_generator(g: &GeneratorSpec, prefix: &str) -> Result<(), ShapeError> {
    let parts = parts(g);
    let key = |k: &str| format!("{prefix}.{k}");
    if parts == 0 {
        return Err(ShapeError::new(
            key("points"),
            "the generating surface needs at least one primitive",
        ));
    }
    for p in &g.points {
        positive(&key("points"), p[3], "a point's radius")?;
    }
    for c in &g.cones {
        positive(&key("cones"), c[6], "a cone's radius")?;
        positive(&key("cones"), c[7], "a cone's radius")?;
        let length = DVec3::new(c[3] - c[0], c[4] - c[1], c[5] - c[2]).length();
        positive(&key("cones"), length, "a cone's length")?;
        if c[8].abs() > MAX_BEND_DEGREES {
            return Err(ShapeError::new(
                key("cones"),
                format!(
                    "a cone may bend by at most {MAX_BEND_DEGREES}°, not {}°",
                    c[8]
                ),
            ));
        }
        if support_of(c[6].max(c[7])) * c[8].abs().to_radians() >= length {
            return Err(ShapeError::new(
                key("cones"),
                format!(
                    "a cone of length {length} bent by {}° is too thick for its bend: its field would fold over the centre of curvature",
                    c[8]
                ),
            ));
        }
    }
    for t in &g.tori {
        positive(&key("tori"), t[3], "a torus's major radius")?;
        positive(&key("tori"), t[4], "a torus's radius")?;
    }
    if !(g.exponent >= 1.0 && g.exponent <= 400.0) {
        return Err(ShapeError::new(
            key("exponent"),
            format!(
                "the blending exponent n must lie from 1 to 400, not {}",
                g.exponent
            ),
        ));
    }
    if let Some([i, k]) = g
        .pairs
        .iter()
        .find(|[i, k]| i == k || *i as usize >= parts || *k as usize >= parts)
    {
        return Err(ShapeError::new(
            key("pairs"),
            format!(
                "the pair ({i}, {k}) must name two different parts of the {parts} the generating surface has (numbered from 0: points, then cones, then tori)"
            ),
        ));
    }
    Ok(())
}

/// The generating surface's BlobTree, its parts carrying growth time `time`; `whorl` is the
/// whorl (from 0 at the apex) it is placed in, for parts present only from a later whorl.
fn generating_surface(g: &GeneratorSpec, time: f64, whorl: f64) -> Option<Node> {
    let around = Texture::around(time);
    let mut parts: Vec<Option<Node>> = Vec::new();
    for p in &g.points {
        parts.push(Some(Node::leaf(
            Primitive::Point {
                centre: DVec3::new(p[0], p[1], p[2]),
                radius: support_of(p[3]),
            },
            around,
        )));
    }
    for c in &g.cones {
        let (from, to) = (DVec3::new(c[0], c[1], c[2]), DVec3::new(c[3], c[4], c[5]));
        parts.push((whorl >= c[9]).then(|| bent_cone(from, to, [c[6], c[7]], c[8], time)));
    }
    for t in &g.tori {
        parts.push(Some(Node::leaf(
            Primitive::Torus {
                centre: DVec3::new(t[0], t[1], t[2]),
                axis: DVec3::Z,
                major: t[3],
                radius: support_of(t[4]),
            },
            around,
        )));
    }
    combine(parts, g.exponent, &g.pairs)
}

/// Parts combined by eq 4 with exponent `n`, or by controlled blending of `pairs` (eq 6);
/// parts that are `None` (not yet grown) drop out with their pairs.
fn combine(parts: Vec<Option<Node>>, n: f64, pairs: &[[u32; 2]]) -> Option<Node> {
    let mut index = vec![usize::MAX; parts.len()];
    let mut kept = Vec::new();
    for (i, part) in parts.into_iter().enumerate() {
        if let Some(part) = part {
            index[i] = kept.len();
            kept.push(part);
        }
    }
    if kept.len() <= 1 {
        return kept.pop();
    }
    Some(if pairs.is_empty() {
        if n == 1.0 {
            Node::blend(kept)
        } else {
            Node::superelliptic(n, kept)
        }
    } else {
        let pairs = pairs
            .iter()
            .map(|&[i, k]| [index[i as usize], index[k as usize]])
            .filter(|p| p.iter().all(|&i| i != usize::MAX))
            .collect();
        Node::controlled(kept, pairs)
    })
}

/// The frame of a generator cone from `from` to `to`, with its length: x along the cone, z
/// as close to the generating surface's w as x allows (the bend turns x towards y, about z).
pub fn cone_frame(from: DVec3, to: DVec3) -> (DAffine3, f64) {
    let length = from.distance(to);
    let x = (to - from) / length;
    let z = (DVec3::Z - x * x.z).try_normalize().unwrap_or(DVec3::X);
    let y = z.cross(x);
    let frame = DAffine3 {
        matrix3: DMat3::from_cols(x, y, z),
        translation: from,
    };
    (frame, length)
}

/// A tapered segment from `from` to `to`, bent by `bend` degrees about the generating
/// surface's w axis; its pattern position is the angle, about w, of each point as it lies
/// before the bend.
fn bent_cone(from: DVec3, to: DVec3, radii: [f64; 2], bend: f64, time: f64) -> Node {
    let (frame, length) = cone_frame(from, to);
    let cone = Node::leaf(
        Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * length,
            radii: radii.map(support_of),
        },
        Texture::around(time).moved(frame),
    );
    let bend = Bend::new(bend.to_radians(), length);
    Node::transform(frame, Node::warp(bend, cone))
}

/// The instances of the generating surface along the helico-spiral: one per growth step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instances {
    pub helix: Helix,
    /// Radians between consecutive instances.
    step: f64,
    /// Instances per whorl.
    per_whorl: u32,
    /// Pattern rows between consecutive instances.
    time_step: f64,
    /// Instances in the whole shell.
    pub count: u32,
}

impl Instances {
    pub fn new(spec: &ImplicitSpec, rows: usize) -> Self {
        let per_whorl = spec.sections * spec.surfaces;
        let count = spec.whorls * per_whorl;
        Self {
            helix: Helix::new(&spec.spiral),
            step: spec.whorl_angle.to_radians() / f64::from(per_whorl),
            per_whorl,
            time_step: (rows.max(2) - 1) as f64 / f64::from((count - 1).max(1)),
            count,
        }
    }

    /// P(·, θ) of eq 8 for instance `k`, fractions allowed.
    pub fn placement(&self, k: f64) -> DAffine3 {
        self.helix.placement(k * self.step)
    }

    /// D(θ) at instance `k`.
    pub fn size(&self, k: f64) -> f64 {
        self.helix.size(k * self.step)
    }

    /// The whorl instance `k` lies in, counted from 0 at the apex, with its fraction.
    pub fn whorl(&self, k: f64) -> f64 {
        k / f64::from(self.per_whorl)
    }

    /// The pattern row instance `k` grows on.
    pub fn time(&self, k: f64) -> f64 {
        k * self.time_step
    }
}

/// A BlobTree being gathered, with the box of what each growth step adds.
struct Gathered {
    reach: Vec<Bounds>,
}

impl Gathered {
    /// `node`, placed at instance `at` and born at growth step `birth`.
    fn placed(&mut self, at: DAffine3, node: Node, birth: u32) -> Node {
        let node = Node::transform(at, node).born_at(birth);
        if let Some(b) = self.reach.get_mut(birth as usize) {
            *b = b.union(&node.bounds);
        }
        node
    }
}

/// The generating surface `g` placed at the instances `scaled` gives (k, with the factor the
/// generating surface is scaled by about its centre) and blended into sections of `surfaces`
/// instances (eq 9), instance k joining section k / `surfaces` and born at growth step
/// k − `ahead` (or 0). Empty sections are left out.
fn sections(
    g: &GeneratorSpec,
    instances: &Instances,
    scaled: impl Iterator<Item = (u32, f64)>,
    surfaces: u32,
    ahead: u32,
    gathered: &mut Gathered,
) -> Vec<(u32, Node)> {
    let mut out: Vec<(u32, Vec<Node>)> = Vec::new();
    for (k, scale) in scaled {
        let kf = f64::from(k);
        // The hollow ahead of the edge shows the edge's pattern on its inside.
        let time = instances.time(kf.min(f64::from(instances.count - 1)));
        let Some(surface) = generating_surface(g, time, instances.whorl(kf)) else {
            continue;
        };
        let at = instances.placement(kf) * DAffine3::from_scale(DVec3::splat(scale));
        let placed = gathered.placed(at, surface, k.saturating_sub(ahead));
        let section = k / surfaces;
        match out.last_mut() {
            Some((s, members)) if *s == section => members.push(placed),
            _ => out.push((section, vec![placed])),
        }
    }
    out.into_iter()
        .map(|(s, members)| (s, Node::blend(members)))
        .collect()
}

/// Sections combined as the spec's blending says, with parts each paired with the sections
/// it names (eq 10: a part blends only with those).
fn joined(blending: Blending, sections: Vec<Node>, parts: Vec<(Node, Vec<usize>)>) -> Node {
    match blending {
        Blending::All => Node::blend(
            sections
                .into_iter()
                .chain(parts.into_iter().map(|p| p.0))
                .collect(),
        ),
        Blending::Neighbours => {
            let n = sections.len();
            let mut pairs: Vec<[usize; 2]> = (1..n).map(|i| [i - 1, i]).collect();
            let mut children = sections;
            for (part, with) in parts {
                let index = children.len();
                pairs.extend(with.into_iter().filter(|&s| s < n).map(|s| [s, index]));
                children.push(part);
            }
            Node::controlled(children, pairs)
        }
    }
}

/// Voxels a spine, a ridge or a canal spine is at least thick (as a radius), so that the
/// polygonizer shows it joined to the shell; bumps thinner than that are left out.
pub const THINNEST_VOXELS: f64 = 1.0;

/// The shell of `spec` as one BlobTree (eqs 9–15), instance k carrying growth time
/// k·(rows − 1)/(K − 1). Spines placed by the pattern read the pigment of `pattern` (seeded
/// by `seed`) on the row each varix forms on; bumps and canal spines take their random
/// sizes and bends from `seed`.
pub fn whorl(
    spec: &ImplicitSpec,
    pattern: &PatternSpec,
    seed: u64,
    rows: usize,
) -> Result<Whorl, ShapeError> {
    check(spec)?;
    let instances = Instances::new(spec, rows);
    let count = instances.count;
    let mut gathered = Gathered {
        reach: vec![Bounds::EMPTY; count as usize],
    };
    let mut sections = sections(
        &spec.generator,
        &instances,
        (0..count).map(|k| (k, 1.0)),
        spec.surfaces,
        0,
        &mut gathered,
    );
    let body = joined(
        spec.blending,
        sections.iter().map(|s| s.1.clone()).collect(),
        Vec::new(),
    );
    let v = &spec.varices;
    let sigma_max = v.spines.iter().map(|s| s[2]).fold(0.0, f64::max);
    // The voxel the grown shell will be polygonized with: its extent, with the longest spine.
    let last = f64::from(count - 1);
    let reach = (v.length * sigma_max).max(spec.canal_spines.length) * instances.size(last);
    let voxel = (body.bounds.max - body.bounds.min + 2.0 * reach).max_element()
        / f64::from(spec.resolution);
    let thinnest = |k: f64| THINNEST_VOXELS * voxel / instances.size(k);
    // A varix closes every section (at its last instance), when the spec has spines.
    let varix_rows: Vec<u32> = if v.spines.is_empty() {
        Vec::new()
    } else {
        (1..=spec.whorls * spec.sections)
            .map(|i| i * spec.surfaces - 1)
            .collect()
    };
    let pigment = match v.placement {
        Placement::Pattern if !v.spines.is_empty() => pigment_at(
            pattern,
            seed,
            &varix_rows
                .iter()
                .map(|&k| instances.time(f64::from(k)).round() as usize)
                .collect::<Vec<_>>(),
        )?,
        _ => Vec::new(),
    };
    let mut parts = Vec::new();
    let mut varices = Vec::new();
    let mut bump_noise = Noise::new(seed, BUMP_STREAM);
    let mut canal_noise = Noise::new(seed, CANAL_STREAM);
    let section_of = |k: u32| sections.iter().position(|s| s.0 == k / spec.surfaces);
    let mut extra: Vec<Vec<Node>> = vec![Vec::new(); sections.len()];
    for (i, &k) in varix_rows.iter().enumerate() {
        let kf = f64::from(k);
        let whorl_number = k / (spec.sections * spec.surfaces) + 1;
        let spines = match v.placement {
            Placement::Table => table_spines(&v.spines, whorl_number),
            Placement::Pattern => pattern_spines(&v.spines, whorl_number, &pigment[i]),
        };
        let at = instances.placement(kf);
        let on_surface = standing(&body, &at, &spines);
        let time = instances.time(kf);
        let mut members: Vec<Node> = varix(v, &on_surface, sigma_max, thinnest(kf), time)
            .into_iter()
            .collect();
        let from_opening = varix_rows.len() - i;
        let mut canal = Vec::new();
        if from_opening <= CANAL_VARICES {
            let varix_number = (CANAL_VARICES + 1 - from_opening) as f64;
            let sizes: Vec<f64> = spec
                .canal_spines
                .spines
                .iter()
                .filter(|s| s[0].round() == varix_number)
                .map(|s| s[1])
                .collect();
            if let Some(cone) = spec
                .generator
                .cones
                .iter()
                .find(|c| instances.whorl(kf) >= c[9])
            {
                canal = canal_row(
                    cone,
                    &sizes,
                    [spec.canal_spines.length, spec.canal_spines.radius],
                    thinnest(kf),
                    time,
                    &mut canal_noise,
                );
            }
        }
        let canal_spines = canal.len();
        members.extend(canal);
        varices.push(Varix {
            instance: k,
            canal_spines,
            spines: on_surface,
        });
        if !members.is_empty() {
            let part = gathered.placed(at, Node::blend(members), k);
            let with = [section_of(k), section_of(k + 1)]
                .into_iter()
                .flatten()
                .collect();
            parts.push((part, with));
        }
        // The bumps of the section this varix closes, in sets between it and the one before.
        let Some(section) = section_of(k) else {
            continue;
        };
        for j in 1..=v.bump_sets {
            let kb =
                kf - f64::from(spec.surfaces) * (1.0 - f64::from(j) / f64::from(v.bump_sets + 1));
            if kb < 0.0 {
                continue;
            }
            let at = instances.placement(kb);
            let bumps = bump_set(
                &standing(&body, &at, &spines),
                v.bump_size,
                v.bump_spread,
                thinnest(kb),
                instances.time(kb),
                &mut bump_noise,
            );
            for bump in bumps {
                extra[section].push(gathered.placed(at, bump, kb.round() as u32));
            }
        }
    }
    for ((_, node), bumps) in sections.iter_mut().zip(extra) {
        if !bumps.is_empty() {
            let whorl = std::mem::replace(node, Node::blend(Vec::new()));
            *node =
                Node::superelliptic(BUMP_EXPONENT, std::iter::once(whorl).chain(bumps).collect());
        }
    }
    let shell = joined(
        spec.blending,
        sections.into_iter().map(|s| s.1).collect(),
        parts,
    );
    let tree = match inside(spec, &instances, voxel, &mut gathered) {
        Some(inside) => Node::difference(shell, inside),
        None => shell,
    };
    Ok(Whorl {
        tree,
        instances: count,
        reach: gathered.reach,
        front: instances.helix.growth_direction(last * instances.step),
        varices,
    })
}

/// Voxels the wall is at least thick where the shell is hollow.
pub const WALL_VOXELS: f64 = 2.5;
/// The smallest the hollow's generating surface is shrunk to for the wall to keep
/// [`WALL_VOXELS`]; closer to the apex, where it would have to shrink further or where the
/// shrunk instances no longer join into one tube, the shell is solid.
const SMALLEST_HOLLOW: f64 = 0.3;

/// The hollow inside of eq 14: the inside generating surface placed like the shell's, up to
/// `ahead` instances beyond the growing edge, each born `ahead` growth steps early, so that
/// the aperture is open at every stage. Where the wall it leaves would be thinner than
/// [`WALL_VOXELS`] at the spec's resolution, it is shrunk about its centre until the wall is
/// that thick, as spines are thickened, so that a coarse grid shows a whole wall, not a
/// perforated one. The paper subtracts the previous whorl from this inside whorl so that the
/// cut leaves it intact, and adds an inside wall back (eq 15) because its opening is not
/// round. Our inside surface is concentric with the body's and smaller, so it never reaches
/// the previous whorl and its aperture is already round: neither step is needed.
fn inside(
    spec: &ImplicitSpec,
    instances: &Instances,
    voxel: f64,
    gathered: &mut Gathered,
) -> Option<Node> {
    let o = &spec.opening;
    let hollow = generating_surface(&o.inside, 0.0, f64::INFINITY)?;
    let solid = generating_surface(&spec.generator, 0.0, f64::INFINITY)?;
    // (outer, hollow) extents in units of D, in eight directions of the generating curve.
    let extents: Vec<[f64; 2]> = (0..8)
        .filter_map(|i| {
            let d = outward(45.0 * f64::from(i));
            let at = DAffine3::IDENTITY;
            Some([
                edge_distance(&solid, &at, d)?,
                edge_distance(&hollow, &at, d)?,
            ])
        })
        .collect();
    let scale = |k: u32| {
        let wall = WALL_VOXELS * voxel / instances.size(f64::from(k));
        extents
            .iter()
            .map(|[outer, hollow]| (outer - wall) / hollow)
            .fold(1.0, f64::min)
    };
    // The hollow starts where consecutive instances join into one tube: where the fields of
    // two neighbours sum past the iso-value halfway between their centres.
    let placed = |k: u32| {
        let at = instances.placement(f64::from(k)) * DAffine3::from_scale(DVec3::splat(scale(k)));
        (at, Node::transform(at, hollow.clone()))
    };
    let joins = |k: u32| {
        let ((a, na), (b, nb)) = (placed(k), placed(k + 1));
        let middle = (a.translation + b.translation) * 0.5;
        na.field(middle) + nb.field(middle) >= ISO
    };
    let end = instances.count + o.ahead;
    let first = (0..end).find(|&k| scale(k) >= SMALLEST_HOLLOW && joins(k))?;
    let parts = sections(
        &o.inside,
        instances,
        (first..end).map(|k| (k, scale(k))),
        spec.surfaces,
        o.ahead,
        gathered,
    );
    (!parts.is_empty()).then(|| {
        joined(
            spec.blending,
            parts.into_iter().map(|s| s.1).collect(),
            Vec::new(),
        )
    })
}
