//! The skeletal primitives of the BlobTree (Galbraith, Prusinkiewicz & Wyvill, §2.2): each is a
//! skeleton (a point, a tapered segment, a circle) whose field falls off with the distance from
//! it, normalised by a field radius, through [`falloff`]. A line segment is the cone whose two
//! radii are equal. Radii here are field radii (supports); [`support_of`] turns the radius of
//! the surface a lone primitive shows into one.
//!
//! [`support_of`]: super::falloff::support_of

use super::falloff::{falloff, falloff_slope, surface_ratio};
use crate::mesh::Bounds;
use glam::{DAffine3, DVec3};

/// One skeletal primitive.
#[derive(Clone, Debug, PartialEq)]
pub enum Primitive {
    /// A point with field radius `radius`: a sphere alone.
    Point { centre: DVec3, radius: f64 },
    /// A segment from `from` to `to` whose field radius changes linearly from `radii[0]` to
    /// `radii[1]`: a tapered cylinder with rounded ends alone.
    Cone {
        from: DVec3,
        to: DVec3,
        radii: [f64; 2],
    },
    /// A circle of radius `major` about `axis` (a unit vector) through `centre`, with field
    /// radius `radius` around it.
    Torus {
        centre: DVec3,
        axis: DVec3,
        major: f64,
        radius: f64,
    },
}

impl Primitive {
    /// The field at `p`, in [0, 1].
    pub fn field(&self, p: DVec3) -> f64 {
        match *self {
            Primitive::Point { centre, radius } => {
                falloff(p.distance_squared(centre) / (radius * radius))
            }
            Primitive::Cone { from, to, radii } => {
                let (axis, _, t) = projection(p, from, to);
                let t = t.clamp(0.0, 1.0);
                let r = radii[0] + t * (radii[1] - radii[0]);
                falloff(p.distance_squared(from + t * axis) / (r * r))
            }
            Primitive::Torus {
                centre,
                axis,
                major,
                radius,
            } => {
                let (h, _, length) = ring_offset(p, centre, axis);
                let rho = length - major;
                falloff((rho * rho + h * h) / (radius * radius))
            }
        }
    }

    /// The field at `p` with its gradient, by the chain rule through the squared normalised
    /// distance d² (the field is [`Primitive::field`], bit for bit). Beyond the support both
    /// are zero, and the gradient is not worked out.
    pub fn field_gradient(&self, p: DVec3) -> (f64, DVec3) {
        const NONE: (f64, DVec3) = (0.0, DVec3::ZERO);
        let (d2, grad_d2) = match *self {
            Primitive::Point { centre, radius } => {
                let r2 = radius * radius;
                let d2 = p.distance_squared(centre) / r2;
                if d2 >= 1.0 {
                    return NONE;
                }
                (d2, (p - centre) * (2.0 / r2))
            }
            Primitive::Cone { from, to, radii } => {
                let (axis, length2, t) = projection(p, from, to);
                let free = t > 0.0 && t < 1.0;
                let t = t.clamp(0.0, 1.0);
                let r = radii[0] + t * (radii[1] - radii[0]);
                let v = p - (from + t * axis);
                let d2 = p.distance_squared(from + t * axis) / (r * r);
                if d2 >= 1.0 {
                    return NONE;
                }
                // Where t follows p, the radius does too: ∂(1/r²)/∂p = −2 r′ ∇t / r³.
                let taper = if free {
                    axis * (-2.0 * d2 * (radii[1] - radii[0]) / (r * length2))
                } else {
                    DVec3::ZERO
                };
                (d2, v * (2.0 / (r * r)) + taper)
            }
            Primitive::Torus {
                centre,
                axis,
                major,
                radius,
            } => {
                let (h, ring, length) = ring_offset(p, centre, axis);
                let rho = length - major;
                let r2 = radius * radius;
                let d2 = (rho * rho + h * h) / r2;
                if d2 >= 1.0 {
                    return NONE;
                }
                let outward = if length > 0.0 {
                    ring / length
                } else {
                    DVec3::ZERO
                };
                (d2, (outward * rho + axis * h) * (2.0 / r2))
            }
        };
        (falloff(d2), grad_d2 * falloff_slope(d2))
    }

