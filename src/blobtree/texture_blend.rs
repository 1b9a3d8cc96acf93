//! Pattern coordinates on an implicit surface, blended by field value (Tigges & Wyvill 1999, as
//! Galbraith et al. §3.4 texture the spines and bumps): every primitive carries its own
//! coordinates, growth time and position along the generating curve, and a surface point takes
//! the average of those of the primitives around it, each weighted by its field there. The
//! position along the curve is periodic, so it is averaged as an angle (on the unit circle):
//! two primitives at 0.99 and 0.01 blend to 0, not to 0.5.

use glam::{DAffine3, DVec3};
use std::f64::consts::TAU;

/// The pattern coordinates a primitive carries: its growth time, and, for its position along
/// the generating curve, the angle of a point about the w axis of the generating surface,
/// measured in the generating curve's plane from +u (towards the shell axis, where whorls meet
/// and the pattern's seam hides) through +v.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texture {
    /// Growth time, in pattern rows.
    pub time: f64,
    /// Carries the primitive's coordinates to the generating surface's.
    frame: DAffine3,
}

impl Texture {
    /// Coordinates of a primitive in the generating surface's own space.
    pub fn around(time: f64) -> Self {
        Self {
            time,
            frame: DAffine3::IDENTITY,
        }
    }

    /// The same coordinates for a primitive expressed in new coordinates, `inverse` carrying
    /// the new coordinates to the old (the inverse of the map that moved it).
    pub fn moved(self, inverse: DAffine3) -> Self {
        Self {
            frame: self.frame * inverse,
            ..self
        }
    }

    /// The direction of the point `p` about the w axis, as (cos, sin) of its angle from +u:
    /// the position along the curve, without trigonometry. (1, 0) on the axis itself.
    fn direction_at(&self, p: DVec3) -> (f64, f64) {
        let q = self.frame.transform_point3(p);
        let length = (q.x * q.x + q.y * q.y).sqrt();
        if length > 0.0 {
            (q.x / length, q.y / length)
        } else {
            (1.0, 0.0)
        }
    }
}

/// Field-weighted sums of pattern coordinates.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Paint {
    weight: f64,
    cos: f64,
    sin: f64,
    time: f64,
    /// Whether the point lies on a surface carved by a CSG difference: the inside of a wall.
    pub inner: bool,
}

impl Paint {
    /// A primitive's coordinates at local point `p`, weighted by its field `f`.
    pub fn of(texture: &Texture, p: DVec3, f: f64) -> Self {
        let (cos, sin) = texture.direction_at(p);
        Self {
            weight: f,
            cos: f * cos,
            sin: f * sin,
            time: f * texture.time,
            inner: false,
        }
    }

    /// The same contribution, on a carved surface.
    pub fn carved(self) -> Paint {
        Paint {
            inner: true,
            ..self
        }
    }

    /// (position along the curve in [0, 1), growth time): the weighted averages.
    pub fn coordinates(&self) -> [f64; 2] {
        if self.weight <= 0.0 {
            return [0.0, 0.0];
        }
        let along = (libm::atan2(self.sin, self.cos) / TAU).rem_euclid(1.0);
        [along, self.time / self.weight]
    }
}

impl std::ops::Add for Paint {
    type Output = Paint;

    /// The sum of two blended contributions.
    fn add(self, other: Paint) -> Paint {
        Paint {
            weight: self.weight + other.weight,
            cos: self.cos + other.cos,
            sin: self.sin + other.sin,
            time: self.time + other.time,
            inner: self.inner || other.inner,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_blend_by_weight_and_wrap_around_the_curve() {
        let (a, b) = (Texture::around(10.0), Texture::around(20.0));
        let at = |turn: f64| DVec3::new((turn * TAU).cos(), (turn * TAU).sin(), 0.3);
        let (pa, pb) = (at(0.98), at(0.04));
        let blend = Paint::of(&a, pa, 1.0) + Paint::of(&b, pb, 1.0);
        let [along, time] = blend.coordinates();
        assert!((time - 15.0).abs() < 1e-12);
        assert!((along - 0.01).abs() < 1e-9, "{along}");
        let weighted = Paint::of(&a, DVec3::ZERO, 3.0) + Paint::of(&b, DVec3::ZERO, 1.0);
        assert!((weighted.coordinates()[1] - 12.5).abs() < 1e-12);
    }

    #[test]
    fn the_angle_runs_around_the_local_w_axis_from_u() {
        let t = Texture::around(0.0);
        let at = |p: DVec3| Paint::of(&t, p, 1.0).coordinates()[0];
        assert!(at(DVec3::new(1.0, 0.0, 5.0)).abs() < 1e-12);
        assert!((at(DVec3::new(0.0, 1.0, 0.0)) - 0.25).abs() < 1e-12);
        assert!((at(DVec3::new(-1.0, 1e-9, 0.0)) - 0.5).abs() < 1e-6);
    }
}
