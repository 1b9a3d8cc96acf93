//! The bend warp (Barr 1984, as the BlobTree's warp operator w; Galbraith et al. bend cones
//! into curving spines and the canal with it): the slab 0 ≤ x ≤ length of the child's space is
//! bent into an arc turning by `angle` about the z axis, from +x towards +y; what lies before
//! the slab is left in place and what lies beyond it follows the arc's end rigidly. Fields are
//! evaluated through the inverse map, so a bent primitive is exact, not a chain of pieces.

use crate::mesh::Bounds;
use glam::{DMat3, DVec2, DVec3};

/// The largest turn of one bend: within it the three regions (before, along, beyond the arc)
/// never overlap.
pub const MAX_BEND_DEGREES: f64 = 90.0;

/// A bend of the slab 0 ≤ x ≤ `length` by `angle` radians (|angle| ≤ 90°), with what every
/// evaluation through it needs computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bend {
    angle: f64,
    length: f64,
    /// (cos, sin) of |angle|: the direction of the arc's end.
    end: DVec2,
}

impl Bend {
    pub fn new(angle: f64, length: f64) -> Self {
        let phi = angle.abs();
        Self {
            angle,
            length,
            end: DVec2::new(libm::cos(phi), libm::sin(phi)),
        }
    }

    /// Whether it bends nothing (an angle of zero): the identity map.
    pub fn is_straight(&self) -> bool {
        self.angle == 0.0
    }

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

    /// Which of the three regions the bent point `p` lies in, with its offset d from the
    /// centre of curvature (0, r) in the bending plane.
    pub fn place(&self, p: DVec3) -> Place {
        if self.angle == 0.0 {
            return Place::Unbent;
        }
        let d = DVec2::new(p.x, p.y * self.angle.signum() - self.radius());
        if d.x < 0.0 {
            Place::Unbent
        } else if d.dot(self.end) > 0.0 {
            Place::Beyond(d)
        } else {
            Place::Arc(d)
        }
    }

    /// Where the bent point `p`, in region `place`, came from.
    pub fn unbend(&self, p: DVec3, place: Place) -> DVec3 {
        let (sign, r, end) = (self.angle.signum(), self.radius(), self.end);
        match place {
            Place::Unbent => p,
            Place::Beyond(d) => {
                let rho = d.dot(DVec2::new(end.y, -end.x));
                DVec3::new(self.length + d.dot(end), (r - rho) * sign, p.z)
            }
            Place::Arc(d) => {
                let theta = libm::atan2(d.x, -d.y);
                DVec3::new(theta * r, (r - d.length()) * sign, p.z)
            }
        }
    }

    /// Where the bent point `p` came from: the map fields are evaluated through.
    pub fn inverse(&self, p: DVec3) -> DVec3 {
        self.unbend(p, self.place(p))
    }

    /// The Jacobian J (dq = J dp) of [`Bend::inverse`] at a point in region `place`, so that
    /// a field evaluated through the bend has the gradient Jᵀ ∇f: exact in each of the three
    /// regions.
    pub fn jacobian(&self, place: Place) -> DMat3 {
        let (sign, r, end) = (self.angle.signum(), self.radius(), self.end);
        // Rows of J in the xy plane: ∂q.x/∂(p.x, p.y) and ∂q.y/∂(p.x, p.y).
        let (row_x, row_y) = match place {
            Place::Unbent => return DMat3::IDENTITY,
            Place::Beyond(_) => (
                DVec2::new(end.x, end.y * sign),
                DVec2::new(-end.y * sign, end.x),
            ),
            Place::Arc(d) => {
                let (len2, len) = (d.length_squared(), d.length());
                (
                    DVec2::new(-d.y, d.x * sign) * (r / len2),
                    DVec2::new(-d.x * sign, -d.y) / len,
                )
            }
        };
        DMat3::from_cols(
            DVec3::new(row_x.x, row_y.x, 0.0),
            DVec3::new(row_x.y, row_y.y, 0.0),
            DVec3::Z,
        )
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

    /// A ball (centre, radius) in the unbent space holding the inverse image of the ball of
    /// `reach` about `centre`: the inverse stretches distances along the arc by r / ρ at the
    /// distance ρ from the centre of curvature and is rigid before and beyond it. `None` when
    /// the ball reaches the centre of curvature, where the stretch is unbounded.
    pub fn inverse_ball(&self, centre: DVec3, reach: f64) -> Option<(DVec3, f64)> {
        if self.angle == 0.0 {
            return Some((centre, reach));
        }
        let r = self.radius();
        let nearest = DVec2::new(centre.x, centre.y * self.angle.signum() - r).length() - reach;
        (nearest > 0.0).then(|| (self.inverse(centre), reach * (r / nearest).max(1.0)))
    }
}

/// Where a bent point lies: before the slab or unbent, beyond the arc's end, or along the arc,
/// with its offset from the centre of curvature.
#[derive(Clone, Copy)]
pub enum Place {
    Unbent,
    Beyond(DVec2),
    Arc(DVec2),
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unbent points before, along and beyond the slab of a bend of length 2.
    const UNBENT: [DVec3; 4] = [
        DVec3::new(-0.5, 0.1, 0.2),
        DVec3::new(0.7, -0.2, 0.0),
        DVec3::new(1.9, 0.3, -0.1),
        DVec3::new(2.6, 0.05, 0.4),
    ];

    #[test]
    fn inverse_undoes_forward_before_along_and_beyond_the_arc() {
        for angle in [30f64, -30.0, 9.0, 90.0] {
            let bend = Bend::new(angle.to_radians(), 2.0);
            for q in UNBENT {
                let back = bend.inverse(bend.forward(q));
                assert!(back.distance(q) < 1e-12, "{angle}°: {q} → {back}");
            }
        }
    }

    #[test]
    fn the_jacobian_matches_differences_of_the_inverse_in_every_region() {
        for angle in [30f64, -45.0, 90.0] {
            let bend = Bend::new(angle.to_radians(), 2.0);
            for q in UNBENT {
                let p = bend.forward(q);
                let j = bend.jacobian(bend.place(p));
                let h = 1e-6;
                for (axis, column) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().zip(0..) {
                    let diff =
                        (bend.inverse(p + axis * h) - bend.inverse(p - axis * h)) / (2.0 * h);
                    let exact = j.col(column);
                    assert!(
                        diff.distance(exact) < 1e-6,
                        "{angle}° at {q}: {diff} vs {exact}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_tip_turns_by_the_angle() {
        let bend = Bend::new(30f64.to_radians(), 1.0);
        let a = bend.forward(DVec3::new(1.0, 0.0, 0.0));
        let b = bend.forward(DVec3::new(1.5, 0.0, 0.0));
        let turn = (b - a).y.atan2((b - a).x).to_degrees();
        assert!((turn - 30.0).abs() < 1e-9);
        assert!(a.y > 0.0, "towards +y");
    }

    #[test]
    fn bounds_hold_the_bent_box() {
        let bend = Bend::new(60f64.to_radians(), 3.0);
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
