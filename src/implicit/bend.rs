//! The bend warp (Barr 1984, as the BlobTree's warp operator w; Galbraith et al. bend cones
//! into curving spines and the canal with it): the slab 0 ≤ x ≤ length of the child's space is
//! bent into an arc turning by `angle` about the z axis, from +x towards +y; what lies before
//! the slab is left in place and what lies beyond it follows the arc's end rigidly. Fields are
//! evaluated through the inverse map, so a bent primitive is exact, not a chain of pieces.

use crate::mesh::Bounds;
use glam::{DVec2, DVec3};

/// The largest turn of one bend: within it the three regions (before, along, beyond the arc)
/// never overlap.
pub const MAX_BEND_DEGREES: f64 = 90.0;

/// A bend of the slab 0 ≤ x ≤ `length` by `angle` radians (|angle| ≤ 90°).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bend {
    pub angle: f64,
    pub length: f64,
}

impl Bend {
    /// Radius of the arc the x axis is bent into.
    fn radius(&self) -> f64 {
        self.length / self.angle.abs()
    }

    /// Where the unbent point `q` goes.
    pub fn forward(&self, q: DVec3) -> DVec3 {
        if self.angle == 0.0 {
            return q;
        }
        let sign = self.angle.signum();
        let r = self.radius();
        let y = q.y * sign;
        let along = q.x.clamp(0.0, self.length);
        let theta = along / r;
        let (s, c) = (libm::sin(theta), libm::cos(theta));
        let rho = r - y;
        let beyond = q.x - along;
        DVec3::new(rho * s + beyond * c, (r - rho * c + beyond * s) * sign, q.z)
    }

    /// Where the bent point `p` came from: the map fields are evaluated through.
    pub fn inverse(&self, p: DVec3) -> DVec3 {
        if self.angle == 0.0 {
            return p;
        }
        let sign = self.angle.signum();
        let (r, phi) = (self.radius(), self.angle.abs());
        // Relative to the centre of curvature (0, r).
        let d = DVec2::new(p.x, p.y * sign - r);
        if d.x < 0.0 {
            return p;
        }
        let end = DVec2::new(libm::cos(phi), libm::sin(phi));
        let beyond = d.dot(end);
        if beyond > 0.0 {
            let rho = d.dot(DVec2::new(end.y, -end.x));
            return DVec3::new(self.length + beyond, (r - rho) * sign, p.z);
        }
        let theta = libm::atan2(d.x, -d.y);
        DVec3::new(theta * r, (r - d.length()) * sign, p.z)
    }

    /// The box holding the bent image of `child` (a box in the unbent space).
    pub fn bounds(&self, child: &Bounds) -> Bounds {
        if self.angle == 0.0 {
            return *child;
        }
        const STEPS: usize = 16;
        let mut out = Bounds::EMPTY;
        let xs = (0..=STEPS).map(|i| {
            let t = i as f64 / STEPS as f64;
            child.min.x + t * (child.max.x - child.min.x)
        });
        let arc = (0..=STEPS).map(|i| i as f64 / STEPS as f64 * self.length);
        for x in xs.chain(arc.filter(|x| (child.min.x..=child.max.x).contains(x))) {
            for y in [child.min.y, child.max.y] {
                for z in [child.min.z, child.max.z] {
                    out.include(self.forward(DVec3::new(x, y, z)));
                }
            }
        }
        // Between samples the arc bulges out by at most its sagitta.
        let reach = self.radius() + child.min.y.abs().max(child.max.y.abs());
        let step = self.angle.abs() / STEPS as f64;
        let sag = reach * (1.0 - libm::cos(step * 0.5));
        Bounds {
            min: out.min - DVec3::new(sag, sag, 0.0),
            max: out.max + DVec3::new(sag, sag, 0.0),
        }
    }

    /// How much the inverse map can stretch distances within `child` (a box in the unbent
    /// space): along the arc, r / (r − |y|). Infinite when the box reaches the centre of
    /// curvature, where the bend folds.
    pub fn stretch(&self, child: &Bounds) -> f64 {
        if self.angle == 0.0 {
            return 1.0;
        }
        let r = self.radius();
        let y = child.min.y.abs().max(child.max.y.abs());
        if y >= r { f64::INFINITY } else { r / (r - y) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_undoes_forward_before_along_and_beyond_the_arc() {
        for angle in [30f64, -30.0, 9.0, 90.0] {
            let bend = Bend {
                angle: angle.to_radians(),
                length: 2.0,
            };
            for q in [
                DVec3::new(-0.5, 0.1, 0.2),
                DVec3::new(0.7, -0.2, 0.0),
                DVec3::new(1.9, 0.3, -0.1),
                DVec3::new(2.6, 0.05, 0.4),
            ] {
                let back = bend.inverse(bend.forward(q));
                assert!(back.distance(q) < 1e-12, "{angle}°: {q} → {back}");
            }
        }
    }

    #[test]
    fn the_tip_turns_by_the_angle() {
        let bend = Bend {
            angle: 30f64.to_radians(),
            length: 1.0,
        };
        let a = bend.forward(DVec3::new(1.0, 0.0, 0.0));
        let b = bend.forward(DVec3::new(1.5, 0.0, 0.0));
        let turn = (b - a).y.atan2((b - a).x).to_degrees();
        assert!((turn - 30.0).abs() < 1e-9);
        assert!(a.y > 0.0, "towards +y");
    }

    #[test]
    fn bounds_hold_the_bent_box() {
        let bend = Bend {
            angle: 60f64.to_radians(),
            length: 3.0,
        };
        let child = Bounds {
            min: DVec3::new(-0.2, -0.3, -0.3),
            max: DVec3::new(3.3, 0.3, 0.3),
        };
        let b = bend.bounds(&child);
        for i in 0..=200 {
            for y in [-0.3, 0.0, 0.3] {
                let x = -0.2 + 3.5 * f64::from(i) / 200.0;
                let p = bend.forward(DVec3::new(x, y, 0.3));
                assert!(p.cmpge(b.min).all() && p.cmple(b.max).all(), "{p}");
            }
        }
    }
}
