//! One facet of a band between two rings of apexes, the flat quadrilateral Kawaguchi's
//! polyhedra (chambers and trunks alike) are drawn with: its corners in order around it, their
//! pattern coordinates, and the face's orientation.

use glam::DVec3;

/// Facet j of the band from ring `a` up to ring `b` (each of N apexes, closed): corners
/// aⱼ, aⱼ₊₁, bⱼ₊₁, bⱼ.
pub(crate) struct Facet {
    pub corners: [DVec3; 4],
    /// Pattern coordinates of the corners: j/N along the ring, and the ring's row.
    pub pattern: [[f64; 2]; 4],
    /// The cross product of the diagonals: along the facet's normal, for rings
    /// counter-clockwise about the direction from `a` to `b` outwards, and never zero where
    /// two corners meet (a quad collapsed to a triangle).
    pub face: DVec3,
}

impl Facet {
    pub fn new([a, b]: [&[DVec3]; 2], [row_a, row_b]: [f64; 2], j: usize) -> Self {
        let n = a.len();
        let k = (j + 1) % n;
        let corners = [a[j], a[k], b[k], b[j]];
        let x = |j: usize| j as f64 / n as f64;
        Self {
            corners,
            pattern: [
                [x(j), row_a],
                [x(j + 1), row_a],
                [x(j + 1), row_b],
                [x(j), row_b],
            ],
            face: (corners[2] - corners[0]).cross(corners[3] - corners[1]),
        }
    }
}
