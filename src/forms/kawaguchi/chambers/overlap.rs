//! Whorls that pass through one another. Kawaguchi's shells coil so that each whorl rests on
//! or beside the one before; a ratio too small for the turn (or a ratio of exactly 1, whose
//! chambers come round onto themselves) makes a later whorl pass through an earlier one, and
//! the mesh then encloses part of space twice: no solid a printer or a mesh library accepts.
//!
//! One similarity carries every chamber onto the next (see [`ChamberStack`]), so chambers k
//! and k + d meet exactly when chambers 0 and d do: the whole stack is checked by comparing
//! the first chamber with each later one, d ≥ 2 (chamber 1 shares its bottom base with the
//! first's top). Two chambers meet when a side triangle of one crosses a side triangle of the
//! other, or when one lies inside the other (the winding number of its centre, which also
//! finds chambers lying exactly on one another).

use super::chamber_stack::{ChamberStack, RingKind};
use crate::mesh::Bounds;
use glam::{DAffine3, DVec3};

/// One chamber as a closed polyhedron: its side triangles and the fans closing its two bases.
struct Chamber {
    sides: Vec<[DVec3; 3]>,
    bases: Vec<[DVec3; 3]>,
    centre: DVec3,
    bounds: Bounds,
}

impl Chamber {
    fn new(stack: &ChamberStack, frame: &DAffine3) -> Self {
        let bottom = stack.ring(frame, RingKind::Bottom);
        let top = stack.ring(frame, RingKind::Top);
        let n = bottom.len();
        let mut sides = Vec::with_capacity(2 * n);
        for j in 0..n {
            let k = (j + 1) % n;
            sides.push([bottom[j], bottom[k], top[k]]);
            sides.push([bottom[j], top[k], top[j]]);
        }
        let middle = |ring: &[DVec3]| ring.iter().sum::<DVec3>() / n as f64;
        let (b, t) = (middle(&bottom), middle(&top));
        let bases = (0..n)
            .flat_map(|j| {
                let k = (j + 1) % n;
                [[b, bottom[k], bottom[j]], [t, top[j], top[k]]]
            })
            .collect();
        let mut bounds = Bounds::EMPTY;
        for &p in bottom.iter().chain(&top) {
            bounds.include(p);
        }
        Self {
            sides,
            bases,
            centre: (b + t) / 2.0,
            bounds,
        }
    }

    /// Whether `p` lies inside: the generalised winding number of the closed surface about it
    /// (the solid angles of its triangles, Van Oosterom & Strackee) is 1 inside, 0 outside.
    fn contains(&self, p: DVec3) -> bool {
        if !inside(&self.bounds, p) {
            return false;
        }
        let angle: f64 = self
            .sides
            .iter()
            .chain(&self.bases)
            .map(|t| solid_angle(t, p))
            .sum();
        (angle / (4.0 * std::f64::consts::PI)).abs() > 0.5
    }
}

fn inside(b: &Bounds, p: DVec3) -> bool {
    p.cmpge(b.min).all() && p.cmple(b.max).all()
}

fn overlap(a: &Bounds, b: &Bounds) -> bool {
    a.min.cmple(b.max).all() && b.min.cmple(a.max).all()
}

fn bounds_of(t: &[DVec3; 3]) -> Bounds {
    let mut b = Bounds::EMPTY;
    t.iter().for_each(|&p| b.include(p));
    b
}

/// The solid angle triangle `t` subtends at `p` (signed by its winding).
fn solid_angle(t: &[DVec3; 3], p: DVec3) -> f64 {
    let [a, b, c] = t.map(|q| q - p);
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let numerator = a.dot(b.cross(c));
    let denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    2.0 * numerator.atan2(denominator)
}

/// Whether the segment from `p` to `q` passes through the inside of triangle `t` (Möller &
/// Trumbore's ray test, bounded to the segment; a segment in the triangle's plane does not).
fn segment_crosses(p: DVec3, q: DVec3, t: &[DVec3; 3]) -> bool {
    let d = q - p;
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let h = d.cross(e2);
    let det = e1.dot(h);
    if det.abs() <= 1e-12 * e1.length() * e2.length() * d.length() {
        return false;
    }
    let s = p - t[0];
    let u = s.dot(h) / det;
    let qv = s.cross(e1);
    let v = d.dot(qv) / det;
    let at = e2.dot(qv) / det;
    const IN: f64 = 1e-9;
    u > IN && v > IN && u + v < 1.0 - IN && at > IN && at < 1.0 - IN
}

/// Whether two triangles cross: an edge of one passes through the other.
fn triangles_cross(a: &[DVec3; 3], b: &[DVec3; 3]) -> bool {
    let edges_through =
        |s: &[DVec3; 3], t: &[DVec3; 3]| (0..3).any(|i| segment_crosses(s[i], s[(i + 1) % 3], t));
    edges_through(a, b) || edges_through(b, a)
}

/// Whether two chambers meet: their sides cross, or one holds the other's centre.
fn meet(a: &Chamber, b: &Chamber) -> bool {
    if !overlap(&a.bounds, &b.bounds) {
        return false;
    }
    let near = |c: &Chamber, other: &Bounds| -> Vec<([DVec3; 3], Bounds)> {
        c.sides
            .iter()
            .map(|t| (*t, bounds_of(t)))
            .filter(|(_, tb)| overlap(tb, other))
            .collect()
    };
    let (sa, sb) = (near(a, &b.bounds), near(b, &a.bounds));
    let crossing = sa.iter().any(|(ta, ba)| {
        sb.iter()
            .any(|(tb, bb)| overlap(ba, bb) && triangles_cross(ta, tb))
    });
    crossing || a.contains(b.centre) || b.contains(a.centre)
}

/// How many chambers apart two chambers that pass through one another are, the fewest such
/// (None when no whorl meets another).
pub fn whorls_overlap(stack: &ChamberStack) -> Option<usize> {
    let first = stack.first_frame();
    let chamber = Chamber::new(stack, &first);
    let mut frame = stack.next_frame(&first);
    for d in 2..stack.chambers() {
        frame = stack.next_frame(&frame);
        if meet(&chamber, &Chamber::new(stack, &frame)) {
            return Some(d);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    const TRIANGLE: [DVec3; 3] = [DVec3::ZERO, DVec3::X, DVec3::Y];

    #[test]
    fn a_segment_through_a_triangle_crosses_it_and_one_beside_it_does_not() {
        let through = (DVec3::new(0.2, 0.2, -1.0), DVec3::new(0.2, 0.2, 1.0));
        assert!(segment_crosses(through.0, through.1, &TRIANGLE));
        let beside = (DVec3::new(0.8, 0.8, -1.0), DVec3::new(0.8, 0.8, 1.0));
        assert!(!segment_crosses(beside.0, beside.1, &TRIANGLE));
        let short = (DVec3::new(0.2, 0.2, 0.5), DVec3::new(0.2, 0.2, 1.0));
        assert!(!segment_crosses(short.0, short.1, &TRIANGLE));
    }

    #[test]
    fn the_solid_angles_of_a_closed_surface_sum_to_four_pi_inside_and_zero_outside() {
        let [a, b, c, d] = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        let tetrahedron = [[a, c, b], [a, b, d], [a, d, c], [b, c, d]];
        let winding = |p: DVec3| -> f64 {
            tetrahedron.iter().map(|t| solid_angle(t, p)).sum::<f64>()
                / (4.0 * std::f64::consts::PI)
        };
        assert!((winding(DVec3::splat(0.1)).abs() - 1.0).abs() < 1e-12);
        assert!(winding(DVec3::splat(2.0)).abs() < 1e-12);
    }
}
