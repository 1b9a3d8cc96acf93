//! The logarithmic helico-spiral 𝓗 of Fowler, Meinhardt & Prusinkiewicz 1992, §2.1.
//!
//! In cylindrical coordinates (eq 1): θ = t, r = r₀ ξᵣᵗ, z = z₀ ξ_zᵗ. The paper gives the
//! growth per angular step Δθ as λᵣ = ξᵣ^Δθ and λ_z = ξ_z^Δθ (eq 2); [`SpiralWalk`] follows the
//! incremental form of eq 2, [`HelicoSpiral`] the closed form of eq 1 and its derivatives, from
//! which the Frenet frame (eq 3) is computed.

use glam::DVec3;

/// The helico-spiral of eq 1, parametrised by the angle t (radians).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HelicoSpiral {
    /// r₀: distance from the axis at t = 0.
    pub r0: f64,
    /// z₀: height above the plane z = 0 at t = 0.
    pub z0: f64,
    /// ln ξᵣ: the radial growth rate per radian.
    pub ln_xi_r: f64,
    /// ln ξ_z: the axial growth rate per radian.
    pub ln_xi_z: f64,
}

impl HelicoSpiral {
    /// The spiral whose radius grows by `lambda_r` and height by `lambda_z` every
    /// `delta_theta` radians (eq 2: λ = ξ^Δθ).
    pub fn from_step(r0: f64, z0: f64, lambda_r: f64, lambda_z: f64, delta_theta: f64) -> Self {
        Self {
            r0,
            z0,
            ln_xi_r: lambda_r.ln() / delta_theta,
            ln_xi_z: lambda_z.ln() / delta_theta,
        }
    }

    /// 𝓗(t), eq 1.
    pub fn point(&self, t: f64) -> DVec3 {
        let r = self.r0 * (self.ln_xi_r * t).exp();
        let z = self.z0 * (self.ln_xi_z * t).exp();
        DVec3::new(r * t.cos(), r * t.sin(), z)
    }

    /// 𝓗′(t), the first derivative with respect to t.
    pub fn derivative(&self, t: f64) -> DVec3 {
        let a = self.ln_xi_r;
        let r = self.r0 * (a * t).exp();
        let z = self.z0 * (self.ln_xi_z * t).exp();
        let (s, c) = t.sin_cos();
        DVec3::new(r * (a * c - s), r * (a * s + c), self.ln_xi_z * z)
    }

    /// 𝓗″(t), the second derivative with respect to t.
    pub fn second_derivative(&self, t: f64) -> DVec3 {
        let a = self.ln_xi_r;
        let r = self.r0 * (a * t).exp();
        let z = self.z0 * (self.ln_xi_z * t).exp();
        let (s, c) = t.sin_cos();
        DVec3::new(
            r * ((a * a - 1.0) * c - 2.0 * a * s),
            r * ((a * a - 1.0) * s + 2.0 * a * c),
            self.ln_xi_z * self.ln_xi_z * z,
        )
    }
}

/// One point of the incremental walk of eq 2: θᵢ, rᵢ, zᵢ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpiralPoint {
    pub theta: f64,
    pub r: f64,
    pub z: f64,
}

impl SpiralPoint {
    /// The point in Cartesian coordinates.
    pub fn position(&self) -> DVec3 {
        DVec3::new(self.r * self.theta.cos(), self.r * self.theta.sin(), self.z)
    }
}

/// The incremental form of eq 2: θᵢ₊₁ = θᵢ + Δθ, rᵢ₊₁ = rᵢ λᵣ, zᵢ₊₁ = zᵢ λ_z.
#[derive(Clone, Debug)]
pub struct SpiralWalk {
    next: SpiralPoint,
    delta_theta: f64,
    lambda_r: f64,
    lambda_z: f64,
}

impl SpiralWalk {
    /// Starts at θ = 0, r = r₀, z = z₀.
    pub fn new(r0: f64, z0: f64, lambda_r: f64, lambda_z: f64, delta_theta: f64) -> Self {
        Self {
            next: SpiralPoint {
                theta: 0.0,
                r: r0,
                z: z0,
            },
            delta_theta,
            lambda_r,
            lambda_z,
        }
    }
}

impl Iterator for SpiralWalk {
    type Item = SpiralPoint;

    fn next(&mut self) -> Option<SpiralPoint> {
        let current = self.next;
        self.next = SpiralPoint {
            theta: current.theta + self.delta_theta,
            r: current.r * self.lambda_r,
            z: current.z * self.lambda_z,
        };
        Some(current)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn walk_is_a_geometric_progression_matching_eq_1() {
        let dtheta = 10f64.to_radians();
        let spiral = HelicoSpiral::from_step(1.0, 1.9, 1.007, 1.007, dtheta);
        let walk = SpiralWalk::new(1.0, 1.9, 1.007, 1.007, dtheta);
        let points: Vec<_> = walk.take(200).collect();
        for pair in points.windows(2) {
            assert!((pair[1].r / pair[0].r - 1.007).abs() < 1e-12);
            assert!((pair[1].z / pair[0].z - 1.007).abs() < 1e-12);
            assert!((pair[1].theta - pair[0].theta - dtheta).abs() < 1e-12);
        }
        for p in &points {
            let q = spiral.point(p.theta);
            assert!((p.position() - q).length() < 1e-9 * q.length());
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let spiral = HelicoSpiral::from_step(1.3, 0.7, 1.03, 1.01, PI / 18.0);
        for &t in &[0.0, 1.0, 7.5, 20.0] {
            let h = 1e-5;
            let d1 = (spiral.point(t + h) - spiral.point(t - h)) / (2.0 * h);
            let d2 = (spiral.derivative(t + h) - spiral.derivative(t - h)) / (2.0 * h);
            let scale = spiral.point(t).length();
            assert!((d1 - spiral.derivative(t)).length() < 1e-6 * scale);
            assert!((d2 - spiral.second_derivative(t)).length() < 1e-6 * scale);
        }
    }
}
