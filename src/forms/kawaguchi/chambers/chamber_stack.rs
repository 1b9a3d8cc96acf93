//! Kawaguchi's accumulated chambers (1982, "Structure analysis" and "Relationship between two
//! flat surfaces"): every chamber is a polyhedron between two similar N-gons, and each new
//! chamber sits on the previous one's top base. One similarity therefore carries every chamber
//! onto the next, and its powers lay the chambers out on a logarithmic spiral.
//!
//! In a chamber's own frame the bottom base is the mouth polygon in the plane z = 0, centred
//! on the origin. Its top base is the bottom base scaled by the growth ratio r, inclined by
//! Q = (Qx, Qy, Qz) (rotations about x, then y, then z, about the base's centre) and moved to
//! the position T = (Tx, Ty, Tz):
//!
//! > C(x) = T + r R(Q) x,   T = (Tx, Ty, H)
//!
//! The paper: "the width, H, is the distance between the top and bottom bases, and the
//! position is nothing but the transferring of axis x and y, which reaches the top and bottom
//! bases", and "the width relationship, T_z, is fixed": T_z is the width H, and (Tx, Ty) move
//! the top base sideways from straight above the bottom base, making the chamber oblique.
//! Chambers accumulate base on base, so the next chamber's bottom base is this one's top base
//! and one period of growth is C itself, a similarity of ratio r. A position that leaves the
//! vertical moves the centre of similitude along the axis of R(Q): each whorl advances past
//! the last instead of resting on it, and the spiral "starts to form in the shape of horns of
//! sheep or goats" (fig. 5).
//!
//! Shell space is the one every form shares (the spiral's axis along z, growing towards +z):
//! the centre of similitude of C — the apex the chambers shrink towards — is put at the origin
//! and the axis of R(Q) along z.

use super::mouth::mouth_polygon;
use crate::mesh::{Bounds, MAX_GROWTH_DECADES};
use crate::shape::ShapeError;
use crate::spec::form::chambers::{ChamberSpec, ChambersSpec, Pair};
use crate::spec::handedness::Handedness;
use glam::{DAffine3, DMat3, DQuat, DVec3};

/// Where a septum's suture band ends, as a fraction of the chamber's width from its bottom base.
pub const SUTURE: f64 = 0.12;

/// The siphuncle's size, as a fraction of the septum it pierces: the tube that joins every
/// chamber of a hollow stack to the next, near the centre of each septum as in *Nautilus*.
pub const SIPHUNCLE: f64 = 0.12;

/// The most a septum's half may take of its chamber's width, so that every chamber keeps a
/// cavity however thick the wall is asked to be.
const MOST_SEPTUM: f64 = 0.25;

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

/// The most chambers a stack of growth ratio `ratio` may have (at least 1): as many as keep its
/// growth from first to last chamber within 10^[`MAX_GROWTH_DECADES`].
pub(crate) fn most_chambers(ratio: f64) -> u32 {
    let decades = ratio.log10().abs();
    if decades > 0.0 {
        (MAX_GROWTH_DECADES / decades)
            .floor()
            .clamp(1.0, f64::from(u32::MAX)) as u32
    } else {
        u32::MAX
    }
}

