//! The sweep's cross-field checks: a curve with the control points its closedness needs, a
//! growth from apex to opening that a file can hold, and a mesh within the vertex cap. Each
//! violation is repaired from the fallback and reported.

use crate::mesh::{MAX_GROWTH_DECADES, MAX_VERTICES};
use crate::spec::fields;
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

/// How many tenfold the sweep grows from apex to opening, the fastest of its radius, height
/// and curve, and of its curve against its radius and height; and the whorls that would grow
/// it by [`MAX_GROWTH_DECADES`].
fn growth_decades(s: &SweepSpec) -> (f64, f64) {
    let [r, z, c] = [s.spiral.lambda_r, s.spiral.lambda_z, s.curve.lambda_c].map(f64::log10);
    // The curve against the spiral too: a curve that shrinks as the whorls widen leaves a rim
    // small beside the shell's size at the opening.
    let per_step = [r, z, c, c - r, c - z]
        .map(f64::abs)
        .into_iter()
        .fold(0.0, f64::max);
    let steps_per_whorl = 360.0 / s.spiral.delta_theta;
    let most = MAX_GROWTH_DECADES / (per_step * steps_per_whorl);
    (per_step * steps_per_whorl * s.spiral.whorls, most)
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

/// A sweep's curve must have the control points its closedness needs, its growth stay within
/// [`MAX_GROWTH_DECADES`], and its mesh fit the vertex cap.
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
    let (decades, most) = growth_decades(s);
    if decades > MAX_GROWTH_DECADES {
        // Down to the hundredth of a whorl, as the panel shows whorls; rates so fast that not
        // even the panel's fewest whorls fit take the preset's rates and whorls.
        let whorls = (most * 100.0).floor() / 100.0;
        let asked = format!(
            "{} whorls at λᵣ = {}, λ_z = {}, λ_c = {} every {}° grow the shell 10^{decades:.0} times from its apex: at most {whorls} whorls at these rates (a float32 file keeps no finer detail than 10^-{MAX_GROWTH_DECADES} of a shell)",
            s.spiral.whorls,
            s.spiral.lambda_r,
            s.spiral.lambda_z,
            s.curve.lambda_c,
            s.spiral.delta_theta
        );
        let used = if whorls >= fields::range("sweep", "form.spiral.whorls").0 {
            s.spiral.whorls = whorls;
            whorls.to_string()
        } else {
            s.spiral.lambda_r = f.spiral.lambda_r;
            s.spiral.lambda_z = f.spiral.lambda_z;
            s.curve.lambda_c = f.curve.lambda_c;
            if growth_decades(s).0 > MAX_GROWTH_DECADES {
                s.spiral.whorls = f.spiral.whorls;
                s.spiral.delta_theta = f.spiral.delta_theta;
            }
            "the preset's rates".to_string()
        };
        problems.push(Problem::new(
            "form.spiral.whorls",
            format!("{asked}; used {used}"),
        ));
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
