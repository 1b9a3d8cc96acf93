//! The shell surface of Fowler et al. 1992 §2: the generating curve 𝓒, scaled by ξ_c^t about its
//! origin, oriented by a frame (§2.3) and carried along the helico-spiral 𝓗, displaced along
//! the normal by the sculpture (§2.5). This module evaluates the surface one rim at a time;
//! [`super::sweep_mesh`] turns rims into a growing mesh.
//!
//! Beyond the paper, the last `lip_length` degrees may depart from self-similarity (the curve
//! flares and the wall thickens towards the opening), and the wall has a thickness: each rim
//! carries the distance of the inner surface below the outer one.
//!
//! Normals are smooth: without sculpture they are ∂P/∂s × ∂P/∂t (the curve's analytic tangent
//! and a central difference along t); with sculpture the displaced surface is differenced in both
//! directions, so the normals follow the ribs.

use super::arc_length::ArcLength;
use super::bezier_curve::BezierCurve;
use super::frame::{CurveAxes, Frame};
use super::helico_spiral::{HelicoSpiral, SpiralPoint};
use super::sculpture;
use crate::shape::ShapeError;
use crate::spec::form::sweep::FrameMode;
use crate::spec::form::sweep::{SculptureSpec, SweepSpec, WallSpec};
use crate::spec::handedness::Handedness;
use glam::DVec3;
use std::f64::consts::TAU;

/// Step in t (radians) for differences along the spiral.
const DT: f64 = 1e-4;
/// Step in s for differences along the curve.
const DS: f64 = 1e-4;

/// A point of the generating curve: position, derivative and arc-length fraction.
#[derive(Clone, Copy, Debug)]
struct CurveSample {
    c: DVec3,
    dc: DVec3,
    l: f64,
}

/// One of the n + 1 points of a rim, with its neighbours along the curve for differences.
#[derive(Clone, Copy, Debug)]
struct Column {
    before: CurveSample,
    at: CurveSample,
    after: CurveSample,
}

/// The curve placed at one value of t.
#[derive(Clone, Copy, Debug)]
struct Slice {
    t: f64,
    origin: DVec3,
    axes: CurveAxes,
    scale: f64,
}

/// A point of a rim on the outer surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RimPoint {
    pub position: DVec3,
    /// Outward unit normal.
    pub normal: DVec3,
    /// Unit tangent in the direction of growth.
    pub along_t: DVec3,
    /// Unit tangent along the generating curve.
    pub along_s: DVec3,
}

/// One rim: the n + 1 points of the outer surface at angle t, and the wall thickness there.
#[derive(Clone, Debug, PartialEq)]
pub struct Rim {
    pub t: f64,
    pub points: Vec<RimPoint>,
    /// Distance of the inner surface below the outer one (0: a single surface).
    pub thickness: f64,
}

impl Rim {
    /// The inner surface's point under outer point `j`.
    pub fn inner(&self, j: usize) -> DVec3 {
        let p = &self.points[j];
        p.position - p.normal * self.thickness
    }
}

/// A swept shell surface, ready to be evaluated rim by rim.
#[derive(Clone, Debug)]
pub struct Sweep {
    spiral: HelicoSpiral,
    lambda: [f64; 3],
    step: f64,
    rims: usize,
    ln_xi_c: f64,
    mode: FrameMode,
    rotations: [f64; 3],
    sculpture: SculptureSpec,
    sculpted: bool,
    wall: WallSpec,
    columns: Vec<Column>,
    closed: bool,
    /// +1 when ∂P/∂s × ∂P/∂t points out of the shell, −1 otherwise.
    orientation: f64,
    handedness: Handedness,
}

