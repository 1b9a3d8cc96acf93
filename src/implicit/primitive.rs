//! The skeletal primitives of the BlobTree (Galbraith, Prusinkiewicz & Wyvill, §2.2): each is a
//! skeleton (a point, a tapered segment, a circle) whose field falls off with the distance from
//! it, normalised by a field radius, through [`falloff`]. A line segment is the cone whose two
//! radii are equal. Radii here are field radii (supports); [`support_of`] turns the radius of
//! the surface a lone primitive shows into one.
//!
//! [`support_of`]: super::falloff::support_of

use super::falloff::{SLOPE, falloff};
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
                let axis = to - from;
                let length2 = axis.length_squared();
                let t = if length2 > 0.0 {
                    ((p - from).dot(axis) / length2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let r = radii[0] + t * (radii[1] - radii[0]);
                falloff(p.distance_squared(from + t * axis) / (r * r))
            }
            Primitive::Torus {
                centre,
                axis,
                major,
                radius,
            } => {
                let q = p - centre;
                let h = q.dot(axis);
                let rho = (q - h * axis).length() - major;
                falloff((rho * rho + h * h) / (radius * radius))
            }
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

    /// A bound on |∇f|: the falloff's steepest slope over the smallest field radius, times how
    /// fast the normalised distance can change.
    pub fn lipschitz(&self) -> f64 {
        match *self {
            Primitive::Point { radius, .. } | Primitive::Torus { radius, .. } => SLOPE / radius,
            Primitive::Cone { from, to, radii } => {
                let (small, large) = (radii[0].min(radii[1]), radii[0].max(radii[1]));
                let length = from.distance(to);
                let taper = if length > 0.0 {
                    (radii[1] - radii[0]).abs() / length
                } else {
                    0.0
                };
                SLOPE / small * (1.0 + large / small * taper)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::implicit::falloff::{ISO, surface_ratio};

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
    fn the_field_vanishes_outside_the_bounds_and_changes_no_faster_than_the_bound() {
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
        for p in &primitives {
            let b = p.bounds();
            let l = p.lipschitz();
            for i in 0..4000 {
                let t = f64::from(i);
                let at = DVec3::new((t * 0.37).sin(), (t * 0.53).cos(), (t * 0.71).sin()) * 2.0;
                if p.field(at) > 0.0 {
                    assert!(
                        at.cmpge(b.min).all() && at.cmple(b.max).all(),
                        "{p:?} at {at}"
                    );
                }
                let step = DVec3::new(1e-4, -2e-4, 1.5e-4);
                let slope = (p.field(at + step) - p.field(at)).abs() / step.length();
                assert!(slope <= l * 1.0001, "{p:?}: slope {slope} > {l}");
            }
        }
    }
}
