//! Which triangles of a welded mesh form bodies: connected pieces (triangles sharing a vertex,
//! joined by union-find), and whether every edge is matched by one running the other way,
//! which a closed, consistently wound surface needs.

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

/// Whether every directed edge of a set of triangles is matched by one running the other way,
/// kept as one number: each edge adds a 64-bit hash of its two vertices when it runs from the
/// lower index to the higher and subtracts it when it runs back, so a closed, consistently
/// wound surface sums to zero exactly, and an open or inconsistent one to zero only if hashes
/// of distinct edges cancel (odds of 2⁻⁶⁴). A table of the edges themselves would take a
/// dozen megabytes for the Murex, whose first touches alone cost more than a frame.
#[derive(Default)]
pub(crate) struct Edges {
    sum: u64,
}

impl Edges {
    /// Counts the three edges of triangle `t` (in its winding).
    pub fn add(&mut self, t: [u32; 3]) {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let h = mix(u64::from(a.min(b)) << 32 | u64::from(a.max(b)));
            self.sum = if a < b {
                self.sum.wrapping_add(h)
            } else {
                self.sum.wrapping_sub(h)
            };
        }
    }

    /// Whether every edge is matched by its reverse.
    pub fn matched(&self) -> bool {
        self.sum == 0
    }
}

/// SplitMix64's finaliser: every bit of the edge moves every bit of its hash.
fn mix(mut x: u64) -> u64 {
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
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
        assert!(closed.matched());
        let mut open = Edges::default();
        TETRAHEDRON[..3].iter().for_each(|&t| open.add(t));
        assert!(!open.matched());
        let mut flipped = Edges::default();
        TETRAHEDRON[..3].iter().for_each(|&t| flipped.add(t));
        flipped.add([0, 2, 3]);
        assert!(!flipped.matched());
        // Two closed solids sharing a face (coinciding caps) still match edge for edge.
        TETRAHEDRON
            .iter()
            .for_each(|&t| closed.add(t.map(|i| if i == 3 { 4 } else { i })));
        assert!(closed.matched());
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