impl Sweep {
    pub fn new(spec: &SweepSpec) -> Result<Self, ShapeError> {
        let points: Vec<DVec3> = spec.curve.points.iter().map(|&p| DVec3::from(p)).collect();
        let curve = BezierCurve::from_points(&points, spec.curve.closed).ok_or_else(|| {
            ShapeError::new(
                "form.curve.points",
                format!(
                    "a {} curve needs {}, got {} points",
                    if spec.curve.closed { "closed" } else { "open" },
                    if spec.curve.closed {
                        "3k (k ≥ 1)"
                    } else {
                        "3k + 1 (k ≥ 1)"
                    },
                    points.len()
                ),
            )
        })?;
        let s = &spec.spiral;
        let delta_theta = s.delta_theta.to_radians();
        let sub = f64::from(s.subdivisions.max(1));
        let step = delta_theta / sub;
        let steps = (s.whorls * TAU / step).round().max(1.0) as usize;
        let n = spec.curve.segments.max(1) as usize;
        let table = ArcLength::new(&curve);
        let params = if spec.curve.reparametrize {
            table.equal_arcs(&curve, n)
        } else {
            (0..=n)
                .map(|i| curve.s_max() * i as f64 / n as f64)
                .collect()
        };
        // On a closed curve s wraps, so the last point (s_max) is the first (0) bit for bit.
        let sample = |s: f64| {
            let s = if curve.is_closed() {
                s.rem_euclid(curve.s_max())
            } else {
                s.clamp(0.0, curve.s_max())
            };
            CurveSample {
                c: curve.point(s),
                dc: curve.derivative(s),
                l: table.length_at(&curve, s) / table.total(),
            }
        };
        let mut columns: Vec<Column> = params
            .iter()
            .map(|&s| Column {
                before: sample(s - DS),
                at: sample(s),
                after: sample(s + DS),
            })
            .collect();
        // The neighbours of the last point wrap too, but s_max + DS wraps to DS give or take
        // a float step: the last column is the first, so that the sculpted normal, and with it
        // the inner wall, closes the seam bit for bit as the outer surface does.
        if curve.is_closed() {
            columns[n] = columns[0];
        }
        let orientation = if curve.signed_area_uv() < 0.0 {
            -1.0
        } else {
            1.0
        };
        Ok(Self {
            spiral: HelicoSpiral::from_step(s.r0, s.z0, s.lambda_r, s.lambda_z, delta_theta),
            lambda: [
                s.lambda_r.powf(1.0 / sub),
                s.lambda_z.powf(1.0 / sub),
                spec.curve.lambda_c.powf(1.0 / sub),
            ],
            step,
            rims: steps + 1,
            ln_xi_c: spec.curve.lambda_c.ln() / delta_theta,
            mode: spec.orientation.frame,
            rotations: [
                spec.orientation.rotate_e1.to_radians(),
                spec.orientation.rotate_e2.to_radians(),
                spec.orientation.rotate_e3.to_radians(),
            ],
            sculpted: sculpture::is_sculpted(&spec.sculpture),
            sculpture: spec.sculpture.clone(),
            wall: spec.wall.clone(),
            columns,
            closed: curve.is_closed(),
            orientation,
            handedness: s.handedness,
        })
    }

    /// Number of rims from apex to opening.
    pub fn rims(&self) -> usize {
        self.rims
    }

    /// n + 1, the points per rim.
    pub fn points_per_rim(&self) -> usize {
        self.columns.len()
    }

    /// The angle between consecutive rims (radians).
    pub fn step(&self) -> f64 {
        self.step
    }

    /// Growth per rim (λᵣ, λ_z, λ_c), eq 2 at the mesh's resolution.
    pub fn lambda(&self) -> [f64; 3] {
        self.lambda
    }

    /// t at the opening.
    pub fn t_max(&self) -> f64 {
        (self.rims - 1) as f64 * self.step
    }

    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// +1 when ∂P/∂s × ∂P/∂t points outwards; mesh builders use it to wind triangles.
    pub fn orientation(&self) -> f64 {
        self.orientation
    }

    pub fn handedness(&self) -> Handedness {
        self.handedness
    }

    /// Whether the wall has a thickness (an inner surface exists).
    pub fn has_wall(&self) -> bool {
        self.wall.thickness > 0.0
    }

