//! The mouth polygon of Kawaguchi's chambers (1982, "Formation of polygons", fig. 1): N apexes
//! on an ellipse, whose radius is pushed out by convex and in by concave protuberances for
//! the unique mouths of real shells.

use crate::shape::ShapeError;
use crate::spec::form::chambers::MouthSpec;
use glam::DVec2;
use std::f64::consts::TAU;

/// Smallest radius factor an apex may keep: below it the polygon pinches to its centre.
const MIN_FACTOR: f64 = 0.02;

/// The radius factor 1 + offset(φ) at angle φ, the offsets interpolated around the ellipse by
/// a periodic Catmull-Rom spline (smooth, and through every listed value).
fn factor(offsets: &[f64], phi: f64) -> f64 {
    let m = offsets.len();
    if m == 0 {
        return 1.0;
    }
    let x = phi / TAU * m as f64;
    let i = x.floor() as isize;
    let t = x - i as f64;
    let at = |k: isize| offsets[k.rem_euclid(m as isize) as usize];
    let (p0, p1, p2, p3) = (at(i - 1), at(i), at(i + 1), at(i + 2));
    let offset = 0.5
        * (2.0 * p1
            + (p2 - p0) * t
            + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t * t
            + (3.0 * p1 - p0 - 3.0 * p2 + p3) * t * t * t);
    1.0 + offset
}

/// The N apexes of the mouth, counter-clockwise in the base plane, centred on the origin.
///
/// Apex j lies at parameter φⱼ = 2πj/N on the ellipse (a cos φ, b sin φ), scaled by its
/// radius factor. The polar angle of those points rises with φ, so while every factor stays
/// positive the polygon is star-shaped about its centre and cannot cross itself; a factor at
/// or below zero folds it over, and is refused.
pub fn mouth_polygon(spec: &MouthSpec) -> Result<Vec<DVec2>, ShapeError> {
    if spec.apexes < 3 {
        return Err(ShapeError::new(
            "form.mouth.apexes",
            format!("a polygon needs at least 3 apexes, not {}", spec.apexes),
        ));
    }
    for (key, r) in [("radius_a", spec.radius_a), ("radius_b", spec.radius_b)] {
        if !(r > 0.0 && r.is_finite()) {
            return Err(ShapeError::new(
                format!("form.mouth.{key}"),
                format!("a radius must be a positive number, not {r}"),
            ));
        }
    }
    let n = spec.apexes as usize;
    (0..n)
        .map(|j| {
            let phi = TAU * j as f64 / n as f64;
            let f = factor(&spec.protuberances, phi);
            if f < MIN_FACTOR || !f.is_finite() {
                return Err(ShapeError::new("form.mouth.protuberances", format!(
                    "the offsets fold the mouth polygon over itself at apex {j} of {n} (its radius factor is {f:.3}); keep every offset above −{:.2}",
                    1.0 - MIN_FACTOR
                )));
            }
            Ok(DVec2::new(spec.radius_a * phi.cos(), spec.radius_b * phi.sin()) * f)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mouth(apexes: u32, protuberances: Vec<f64>) -> MouthSpec {
        MouthSpec {
            apexes,
            radius_a: 2.0,
            radius_b: 1.0,
            protuberances,
        }
    }

    #[test]
    fn a_plain_mouth_is_the_ellipse() {
        let p = mouth_polygon(&mouth(8, vec![])).unwrap();
        assert_eq!(p.len(), 8);
        assert!((p[0] - DVec2::new(2.0, 0.0)).length() < 1e-12);
        assert!((p[2] - DVec2::new(0.0, 1.0)).length() < 1e-12);
    }

    #[test]
    fn protuberances_pass_through_their_values() {
        let p = mouth_polygon(&mouth(8, vec![0.5, 0.0, -0.25, 0.0])).unwrap();
        assert!((p[0].x - 3.0).abs() < 1e-12, "convex at φ = 0");
        assert!((p[2].y - 1.0).abs() < 1e-12, "unchanged at φ = 90°");
        assert!((p[4].x + 1.5).abs() < 1e-12, "concave at φ = 180°");
    }

    #[test]
    fn folding_offsets_and_too_few_apexes_are_refused() {
        let e = mouth_polygon(&mouth(12, vec![0.0, -1.2])).unwrap_err();
        assert_eq!(e.key, "form.mouth.protuberances");
        assert!(e.message.contains("fold the mouth polygon"), "{e}");
        let e = mouth_polygon(&mouth(2, vec![])).unwrap_err();
        assert_eq!(e.key, "form.mouth.apexes");
        assert!(e.message.contains("at least 3 apexes"), "{e}");
    }
}
