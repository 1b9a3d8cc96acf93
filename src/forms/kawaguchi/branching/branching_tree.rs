//! Kawaguchi's growth by branching (1982, "Rules of generating model", rules 1–8): the whole
//! form as a list of segments, each a trunk and the knot after it, in the order growth adds
//! them (generation by generation).
//!
//! - Rule 1: a trunk of diameter D has height H = S·D, S the same for every trunk.
//! - Rule 2: a trunk's bases are parallel (a straight prism).
//! - Rules 3–5: consecutive trunks are joined by a knot whose bases are inclined by α and touch
//!   at one point K on the rim: the next trunk's bottom base is the trunk's top base turned by α
//!   about the tangent at K and scaled about K by the taper r. The side that turns is chosen by
//!   a roll about the axis that advances by the twist at every knot; α follows the tendril's
//!   self-adjustment law ([`Tendril`]).
//! - Rule 6: branches start only at knots, spread evenly around the trunk, leaning out from it
//!   by the branch angle.
//! - Rule 7: a branch's diameter is a multiple of its knot's height, the distance across the
//!   knot on the side opposite K.
//! - Rule 8: a branch stops when its next trunk would be lower than a fixed fraction of the
//!   first trunk's height (the "pixel" of the whole form).
//!
//! Shell space as for every form: the first trunk stands at the origin and grows towards −z,
//! which the display shows as up.

use super::tendril::Tendril;
use crate::pattern::noise::Noise;
use crate::shape::ShapeError;
use crate::spec::form::branching::{BranchingSpec, KnotSpec, Stand};
use glam::{DMat3, DQuat, DVec3};
use std::collections::VecDeque;
use std::f64::consts::TAU;

/// Most segments (trunk and knot) a form may have.
pub const MAX_SEGMENTS: usize = 12_000;
/// Most branches one knot may bear.
const MAX_COUNT: f64 = 24.0;
/// The purpose of the seed's random stream here (apart from the pattern's).
const JITTER_STREAM: u64 = 0x6b6e_6f74;

/// A base of a trunk: a circle (an N-gon) of a diameter, centred in a plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Base {
    pub centre: DVec3,
    /// Columns e₁, e₂ (in the plane of the base) and e₃ (the trunk's axis), orthonormal.
    pub axes: DMat3,
    pub diameter: f64,
}

impl Base {
    /// The N apexes, counter-clockwise about e₃, the first along e₁.
    pub fn ring(&self, sides: usize) -> Vec<DVec3> {
        (0..sides)
            .map(|j| self.centre + self.radial(TAU * j as f64 / sides as f64) * self.diameter / 2.0)
            .collect()
    }

    /// The unit direction at angle φ in the base's plane.
    pub fn radial(&self, phi: f64) -> DVec3 {
        self.axes.x_axis * phi.cos() + self.axes.y_axis * phi.sin()
    }

    pub fn axis(&self) -> DVec3 {
        self.axes.z_axis
    }

    /// The parallel base at `height` along the axis (rule 2).
    pub fn lifted(&self, height: f64) -> Base {
        Base {
            centre: self.centre + self.axis() * height,
            ..*self
        }
    }
}

/// One trunk and the knot after it.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// The trunk's bottom base.
    pub base: Base,
    /// H = S·D.
    pub height: f64,
    /// The next trunk's bottom base across the knot; none where the branch ends.
    pub next: Option<Base>,
    /// Trunks from the first trunk of the form to this one, counting along branches.
    pub generation: usize,
    /// 0 on the main trunk, 1 on its branches, and so on.
    pub depth: usize,
    /// For a branch's first trunk: the segment whose knot it grows from, and how many
    /// branching knots came before that one on its branch (the series index).
    pub parent: Option<(usize, u32)>,
    /// The segment before this one along the same branch (whose knot leads to this trunk);
    /// none for a branch's first trunk and the first trunk of the form.
    pub previous: Option<usize>,
    /// The index of this trunk along its branch.
    pub index: u32,
    /// The knot's height: across the knot on the side opposite K, where it is widest (rule 7);
    /// zero where the branch ends.
    pub knot_height: f64,
}

/// A growing branch, waiting for its next trunk.
struct Tip {
    base: Base,
    tendril: Tendril,
    index: u32,
    branchings: u32,
    roll: f64,
    generation: usize,
    depth: usize,
    parent: Option<(usize, u32)>,
    previous: Option<usize>,
}

