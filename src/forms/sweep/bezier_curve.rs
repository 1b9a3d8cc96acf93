//! The generating curve 𝓒 (Fowler et al. 1992, §2.2): one or more cubic Bézier segments in the
//! curve's own uvw coordinate system, open or closed.
//!
//! The parameter s runs from 0 to the number of segments; segment k covers [k, k + 1].

use glam::DVec3;

/// A chain of cubic Bézier segments sharing end points.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve {
    segments: Vec<[DVec3; 4]>,
    closed: bool,
}

impl BezierCurve {
    /// Builds the chain from its control points. An open curve of k segments has 3k + 1 points
    /// (P₀, then two handles and an end point per segment); a closed one has 3k, the last
    /// segment returning to P₀. Returns `None` when the count does not fit.
    pub fn from_points(points: &[DVec3], closed: bool) -> Option<Self> {
        let n = points.len();
        let segments = match (closed, n % 3) {
            (false, 1) if n >= 4 => (n - 1) / 3,
            (true, 0) if n >= 3 => n / 3,
            _ => return None,
        };
        let at = |i: usize| points[i % n];
        let segments = (0..segments)
            .map(|k| [at(3 * k), at(3 * k + 1), at(3 * k + 2), at(3 * k + 3)])
            .collect();
        Some(Self { segments, closed })
    }

    /// Whether the curve returns to its first point.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The parameter range [0, s_max].
    pub fn s_max(&self) -> f64 {
        self.segments.len() as f64
    }

    fn locate(&self, s: f64) -> (&[DVec3; 4], f64) {
        let last = self.segments.len() - 1;
        let k = (s.floor().max(0.0) as usize).min(last);
        (&self.segments[k], (s - k as f64).clamp(0.0, 1.0))
    }

    /// 𝓒(s), in the Bernstein form so that the end points are reproduced exactly.
    pub fn point(&self, s: f64) -> DVec3 {
        let ([p0, p1, p2, p3], x) = self.locate(s);
        let y = 1.0 - x;
        *p0 * (y * y * y) + *p1 * (3.0 * y * y * x) + *p2 * (3.0 * y * x * x) + *p3 * (x * x * x)
    }

    /// d𝓒/ds.
    pub fn derivative(&self, s: f64) -> DVec3 {
        let ([p0, p1, p2, p3], x) = self.locate(s);
        let y = 1.0 - x;
        (*p1 - *p0) * (3.0 * y * y) + (*p2 - *p1) * (6.0 * y * x) + (*p3 - *p2) * (3.0 * x * x)
    }

    /// Twice the signed area enclosed in the uv plane (the curve closed by its chord when open):
    /// positive when the curve turns counter-clockwise, which fixes which side is outside.
    pub fn signed_area_uv(&self) -> f64 {
        let samples = 64 * self.segments.len();
        let mut area = 0.0;
        for i in 0..samples {
            let a = self.point(self.s_max() * i as f64 / samples as f64);
            let b = self.point(self.s_max() * (i + 1) as f64 / samples as f64);
            area += a.x * b.y - b.x * a.y;
        }
        let (first, last) = (self.point(0.0), self.point(self.s_max()));
        area + last.x * first.y - first.x * last.y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec3> {
        let p = |u, v| DVec3::new(u, v, 0.0);
        vec![
            p(0.0, 0.0),
            p(0.3, 0.0),
            p(0.7, 0.0),
            p(1.0, 0.0),
            p(1.0, 0.3),
            p(1.0, 0.7),
            p(1.0, 1.0),
            p(0.7, 1.0),
            p(0.3, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.7),
            p(0.0, 0.3),
        ]
    }

    #[test]
    fn closed_curve_returns_exactly_to_its_start() {
        let c = BezierCurve::from_points(&square(), true).unwrap();
        assert_eq!(c.point(0.0), c.point(c.s_max()));
        assert!(c.signed_area_uv() > 1.9 && c.signed_area_uv() < 2.1);
    }

    #[test]
    fn point_counts_are_checked() {
        assert!(BezierCurve::from_points(&square(), false).is_none());
        assert!(BezierCurve::from_points(&square()[..10], false).is_some());
        assert!(BezierCurve::from_points(&square()[..2], true).is_none());
    }

    #[test]
    fn derivative_matches_finite_differences() {
        let c = BezierCurve::from_points(&square()[..10], false).unwrap();
        for &s in &[0.1, 0.5, 1.5, 2.9] {
            let h = 1e-6;
            let fd = (c.point(s + h) - c.point(s - h)) / (2.0 * h);
            assert!((fd - c.derivative(s)).length() < 1e-6);
        }
    }
}