    /// Where `p` lies along the primitive's own parameterisation, from 0 to 1, for a colour
    /// ramp painted on it (Galbraith et al. §3.4: each part textured in its own coordinates):
    /// along a cone's segment from `from` (0) to `to` (1); on a point, from the edge of its
    /// field (0) to a lone point's surface and inside it (1), so that a bump is darkest on its
    /// top and fades where it melts into the whorl; 0 on a torus.
    pub fn along(&self, p: DVec3) -> f64 {
        match *self {
            Primitive::Point { centre, radius } => {
                let d = p.distance(centre) / radius;
                ((1.0 - d) / (1.0 - surface_ratio())).clamp(0.0, 1.0)
            }
            Primitive::Cone { from, to, .. } => projection(p, from, to).2.clamp(0.0, 1.0),
            Primitive::Torus { .. } => 0.0,
        }
    }

    /// Where `p` lies on the primitive's own 2D parameterisation, by which an image is mapped
    /// onto it (the paper's faster texturing, §3.4): (around, along), each in [0, 1]. On a
    /// cone, around its segment from a direction square to it (the same for the same cone),
    /// and along the segment ([`Primitive::along`]); on a point, around its x axis (the way a
    /// bump stands out of its surface, `bumps.rs`) from y, and along from a right angle to x,
    /// where a bump leaves its surface, to x, its top; on a torus, around its axis, 0 along.
    pub fn mapped(&self, p: DVec3) -> [f64; 2] {
        let turn = |y: f64, x: f64| (libm::atan2(y, x) / std::f64::consts::TAU).rem_euclid(1.0);
        let around = |axis: DVec3, q: DVec3| {
            let x = axis.any_orthonormal_vector();
            turn(q.dot(axis.cross(x)), q.dot(x))
        };
        match *self {
            Primitive::Point { centre, .. } => {
                let q = p - centre;
                let off_axis = q.y.hypot(q.z);
                let from_top = libm::atan2(off_axis, q.x) / std::f64::consts::FRAC_PI_2;
                [turn(q.z, q.y), (1.0 - from_top).clamp(0.0, 1.0)]
            }
            Primitive::Cone { from, to, .. } => [
                around((to - from).normalize_or(DVec3::Z), p - from),
                self.along(p),
            ],
            Primitive::Torus { centre, axis, .. } => [around(axis, p - centre), 0.0],
        }
    }

    /// The primitive moved by a similarity `m` (a map that scales all lengths by `scale`).
    pub fn moved(&self, m: &DAffine3, scale: f64) -> Primitive {
        match *self {
            Primitive::Point { centre, radius } => Primitive::Point {
                centre: m.transform_point3(centre),
                radius: radius * scale,
            },
            Primitive::Cone { from, to, radii } => Primitive::Cone {
                from: m.transform_point3(from),
                to: m.transform_point3(to),
                radii: radii.map(|r| r * scale),
            },
            Primitive::Torus {
                centre,
                axis,
                major,
                radius,
            } => Primitive::Torus {
                centre: m.transform_point3(centre),
                axis: m.transform_vector3(axis).normalize(),
                major: major * scale,
                radius: radius * scale,
            },
        }
    }

    /// The box outside which the field is zero.
    pub fn bounds(&self) -> Bounds {
        match *self {
            Primitive::Point { centre, radius } => Bounds {
                min: centre - radius,
                max: centre + radius,
            },
            Primitive::Cone { from, to, radii } => Bounds {
                min: (from - radii[0]).min(to - radii[1]),
                max: (from + radii[0]).max(to + radii[1]),
            },
            Primitive::Torus {
                centre,
                axis,
                major,
                radius,
            } => {
                // The circle's extent along each world axis is major·√(1 − axisᵢ²).
                let reach =
                    (DVec3::ONE - axis * axis).max(DVec3::ZERO).map(f64::sqrt) * major + radius;
                Bounds {
                    min: centre - reach,
                    max: centre + reach,
                }
            }
        }
    }