/// Every segment of a branching form, in growth order.
pub struct BranchingTree {
    pub segments: Vec<Segment>,
    /// The unit direction, in each segment's top base, of the side its knot turns towards.
    pub rolls: Vec<DVec3>,
}

/// The rotation of `v` by `degrees` about the unit `axis`.
fn turned(v: DVec3, axis: DVec3, degrees: f64) -> DVec3 {
    DQuat::from_axis_angle(axis, degrees.to_radians()) * v
}

impl BranchingTree {
    pub fn new(spec: &BranchingSpec, seed: u64) -> Result<Self, ShapeError> {
        check(spec)?;
        let mut noise = Noise::new(seed, JITTER_STREAM);
        let mut jitter = move || spec.jitter * noise.signed();
        let s = spec.trunk.slenderness;
        let threshold = spec.pixel();
        let root = Base {
            centre: DVec3::ZERO,
            axes: first_axes(spec),
            diameter: spec.trunk.diameter,
        };
        let mut queue = VecDeque::from([Tip {
            base: root,
            tendril: Tendril::start(&spec.knot),
            index: 0,
            branchings: 0,
            roll: 0.0,
            generation: 0,
            depth: 0,
            parent: None,
            previous: None,
        }]);
        let mut tree = Self {
            segments: Vec::new(),
            rolls: Vec::new(),
        };
        while let Some(tip) = queue.pop_front() {
            if tree.segments.len() >= MAX_SEGMENTS {
                return Err(ShapeError::new(
                    "form.knots",
                    format!(
                        "the form would have more than the cap of {MAX_SEGMENTS} trunks; lower the knots per branch, the depth, the branch count or the picture's pixels"
                    ),
                ));
            }
            let base = tip.base;
            let height = s * base.diameter;
            let top = base.lifted(height);
            let roll_angle = tip.roll + spec.knot.twist + jitter();
            let alpha = tip.tendril.alpha;
            let side = top.radial(roll_angle.to_radians()) * alpha.signum();
            let hinge = top.centre + side * top.diameter / 2.0;
            let rotation = DQuat::from_axis_angle(
                top.axis().cross(side).normalize(),
                alpha.abs().to_radians(),
            );
            let next = Base {
                centre: hinge + rotation * (top.centre - hinge) * spec.trunk.taper,
                axes: DMat3::from_quat(rotation) * top.axes,
                diameter: top.diameter * spec.trunk.taper,
            };
            let far = top.centre - side * top.diameter / 2.0;
            let across = hinge + rotation * (far - hinge) * spec.trunk.taper;
            let grows_on = tip.index + 1 < spec.knots && s * next.diameter >= threshold;
            let (tendril, turn) = tip.tendril.next(&spec.knot);
            let k = tree.segments.len();
            tree.segments.push(Segment {
                base,
                height,
                next: grows_on.then_some(next),
                generation: tip.generation,
                depth: tip.depth,
                parent: tip.parent,
                previous: tip.previous,
                index: tip.index,
                knot_height: if grows_on {
                    (across - far).length()
                } else {
                    0.0
                },
            });
            tree.rolls.push(side);
            if !grows_on {
                continue;
            }
            queue.push_back(Tip {
                base: next,
                tendril,
                index: tip.index + 1,
                branchings: tip.branchings,
                roll: roll_angle,
                generation: tip.generation + 1,
                depth: tip.depth,
                parent: None,
                previous: Some(k),
            });
            let b = &spec.branches;
            let branching = if b.every > 0 {
                (tip.index + 1) % b.every == 0
            } else {
                turn
            };
            if !branching || tip.depth as u32 >= spec.depth {
                continue;
            }
            let series = f64::from(tip.branchings);
            let diameter = b.scale * b.scale_growth.powf(series) * tree.segments[k].knot_height;
            if let Some(last) = queue.back_mut() {
                last.branchings += 1;
            }
            if s * diameter < threshold {
                continue;
            }
            let count = (f64::from(b.count) + b.count_step * series)
                .round()
                .clamp(1.0, MAX_COUNT) as u32;
            let middle = (top.centre + next.centre) / 2.0;
            let along = (top.axis() + next.axis()).normalize();
            let reach = branch_reach(top.diameter * (1.0 + spec.trunk.taper) / 4.0, diameter);
            for m in 0..count {
                let out = turned(-side, top.axis(), 360.0 * f64::from(m) / f64::from(count));
                let lean = b.angle + b.angle_step * series + jitter();
                let axis = turned(along, along.cross(out).normalize(), lean);
                let up = (along - axis * along.dot(axis)).normalize_or(out);
                queue.push_back(Tip {
                    base: Base {
                        centre: middle + out * reach,
                        axes: DMat3::from_cols(up, axis.cross(up), axis),
                        diameter,
                    },
                    tendril: Tendril::start(&spec.knot),
                    index: 0,
                    branchings: 0,
                    roll: 0.0,
                    generation: tip.generation + 1,
                    depth: tip.depth + 1,
                    parent: Some((k, tip.branchings)),
                    previous: None,
                });
            }
        }
        Ok(tree)
    }

