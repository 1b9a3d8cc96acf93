//! Seeded randomness with a specified output (PCG-32, via `rand_pcg`), so that the same seed
//! gives the same pattern on every platform.

use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg32;

/// A random stream for one purpose of one pattern.
pub struct Noise(Pcg32);

impl Noise {
    /// The stream for `seed`; `purpose` separates independent uses of the same seed.
    pub fn new(seed: u64, purpose: u64) -> Self {
        Self(Pcg32::seed_from_u64(
            seed ^ purpose.wrapping_mul(0x9e37_79b9_7f4a_7c15),
        ))
    }

    /// Uniform in [0, 1), with 32 random bits.
    pub fn unit(&mut self) -> f64 {
        f64::from(self.0.next_u32()) / 4_294_967_296.0
    }

    /// Uniform in [−1, 1).
    pub fn signed(&mut self) -> f64 {
        2.0 * self.unit() - 1.0
    }

    /// `count` values `mean` · (1 ± `fraction`), uniform: a parameter that fluctuates from cell
    /// to cell (ρ ± 2.5 % in the paper's figures).
    pub fn fluctuating(&mut self, mean: f64, fraction: f64, count: usize) -> Vec<f64> {
        (0..count)
            .map(|_| mean * (1.0 + fraction * self.signed()))
            .collect()
    }

    /// Uniform integer in [0, n).
    pub fn below(&mut self, n: usize) -> usize {
        ((self.unit() * n as f64) as usize).min(n.saturating_sub(1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stream_is_fixed_by_the_seed() {
        let a: Vec<f64> = (0..5)
            .map({
                let mut n = Noise::new(42, 1);
                move |_| n.unit()
            })
            .collect();
        let b: Vec<f64> = (0..5)
            .map({
                let mut n = Noise::new(42, 1);
                move |_| n.unit()
            })
            .collect();
        let c = Noise::new(42, 2).unit();
        assert_eq!(a, b);
        assert_ne!(a[0], c);
        assert!(a.iter().all(|x| (0.0..1.0).contains(x)));
    }
}