    /// Position of the rim along the curve as the pattern sees it: point j of n.
    pub fn edge_coordinate(&self, j: usize) -> f64 {
        j as f64 / (self.columns.len() - 1) as f64
    }

    /// 0 before the lip, rising smoothly to 1 at the opening.
    fn lip(&self, t: f64) -> f64 {
        let length = self.wall.lip_length.to_radians();
        if length <= 0.0 {
            return 0.0;
        }
        let x = ((t - (self.t_max() - length)) / length).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x)
    }

    fn slice(&self, t: f64, origin: DVec3, scale: f64) -> Slice {
        let frame = Frame::at(self.mode, &self.spiral, t);
        Slice {
            t,
            origin,
            axes: frame.curve_axes(self.rotations),
            scale: scale * (1.0 + self.wall.lip_flare * self.lip(t)),
        }
    }

    /// The curve placed at t by the closed form of eq 1.
    fn slice_at(&self, t: f64) -> Slice {
        self.slice(t, self.spiral.point(t), (self.ln_xi_c * t).exp())
    }

    fn base(&self, slice: &Slice, c: &CurveSample) -> DVec3 {
        slice.origin + slice.axes.place(c.c, slice.scale)
    }

    /// Outward normal of the unsculpted surface, from slices at t − h, t, t + h.
    fn base_normal(&self, slices: [&Slice; 3], c: &CurveSample) -> DVec3 {
        let along_s = slices[1].axes.place(c.dc, slices[1].scale);
        let along_t = self.base(slices[2], c) - self.base(slices[0], c);
        (along_s.cross(along_t) * self.orientation).normalize_or(slices[1].axes.u)
    }

    /// The sculpted surface point, from slices at t − h, t, t + h.
    fn sculpted(&self, slices: [&Slice; 3], c: &CurveSample) -> DVec3 {
        let p = self.base(slices[1], c);
        if !self.sculpted {
            return p;
        }
        let d = sculpture::displacement(&self.sculpture, c.l, slices[1].t);
        p + self.base_normal(slices, c) * (d * slices[1].scale)
    }

    /// The rim at angle t whose spiral point and curve scale are `at` and `scale` (from the
    /// incremental walk of eq 2); neighbouring slices for differences use the closed form.
    pub fn rim(&self, at: SpiralPoint, scale: f64) -> Rim {
        let t = at.theta;
        let centre = self.slice(t, at.position(), scale);
        let s = [-2.0, -1.0, 1.0, 2.0].map(|k| self.slice_at(t + k * DT));
        let slices = [&s[0], &s[1], &centre, &s[2], &s[3]];
        let points = self
            .columns
            .iter()
            .map(|col| {
                let mid = [slices[1], slices[2], slices[3]];
                let position = self.sculpted(mid, &col.at);
                let along_t = self.sculpted([slices[2], slices[3], slices[4]], &col.at)
                    - self.sculpted([slices[0], slices[1], slices[2]], &col.at);
                let along_s = self.sculpted(mid, &col.after) - self.sculpted(mid, &col.before);
                let normal = if self.sculpted {
                    (along_s.cross(along_t) * self.orientation).normalize_or(centre.axes.u)
                } else {
                    self.base_normal(mid, &col.at)
                };
                RimPoint {
                    position,
                    normal,
                    along_t: along_t.normalize_or(centre.axes.w),
                    along_s: along_s.normalize_or(centre.axes.v),
                }
            })
            .collect();
        let thickness = self.wall.thickness
            * (1.0 + (self.wall.lip_thickening - 1.0) * self.lip(t))
            * centre.scale;
        Rim {
            t,
            points,
            thickness,
        }
    }

    /// The rim at t computed from the closed form alone (for bounds and tests).
    pub fn rim_at(&self, t: f64) -> Rim {
        let p = self.spiral.point(t);
        let at = SpiralPoint {
            theta: t,
            r: p.truncate().length(),
            z: p.z,
        };
        self.rim(at, (self.ln_xi_c * t).exp())
    }
}
