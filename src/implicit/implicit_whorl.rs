//! A shell whorl as a BlobTree (Galbraith, Prusinkiewicz & Wyvill §2.1 and §3.1): the generating
//! surface is placed along the helico-spiral by P(B, θ) (eq 8), its instances blend into
//! sections (eq 9), and the sections combine by blending or by controlled blending with their
//! neighbours only (eq 10). Each instance is one growth step.
//!
//! The paper's equations 1–3, as we read them: R(θ) = R₀ λ^(θ/2π); H(θ) = R(θ) cot β; and, for
//! circles of consecutive whorls that touch, D(θ) = R(θ)(λ − 1) / ((λ + 1) sin β), which gives
//! the paper's D = 0.341 R for β = 22.5°, λ = 1.3. The paper's y axis is our z: as for all our
//! shells, the apex points towards −z and growth goes towards +z (the display turns it apex up).

use super::bend::{Bend, MAX_BEND_DEGREES};
use super::blob_tree::Node;
use super::falloff::support_of;
use super::primitive::Primitive;
use super::texture_blend::Texture;
use crate::growing_shape::GeometryError;
use crate::mesh::Bounds;
use crate::spec::form::Handedness;
use crate::spec::implicit::{Blending, GeneratorSpec, HelixSpec, ImplicitSpec};
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
    /// +1 dextral, −1 sinistral (the y axis mirrored).
    mirror: f64,
}