    /// Generations from the first trunk to the last.
    pub fn generations(&self) -> usize {
        self.segments.last().map_or(0, |s| s.generation + 1)
    }
}

/// The first trunk's base axes: e₃ upright (−z), or leaning so that the axis of the main stem's
/// coil stands upright ([`Stand`]).
fn first_axes(spec: &BranchingSpec) -> DMat3 {
    let upright = DMat3::from_cols(DVec3::X, DVec3::NEG_Y, DVec3::NEG_Z);
    match spec.stand {
        Stand::Trunk => upright,
        Stand::Coil => {
            let lean = DQuat::from_rotation_arc(upright * coil_axis(&spec.knot), DVec3::NEG_Z);
            DMat3::from_quat(lean) * upright
        }
    }
}

/// The axis of the coil that knots of angle α and twist τ wind, in the first trunk's base axes.
///
/// In the frame of a knot whose x axis points to its bending side (its roll), the knot turns the
/// trunk by α about y, and the next knot's bending side lies τ further about the new axis: the
/// frame of the next knot is this one's turned by C = R_y(α)·R_z(τ). The same C at every knot
/// makes each knot's turn, seen from the shell, a rotation about one fixed direction: the axis
/// of C, taken from the first knot's frame (the first roll is τ) back to the base's axes, and
/// pointed the way the trunks climb (along the first trunk, not against it). With neither bend
/// nor twist, the trunk's own axis. Where α changes from knot to knot (θ ≠ 0), the coil of the
/// first knot's α.
fn coil_axis(knot: &KnotSpec) -> DVec3 {
    let step = DQuat::from_rotation_y(knot.angle.to_radians())
        * DQuat::from_rotation_z(knot.twist.to_radians());
    let (axis, angle) = step.to_axis_angle();
    if angle.abs() < 1e-9 || !axis.is_finite() {
        return DVec3::Z;
    }
    let axis = DQuat::from_rotation_z(knot.twist.to_radians()) * axis;
    if axis.z < 0.0 { -axis } else { axis }
}

/// How far from its knot's axis a branch of diameter `d` starts, in a knot of mean radius
/// `r`: inside the knot, its outer edge on the knot's mean rim (r − d/2), but never nearer the
/// axis than r/16. Branches wider than their knot (the tentacles') thus start near its centre,
/// each on its own side: started on the axis itself, two branches leaning ±90° (or 0°) would
/// start back to back, their bases one on another, a face on a face.
fn branch_reach(r: f64, d: f64) -> f64 {
    (r - d / 2.0).max(r / 16.0)
}

/// The checks that need no growth: each names its key.
fn check(spec: &BranchingSpec) -> Result<(), ShapeError> {
    let t = &spec.trunk;
    let positive = [
        ("form.trunk.diameter", "the diameter D₀", t.diameter),
        ("form.trunk.slenderness", "S = H/D", t.slenderness),
        ("form.trunk.taper", "the taper", t.taper),
    ];
    for (key, what, x) in positive {
        if !(x > 0.0 && x.is_finite()) {
            return Err(ShapeError::new(
                key,
                format!("{what} must be above 0, not {x}"),
            ));
        }
    }
    if spec.pixels == 0 {
        return Err(ShapeError::new(
            "form.pixels",
            "rule 8 needs a picture of at least one pixel",
        ));
    }
    if t.sides < 3 {
        return Err(ShapeError::new(
            "form.trunk.sides",
            format!("a trunk's section needs at least 3 sides, not {}", t.sides),
        ));
    }
    if spec.knot.k0 >= spec.knot.k1 {
        return Err(ShapeError::new(
            "form.knot.k0",
            format!(
                "the lower limit k₀ ({}°) must be below the upper limit k₁ ({}°)",
                spec.knot.k0, spec.knot.k1
            ),
        ));
    }
    if spec.knots == 0 {
        return Err(ShapeError::new(
            "form.knots",
            "a branch needs at least one trunk",
        ));
    }
    Ok(())
}
