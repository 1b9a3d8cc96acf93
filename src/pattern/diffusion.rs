//! The discrete Laplacian along the growing edge (Δx = 1): a[i−1] − 2a[i] + a[i+1], with
//! zero-flux ends (the missing neighbour mirrors the end cell) or a ring.

use crate::spec::pattern::Boundary;

/// Writes the Laplacian of `v` into `out`.
pub fn laplacian(v: &[f64], boundary: Boundary, out: &mut [f64]) {
    let n = v.len();
    debug_assert_eq!(out.len(), n);
    if n == 1 {
        out[0] = 0.0;
        return;
    }
    for i in 1..n - 1 {
        out[i] = v[i - 1] - 2.0 * v[i] + v[i + 1];
    }
    match boundary {
        Boundary::ZeroFlux => {
            out[0] = v[1] - v[0];
            out[n - 1] = v[n - 2] - v[n - 1];
        }
        Boundary::Periodic => {
            out[0] = v[n - 1] - 2.0 * v[0] + v[1];
            out[n - 1] = v[n - 2] - 2.0 * v[n - 1] + v[0];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_flux_conserves_mass_and_a_ring_wraps() {
        let v = [1.0, 4.0, 2.0, 0.5, 3.0];
        let mut out = [0.0; 5];
        laplacian(&v, Boundary::ZeroFlux, &mut out);
        assert!(out.iter().sum::<f64>().abs() < 1e-12);
        assert_eq!(out[0], 3.0);
        laplacian(&v, Boundary::Periodic, &mut out);
        assert!(out.iter().sum::<f64>().abs() < 1e-12);
        assert_eq!(out[0], 3.0 - 2.0 + 4.0);
        assert_eq!(out[4], 0.5 - 6.0 + 1.0);
    }
}
