//! A swept shell's mesh as fine as the picture it is drawn in (a gallery card, a tile of the
//! parameter map). Every rim of a shell has the same points and every whorl the same rims, so
//! the first whorls, a few pixels across in a picture, cost as many triangles as the last; a
//! software rasterizer pays for each. Here the mesh has fewer points per rim (the first of 4, 5,
//! 7, 9, 12, … that keeps the largest rims within `tolerance`, half a pixel, of the spec's own)
//! and keeps only some of the rims of the mesh with that many points a rim: a rim is left out
//! where the band from the rim kept before it to the one after lies within `tolerance` of it
//! and turns its normals by under [`NORMAL_TOLERANCE`] (so that a rib's shading stays). The
//! rims kept are that mesh's, bit for bit. The tolerance is checked on the outer surface; the
//! inner one, a wall's thickness below, departs by about as much.

use super::surface::{Rim, RimPoint, Sweep};
use crate::shape::ShapeError;
use crate::spec::form::sweep::SweepSpec;
use std::f64::consts::TAU;

/// Radians a normal may turn from the one interpolated between the kept rims or points.
const NORMAL_TOLERANCE: f64 = 0.1;

/// Whether `p`, at fraction `f` of the way from `a` to `b`, lies within `tolerance` of the
/// point the straight segment from `a` to `b` puts there, its normal within
/// [`NORMAL_TOLERANCE`] of theirs interpolated.
fn near(a: &RimPoint, b: &RimPoint, f: f64, p: &RimPoint, tolerance: f64) -> bool {
    let normal = a.normal.lerp(b.normal, f).normalize_or_zero();
    a.position.lerp(b.position, f).distance(p.position) <= tolerance
        && normal.dot(p.normal) >= NORMAL_TOLERANCE.cos()
}

/// Whether `between`, at fraction `f` of the way from `a` to `b`, is where the straight band
/// from `a` to `b` puts it, within `tolerance`, and faces the same way.
fn close(a: &Rim, b: &Rim, between: &Rim, f: f64, tolerance: f64) -> bool {
    (a.points.iter().zip(&b.points).zip(&between.points))
        .all(|((a, b), p)| near(a, b, f, p, tolerance))
}

/// Which rims a picture keeps, decided as they come: the first and the last always, and in
/// between one wherever leaving it out too would carry a band beyond the tolerance.
pub(crate) struct RimThinning {
    tolerance: f64,
    /// The last rim kept.
    kept: Option<Rim>,
    /// The rims since then, not kept yet; the last of them ends the band from `kept`.
    held: Vec<Rim>,
}

impl RimThinning {
    pub(crate) fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            kept: None,
            held: Vec::new(),
        }
    }

    /// Whether the band from the last rim kept to `rim` passes within the tolerance of every
    /// rim held between them.
    fn spans(&self, kept: &Rim, rim: &Rim) -> bool {
        self.held.iter().all(|h| {
            let f = (h.t - kept.t) / (rim.t - kept.t);
            close(kept, rim, h, f, self.tolerance)
        })
    }

    /// The band still open, while rims are held: the last rim kept and the newest rim, which
    /// the growing edge joins (within the tolerance of every rim between).
    pub(crate) fn open(&self) -> Option<(&Rim, &Rim)> {
        Some((self.kept.as_ref()?, self.held.last()?))
    }

    /// Takes the next rim of the full mesh (`last`: the opening's); returns the rims to add to
    /// the mesh now, in order: none while the band can still stretch, else the rim that ends
    /// it, and the last rim at the end.
    pub(crate) fn take(&mut self, rim: Rim, last: bool) -> Vec<Rim> {
        let mut add = Vec::new();
        match &self.kept {
            None => {
                self.kept = Some(rim.clone());
                add.push(rim);
                return add;
            }
            Some(kept) if !self.spans(kept, &rim) => {
                let end = self.held.pop().expect("a band that fails holds a rim");
                self.held.clear();
                self.kept = Some(end.clone());
                add.push(end);
            }
            Some(_) => {}
        }
        if last {
            self.held.clear();
            self.kept = Some(rim.clone());
            add.push(rim);
        } else {
            self.held.push(rim);
        }
        add
    }
}

