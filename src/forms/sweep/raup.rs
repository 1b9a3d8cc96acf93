//! Raup's coiling parameters of a swept shell (D. M. Raup, "Geometric analysis of shell
//! coiling: general problems", J. Paleontology 40, 1966), read from its spec and written into
//! it: the coordinates of his cube of shell forms.
//!
//! - W, the whorl expansion rate: how much the generating curve's size and its distance from
//!   the axis grow in one whorl.
//! - D, the curve's distance from the axis: its inner edge's distance over its outer edge's
//!   (0: the curve touches the axis; near 1: a thin tube far from it).
//! - T, the translation rate: the height of the curve's centre along the axis over its distance
//!   from the axis, which stays the same as the shell grows.
//!
//! Raup's shell is self-similar: the distance, the height and the curve grow at one rate
//! (λᵣ = λ_z = λ_c = λ per step Δθ, so W = λ^(360°/Δθ), eq 2 of Fowler, Meinhardt &
//! Prusinkiewicz 1992), and the curve lies in a plane through the axis: the axis-aligned frame,
//! in which the curve's u points towards the axis and its v along it. With the curve at the
//! apex spanning u₁ ≤ u ≤ u₂ and its centre at (u_c, v_c), the outer edge is at r₀ − u₁, the
//! inner at r₀ − u₂, and
//!
//!   D = (r₀ − u₂) / (r₀ − u₁),   T = (z₀ + v_c) / (r₀ − u_c).
//!
//! Writing a coordinate sets the three rates to the one of W and moves r₀ (for D) and z₀ (for
//! D and T) so that the other two coordinates stay; the curve itself is kept. A shell that is
//! not self-similar is read by its radial rate. In a Frenet frame the curve leans out of the
//! plane through the axis by the spiral's pitch, and the coordinates read are those of the
//! axis-aligned curve.

use super::bezier_curve::BezierCurve;
use crate::spec::form::sweep::SweepSpec;
use glam::DVec3;

/// One of Raup's three coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coordinate {
    W,
    D,
    T,
}

impl Coordinate {
    /// The coordinate a map's key names (`raup.w`, `raup.d`, `raup.t`).
    pub fn of_key(key: &str) -> Option<Self> {
        match key {
            "raup.w" => Some(Self::W),
            "raup.d" => Some(Self::D),
            "raup.t" => Some(Self::T),
            _ => None,
        }
    }
}

/// Points the curve is sampled at to find its extent.
const SAMPLES: usize = 256;

/// The curve's extent across (u₁, u₂) and its centre (u_c, v_c), at the apex.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Extent {
    u1: f64,
    u2: f64,
    uc: f64,
    vc: f64,
}

impl Extent {
    fn of(sweep: &SweepSpec) -> Option<Self> {
        let points: Vec<DVec3> = sweep.curve.points.iter().map(|&p| DVec3::from(p)).collect();
        let curve = BezierCurve::from_points(&points, sweep.curve.closed)?;
        let (mut low, mut high) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for i in 0..=SAMPLES {
            let p = curve.point(curve.s_max() * i as f64 / SAMPLES as f64);
            low = low.min(p);
            high = high.max(p);
        }
        let centre = (low + high) / 2.0;
        Some(Self {
            u1: low.x,
            u2: high.x,
            uc: centre.x,
            vc: centre.y,
        })
    }
}

/// W, D and T of a swept shell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Raup {
    pub w: f64,
    pub d: f64,
    pub t: f64,
}

impl Raup {
    /// The coordinates of `sweep`, or `None` where they mean nothing: a curve without extent
    /// across, or whose outer edge or centre is not off the axis.
    pub fn of(sweep: &SweepSpec) -> Option<Self> {
        Self::read(sweep, &Extent::of(sweep)?)
    }

    /// The coordinates of `sweep`, whose curve's extent is `e`.
    fn read(sweep: &SweepSpec, e: &Extent) -> Option<Self> {
        let s = &sweep.spiral;
        let (outer, centre) = (s.r0 - e.u1, s.r0 - e.uc);
        if !(e.u2 > e.u1 && outer > 0.0 && centre > 0.0) {
            return None;
        }
        Some(Self {
            w: s.lambda_r.powf(360.0 / s.delta_theta),
            d: (s.r0 - e.u2) / outer,
            t: (s.z0 + e.vc) / centre,
        })
    }