    /// Bounds (lowest, highest) on the field throughout the ball of `reach` about `centre`:
    /// the distance to the skeleton changes no faster than the point, and the falloff only
    /// falls with it. A cone's field radius is taken over the part of its axis the ball
    /// projects onto (t moves by at most reach / |axis|), so that a tapering spine is bounded
    /// by its radius there, not by its widest.
    pub fn range(&self, centre: DVec3, reach: f64) -> (f64, f64) {
        let (distance, [thin, thick]) = match *self {
            Primitive::Point { centre: c, radius } => (centre.distance(c), [radius, radius]),
            Primitive::Cone { from, to, radii } => {
                let (axis, length2, t) = projection(centre, from, to);
                let spread = if length2 > 0.0 {
                    reach / length2.sqrt()
                } else {
                    0.0
                };
                let radius = |t: f64| radii[0] + t.clamp(0.0, 1.0) * (radii[1] - radii[0]);
                let (a, b) = (radius(t - spread), radius(t + spread));
                (
                    centre.distance(from + t.clamp(0.0, 1.0) * axis),
                    [a.min(b), a.max(b)],
                )
            }
            Primitive::Torus {
                centre: c,
                axis,
                major,
                radius,
            } => {
                let (h, _, length) = ring_offset(centre, c, axis);
                let rho = length - major;
                ((rho * rho + h * h).sqrt(), [radius, radius])
            }
        };
        let near = (distance - reach).max(0.0) / thick;
        let far = (distance + reach) / thin;
        (falloff(far * far), falloff(near * near))
    }
}

/// The cone's axis `to − from`, its squared length and the parameter t of the projection of `p`
/// onto the axis's line (0 for a cone of no length), before any clamping.
fn projection(p: DVec3, from: DVec3, to: DVec3) -> (DVec3, f64, f64) {
    let axis = to - from;
    let length2 = axis.length_squared();
    let t = if length2 > 0.0 {
        (p - from).dot(axis) / length2
    } else {
        0.0
    };
    (axis, length2, t)
}

