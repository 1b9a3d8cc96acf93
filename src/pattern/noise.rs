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
    pub fn fluctuating(&mut self, mean: f64, fraction: f64, count: usize) -> Vec<f32> {
        (0..count)
            .map(|_| (mean * (1.0 + fraction * self.signed())) as f32)
            .collect()
    }

    /// Normal with mean `mean` and standard deviation `deviation` (Box–Muller, through `libm`
    /// so that every platform gives the same bits).
    pub fn normal(&mut self, mean: f64, deviation: f64) -> f64 {
        let u = 1.0 - self.unit();
        let v = self.unit();
        let z = libm::sqrt(-2.0 * libm::log(u)) * libm::cos(std::f64::consts::TAU * v);
        mean + deviation * z
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

    #[test]
    fn normal_values_have_the_asked_mean_and_deviation() {
        let mut n = Noise::new(7, 3);
        let x: Vec<f64> = (0..20_000).map(|_| n.normal(1.0, 0.2)).collect();
        let mean = x.iter().sum::<f64>() / x.len() as f64;
        let var = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / x.len() as f64;
        assert!((mean - 1.0).abs() < 0.01, "{mean}");
        assert!((var.sqrt() - 0.2).abs() < 0.01, "{}", var.sqrt());
        assert!(x.iter().all(|v| v.is_finite()));
    }
}