/// Refuses `chambers` chambers at growth ratio `ratio` when they grow beyond
/// [`MAX_GROWTH_DECADES`], saying how many this ratio allows.
pub(crate) fn check_growth(chambers: u32, ratio: f64) -> Result<(), ShapeError> {
    let most = most_chambers(ratio);
    if chambers <= most {
        return Ok(());
    }
    let decades = f64::from(chambers) * ratio.log10();
    let (verb, decades) = if decades < 0.0 {
        ("shrink the last to", format!("10^{:.0} of", decades))
    } else {
        ("grow the last to", format!("10^{:.0} times", decades))
    };
    Err(ShapeError::new(
        "form.chambers",
        format!(
            "{chambers} chambers at ratio {ratio} {verb} {decades} the first: at most {most} at this ratio (a float32 file keeps no finer detail than 10^-{MAX_GROWTH_DECADES} of a shell)"
        ),
    ))
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

/// The chamber that grows as the chambers of links made before T was read as the top base's
/// position: those placed the next chamber's bottom base at T beyond the top base, in the top
/// base's own scaled frame, so that one period of growth was x ↦ (0, 0, H) + r R(Q)(x + T).
/// The chamber reaching the next bottom base in one step has the position
/// (0, 0, H) + r R(Q) T instead: the same similarity, so the same spiral, without the joints.
/// Returns that chamber (its width H and sideways position (Tx, Ty)); the caller checks it.
pub fn chamber_of_shift_beyond_top(spec: &ChamberSpec, beyond: DVec3) -> ChamberSpec {
    let position = DVec3::new(0.0, 0.0, spec.width) + spec.ratio * (inclination(spec) * beyond);
    ChamberSpec {
        width: position.z,
        shift: Pair {
            x: position.x,
            y: position.y,
        },
        ..spec.clone()
    }
}

/// The chambers of one [`ChambersSpec`], placed in shell space.
pub struct ChamberStack {
    /// The mouth polygon in the base plane (z = 0).
    bottom: Vec<DVec3>,
    /// C: a chamber's bottom frame to its top frame, which is the next chamber's bottom frame.
    chamber: DAffine3,
    /// The first chamber's frame in shell space.
    placement: DAffine3,
    chambers: usize,
    septa: bool,
    /// The wall's thickness as a fraction of a ring's size about its centre (0: solid).
    wall: f64,
    /// Where a hollow chamber's cavity begins above its bottom base and ends below its top
    /// base, as a fraction of the chamber's width: half a septum.
    septum: f64,
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
        if !(c.shift.x.is_finite() && c.shift.y.is_finite()) {
            return Err(ShapeError::new(
                "form.chamber.shift",
                format!(
                    "the position (Tx, Ty) must be numbers, not ({}, {})",
                    c.shift.x, c.shift.y
                ),
            ));
        }
        if spec.chambers == 0 {
            return Err(ShapeError::new(
                "form.chambers",
                "a shell needs at least one chamber",
            ));
        }
        check_growth(spec.chambers, c.ratio)?;
        if !(0.0..1.0).contains(&spec.wall) {
            return Err(ShapeError::new(
                "form.wall",
                format!(
                    "the wall must be at least 0 (solid chambers) and less than 1 (a chamber's whole radius), not {}",
                    spec.wall
                ),
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
            DVec3::new(c.shift.x, c.shift.y, c.width),
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
        // The bottom base must stay below the top base's plane too, or the next chamber's
        // side would fold back over this one's.
        let from_top = chamber.inverse();
        if let Some(j) = bottom
            .iter()
            .position(|&p| from_top.transform_point3(p).z >= 0.0)
        {
            return Err(ShapeError::new(
                "form.chamber.shift",
                format!(
                    "the chamber leans over so far that its bottom base crosses the top base's plane at apex {j}; raise the width H or lower the position (Tx, Ty) or the inclination Q"
                ),
            ));
        }
        let placement = placement(&chamber, &top, rotation);
        let septum = septum(&bottom, &chamber, spec.wall);
        Ok(Self {
            bottom,
            chamber,
            placement,
            chambers: spec.chambers as usize,
            septa: spec.septa,
            wall: spec.wall,
            septum,
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

    /// The first chamber's bottom base's perimeter.
    pub fn perimeter(&self) -> f64 {
        let n = self.bottom.len();
        (0..n)
            .map(|j| self.bottom[j].distance(self.bottom[(j + 1) % n]))
            .sum()
    }

    /// r: the growth ratio from each chamber to the next.
    pub fn ratio(&self) -> f64 {
        self.chamber.matrix3.x_axis.length()
    }

    /// The rings a chamber adds above its bottom base (the previous chamber's top base, or
    /// for the first chamber the apex base), in growth order: the end of its suture band when
    /// septa are marked, and its top base.
    pub fn rings_above_bottom(&self) -> impl Iterator<Item = RingKind> {
        let suture = self.septa.then_some(RingKind::Suture);
        suture.into_iter().chain([RingKind::Top])
    }

    /// The first chamber's frame: its bottom base's local coordinates to shell space.
    pub fn first_frame(&self) -> DAffine3 {
        self.placement
    }

    /// The frame of the chamber after the one whose frame is `frame`.
    pub fn next_frame(&self, frame: &DAffine3) -> DAffine3 {
        *frame * self.chamber
    }

    /// The frame of chamber `c`, reached by the same steps as growth takes.
    pub fn frame(&self, c: usize) -> DAffine3 {
        (0..c).fold(self.first_frame(), |f, _| self.next_frame(&f))
    }

    /// The apexes of one ring of the chamber whose frame is `frame`, in shell space before
    /// mirroring. A top base is computed as the next chamber's bottom base, by the same
    /// operations, so the two are equal bit for bit.
    pub fn ring(&self, frame: &DAffine3, kind: RingKind) -> Vec<DVec3> {
        let placed = |frame: DAffine3, local: &dyn Fn(DVec3) -> DVec3| -> Vec<DVec3> {
            self.bottom
                .iter()
                .map(|&p| frame.transform_point3(local(p)))
                .collect()
        };
        match kind {
            RingKind::Bottom => placed(*frame, &|p| p),
            RingKind::Top => placed(self.next_frame(frame), &|p| p),
            RingKind::Suture => placed(*frame, &|p| {
                p.lerp(self.chamber.transform_point3(p), SUTURE)
            }),
        }
    }

    /// Whether the chambers are hollow: walled, with septa between them.
    pub fn hollow(&self) -> bool {
        self.wall > 0.0
    }

    /// Where a hollow chamber's cavity begins above the bottom base (and ends as far below
    /// the top base), as a fraction of the chamber's width.
    pub fn septum(&self) -> f64 {
        self.septum
    }

    /// A ring of the cavity inside the chamber whose frame is `frame`, at `level` of its width
    /// (0 the bottom base, 1 the top base): the chamber's side at that level, drawn in towards
    /// its centre by the wall, and further by `scale` (1 for the cavity's side, [`SIPHUNCLE`]
    /// for the siphuncle through a septum). Every chamber's cavity is the same similarity's
    /// image of the one before, as its chamber is.
    pub fn cavity_ring(&self, frame: &DAffine3, level: f64, scale: f64) -> Vec<DVec3> {
        let side: Vec<DVec3> = self
            .bottom
            .iter()
            .map(|&p| p.lerp(self.chamber.transform_point3(p), level))
            .collect();
        let centre = side.iter().sum::<DVec3>() / side.len() as f64;
        let shrink = (1.0 - self.wall) * scale;
        side.iter()
            .map(|&p| frame.transform_point3(centre + (p - centre) * shrink))
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
        mirror * self.placement * self.chamber * self.placement.inverse() * mirror
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

/// Half a septum as a fraction of a chamber's width: half the wall's thickness (`wall` times
/// the bottom base's mean radius) over the distance between the centres of the bottom and
/// top bases, so that the septum between two cavities is as thick as the wall; at most
/// [`MOST_SEPTUM`].
fn septum(bottom: &[DVec3], chamber: &DAffine3, wall: f64) -> f64 {
    let centre = bottom.iter().sum::<DVec3>() / bottom.len() as f64;
    let radius = bottom.iter().map(|&p| p.distance(centre)).sum::<f64>() / bottom.len() as f64;
    let width = chamber.transform_point3(centre).distance(centre);
    (wall * radius / (2.0 * width)).min(MOST_SEPTUM)
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
