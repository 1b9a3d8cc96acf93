//! Marching tetrahedra's tables: the Kuhn triangulation of a voxel into six tetrahedra that all
//! share the diagonal from its lowest to its highest corner (so neighbouring voxels split their
//! common faces alike), the grid edges they use, and how the surface cuts each tetrahedron for
//! each set of its corners inside, worked out at compile time.

use super::grid::{SIDE, at_local};

/// The seven directions from a voxel corner to the corners that dominate it, as offsets
/// along x, y and z: every edge of the Kuhn triangulation is one of them.
pub(super) const DIRECTIONS: [[usize; 3]; 7] = [
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [0, 1, 1],
    [1, 1, 1],
];

/// Grid edges a chunk has, by [`edge_key`]: one in each direction from each sample.
pub(super) const EDGES: usize = SIDE * SIDE * SIDE * DIRECTIONS.len();

/// The six tetrahedra of a voxel, as corner numbers (bit k: offset along axis k): each walks
/// from corner 0 to corner 7 adding one axis at a time, in one of the six orders.
pub(super) const TETRAHEDRA: [[usize; 4]; 6] = [
    [0, 1, 3, 7],
    [0, 1, 5, 7],
    [0, 2, 3, 7],
    [0, 2, 6, 7],
    [0, 4, 5, 7],
    [0, 4, 6, 7],
];

/// A grid edge of a voxel, from corner `lo` to the corner `hi` that dominates it, along
/// [`DIRECTIONS`]`[direction]`.
#[derive(Clone, Copy)]
pub(super) struct Edge {
    pub(super) lo: usize,
    pub(super) hi: usize,
    pub(super) direction: usize,
}

/// How the surface cuts a tetrahedron with a given set of corners inside: the edges its
/// vertices lie on, in the order they are made, and its triangles over them, wound to face
/// from the inside corners towards the outside ones. The winding is decided here, with each
/// vertex at its edge's midpoint, not from where the vertices end up: wherever on its open
/// edge each vertex lies the triangle keeps that orientation.
#[derive(Clone, Copy)]
pub(super) struct Cut {
    pub(super) edges: [Edge; 4],
    pub(super) edge_count: usize,
    pub(super) triangles: [[usize; 3]; 2],
    pub(super) triangle_count: usize,
}

/// The cut of each tetrahedron of [`TETRAHEDRA`] for each set of its corners inside (bit i:
/// its corner i): one inside corner (or one outside) gives a triangle over the three edges from
/// it; two give the quad a0–b0, a0–b1, a1–b1, a1–b0 as two triangles.
pub(super) static CUTS: [[Cut; 16]; 6] = {
    const NONE: Edge = Edge {
        lo: 0,
        hi: 0,
        direction: 0,
    };
    const EMPTY: Cut = Cut {
        edges: [NONE; 4],
        edge_count: 0,
        triangles: [[0; 3]; 2],
        triangle_count: 0,
    };
    const fn edge(a: usize, b: usize) -> Edge {
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        let (l, h) = (offset(lo), offset(hi));
        let mut direction = 0;
        while !(l[0] + DIRECTIONS[direction][0] == h[0]
            && l[1] + DIRECTIONS[direction][1] == h[1]
            && l[2] + DIRECTIONS[direction][2] == h[2])
        {
            direction += 1;
        }
        Edge { lo, hi, direction }
    }
    const fn midpoint(e: Edge) -> [f64; 3] {
        let (l, h) = (offset(e.lo), offset(e.hi));
        [
            (l[0] + h[0]) as f64 * 0.5,
            (l[1] + h[1]) as f64 * 0.5,
            (l[2] + h[2]) as f64 * 0.5,
        ]
    }
    const fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
    }
    const fn mean(corners: &[usize; 4], count: usize) -> [f64; 3] {
        let mut sum = [0.0; 3];
        let mut i = 0;
        while i < count {
            let o = offset(corners[i]);
            sum = [
                sum[0] + o[0] as f64,
                sum[1] + o[1] as f64,
                sum[2] + o[2] as f64,
            ];
            i += 1;
        }
        let n = count as f64;
        [sum[0] / n, sum[1] / n, sum[2] / n]
    }
    let mut cuts = [[EMPTY; 16]; 6];
    let mut t = 0;
    while t < 6 {
        let tet = TETRAHEDRA[t];
        let mut mask = 1;
        while mask < 15 {
            let (mut ins, mut outs) = ([0; 4], [0; 4]);
            let (mut n_in, mut n_out) = (0, 0);
            let mut i = 0;
            while i < 4 {
                if mask & 1 << i != 0 {
                    ins[n_in] = tet[i];
                    n_in += 1;
                } else {
                    outs[n_out] = tet[i];
                    n_out += 1;
                }
                i += 1;
            }
            let (a, b) = (mean(&outs, n_out), mean(&ins, n_in));
            let outward = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
            let mut cut = EMPTY;
            if n_in == 2 {
                cut.edges = [
                    edge(ins[0], outs[0]),
                    edge(ins[0], outs[1]),
                    edge(ins[1], outs[1]),
                    edge(ins[1], outs[0]),
                ];
                cut.edge_count = 4;
                cut.triangles = [[0, 1, 2], [0, 2, 3]];
                cut.triangle_count = 2;
            } else {
                let (apex, base) = if n_in == 1 {
                    (ins[0], outs)
                } else {
                    (outs[0], ins)
                };
                cut.edges = [
                    edge(apex, base[0]),
                    edge(apex, base[1]),
                    edge(apex, base[2]),
                    NONE,
                ];
                cut.edge_count = 3;
                cut.triangle_count = 1;
                cut.triangles[0] = [0, 1, 2];
            }
            let mut k = 0;
            while k < cut.triangle_count {
                let [i, j, l] = cut.triangles[k];
                let m = [
                    midpoint(cut.edges[i]),
                    midpoint(cut.edges[j]),
                    midpoint(cut.edges[l]),
                ];
                let (u, v) = (sub(m[1], m[0]), sub(m[2], m[0]));
                let face = [
                    u[1] * v[2] - u[2] * v[1],
                    u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0],
                ];
                if face[0] * outward[0] + face[1] * outward[1] + face[2] * outward[2] < 0.0 {
                    cut.triangles[k] = [i, l, j];
                }
                k += 1;
            }
            cuts[t][mask] = cut;
            mask += 1;
        }
        t += 1;
    }
    cuts
};

/// The offset along x, y and z of a voxel's corner number `corner` (bit k: along axis k).
pub(super) const fn offset(corner: usize) -> [usize; 3] {
    [corner & 1, (corner >> 1) & 1, (corner >> 2) & 1]
}

/// The key of the grid edge from sample `lo` (its index in a chunk) along a direction.
pub(super) fn edge_key(lo: usize, direction: usize) -> usize {
    lo * DIRECTIONS.len() + direction
}

/// The first sample and the direction of the edge with key `key`: the inverse of [`edge_key`].
pub(super) fn edge_of(key: usize) -> ([usize; 3], usize) {
    (at_local(key / DIRECTIONS.len()), key % DIRECTIONS.len())
}