    /// The coordinate `c`.
    pub fn get(&self, c: Coordinate) -> f64 {
        match c {
            Coordinate::W => self.w,
            Coordinate::D => self.d,
            Coordinate::T => self.t,
        }
    }

    /// The values of `sweep`'s spec, by their keys, that give it coordinate `c` = `value` and
    /// keep the other two: the three rates at the one of W, and r₀ and z₀. `None` where `sweep`
    /// has no coordinates, or D is 1 or more (a curve of no width).
    pub fn written(
        sweep: &SweepSpec,
        c: Coordinate,
        value: f64,
    ) -> Option<Vec<(&'static str, f64)>> {
        let e = Extent::of(sweep)?;
        let mut raup = Self::read(sweep, &e)?;
        match c {
            Coordinate::W => raup.w = value,
            Coordinate::D => raup.d = value,
            Coordinate::T => raup.t = value,
        }
        if raup.d >= 1.0 {
            return None;
        }
        let lambda = raup.w.powf(sweep.spiral.delta_theta / 360.0);
        // D (r₀ − u₁) = r₀ − u₂, and T (r₀ − u_c) = z₀ + v_c.
        let r0 = (e.u2 - raup.d * e.u1) / (1.0 - raup.d);
        let z0 = raup.t * (r0 - e.uc) - e.vc;
        Some(vec![
            ("form.spiral.lambda_r", lambda),
            ("form.spiral.lambda_z", lambda),
            ("form.curve.lambda_c", lambda),
            ("form.spiral.r0", r0),
            ("form.spiral.z0", z0),
        ])
    }
}

/// Points of the curve's outline in the whorls' test.
const OUTLINE: usize = 96;

/// Whether each whorl of `sweep` (self-similar: its rates taken as the radial one) lies apart
/// from the next: Raup's open coiling, whose whorls do not touch. Where the curve is closed,
/// the next whorl's section in the same plane through the axis is the curve's scaled by W about
/// the apex's origin, and the two sections are apart when no edges of theirs cross and neither
/// holds a point of the other. `None` for an open curve (its section encloses nothing) or a
/// shell without coordinates.
pub fn whorls_apart(sweep: &SweepSpec) -> Option<bool> {
    let raup = Raup::of(sweep)?;
    if !sweep.curve.closed {
        return None;
    }
    let points: Vec<DVec3> = sweep.curve.points.iter().map(|&p| DVec3::from(p)).collect();
    let curve = BezierCurve::from_points(&points, true)?;
    let (r0, z0) = (sweep.spiral.r0, sweep.spiral.z0);
    let this: Vec<[f64; 2]> = (0..OUTLINE)
        .map(|i| {
            let p = curve.point(curve.s_max() * i as f64 / OUTLINE as f64);
            [r0 - p.x, z0 + p.y]
        })
        .collect();
    let next: Vec<[f64; 2]> = this
        .iter()
        .map(|&[r, z]| [r * raup.w, z * raup.w])
        .collect();
    Some(!outlines_meet(&this, &next))
}

/// Whether two closed outlines cross or one holds the other's first point.
fn outlines_meet(a: &[[f64; 2]], b: &[[f64; 2]]) -> bool {
    let edges = |p: &[[f64; 2]]| {
        let n = p.len();
        (0..n)
            .map(move |i| (p[i], p[(i + 1) % n]))
            .collect::<Vec<_>>()
    };
    let (ea, eb) = (edges(a), edges(b));
    let cross = ea
        .iter()
        .any(|&(p, q)| eb.iter().any(|&(r, s)| segments_cross(p, q, r, s)));
    cross || holds(a, b[0]) || holds(b, a[0])
}

fn segments_cross(p: [f64; 2], q: [f64; 2], r: [f64; 2], s: [f64; 2]) -> bool {
    let side = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    let (d1, d2) = (side(p, q, r), side(p, q, s));
    let (d3, d4) = (side(r, s, p), side(r, s, q));
    d1 * d2 <= 0.0 && d3 * d4 <= 0.0
}