/// Points per rim for a picture: the first of 4, 5, 7, 9, 12, … (each a quarter more; never
/// more than the spec's own) whose rims, along the last whorl, stay within `tolerance` of the
/// spec's own rims there (`full`, its surface). A rim departs most from its curve where it is
/// largest, and a shell's largest rims are its last.
pub(crate) fn points_per_rim(
    spec: &SweepSpec,
    full: &Sweep,
    tolerance: f64,
) -> Result<u32, ShapeError> {
    let t_max = full.t_max();
    let ts: Vec<f64> = (0..8)
        .map(|k| (t_max - TAU * f64::from(k) / 8.0).max(0.0))
        .collect();
    let fine: Vec<Rim> = ts.iter().map(|&t| full.rim_at(t)).collect();
    let mut segments = 4;
    while segments < spec.curve.segments {
        let mut coarse_spec = spec.clone();
        coarse_spec.curve.segments = segments;
        let coarse = Sweep::new(&coarse_spec)?;
        let keeps = ts
            .iter()
            .zip(&fine)
            .all(|(&t, fine)| follows(&coarse.rim_at(t), fine, tolerance));
        if keeps {
            return Ok(segments);
        }
        segments = (segments * 5).div_ceil(4);
    }
    Ok(spec.curve.segments)
}

/// Whether every point of `fine` lies within `tolerance` of the polyline of `coarse` at the
/// same fraction of the curve, facing about the same way.
fn follows(coarse: &Rim, fine: &Rim, tolerance: f64) -> bool {
    let n = (fine.points.len() - 1) as f64;
    let m = (coarse.points.len() - 1) as f64;
    fine.points.iter().enumerate().all(|(j, p)| {
        let x = j as f64 / n * m;
        let i = (x.floor() as usize).min(coarse.points.len() - 2);
        near(
            &coarse.points[i],
            &coarse.points[i + 1],
            x - i as f64,
            p,
            tolerance,
        )
    })
}

/// Half a pixel, in the shell's units, of a picture `pixels` wide of a shell whose bounding
/// sphere has `radius`: the camera frames that sphere's diameter across about the picture's
/// width, so a pixel is about 2 · radius / pixels (in perspective the sphere's near side is
/// drawn somewhat larger).
pub(crate) fn half_pixel(radius: f64, pixels: u32) -> f64 {
    radius / f64::from(pixels.max(1))
}

/// Points per rim of a circle of `radius` (in pixels) so that its chords depart from it by
/// at most half a pixel: what [`points_per_rim`] finds for a round generating curve.
#[cfg(test)]
fn round_points(radius: f64) -> u32 {
    (std::f64::consts::PI / (1.0 - 0.5 / radius).acos()).ceil() as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::presets;
    use crate::spec::form::Form;

    fn sweep(id: &str) -> SweepSpec {
        let preset = presets().iter().find(|p| p.id == id).expect(id);
        match &preset.spec.form {
            Form::Sweep(s) => s.clone(),
            _ => unreachable!("{id} is swept"),
        }
    }

    #[test]
    fn a_round_curve_gets_the_points_a_circle_needs() {
        let spec = sweep("turbinate");
        let full = Sweep::new(&spec).unwrap();
        let last = full.rim_at(full.t_max());
        let radius = last.points[0].position.distance(last.points[32].position) / 2.0;
        for pixels in [4.0, 10.0, 30.0] {
            let tolerance = radius / pixels / 2.0;
            let n = points_per_rim(&spec, &full, tolerance).unwrap();
            let circle = round_points(pixels);
            assert!(
                n >= circle.min(spec.curve.segments) && n <= (circle * 2).max(8),
                "a tube {pixels} pixels in radius: {n} points, a circle needs {circle}"
            );
        }
    }

    #[test]
    fn a_straight_run_of_rims_is_one_band() {
        let full = Sweep::new(&sweep("turbinate")).unwrap();
        let ts: Vec<f64> = (0..=10).map(|k| f64::from(k) * 1e-6).collect();
        let mut thinning = RimThinning::new(1e-3);
        let mut kept = Vec::new();
        for (k, &t) in ts.iter().enumerate() {
            let rim = full.rim_at(t);
            kept.extend(thinning.take(rim, k == 10).into_iter().map(|r| r.t));
        }
        assert_eq!(kept, [ts[0], ts[10]]);
    }

    #[test]
    fn no_tolerance_keeps_every_rim() {
        let full = Sweep::new(&sweep("turbinate")).unwrap();
        let ts: Vec<f64> = (0..40).map(|k| f64::from(k) * full.step()).collect();
        let mut thinning = RimThinning::new(0.0);
        let mut kept = Vec::new();
        for (k, &t) in ts.iter().enumerate() {
            let rim = full.rim_at(t);
            kept.extend(
                thinning
                    .take(rim, k == ts.len() - 1)
                    .into_iter()
                    .map(|r| r.t),
            );
        }
        assert_eq!(kept, ts);
    }
}
