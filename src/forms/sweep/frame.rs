//! Orientation of the generating curve's uvw system along the helico-spiral (Fowler et al.
//! 1992, §2.3).
//!
//! Two reference frames (e₁, e₂, e₃) are offered, and the curve's axes are laid on them as the
//! paper does: w along e₁, u along e₂, v along e₃.
//! - **Axis-aligned**: e₁ is the horizontal tangent of the circle about the shell axis, e₂ points
//!   horizontally towards the axis and e₃ along the axis, so v is parallel to the shell axis and
//!   the curve lies in a plane through the axis.
//! - **Frenet** (eq 3): e₁ = 𝓗′/|𝓗′|, e₃ = e₁ × 𝓗″ / |e₁ × 𝓗″|, e₂ = e₃ × e₁, so the curve lies
//!   in the plane normal to the spiral (orthoconical growth markings).
//!
//! For a flat spiral both frames coincide, so the same curve gives comparable shells in either
//! mode. On top of either, the user may rotate uvw about e₁, e₂ and e₃.

use super::helico_spiral::HelicoSpiral;
use crate::spec::form::sweep::FrameMode;
use glam::{DMat3, DVec3};

/// An orthonormal frame (e₁, e₂, e₃) at a point of the helico-spiral.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub e1: DVec3,
    pub e2: DVec3,
    pub e3: DVec3,
}

impl Frame {
    /// The Frenet frame of eq 3, from the analytic derivatives of 𝓗. A spiral that does not
    /// curve has none (r₀ = 0 makes 𝓗 the axis itself, or a point): the axis-aligned frame
    /// stands in, which is the Frenet frame of a flat spiral.
    pub fn frenet(spiral: &HelicoSpiral, t: f64) -> Self {
        let e1 = spiral.derivative(t).try_normalize();
        match e1.and_then(|e1| Some((e1, e1.cross(spiral.second_derivative(t)).try_normalize()?))) {
            Some((e1, e3)) => Self {
                e1,
                e2: e3.cross(e1),
                e3,
            },
            None => Self::axis_aligned(t),
        }
    }

    /// The axis-aligned frame at angle t.
    pub fn axis_aligned(t: f64) -> Self {
        let (s, c) = t.sin_cos();
        Self {
            e1: DVec3::new(-s, c, 0.0),
            e2: DVec3::new(-c, -s, 0.0),
            e3: DVec3::Z,
        }
    }

    /// The frame of the given mode at t.
    pub fn at(mode: FrameMode, spiral: &HelicoSpiral, t: f64) -> Self {
        match mode {
            FrameMode::AxisAligned => Self::axis_aligned(t),
            FrameMode::Frenet => Self::frenet(spiral, t),
        }
    }

    /// The curve's axes (u, v, w) after the user's rotations (radians) about e₁, e₂ and e₃,
    /// applied in that order.
    pub fn curve_axes(&self, rotations: [f64; 3]) -> CurveAxes {
        let to_world = DMat3::from_cols(self.e1, self.e2, self.e3);
        let local = DMat3::from_rotation_z(rotations[2])
            * DMat3::from_rotation_y(rotations[1])
            * DMat3::from_rotation_x(rotations[0]);
        let m = to_world * local;
        CurveAxes {
            u: m * DVec3::Y,
            v: m * DVec3::Z,
            w: m * DVec3::X,
        }
    }
}

/// The generating curve's coordinate axes in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveAxes {
    pub u: DVec3,
    pub v: DVec3,
    pub w: DVec3,
}

impl CurveAxes {
    /// A point given in curve coordinates (u, v, w), scaled by `scale`, in world space relative
    /// to the curve's origin.
    pub fn place(&self, c: DVec3, scale: f64) -> DVec3 {
        (self.u * c.x + self.v * c.y + self.w * c.z) * scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frenet_frame_is_orthonormal_with_e1_along_the_tangent() {
        let spiral = HelicoSpiral::from_step(1.0, 1.9, 1.007, 1.02, 10f64.to_radians());
        for i in 0..100 {
            let t = i as f64 * 0.37;
            let f = Frame::frenet(&spiral, t);
            for (a, b) in [(f.e1, f.e2), (f.e2, f.e3), (f.e3, f.e1)] {
                assert!(a.dot(b).abs() < 1e-12);
            }
            for e in [f.e1, f.e2, f.e3] {
                assert!((e.length() - 1.0).abs() < 1e-12);
            }
            assert!(f.e1.cross(f.e2).distance(f.e3) < 1e-12);
            let tangent = spiral.derivative(t).normalize();
            assert!(f.e1.distance(tangent) < 1e-12);
        }
    }

    #[test]
    fn frames_agree_for_a_flat_spiral_without_growth_in_z() {
        let spiral = HelicoSpiral::from_step(1.0, 0.0, 1.0, 1.0, 0.1);
        for i in 0..20 {
            let t = i as f64 * 0.5;
            let (a, b) = (Frame::frenet(&spiral, t), Frame::axis_aligned(t));
            assert!(a.e1.distance(b.e1) < 1e-12);
            assert!(a.e2.distance(b.e2) < 1e-12);
            assert!(a.e3.distance(b.e3) < 1e-12);
        }
    }

    #[test]
    fn rotations_turn_the_curve_axes_about_the_frame() {
        let f = Frame::axis_aligned(0.3);
        let plain = f.curve_axes([0.0; 3]);
        assert!(plain.u.distance(f.e2) < 1e-15 && plain.v.distance(f.e3) < 1e-15);
        let rolled = f.curve_axes([std::f64::consts::FRAC_PI_2, 0.0, 0.0]);
        assert!(rolled.w.distance(f.e1) < 1e-12, "rotation about e1 keeps w");
        assert!(rolled.u.distance(f.e3) < 1e-12, "and turns u onto e3");
    }
}
