//! Kawaguchi's accumulated chambers (1982, "Structure analysis" and "Relationship between two
//! flat surfaces"): every chamber is a polyhedron between two similar N-gons, and each new
//! chamber sits on the previous one's top base. One similarity therefore carries every chamber
//! onto the next, and its powers lay the chambers out on a logarithmic spiral.
//!
//! In a chamber's own frame the bottom base is the mouth polygon in the plane z = 0, centred
//! on the origin. Its top base is the bottom base scaled by the growth ratio r, inclined by
//! Q = (Qx, Qy, Qz) (rotations about x, then y, then z, about the base's centre) and lifted by
//! the width H along z:
//!
//! > C(x) = (0, 0, H) + r R(Q) x
//!
//! The next chamber's bottom base is that top base shifted by T = (Tx, Ty, Tz) in the top
//! base's own scaled frame, so one period of growth is P = C ∘ (x ↦ x + T), a similarity of
//! ratio r. With T = 0 chambers adjoin; with T ≠ 0 they separate, a short sheared joint closes
//! the gap, and the spiral opens into a ram's or goat's horn (fig. 5).
//!
//! Shell space is the one every form shares (the spiral's axis along z, growing towards +z):
//! the centre of similitude of P — the apex the chambers shrink towards — is put at the origin
//! and the axis of R(Q) along z.

use super::mouth::mouth_polygon;
use crate::mesh::Bounds;
use crate::shape::ShapeError;
use crate::spec::form::chambers::{ChamberSpec, ChambersSpec};
use crate::spec::handedness::Handedness;
use glam::{DAffine3, DMat3, DQuat, DVec3};

/// Where a septum's suture band ends, as a fraction of the chamber's width from its bottom base.
pub const SUTURE: f64 = 0.12;

/// One ring of apexes in the sequence that the mesh joins band by band.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingKind {
    /// A chamber's bottom base.
    Bottom,
    /// The end of the suture band above a bottom base (only when septa are marked).
    Suture,
    /// A chamber's top base.
    Top,
}

/// R(Q): the inclination of the top base, rotations about x, then y, then z.
fn inclination(spec: &ChamberSpec) -> DQuat {
    let [x, y, z] = spec.inclination.to_array().map(f64::to_radians);
    DQuat::from_rotation_z(z) * DQuat::from_rotation_y(y) * DQuat::from_rotation_x(x)
}

/// The angle one chamber turns the growth by (radians): the rotation angle of R(Q).
pub fn turn_per_chamber(spec: &ChamberSpec) -> f64 {
    inclination(spec).to_axis_angle().1
}

/// The chambers of one [`ChambersSpec`], placed in shell space.
pub struct ChamberStack {
    /// The mouth polygon in the base plane (z = 0).
    bottom: Vec<DVec3>,
    /// The same polygon as the top base, in the bottom base's frame.
    top: Vec<DVec3>,
    /// C: a chamber's bottom frame to its top frame.
    chamber: DAffine3,
    /// P: one chamber's bottom frame to the next one's.
    period: DAffine3,
    /// The first chamber's frame in shell space.
    placement: DAffine3,
    chambers: usize,
    adjoining: bool,
    septa: bool,
    handedness: Handedness,
}

impl ChamberStack {
    pub fn new(spec: &ChambersSpec) -> Result<Self, ShapeError> {
        let c = &spec.chamber;
        if !(c.ratio > 0.0 && c.ratio.is_finite()) {
            return Err(ShapeError::new(
                "form.chamber.ratio",
                format!("the growth ratio r must be above 0, not {}", c.ratio),
            ));
        }
        if !(c.width > 0.0 && c.width.is_finite()) {
            return Err(ShapeError::new(
                "form.chamber.width",
                format!(
                    "the width H between the bases must be above 0, not {}",
                    c.width
                ),
            ));
        }
        if c.translation.z < 0.0 {
            return Err(ShapeError::new(
                "form.chamber.translation.z",
                format!(
                    "Tz must not be negative (the next chamber would grow back into this one), not {}",
                    c.translation.z
                ),
            ));
        }
        if spec.chambers == 0 {
            return Err(ShapeError::new(
                "form.chambers",
                "a shell needs at least one chamber",
            ));
        }
        let bottom: Vec<DVec3> = mouth_polygon(&spec.mouth)?
            .into_iter()
            .map(|p| p.extend(0.0))
            .collect();
        let rotation = inclination(c);
        let chamber = DAffine3::from_scale_rotation_translation(
            DVec3::splat(c.ratio),
            rotation,
            DVec3::new(0.0, 0.0, c.width),
        );
        let top: Vec<DVec3> = bottom
            .iter()
            .map(|&p| chamber.transform_point3(p))
            .collect();
        if let Some(j) = top.iter().position(|p| p.z <= 0.0) {
            return Err(ShapeError::new(
                "form.chamber.inclination",
                format!(
                    "the top base crosses the bottom base at apex {j} (the chamber's side there has no height); raise the width H or lower the inclination Q"
                ),
            ));
        }
        let shift = DVec3::from(c.translation.to_array());
        let period = chamber * DAffine3::from_translation(shift);
        let placement = placement(&period, &top, rotation);
        Ok(Self {
            bottom,
            top,
            chamber,
            period,
            placement,
            chambers: spec.chambers as usize,
            adjoining: shift == DVec3::ZERO,
            septa: spec.septa,
            handedness: spec.handedness,
        })
    }

