//! The field every primitive of the BlobTree gives off: Wyvill's compactly supported falloff
//! g(d) = (1 − d²)³ of the normalised distance d = r / R from the skeleton, zero from d = 1 on
//! (Wyvill, McPheeters & Wyvill 1986; the BlobTree of Wyvill, Guy & Galin 1999). The surface is
//! the iso-value 1/2, so a lone primitive's surface lies at d = √(1 − 2^(−1/3)) ≈ 0.454 of its
//! field radius, and summed fields blend smoothly where supports overlap.

/// The field value on the surface: inside is above it.
pub const ISO: f64 = 0.5;

/// d on the surface of a lone primitive: (1 − d²)³ = ISO.
pub fn surface_ratio() -> f64 {
    (1.0 - libm::cbrt(ISO)).sqrt()
}

/// The field radius R that puts a lone primitive's surface at `radius` from its skeleton.
pub fn support_of(radius: f64) -> f64 {
    radius / surface_ratio()
}

/// g(d²): the falloff of the squared normalised distance.
pub fn falloff(d2: f64) -> f64 {
    if d2 >= 1.0 {
        0.0
    } else {
        let a = 1.0 - d2;
        a * a * a
    }
}

/// dg/d(d²): the falloff's derivative in the squared normalised distance, for gradients.
pub fn falloff_slope(d2: f64) -> f64 {
    if d2 >= 1.0 {
        0.0
    } else {
        let a = 1.0 - d2;
        -3.0 * a * a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn falloff_is_one_at_the_skeleton_half_on_the_surface_and_zero_at_the_support() {
        assert_eq!(falloff(0.0), 1.0);
        let s = surface_ratio();
        assert!((falloff(s * s) - ISO).abs() < 1e-12);
        assert_eq!(falloff(1.0), 0.0);
        assert_eq!(falloff(4.0), 0.0);
        assert!((s - 0.4542).abs() < 1e-4);
    }
}
