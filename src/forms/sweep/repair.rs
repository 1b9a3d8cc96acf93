//! The sweep's cross-field checks: a curve with the control points its closedness needs, and a
//! mesh within the vertex cap. Each violation is repaired from the fallback and reported.

use crate::mesh::MAX_VERTICES;
use crate::spec::form::sweep::{CurveSpec, SweepSpec};
use crate::spec::problem::Problem;

/// Vertices of a sweep's mesh: rims × points per rim, doubled with a wall.
fn sweep_vertices(s: &SweepSpec) -> u64 {
    let rims = (s.spiral.whorls * 360.0 / s.spiral.delta_theta * f64::from(s.spiral.subdivisions))
        .round() as u64
        + 1;
    let points = u64::from(s.curve.segments) + 1;
    rims * points * if s.wall.thickness > 0.0 { 2 } else { 1 }
}

/// Whether the curve has the number of control points its closedness needs.
fn curve_fits(curve: &CurveSpec) -> bool {
    let n = curve.points.len();
    if curve.closed {
        n >= 3 && n.is_multiple_of(3)
    } else {
        n >= 4 && n % 3 == 1
    }
}

/// A sweep's curve must have the control points its closedness needs, and its mesh fit the
/// vertex cap.
pub(crate) fn repair(s: &mut SweepSpec, f: &SweepSpec, problems: &mut Vec<Problem>) {
    if !curve_fits(&s.curve) {
        let n = s.curve.points.len();
        let need = if s.curve.closed {
            "3k points (k ≥ 1)"
        } else {
            "3k + 1 points (k ≥ 1)"
        };
        problems.push(Problem::new(
            "form.curve.points",
            format!(
                "a {} curve needs {need}, not {n}; used the preset's curve",
                if s.curve.closed { "closed" } else { "open" }
            ),
        ));
        s.curve.points = f.curve.points.clone();
        s.curve.closed = f.curve.closed;
    }
    let vertices = sweep_vertices(s);
    if vertices > MAX_VERTICES {
        s.spiral.whorls = f.spiral.whorls;
        s.spiral.delta_theta = f.spiral.delta_theta;
        s.spiral.subdivisions = f.spiral.subdivisions;
        s.curve.segments = f.curve.segments;
        problems.push(Problem::new(
            "form",
            format!(
                "the mesh would have {vertices} vertices, more than the cap of {MAX_VERTICES}; used the preset's whorls, angular step, rims per step and segments"
            ),
        ));
    }
}
