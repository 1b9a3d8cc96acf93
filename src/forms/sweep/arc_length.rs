//! Arc-length reparametrization of the generating curve (Fowler et al. 1992, §2.4, eqs 4–7).
//!
//! dl/ds = f(s) = |d𝓒/ds| (eqs 4–5) is integrated over the whole curve to give its length L
//! (eq 6); inverting it (eq 7) gives the parameters s₀ … sₙ whose points divide 𝓒 into n arcs of
//! equal length L/n. The integral is tabulated with Gauss–Legendre quadrature on short
//! sub-intervals, and each sᵢ is then found by Newton's method on l(s) − iL/n, whose derivative
//! is f(s) itself.

use super::bezier_curve::BezierCurve;

/// Sub-intervals per Bézier segment in the length table.
const PIECES_PER_SEGMENT: usize = 32;

/// Five-point Gauss–Legendre nodes and weights on [−1, 1].
const GAUSS: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// The arc length l(s) of a curve, tabulated once so that it can be evaluated and inverted.
#[derive(Clone, Debug)]
pub struct ArcLength {
    /// Parameter at each table knot.
    knots: Vec<f64>,
    /// Arc length from s = 0 to each knot.
    lengths: Vec<f64>,
}

fn integrate(curve: &BezierCurve, a: f64, b: f64) -> f64 {
    let (mid, half) = ((a + b) / 2.0, (b - a) / 2.0);
    GAUSS
        .iter()
        .map(|&(x, w)| w * curve.derivative(mid + half * x).length())
        .sum::<f64>()
        * half
}

impl ArcLength {
    /// Tabulates eq 6 piecewise.
    pub fn new(curve: &BezierCurve) -> Self {
        let pieces = PIECES_PER_SEGMENT * curve.s_max() as usize;
        let knots: Vec<f64> = (0..=pieces)
            .map(|i| curve.s_max() * i as f64 / pieces as f64)
            .collect();
        let mut lengths = Vec::with_capacity(knots.len());
        let mut total = 0.0;
        lengths.push(0.0);
        for pair in knots.windows(2) {
            total += integrate(curve, pair[0], pair[1]);
            lengths.push(total);
        }
        Self { knots, lengths }
    }

    /// L, the length of the whole curve (eq 6).
    pub fn total(&self) -> f64 {
        *self.lengths.last().expect("table has knots")
    }

    fn piece(&self, s: f64) -> usize {
        let i = self.knots.partition_point(|&k| k <= s);
        i.clamp(1, self.knots.len() - 1) - 1
    }

    /// l(s): the arc length from the start of the curve to parameter s.
    pub fn length_at(&self, curve: &BezierCurve, s: f64) -> f64 {
        let i = self.piece(s);
        self.lengths[i] + integrate(curve, self.knots[i], s)
    }

    /// s(l): the parameter at arc length l (eq 7), by Newton's method inside the table piece.
    pub fn parameter_at(&self, curve: &BezierCurve, l: f64) -> f64 {
        let l = l.clamp(0.0, self.total());
        let i = self
            .lengths
            .partition_point(|&x| x <= l)
            .clamp(1, self.knots.len() - 1)
            - 1;
        let (lo, hi) = (self.knots[i], self.knots[i + 1]);
        let span = self.lengths[i + 1] - self.lengths[i];
        let mut s = if span > 0.0 {
            lo + (hi - lo) * (l - self.lengths[i]) / span
        } else {
            lo
        };
        for _ in 0..8 {
            let f = curve.derivative(s).length();
            if f <= f64::EPSILON {
                break;
            }
            let error = self.lengths[i] + integrate(curve, lo, s) - l;
            s = (s - error / f).clamp(lo, hi);
            if error.abs() < 1e-13 * self.total().max(1.0) {
                break;
            }
        }
        s
    }

    /// The n + 1 parameters s₀ = 0 … sₙ = s_max dividing the curve into n arcs of equal length.
    pub fn equal_arcs(&self, curve: &BezierCurve, n: usize) -> Vec<f64> {
        (0..=n)
            .map(|i| match i {
                0 => 0.0,
                i if i == n => curve.s_max(),
                i => self.parameter_at(curve, self.total() * i as f64 / n as f64),
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn lopsided() -> BezierCurve {
        let p = |u, v| DVec3::new(u, v, 0.0);
        BezierCurve::from_points(
            &[
                p(0.0, 0.0),
                p(0.05, 0.0),
                p(0.1, 0.02),
                p(1.0, 1.0),
                p(1.5, 1.5),
                p(2.0, 0.0),
                p(3.0, -0.2),
            ],
            false,
        )
        .unwrap()
    }

    #[test]
    fn straight_line_length_is_exact() {
        let p = |u| DVec3::new(u, 0.0, 0.0);
        let line = BezierCurve::from_points(&[p(0.0), p(0.1), p(0.9), p(2.0)], false).unwrap();
        let table = ArcLength::new(&line);
        assert!((table.total() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn equal_arcs_are_equal() {
        let curve = lopsided();
        let table = ArcLength::new(&curve);
        let s = table.equal_arcs(&curve, 40);
        let target = table.total() / 40.0;
        for pair in s.windows(2) {
            let arc = table.length_at(&curve, pair[1]) - table.length_at(&curve, pair[0]);
            assert!((arc / target - 1.0).abs() < 1e-9, "arc {arc} vs {target}");
        }
    }
}
