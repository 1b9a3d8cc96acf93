//! Which triangles of a welded mesh form bodies: connected pieces (triangles sharing a vertex,
//! joined by union-find), and whether every edge is matched by one running the other way,
//! which a closed, consistently wound surface needs.

use std::collections::HashMap;

/// Connected pieces of a mesh's vertices, as sets that merge.
pub(crate) struct Pieces {
    parent: Vec<u32>,
}

impl Pieces {
    /// `n` vertices, each its own piece.
    pub fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
        }
    }

    /// The vertex that stands for the piece of `i`.
    pub fn find(&mut self, mut i: u32) -> u32 {
        while self.parent[i as usize] != i {
            let grand = self.parent[self.parent[i as usize] as usize];
            self.parent[i as usize] = grand;
            i = grand;
        }
        i
    }

    /// Joins the pieces of `a` and `b` (the smaller representative stands for both).
    pub fn join(&mut self, a: u32, b: u32) {
        let (a, b) = (self.find(a), self.find(b));
        let (low, high) = (a.min(b), a.max(b));
        self.parent[high as usize] = low;
    }
}

/// Directed edges of triangles, each counted against its reverse.
#[derive(Default)]
pub(crate) struct Edges {
    balance: HashMap<(u32, u32), i32>,
}

impl Edges {
    /// Counts the three edges of triangle `t` (in its winding).
    pub fn add(&mut self, t: [u32; 3]) {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let (key, sign) = if a < b { ((a, b), 1) } else { ((b, a), -1) };
            *self.balance.entry(key).or_default() += sign;
        }
    }

    /// Edges not matched by one running the other way: where the surface is open (or wound
    /// inconsistently).
    pub fn unmatched(&self) -> usize {
        self.balance.values().filter(|&&b| b != 0).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tetrahedron's faces, outward.
    const TETRAHEDRON: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

    #[test]
    fn a_closed_solid_has_no_unmatched_edge_and_an_open_one_has() {
        let mut closed = Edges::default();
        TETRAHEDRON.iter().for_each(|&t| closed.add(t));
        assert_eq!(closed.unmatched(), 0);
        let mut open = Edges::default();
        TETRAHEDRON[..3].iter().for_each(|&t| open.add(t));
        assert_eq!(open.unmatched(), 3);
        let mut flipped = Edges::default();
        TETRAHEDRON[..3].iter().for_each(|&t| flipped.add(t));
        flipped.add([0, 2, 3]);
        assert_eq!(flipped.unmatched(), 3);
    }

    #[test]
    fn vertices_joined_by_triangles_share_a_piece() {
        let mut pieces = Pieces::new(7);
        for [a, b, c] in [[0, 1, 2], [4, 5, 6], [2, 3, 1]] {
            pieces.join(a, b);
            pieces.join(b, c);
        }
        let roots: Vec<u32> = (0..7).map(|i| pieces.find(i)).collect();
        assert_eq!(roots, [0, 0, 0, 0, 4, 4, 4]);
    }
}