    /// Number of chambers.
    pub fn chambers(&self) -> usize {
        self.chambers
    }

    /// N: apexes of each base.
    pub fn apexes(&self) -> usize {
        self.bottom.len()
    }

    /// Whether each chamber's bottom base is the previous one's top base (T = 0).
    pub fn adjoining(&self) -> bool {
        self.adjoining
    }

    /// The rings chamber `c` adds, in growth order: its bottom base unless it shares the
    /// previous chamber's top, the end of its suture band when septa are marked, its top base.
    pub fn rings_of(&self, c: usize) -> impl Iterator<Item = RingKind> {
        let bottom = (c == 0 || !self.adjoining).then_some(RingKind::Bottom);
        let suture = self.septa.then_some(RingKind::Suture);
        bottom.into_iter().chain(suture).chain([RingKind::Top])
    }

    /// The first chamber's frame: its bottom base's local coordinates to shell space.
    pub fn first_frame(&self) -> DAffine3 {
        self.placement
    }

    /// The frame of the chamber after the one whose frame is `frame`.
    pub fn next_frame(&self, frame: &DAffine3) -> DAffine3 {
        *frame * self.period
    }

    /// The frame of chamber `c`, reached by the same steps as growth takes.
    pub fn frame(&self, c: usize) -> DAffine3 {
        (0..c).fold(self.first_frame(), |f, _| self.next_frame(&f))
    }

    /// The apexes of one ring of the chamber whose frame is `frame`, in shell space before
    /// mirroring.
    pub fn ring(&self, frame: &DAffine3, kind: RingKind) -> Vec<DVec3> {
        let local = |j: usize| match kind {
            RingKind::Bottom => self.bottom[j],
            RingKind::Top => self.top[j],
            RingKind::Suture => self.bottom[j].lerp(self.top[j], SUTURE),
        };
        (0..self.apexes())
            .map(|j| frame.transform_point3(local(j)))
            .collect()
    }

    /// The direction of growth through a ring: the normal of its base plane (a suture ring
    /// takes the bottom base's).
    pub fn growth_direction(&self, frame: &DAffine3, kind: RingKind) -> DVec3 {
        let local = match kind {
            RingKind::Top => self.chamber.matrix3 * DVec3::Z,
            _ => DVec3::Z,
        };
        (frame.matrix3 * local).normalize()
    }

    /// Where a ring lies in its chamber, from 0 (bottom base) to 1 (top base).
    pub fn level(kind: RingKind) -> f64 {
        match kind {
            RingKind::Bottom => 0.0,
            RingKind::Suture => SUTURE,
            RingKind::Top => 1.0,
        }
    }

    /// How the stack coils: how it is mirrored when shown.
    pub fn handedness(&self) -> Handedness {
        self.handedness
    }

    /// The similarity of shell space (mirrored as shown) that carries every chamber onto the
    /// next.
    pub fn similarity(&self) -> DAffine3 {
        let mirror = DAffine3::from_scale(self.handedness.mirror(DVec3::ONE));
        mirror * self.placement * self.period * self.placement.inverse() * mirror
    }

    /// Bounding box of the fully grown stack.
    pub fn bounds(&self) -> Bounds {
        let mut bounds = Bounds::EMPTY;
        let mut frame = self.first_frame();
        for p in self.ring(&frame, RingKind::Bottom) {
            bounds.include(self.handedness.mirror(p));
        }
        for _ in 0..self.chambers {
            for p in self.ring(&frame, RingKind::Top) {
                bounds.include(self.handedness.mirror(p));
            }
            frame = self.next_frame(&frame);
        }
        bounds
    }
}

/// The first chamber's frame in shell space: the centre of similitude of `period` at the
/// origin, the axis of `rotation` along z, turned so that growth runs towards +z. A stack
/// that does not turn (Q = 0) grows straight along z; one that does not scale (r = 1) has no
/// centre and keeps its first base at the origin.
fn placement(period: &DAffine3, top: &[DVec3], rotation: DQuat) -> DAffine3 {
    let linear = period.matrix3;
    let fixed = DMat3::IDENTITY - linear;
    let centre = if fixed.determinant().abs() > 1e-9 {
        fixed.inverse() * period.translation
    } else {
        DVec3::ZERO
    };
    let (axis, angle) = rotation.to_axis_angle();
    let axis = if angle.abs() > 1e-9 {
        axis
    } else {
        period.translation.normalize_or(DVec3::Z)
    };
    let mouth = top.iter().sum::<DVec3>() / top.len() as f64;
    let axis = if (mouth - centre).dot(axis) < 0.0 {
        -axis
    } else {
        axis
    };
    DAffine3::from_quat(DQuat::from_rotation_arc(axis, DVec3::Z))
        * DAffine3::from_translation(-centre)
}
