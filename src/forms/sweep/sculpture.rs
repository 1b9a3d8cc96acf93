//! Sculpture on the shell surface (Fowler et al. 1992, §2.5): a displacement d along the
//! surface normal, periodic along the generating curve (ribs parallel to the direction of
//! growth), along the helico-spiral (ribs parallel to the generating curve), or both (a
//! lattice). The displacement is returned relative to the current size of the curve, so the
//! caller multiplies it by that size and the ribs grow with the shell.

use crate::spec::form::sweep::{RibSpec, SculptureSpec};
use std::f64::consts::TAU;

/// The periodic rib profile ((1 + cos 2πx) / 2)^p: 1 on a crest (integer x), 0 between ribs.
fn profile(x: f64, sharpness: f64) -> f64 {
    let c = 0.5 * (1.0 + (TAU * x).cos());
    c.powf(sharpness)
}

/// Number of periods of a family whose frequency changes by `change` per whorl, integrated
/// from t = 0: ∫₀ᵗ count · change^(τ/2π) dτ / 2π.
fn periods(count: f64, change: f64, t: f64) -> f64 {
    let whorls = t / TAU;
    if (change - 1.0).abs() < 1e-12 {
        count * whorls
    } else {
        count * (change.powf(whorls) - 1.0) / change.ln()
    }
}

fn is_on(ribs: &RibSpec) -> bool {
    ribs.amplitude != 0.0 && ribs.count > 0.0
}

/// The relative displacement d(l, t) at arc-length fraction l ∈ [0, 1] of the curve and angle t.
///
/// Growth ribs: `count · change^(t/2π)` ribs across the curve, their phase advancing by `drift`
/// periods per whorl (oblique ribs). Curve ribs: `count · change^(t/2π)` ribs per whorl along
/// the spiral, with the phase integrated so that a changing frequency never jumps.
pub fn displacement(sculpture: &SculptureSpec, l: f64, t: f64) -> f64 {
    let mut d = 0.0;
    let g = &sculpture.growth_ribs;
    if is_on(g) {
        let count = g.count * g.frequency_change.powf(t / TAU);
        d += g.amplitude * profile(count * l + g.drift * t / TAU, g.sharpness);
    }
    let c = &sculpture.curve_ribs;
    if is_on(c) {
        d += c.amplitude * profile(periods(c.count, c.frequency_change, t), c.sharpness);
    }
    d
}

/// Whether any sculpture is present.
pub fn is_sculpted(sculpture: &SculptureSpec) -> bool {
    is_on(&sculpture.growth_ribs) || is_on(&sculpture.curve_ribs)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ribs(amplitude: f64, count: f64) -> RibSpec {
        RibSpec {
            amplitude,
            count,
            ..RibSpec::NONE
        }
    }

    #[test]
    fn growth_ribs_are_periodic_along_the_curve() {
        let s = SculptureSpec {
            growth_ribs: ribs(0.1, 8.0),
            curve_ribs: RibSpec::NONE,
        };
        for i in 0..50 {
            let l = i as f64 / 400.0;
            assert!(
                (displacement(&s, l, 2.0) - displacement(&s, l + 1.0 / 8.0, 2.0)).abs() < 1e-12
            );
            assert!((displacement(&s, l, 2.0) - displacement(&s, l, 9.0)).abs() < 1e-12);
        }
        assert!((displacement(&s, 0.0, 0.0) - 0.1).abs() < 1e-15);
        assert!(displacement(&s, 1.0 / 16.0, 0.0).abs() < 1e-15);
    }

    #[test]
    fn curve_ribs_are_periodic_along_the_spiral() {
        let s = SculptureSpec {
            growth_ribs: RibSpec::NONE,
            curve_ribs: ribs(0.05, 12.0),
        };
        let period = TAU / 12.0;
        for i in 0..50 {
            let t = i as f64 * 0.13;
            assert!((displacement(&s, 0.3, t) - displacement(&s, 0.3, t + period)).abs() < 1e-12);
            assert!((displacement(&s, 0.3, t) - displacement(&s, 0.9, t)).abs() < 1e-12);
        }
    }

    #[test]
    fn a_changing_frequency_keeps_the_phase_continuous_and_slows_down() {
        let mut r = ribs(1.0, 10.0);
        r.frequency_change = 0.5;
        let early =
            periods(r.count, r.frequency_change, 0.5) - periods(r.count, r.frequency_change, 0.0);
        let late = periods(r.count, r.frequency_change, TAU * 3.0 + 0.5)
            - periods(r.count, r.frequency_change, TAU * 3.0);
        assert!(
            (late / early - 0.125).abs() < 0.01,
            "three whorls later a period is 8 times longer"
        );
        for i in 0..100 {
            let t = i as f64 * 0.1;
            let step = periods(10.0, 0.5, t + 1e-6) - periods(10.0, 0.5, t);
            assert!(step > 0.0 && step < 1e-4);
        }
    }

    #[test]
    fn drift_gives_oblique_ribs() {
        let mut g = ribs(1.0, 5.0);
        g.drift = 1.0;
        let s = SculptureSpec {
            growth_ribs: g,
            curve_ribs: RibSpec::NONE,
        };
        // Half a whorl later the crest has moved by half a rib period along the curve.
        let crest_at_0 = displacement(&s, 0.0, 0.0);
        assert!((displacement(&s, -0.1, TAU / 2.0) - crest_at_0).abs() < 1e-12);
    }
}