/// Whether the closed outline `poly` holds the point `x` (even-odd rule).
fn holds(poly: &[[f64; 2]], x: [f64; 2]) -> bool {
    let n = poly.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if (a[1] > x[1]) != (b[1] > x[1])
            && x[0] < a[0] + (x[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
        {
            inside = !inside;
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::preset;
    use crate::spec::form::Form;

    fn turbinate() -> SweepSpec {
        match &preset("turbinate").expect("a preset").spec.form {
            Form::Sweep(s) => s.clone(),
            _ => unreachable!("the turbinate shell is swept"),
        }
    }

    fn with(mut sweep: SweepSpec, values: &[(&str, f64)]) -> SweepSpec {
        for &(key, v) in values {
            match key {
                "form.spiral.lambda_r" => sweep.spiral.lambda_r = v,
                "form.spiral.lambda_z" => sweep.spiral.lambda_z = v,
                "form.curve.lambda_c" => sweep.curve.lambda_c = v,
                "form.spiral.r0" => sweep.spiral.r0 = v,
                "form.spiral.z0" => sweep.spiral.z0 = v,
                _ => unreachable!("{key}"),
            }
        }
        sweep
    }

    #[test]
    fn the_turbinate_shell_reads_as_its_spiral_and_curve_say() {
        // λ = 1.007 every 10°, r₀ = 1, z₀ = 1.9; a circle of radius 0.45 about (0, 0) in uv.
        let raup = Raup::of(&turbinate()).unwrap();
        assert!((raup.w - 1.007f64.powi(36)).abs() < 1e-12);
        assert!((raup.d - 0.55 / 1.45).abs() < 1e-3, "{raup:?}");
        assert!((raup.t - 1.9).abs() < 1e-3, "{raup:?}");
    }

    #[test]
    fn writing_a_coordinate_sets_it_and_keeps_the_other_two() {
        let sweep = turbinate();
        let before = Raup::of(&sweep).unwrap();
        for (c, value) in [
            (Coordinate::W, 3.0),
            (Coordinate::D, 0.7),
            (Coordinate::T, -0.5),
        ] {
            let values = Raup::written(&sweep, c, value).unwrap();
            let after = Raup::of(&with(sweep.clone(), &values)).unwrap();
            for other in [Coordinate::W, Coordinate::D, Coordinate::T] {
                let want = if other == c { value } else { before.get(other) };
                assert!(
                    (after.get(other) - want).abs() < 1e-9,
                    "{c:?} = {value}: {after:?}"
                );
            }
        }
        assert_eq!(Raup::written(&sweep, Coordinate::D, 1.0), None, "no width");
    }

    #[test]
    fn whorls_lie_apart_where_w_d_passes_1_or_the_translation_lifts_them_clear() {
        let sweep = turbinate();
        let at = |c: &[(Coordinate, f64)]| {
            let mut s = sweep.clone();
            for &(c, v) in c {
                s = with(s.clone(), &Raup::written(&s, c, v).unwrap());
            }
            whorls_apart(&s).unwrap()
        };
        // D = 0.38: in a plane (T = 0) the whorls touch while W D < 1 (Raup's line W = 1/D).
        let (w, t) = (Coordinate::W, Coordinate::T);
        assert!(!at(&[(t, 0.0), (w, 2.4)]), "W D = 0.91");
        assert!(at(&[(t, 0.0), (w, 2.8)]), "W D = 1.06");
        // Raised along the axis by T (W − 1) of the curve's distance a whorl, they come apart.
        assert!(!at(&[(t, 0.3), (w, 1.5)]));
        assert!(at(&[(t, 3.0), (w, 1.5)]));
        assert_eq!(
            whorls_apart(&sweep),
            Some(false),
            "the turbinate's whorls touch"
        );
    }

    #[test]
    fn a_curve_across_the_axis_has_no_coordinates() {
        let mut sweep = turbinate();
        sweep.spiral.r0 = -1.0;
        assert_eq!(Raup::of(&sweep), None);
    }
}
