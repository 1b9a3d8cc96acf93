//! The tendril's self-adjustment law (Kawaguchi 1982, "Extension of generating model", steps
//! 2–5): the rolling angle α of a branch changes by θ at every knot, α(i) = α(i) ± θ; whenever
//! it leaves k₀ < α < k₁ a force β of the opposite direction acts on it,
//! α(i) = α(i) ± θ ∓ β, and from then on it rolls the other way, until the other limit turns
//! it back again. Without the force (β = 0) α rolls on and never turns.

use crate::spec::form::branching::KnotSpec;

/// The rolling state of one branch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tendril {
    /// α, degrees.
    pub alpha: f64,
    /// The direction α is rolling in: +1 or −1.
    pub sense: f64,
}

impl Tendril {
    /// A branch's state at its first knot.
    pub fn start(knot: &KnotSpec) -> Self {
        Self {
            alpha: knot.angle,
            sense: 1.0,
        }
    }

    /// The state at the next knot, and whether the self-adjusting force acted (the branch
    /// turned).
    pub fn next(self, knot: &KnotSpec) -> (Self, bool) {
        let mut alpha = self.alpha + self.sense * knot.roll;
        let mut sense = self.sense;
        let mut turned = false;
        if knot.beta > 0.0 {
            if alpha > knot.k1 {
                alpha -= knot.beta;
                sense = -1.0;
                turned = true;
            } else if alpha < knot.k0 {
                alpha += knot.beta;
                sense = 1.0;
                turned = true;
            }
        }
        (Self { alpha, sense }, turned)
    }
}