/// `p` relative to a torus's circle about `axis` through `centre`: its height h along the
/// axis, its offset from the axis within the circle's plane, and that offset's length.
fn ring_offset(p: DVec3, centre: DVec3, axis: DVec3) -> (f64, DVec3, f64) {
    let q = p - centre;
    let h = q.dot(axis);
    let ring = q - h * axis;
    (h, ring, ring.length())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::blobtree::falloff::{ISO, surface_ratio};

    fn inside(p: &Primitive, at: DVec3) -> bool {
        p.field(at) > ISO
    }

    #[test]
    fn each_primitive_is_inside_near_its_skeleton_and_outside_beyond_its_surface() {
        let s = surface_ratio();
        let point = Primitive::Point {
            centre: DVec3::new(1.0, 2.0, 3.0),
            radius: 2.0,
        };
        assert!(inside(&point, DVec3::new(1.0, 2.0, 3.0)));
        assert!(inside(&point, DVec3::new(1.0 + 1.9 * s, 2.0, 3.0)));
        assert!(!inside(&point, DVec3::new(1.0, 2.0 + 2.1 * s, 3.0)));

        let segment = Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * 4.0,
            radii: [1.0, 1.0],
        };
        assert!(inside(&segment, DVec3::new(2.0, 0.9 * s, 0.0)));
        assert!(!inside(&segment, DVec3::new(2.0, 1.1 * s, 0.0)));
        assert!(!inside(&segment, DVec3::new(4.0 + 1.1 * s, 0.0, 0.0)));

        let cone = Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::Z * 4.0,
            radii: [2.0, 0.5],
        };
        assert!(inside(&cone, DVec3::new(1.9 * s, 0.0, 0.0)));
        assert!(!inside(&cone, DVec3::new(1.0 * s, 0.0, 4.0)));
        assert!(inside(&cone, DVec3::new(0.4 * s, 0.0, 4.0)));

        let torus = Primitive::Torus {
            centre: DVec3::ZERO,
            axis: DVec3::Z,
            major: 3.0,
            radius: 1.0,
        };
        assert!(inside(&torus, DVec3::new(0.0, 3.0, 0.0)));
        assert!(!inside(&torus, DVec3::ZERO), "the hole is outside");
        assert!(!inside(&torus, DVec3::new(3.0, 0.0, 1.1 * s)));
    }

    #[test]
    fn the_gradient_matches_central_differences_and_the_field_is_the_same() {
        let primitives = [
            Primitive::Point {
                centre: DVec3::new(0.3, -0.2, 0.1),
                radius: 0.9,
            },
            Primitive::Cone {
                from: DVec3::new(-1.0, 0.0, 0.2),
                to: DVec3::new(1.0, 0.5, -0.3),
                radii: [0.9, 0.3],
            },
            Primitive::Torus {
                centre: DVec3::ZERO,
                axis: DVec3::new(1.0, 1.0, 0.0).normalize(),
                major: 0.8,
                radius: 0.5,
            },
        ];
        for p in &primitives {
            for i in 0..2000 {
                let t = f64::from(i);
                let at = DVec3::new((t * 0.37).sin(), (t * 0.53).cos(), (t * 0.71).sin()) * 1.2;
                let (f, g) = p.field_gradient(at);
                assert_eq!(f, p.field(at));
                let h = 1e-6;
                let diff = DVec3::new(
                    p.field(at + DVec3::X * h) - p.field(at - DVec3::X * h),
                    p.field(at + DVec3::Y * h) - p.field(at - DVec3::Y * h),
                    p.field(at + DVec3::Z * h) - p.field(at - DVec3::Z * h),
                ) / (2.0 * h);
                assert!(
                    diff.distance(g) < 1e-5 * (1.0 + g.length()),
                    "{p:?} at {at}: {diff} vs {g}"
                );
            }
        }
    }

    #[test]
    fn the_field_vanishes_outside_the_bounds_and_stays_within_its_range_over_a_ball() {
        let primitives = [
            Primitive::Point {
                centre: DVec3::new(0.3, -0.2, 0.1),
                radius: 0.7,
            },
            Primitive::Cone {
                from: DVec3::new(-1.0, 0.0, 0.2),
                to: DVec3::new(1.0, 0.5, -0.3),
                radii: [0.6, 0.2],
            },
            Primitive::Torus {
                centre: DVec3::ZERO,
                axis: DVec3::new(1.0, 1.0, 0.0).normalize(),
                major: 1.0,
                radius: 0.4,
            },
        ];
        let point = |t: f64| DVec3::new((t * 0.37).sin(), (t * 0.53).cos(), (t * 0.71).sin());
        for p in &primitives {
            let b = p.bounds();
            for i in 0..4000 {
                let at = point(f64::from(i)) * 2.0;
                if p.field(at) > 0.0 {
                    assert!(
                        at.cmpge(b.min).all() && at.cmple(b.max).all(),
                        "{p:?} at {at}"
                    );
                }
            }
            let (mut tight, mut missed) = (0, 0);
            for i in 0..300 {
                let centre = point(f64::from(i) * 1.3) * 1.5;
                let reach = 0.05 + 0.3 * f64::from(i % 7) / 7.0;
                let (lo, hi) = p.range(centre, reach);
                let misses = hi == 0.0;
                for j in 0..60 {
                    let at = centre + point(f64::from(j) * 2.1 + 0.5) * reach / 1.8;
                    let f = p.field(at);
                    assert!(lo <= f && f <= hi, "{p:?}: {f} outside [{lo}, {hi}]");
                    assert!(
                        !misses || f == 0.0,
                        "{p:?} misses {centre} but is {f} at {at}"
                    );
                }
                tight += usize::from(hi - lo < 0.5);
                missed += usize::from(misses);
            }
            assert!(
                tight > 100 && missed > 20,
                "{p:?}: {tight} tight, {missed} missed"
            );
        }
    }

    #[test]
    fn a_tapering_cone_is_bounded_by_its_radius_where_the_ball_is() {
        // A spine: wide at its base, thin at its tip. Beside the tip, the field is zero, and
        // the range must prove it (the base's radius would allow a field of 0.88).
        let spine = Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::new(10.0, 0.0, 0.0),
            radii: [2.0, 0.2],
        };
        let (centre, reach) = (DVec3::new(10.0, 0.5, 0.0), 0.1);
        assert_eq!(spine.range(centre, reach), (0.0, 0.0));
        // Along the axis the radius is taken over all the ball projects onto.
        let (lo, hi) = spine.range(DVec3::new(5.0, 0.0, 0.0), 1.0);
        let widest = spine.field(DVec3::new(4.0, 0.0, 0.0));
        assert!(lo <= spine.field(DVec3::new(6.0, 0.9, 0.0)) && widest <= hi);
    }
}