impl Helix {
    pub fn new(spec: &HelixSpec) -> Self {
        let beta = spec.beta.to_radians();
        Self {
            r0: spec.r0,
            lambda: spec.lambda,
            cot_beta: libm::cos(beta) / libm::sin(beta),
            size: (spec.lambda - 1.0) / ((spec.lambda + 1.0) * libm::sin(beta)),
            mirror: match spec.handedness {
                Handedness::Dextral => 1.0,
                Handedness::Sinistral => -1.0,
            },
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
        DVec3::new(-libm::sin(theta), libm::cos(theta) * self.mirror, 0.0)
    }

    /// P(·, θ) of eq 8: scale by D(θ), then carry the generating surface's u (towards the
    /// axis), v (along the axis, towards the apex: −z) and w (along the growth) to the point
    /// (R(θ), H(θ)) of the half plane at angle θ about the axis.
    pub fn placement(&self, theta: f64) -> DAffine3 {
        let (s, c) = (libm::sin(theta), libm::cos(theta));
        let d = self.size(theta);
        let r = self.radius(theta);
        let u = DVec3::new(-c, -s * self.mirror, 0.0);
        let w = self.growth_direction(theta);
        DAffine3 {
            matrix3: DMat3::from_cols(u * d, DVec3::NEG_Z * d, w * d),
            translation: DVec3::new(r * c, r * s * self.mirror, self.height(theta)),
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
}

fn problem(key: &str, message: String) -> GeometryError {
    GeometryError(format!("{key}: {message}"))
}

/// Checks what the numbers must satisfy for the tree to be built.
pub fn check(spec: &ImplicitSpec) -> Result<(), GeometryError> {
    let h = &spec.spiral;
    if h.lambda <= 1.0 || h.lambda.is_nan() {
        return Err(problem(
            "form.spiral.lambda",
            format!("λ must exceed 1 (whorls grow), not {}", h.lambda),
        ));
    }
    if !(h.beta > 0.0 && h.beta < 90.0) {
        return Err(problem(
            "form.spiral.beta",
            format!("β must lie strictly between 0° and 90°, not {}°", h.beta),
        ));
    }
    if h.r0 <= 0.0 || h.r0.is_nan() {
        return Err(problem(
            "form.spiral.r0",
            format!("R₀ must be positive, not {}", h.r0),
        ));
    }
    if spec.whorls == 0 || spec.sections == 0 || spec.surfaces == 0 {
        return Err(problem(
            "form.whorls",
            "whorls, sections and surfaces must each be at least 1".into(),
        ));
    }
    let instances = u64::from(spec.whorls) * u64::from(spec.sections) * u64::from(spec.surfaces);
    if instances > MAX_INSTANCES {
        return Err(problem(
            "form.surfaces",
            format!(
                "{} whorls × {} sections × {} surfaces make {instances} generating surfaces, more than the cap of {MAX_INSTANCES}",
                spec.whorls, spec.sections, spec.surfaces
            ),
        ));
    }
    if spec.whorl_angle <= 0.0 || spec.whorl_angle.is_nan() {
        return Err(problem(
            "form.whorl_angle",
            format!(
                "the angle of a whorl must be positive, not {}°",
                spec.whorl_angle
            ),
        ));
    }
    if !(MIN_RESOLUTION..=MAX_RESOLUTION).contains(&spec.resolution) {
        return Err(problem(
            "form.resolution",
            format!(
                "the resolution must lie from {MIN_RESOLUTION} to the cap of {MAX_RESOLUTION} voxels, not {}",
                spec.resolution
            ),
        ));
    }
    check_generator(&spec.generator)
}

fn check_generator(g: &GeneratorSpec) -> Result<(), GeometryError> {
    let parts = g.points.len() + g.cones.len() + g.tori.len();
    if parts == 0 {
        return Err(problem(
            "form.generator.points",
            "the generating surface needs at least one primitive".into(),
        ));
    }
    let positive = |key: &str, x: f64, what: &str| {
        if x > 0.0 && x.is_finite() {
            Ok(())
        } else {
            Err(problem(key, format!("{what} must be positive, not {x}")))
        }
    };
    for p in &g.points {
        positive("form.generator.points", p[3], "a point's radius")?;
    }
    for c in &g.cones {
        positive("form.generator.cones", c[6], "a cone's radius")?;
        positive("form.generator.cones", c[7], "a cone's radius")?;
        let length = DVec3::new(c[3] - c[0], c[4] - c[1], c[5] - c[2]).length();
        positive("form.generator.cones", length, "a cone's length")?;
        if c[8].abs() > MAX_BEND_DEGREES {
            return Err(problem(
                "form.generator.cones",
                format!(
                    "a cone may bend by at most {MAX_BEND_DEGREES}°, not {}°",
                    c[8]
                ),
            ));
        }
        if support_of(c[6].max(c[7])) * c[8].abs().to_radians() >= length {
            return Err(problem(
                "form.generator.cones",
                format!(
                    "a cone of length {length} bent by {}° is too thick for its bend: its field would fold over the centre of curvature",
                    c[8]
                ),
            ));
        }
    }
    for t in &g.tori {
        positive("form.generator.tori", t[3], "a torus's major radius")?;
        positive("form.generator.tori", t[4], "a torus's radius")?;
    }
    if !(g.exponent >= 1.0 && g.exponent <= 400.0) {
        return Err(problem(
            "form.generator.exponent",
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
        return Err(problem(
            "form.generator.pairs",
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

/// A tapered segment from `from` to `to`, bent by `bend` degrees about the generating
/// surface's w axis; its pattern position is the angle, about w, of each point as it lies
/// before the bend.
fn bent_cone(from: DVec3, to: DVec3, radii: [f64; 2], bend: f64, time: f64) -> Node {
    let length = from.distance(to);
    let x = (to - from) / length;
    let z = (DVec3::Z - x * x.z).try_normalize().unwrap_or(DVec3::X);
    let y = z.cross(x);
    let frame = DAffine3 {
        matrix3: DMat3::from_cols(x, y, z),
        translation: from,
    };
    let cone = Node::leaf(
        Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * length,
            radii: radii.map(support_of),
        },
        Texture::around(time).moved(frame),
    );
    let bend = Bend {
        angle: bend.to_radians(),
        length,
    };
    Node::transform(frame, Node::warp(bend, cone))
}

/// The shell of `spec` as one BlobTree, instance k carrying growth time k·(rows − 1)/(K − 1).
pub fn whorl(spec: &ImplicitSpec, rows: usize) -> Result<Whorl, GeometryError> {
    check(spec)?;
    let helix = Helix::new(&spec.spiral);
    let per_whorl = spec.sections * spec.surfaces;
    let instances = spec.whorls * per_whorl;
    let step = spec.whorl_angle.to_radians() / f64::from(per_whorl);
    let time_step = (rows.max(2) - 1) as f64 / f64::from((instances - 1).max(1));
    let mut sections = Vec::new();
    let mut reach = Vec::new();
    for section in 0..spec.whorls * spec.sections {
        let members: Vec<Node> = (0..spec.surfaces)
            .filter_map(|j| {
                let k = section * spec.surfaces + j;
                let theta = f64::from(k) * step;
                let whorl = f64::from(k) / f64::from(per_whorl);
                let surface = generating_surface(&spec.generator, f64::from(k) * time_step, whorl);
                let placed = surface.map(|s| Node::transform(helix.placement(theta), s).born_at(k));
                reach.push(placed.as_ref().map_or(Bounds::EMPTY, |n| n.bounds));
                placed
            })
            .collect();
        sections.push(Node::blend(members));
    }
    let tree = match spec.blending {
        Blending::All => Node::blend(sections),
        Blending::Neighbours => {
            let pairs = (1..sections.len()).map(|i| [i - 1, i]).collect();
            Node::controlled(sections, pairs)
        }
    };
    let end = f64::from(instances - 1) * step;
    Ok(Whorl {
        tree,
        instances,
        reach,
        front: helix.growth_direction(end),
    })
}
