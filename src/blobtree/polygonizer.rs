//! Polygonizing a BlobTree chunk by chunk: the field is sampled on a regular grid of cubic
//! voxels, cut into chunks of [`CHUNK`]³ voxels, and each chunk is meshed on its own by
//! marching tetrahedra: every voxel is split into the six tetrahedra of its Kuhn triangulation
//! (all sharing the diagonal from its lowest to its highest corner, so neighbouring voxels
//! split their common faces the same way), and each tetrahedron holds zero, one or two
//! triangles of the surface. The result is a closed 2-manifold for any field, which naive
//! surface nets and plain marching cubes are not: both join four faces at one edge where a
//! voxel face has its diagonal corners on the same side (we met it on our first CSG test with
//! the `fast-surface-nets` crate). A vertex sits on a grid edge, where the field crosses the
//! iso-value, found by one Newton step from the two samples; both chunks sharing a boundary
//! edge compute it from the same global samples, bit for bit, so the chunks' meshes meet
//! without seams and weld by position into one closed surface.
//!
//! A chunk is skipped unseen when the tree culled to it is empty (outside every support) or
//! when bounds on the field over the ball around it ([`Node::range`]) keep it on one side of
//! the iso-value (wholly inside or wholly outside). Normals are the field's exact gradient, and
//! pattern coordinates the primitives' blended coordinates. When a whole surface is meshed at
//! once, each chunk hands the samples and vertices on its faces to the neighbours that share
//! them ([`Seams`]); a chunk meshed again as it grows takes over what it computed before,
//! outside the box its tree changed in ([`ChunkCache`]).

use super::blob_tree::{Node, Probe};
use super::falloff::ISO;
use crate::mesh::{Bounds, Mesh, Surface, Vertex};
use glam::DVec3;
use std::collections::HashMap;

/// Voxels along each side of a chunk.
pub const CHUNK: u32 = 8;

/// The voxel grid over a box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Position of the sample with global index (0, 0, 0).
    origin: DVec3,
    /// Edge length of a voxel.
    pub voxel: f64,
    /// Chunks along x, y and z.
    pub chunks: [u32; 3],
}

/// A chunk's position in the grid.
pub type ChunkIndex = [u32; 3];

impl Grid {
    /// `resolution` voxels along the longest side of `bounds`, with two voxels of empty space
    /// around it so the surface never touches the grid's edge.
    pub fn new(bounds: &Bounds, resolution: u32) -> Self {
        let size = bounds.max - bounds.min;
        let voxel = size.max_element() / f64::from(resolution.max(1));
        let origin = bounds.min - 2.0 * voxel;
        let chunks = ((size / voxel + 4.0) / f64::from(CHUNK))
            .ceil()
            .as_uvec3()
            .max(glam::UVec3::ONE)
            .to_array();
        Self {
            origin,
            voxel,
            chunks,
        }
    }

    pub fn chunk_count(&self) -> usize {
        self.chunks.iter().map(|&c| c as usize).product()
    }

    /// A number for each chunk, in x-fastest order.
    pub fn linear(&self, [x, y, z]: ChunkIndex) -> usize {
        (x + self.chunks[0] * (y + self.chunks[1] * z)) as usize
    }

    /// The chunk with linear number `n`.
    pub fn chunk_at(&self, n: usize) -> ChunkIndex {
        let [cx, cy, _] = self.chunks.map(|c| c as usize);
        [n % cx, n / cx % cy, n / (cx * cy)].map(|i| i as u32)
    }

    /// The position of the sample with global index `i`.
    fn sample(&self, i: [i64; 3]) -> DVec3 {
        self.origin + DVec3::new(i[0] as f64, i[1] as f64, i[2] as f64) * self.voxel
    }

    /// Global index of a chunk's first sample.
    fn first_sample(chunk: ChunkIndex) -> [i64; 3] {
        chunk.map(|c| i64::from(c) * i64::from(CHUNK))
    }

    /// The box of a chunk's samples.
    pub fn region(&self, chunk: ChunkIndex) -> Bounds {
        let first = Self::first_sample(chunk);
        let last = first.map(|i| i + i64::from(CHUNK));
        Bounds {
            min: self.sample(first),
            max: self.sample(last),
        }
    }

    /// The chunks whose samples reach into `b`.
    pub fn chunks_touching(&self, b: &Bounds) -> Vec<ChunkIndex> {
        let range = |axis: usize| {
            let cell = f64::from(CHUNK) * self.voxel;
            let lo = ((b.min[axis] - self.origin[axis]) / cell).floor() - 1.0;
            let hi = ((b.max[axis] - self.origin[axis]) / cell).floor();
            let last = f64::from(self.chunks[axis] - 1);
            (lo.clamp(0.0, last) as u32)..=(hi.clamp(0.0, last) as u32)
        };
        let mut out = Vec::new();
        for z in range(2) {
            for y in range(1) {
                for x in range(0) {
                    out.push([x, y, z]);
                }
            }
        }
        out
    }
}

/// What meshing a chunk leaves behind for meshing it again after a change confined to a box:
/// outside that box the field is unchanged, bit for bit, so samples and vertices there are
/// taken over instead of computed again.
#[derive(Clone, Debug, Default)]
pub struct ChunkCache {
    /// The samples, empty when the chunk was skipped.
    field: Vec<f64>,
    /// Each vertex by its edge.
    vertices: HashMap<usize, Vertex>,
}

/// The samples and vertices on the faces between chunks, each handed by the chunk that meshed
/// it to the neighbour across the face: when every chunk is meshed from one tree at one growth
/// step, both would compute them, bit for bit alike: at 256³ the Murex's chunks would evaluate
/// 1.42 M samples for 1.08 M distinct ones and probe 0.97 M vertices for 0.84 M.
#[derive(Debug, Default)]
pub struct Seams {
    /// What each chunk is handed across its low face on each axis.
    faces: HashMap<(ChunkIndex, usize), Face>,
}

/// What a chunk hands across its high face on one axis, indexed as in the chunk receiving it.
#[derive(Debug, Default)]
struct Face {
    /// The evaluated samples, by sample index.
    samples: Vec<(usize, f64)>,
    /// The vertices on edges within the face, by edge key.
    vertices: Vec<(usize, Vertex)>,
}

impl Seams {
    /// What the neighbours below `chunk` on each axis handed it, taken out.
    fn take(&mut self, chunk: ChunkIndex) -> Vec<Face> {
        (0..3)
            .filter_map(|axis| self.faces.remove(&(chunk, axis)))
            .collect()
    }

    /// Hands the samples of `chunk` (empty when it was never sampled) and the vertices of its
    /// edges (by key) to its neighbours above it on each axis.
    fn hand_over(
        &mut self,
        grid: &Grid,
        chunk: ChunkIndex,
        field: &[f64],
        vertices: impl Iterator<Item = (usize, Vertex)>,
    ) {
        let top = CHUNK as usize;
        // A sample or edge on the high face is the same one on the neighbour's low face.
        let across = |mut i: [usize; 3], axis: usize| {
            i[axis] = 0;
            local(i)
        };
        let mut faces: [Face; 3] = Default::default();
        if !field.is_empty() {
            for (axis, face) in faces.iter_mut().enumerate() {
                for a in 0..SIDE {
                    for b in 0..SIDE {
                        let mut i = [top; 3];
                        i[(axis + 1) % 3] = a;
                        i[(axis + 2) % 3] = b;
                        let f = field[local(i)];
                        if f.is_finite() {
                            face.samples.push((across(i, axis), f));
                        }
                    }
                }
            }
        }
        for (key, vertex) in vertices {
            let (lo, direction) = edge_of(key);
            for (axis, face) in faces.iter_mut().enumerate() {
                if lo[axis] == top && DIRECTIONS[direction][axis] == 0 {
                    face.vertices
                        .push((edge_key(across(lo, axis), direction), vertex));
                }
            }
        }
        for (axis, face) in faces.into_iter().enumerate() {
            let mut neighbour = chunk;
            neighbour[axis] += 1;
            let empty = face.samples.is_empty() && face.vertices.is_empty();
            if neighbour[axis] < grid.chunks[axis] && !empty {
                self.faces.insert((neighbour, axis), face);
            }
        }
    }
}

/// What meshing a chunk takes over instead of computing it.
pub enum Memory<'a> {
    /// What meshing the same chunk left before the tree changed inside `changed` (growth);
    /// the cache is rewritten.
    Cache {
        cache: &'a mut ChunkCache,
        changed: &'a Bounds,
    },
    /// What the neighbours meshed before it from the same tree at the same step handed it; it
    /// hands on its own faces in turn.
    Seams(&'a mut Seams),
}

/// Buffers reused from chunk to chunk.
#[derive(Default)]
pub struct Scratch {
    field: Vec<f64>,
    /// Whether each sample counts as inside.
    inside: Vec<bool>,
    /// Vertex of each (sample, direction) edge met so far in this chunk, or `u32::MAX`.
    vertex_of: Vec<u32>,
    touched: Vec<usize>,
    /// Vertices taken over from a [`Memory`].
    known: Known,
}

/// The vertices a chunk takes over from a [`Memory`], in a table over all its edges by key,
/// cleared through the keys set.
#[derive(Default)]
struct Known {
    table: Vec<Option<Vertex>>,
    keys: Vec<usize>,
}

impl Known {
    fn clear(&mut self) {
        for key in self.keys.drain(..) {
            self.table[key] = None;
        }
        self.table.resize(EDGES, None);
    }

    fn get(&self, key: usize) -> Option<Vertex> {
        self.table[key]
    }
}

impl Extend<(usize, Vertex)> for Known {
    fn extend<I: IntoIterator<Item = (usize, Vertex)>>(&mut self, vertices: I) {
        for (key, vertex) in vertices {
            self.table[key] = Some(vertex);
            self.keys.push(key);
        }
    }
}

/// Samples along each side of a chunk: the corners of its voxels.
const SIDE: usize = CHUNK as usize + 1;

/// The seven directions from a voxel corner to the corners that dominate it, as offsets
/// along x, y and z: every edge of the Kuhn triangulation is one of them.
const DIRECTIONS: [[usize; 3]; 7] = [
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [0, 1, 1],
    [1, 1, 1],
];

/// Grid edges a chunk has, by [`edge_key`]: one in each direction from each sample.
const EDGES: usize = SIDE * SIDE * SIDE * DIRECTIONS.len();

/// The six tetrahedra of a voxel, as corner numbers (bit k: offset along axis k): each walks
/// from corner 0 to corner 7 adding one axis at a time, in one of the six orders.
const TETRAHEDRA: [[usize; 4]; 6] = [
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
struct Edge {
    lo: usize,
    hi: usize,
    direction: usize,
}

/// How the surface cuts a tetrahedron with a given set of corners inside: the edges its
/// vertices lie on, in the order they are made; its triangles over them; and the direction
/// from the inside corners' mean to the outside corners' mean, which the triangles face.
#[derive(Clone, Copy)]
struct Cut {
    edges: [Edge; 4],
    edge_count: usize,
    triangles: [[usize; 3]; 2],
    triangle_count: usize,
    outward: [f64; 3],
}

/// The cut of each tetrahedron of [`TETRAHEDRA`] for each set of its corners inside (bit i:
/// its corner i): one inside corner (or one outside) gives a triangle over the three edges from
/// it; two give the quad a0–b0, a0–b1, a1–b1, a1–b0 as two triangles.
static CUTS: [[Cut; 16]; 6] = {
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
        outward: [0.0; 3],
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
            let mut cut = Cut {
                outward: [a[0] - b[0], a[1] - b[1], a[2] - b[2]],
                ..EMPTY
            };
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
            cuts[t][mask] = cut;
            mask += 1;
        }
        t += 1;
    }
    cuts
};

const fn offset(corner: usize) -> [usize; 3] {
    [corner & 1, (corner >> 1) & 1, (corner >> 2) & 1]
}

fn local(i: [usize; 3]) -> usize {
    i[0] + SIDE * (i[1] + SIDE * i[2])
}

/// The sample with index `n` in a chunk: the inverse of [`local`].
fn at_local(n: usize) -> [usize; 3] {
    [n % SIDE, n / SIDE % SIDE, n / (SIDE * SIDE)]
}

/// The key of the grid edge from sample `lo` (its index in a chunk) along a direction.
fn edge_key(lo: usize, direction: usize) -> usize {
    lo * DIRECTIONS.len() + direction
}

/// The first sample and the direction of the edge with key `key`: the inverse of [`edge_key`].
fn edge_of(key: usize) -> ([usize; 3], usize) {
    (at_local(key / DIRECTIONS.len()), key % DIRECTIONS.len())
}

/// Which side of the iso-value the field of `tree` is proven to keep throughout `region`, by
/// the bounds [`Node::range`] gives over the ball around it: `Some(true)` inside, `Some(false)`
/// outside, `None` when the bounds allow both.
fn one_side(tree: &Node, region: &Bounds) -> Option<bool> {
    let (lo, hi) = tree.range(region.center(), (region.max - region.min).length() * 0.5);
    // A margin for the rounding of the bounds themselves.
    const MARGIN: f64 = 1e-9;
    if lo > ISO + MARGIN {
        Some(true)
    } else if hi < ISO - MARGIN {
        Some(false)
    } else {
        None
    }
}

/// What a sample proven inside (outside) by [`one_side`] holds instead of its field, which is
/// never computed: +∞ (−∞). Only its side matters: a grid edge the surface crosses has both
/// its ends outside every proven block, since a proven block holds no crossing.
fn proven(inside: bool) -> f64 {
    if inside {
        f64::INFINITY
    } else {
        f64::NEG_INFINITY
    }
}

/// Blocks of at most this many voxels along a side are sampled whole; larger ones are proven
/// one-sided or split in eight.
const SAMPLED_BLOCK: usize = 2;
/// Voxels along each side of a chunk's octant: each octant is sampled and meshed with the
/// tree culled to it, smaller and cheaper to evaluate than the chunk's.
const OCTANT: usize = CHUNK as usize / 2;

/// The octant of a chunk that voxel `v` of it lies in, numbered as voxel corners are.
fn octant_of(v: [usize; 3]) -> usize {
    (0..3).map(|k| (v[k] / OCTANT) << k).sum()
}

/// The samples of one chunk, filled block by block.
struct Sampler<'a> {
    grid: &'a Grid,
    /// Global index of the chunk's first sample.
    first: [i64; 3],
    /// The chunk's samples; NaN where not yet filled.
    field: &'a mut [f64],
}

impl Sampler<'_> {
    /// The box of the block of `size` voxels whose first sample is `at` (in the chunk).
    fn region(&self, at: [usize; 3], size: usize) -> Bounds {
        let corner = |d: usize| {
            self.grid
                .sample(std::array::from_fn(|k| self.first[k] + (at[k] + d) as i64))
        };
        Bounds {
            min: corner(0),
            max: corner(size),
        }
    }

    /// Fills the samples of the block of `size` voxels at `at`: marked [`proven`] when the
    /// range of `tree` keeps it on one side, else split in eight, down to blocks of
    /// [`SAMPLED_BLOCK`] whose samples are evaluated, but for those known already. Near a
    /// surface most blocks hold none of it, and so most samples of a chunk the surface passes
    /// through are never evaluated.
    fn block(&mut self, tree: &Node, at: [usize; 3], size: usize) {
        if let Some(inside) = one_side(tree, &self.region(at, size)) {
            self.mark(at, size, inside);
        } else if size > SAMPLED_BLOCK {
            let half = size / 2;
            for octant in 0..8 {
                let o = offset(octant);
                self.block(tree, std::array::from_fn(|k| at[k] + o[k] * half), half);
            }
        } else {
            let (grid, first) = (self.grid, self.first);
            self.each(at, size, |i, f| {
                if !f.is_finite() {
                    *f = tree.field(grid.sample(std::array::from_fn(|k| first[k] + i[k] as i64)));
                }
            });
        }
    }

    /// Marks the samples of a block not filled yet as [`proven`] on one side.
    fn mark(&mut self, at: [usize; 3], size: usize, inside: bool) {
        self.each(at, size, |_, f| {
            if f.is_nan() {
                *f = proven(inside);
            }
        });
    }

    /// Calls `f` with the index and the sample of every sample of the block of `size` voxels
    /// at `at`, its faces included.
    fn each(&mut self, at: [usize; 3], size: usize, mut f: impl FnMut([usize; 3], &mut f64)) {
        for z in at[2]..=at[2] + size {
            for y in at[1]..=at[1] + size {
                for x in at[0]..=at[0] + size {
                    f([x, y, z], &mut self.field[local([x, y, z])]);
                }
            }
        }
    }
}

/// The trees a chunk the surface passes through is meshed with.
struct Culled {
    /// Culled to the chunk and one voxel more on every side: the neighbours that decide a
    /// pinhole (see `class`).
    chunk: Node,
    /// Culled to each octant ([`octant_of`]); `None` where the field is zero throughout it or
    /// proven on one side of the iso-value.
    octants: [Option<Node>; 8],
}

/// Samples the field of `tree` at growth step `step` at a chunk's corners into `field`, and
/// gives the trees culled to the chunk and its octants; `None` when the surface does not pass
/// through it (proven by the culled tree or the field's range, or seen in the samples).
/// `known` first fills in the samples known already (exact, or left NaN). Samples in blocks
/// proven one-sided hold [`proven`] values; `field` is left empty when none was sampled.
fn sample(
    tree: &Node,
    grid: &Grid,
    chunk: ChunkIndex,
    step: u32,
    field: &mut Vec<f64>,
    known: impl FnOnce(&mut [f64]),
) -> Option<Culled> {
    field.clear();
    let region = grid.region(chunk);
    let tree = tree.cull(&region.padded(grid.voxel), step)?;
    one_side(&tree, &region).is_none().then_some(())?;
    field.resize(SIDE * SIDE * SIDE, f64::NAN);
    known(field);
    let mut sampler = Sampler {
        grid,
        first: Grid::first_sample(chunk),
        field,
    };
    let octants = std::array::from_fn(|octant| {
        let at = offset(octant).map(|o| o * OCTANT);
        let region = sampler.region(at, OCTANT);
        // An octant the chunk's tree keeps on one side (a third of them) is never culled.
        if let Some(inside) = one_side(&tree, &region) {
            sampler.mark(at, OCTANT, inside);
            return None;
        }
        let culled = tree.cull(&region, step);
        match &culled {
            Some(t) => sampler.block(t, at, OCTANT),
            None => sampler.mark(at, OCTANT, false),
        }
        culled
    });
    let inside = field.iter().any(|&f| f >= ISO);
    let outside = field.iter().any(|&f| f < ISO);
    (inside && outside).then_some(Culled {
        chunk: tree,
        octants,
    })
}

/// Classifies a chunk's samples (`field`, the chunk's first sample at global index `first`)
/// as inside or outside the surface, into `inside`. A sample alone in its class among its
/// fourteen neighbours along the edges of the Kuhn triangulation is a pinhole: a field that
/// dips below the iso-value (or rises above it) at one sample only, in the crease where two
/// parts meet as in a union, would give a closed bubble far smaller than a voxel, a separate
/// piece of the mesh. Such a sample takes its neighbours' class. Neighbours beyond the chunk
/// are evaluated from `tree` (culled a voxel wider than the chunk), so both chunks sharing a
/// sample decide alike.
fn class(tree: &Node, grid: &Grid, first: [i64; 3], field: &[f64], inside: &mut Vec<bool>) {
    inside.clear();
    inside.extend(field.iter().map(|&f| f >= ISO));
    let mut flips = Vec::new();
    for z in 0..SIDE {
        for y in 0..SIDE {
            for x in 0..SIDE {
                let here = local([x, y, z]);
                let mine = inside[here];
                let at = [x, y, z].map(|i| i as i64);
                let neighbours = DIRECTIONS.iter().flat_map(|d| {
                    [1i64, -1].map(|sign| -> [i64; 3] {
                        std::array::from_fn(|k| at[k] + sign * d[k] as i64)
                    })
                });
                let within = |n: &[i64; 3]| n.iter().all(|&i| (0..SIDE as i64).contains(&i));
                // The neighbours in the chunk first: most samples have one of their class there,
                // and those beyond it cost an evaluation each.
                let alone = neighbours
                    .clone()
                    .filter(within)
                    .all(|n| inside[local(n.map(|i| i as usize))] != mine)
                    && neighbours.filter(|n| !within(n)).all(|n| {
                        let p = grid.sample(std::array::from_fn(|k| first[k] + n[k]));
                        (tree.field(p) >= ISO) != mine
                    });
                if alone {
                    flips.push(here);
                }
            }
        }
    }
    for i in flips {
        inside[i] = !inside[i];
    }
}

/// The box of the grid samples inside the surface of `tree` at growth step `step`, grown by
/// one voxel: the surface's extent, to the grid's resolution.
pub fn surface_box(tree: &Node, grid: &Grid, step: u32) -> Bounds {
    let mut field = Vec::new();
    let mut inside = Bounds::EMPTY;
    for chunk in grid.chunks_touching(&tree.bounds) {
        if sample(tree, grid, chunk, step, &mut field, |_| {}).is_none() {
            continue;
        }
        let first = Grid::first_sample(chunk);
        for (i, f) in field.iter().enumerate() {
            if *f >= ISO {
                let at = at_local(i);
                inside.include(grid.sample(std::array::from_fn(|k| first[k] + at[k] as i64)));
            }
        }
    }
    if inside.is_empty() {
        tree.bounds
    } else {
        inside.padded(grid.voxel)
    }
}

/// The mesh of the surface of `tree` at growth step `step` inside one chunk; empty when the
/// chunk is proven to hold none of it. Samples and vertices that `memory` holds are taken
/// over instead of computed.
pub fn mesh_chunk(
    tree: &Node,
    grid: &Grid,
    chunk: ChunkIndex,
    step: u32,
    scratch: &mut Scratch,
    mut memory: Memory,
) -> Mesh {
    let first = Grid::first_sample(chunk);
    let global = |i: [usize; 3]| std::array::from_fn(|k| first[k] + i[k] as i64);
    // The grid edge with key `key` and the box it spans: a vertex looks at the field there only.
    let edge = |key: usize| {
        let (lo, direction) = edge_of(key);
        let hi = std::array::from_fn(|k| lo[k] + DIRECTIONS[direction][k]);
        (lo, hi)
    };
    let received = match &mut memory {
        Memory::Seams(seams) => seams.take(chunk),
        _ => Vec::new(),
    };
    scratch.known.clear();
    let culled = match &memory {
        Memory::Cache { cache, changed } if !cache.field.is_empty() => {
            let unchanged = |(lo, hi): ([usize; 3], [usize; 3])| {
                let reach = Bounds {
                    min: grid.sample(global(lo)),
                    max: grid.sample(global(hi)),
                };
                !changed.intersects(&reach)
            };
            scratch.known.extend(
                (cache.vertices.iter())
                    .filter(|(key, _)| unchanged(edge(**key)))
                    .map(|(key, v)| (*key, *v)),
            );
            sample(tree, grid, chunk, step, &mut scratch.field, |field| {
                for (i, (f, old)) in field.iter_mut().zip(&cache.field).enumerate() {
                    if old.is_finite() && !changed.contains(grid.sample(global(at_local(i)))) {
                        *f = *old;
                    }
                }
            })
        }
        _ => {
            for face in &received {
                scratch.known.extend(face.vertices.iter().copied());
            }
            sample(tree, grid, chunk, step, &mut scratch.field, |field| {
                for &(i, f) in received.iter().flat_map(|face| &face.samples) {
                    field[i] = f;
                }
            })
        }
    };
    let Some(culled) = culled else {
        match memory {
            Memory::Cache { cache, .. } => {
                cache.field.clear();
                cache.vertices.clear();
            }
            Memory::Seams(seams) => {
                seams.hand_over(grid, chunk, &scratch.field, std::iter::empty());
            }
        }
        return Mesh::default();
    };
    class(
        &culled.chunk,
        grid,
        first,
        &scratch.field,
        &mut scratch.inside,
    );
    scratch.vertex_of.resize(EDGES, u32::MAX);
    let mut mesh = Mesh::default();
    for z in 0..CHUNK as usize {
        for y in 0..CHUNK as usize {
            for x in 0..CHUNK as usize {
                let corner = |c: usize| {
                    let o = offset(c);
                    [x + o[0], y + o[1], z + o[2]]
                };
                let mask = (0..8)
                    .filter(|&c| scratch.inside[local(corner(c))])
                    .fold(0, |m, c| m | 1 << c);
                if mask == 0 || mask == 0xff {
                    continue;
                }
                // The octant's tree holds every primitive that reaches this voxel (an octant
                // without one is proven on one side, so none of its voxels gets here).
                let tree = culled.octants[octant_of([x, y, z])]
                    .as_ref()
                    .unwrap_or(&culled.chunk);
                for (tet, cuts) in TETRAHEDRA.iter().zip(&CUTS) {
                    let inside = (0..4).filter(|&i| mask & 1 << tet[i] != 0);
                    let cut = &cuts[inside.fold(0, |m, i| m | 1 << i)];
                    let mut made = [0; 4];
                    for (slot, edge) in made.iter_mut().zip(&cut.edges[..cut.edge_count]) {
                        let (lo, hi) = (corner(edge.lo), corner(edge.hi));
                        let key = edge_key(local(lo), edge.direction);
                        if scratch.vertex_of[key] == u32::MAX {
                            scratch.vertex_of[key] = mesh.next_index();
                            scratch.touched.push(key);
                            mesh.vertices.push(match scratch.known.get(key) {
                                Some(v) => v,
                                None => surface_vertex(
                                    tree,
                                    [
                                        (grid.sample(global(lo)), scratch.field[local(lo)]),
                                        (grid.sample(global(hi)), scratch.field[local(hi)]),
                                    ],
                                ),
                            });
                        }
                        *slot = scratch.vertex_of[key];
                    }
                    for triangle in &cut.triangles[..cut.triangle_count] {
                        let t = triangle.map(|i| made[i]);
                        // Whether the triangle faces from the inside corners to the outside ones.
                        let at =
                            |i: u32| DVec3::from(mesh.vertices[i as usize].position.map(f64::from));
                        let face = (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0]));
                        let flip = face.dot(DVec3::from(cut.outward)) < 0.0;
                        mesh.triangle(t, flip);
                    }
                }
            }
        }
    }
    let made = scratch
        .touched
        .iter()
        .map(|&key| (key, mesh.vertices[scratch.vertex_of[key] as usize]));
    match memory {
        Memory::Cache { cache, .. } => {
            cache.vertices.clear();
            cache.vertices.extend(made);
            std::mem::swap(&mut cache.field, &mut scratch.field);
        }
        Memory::Seams(seams) => seams.hand_over(grid, chunk, &scratch.field, made),
    }
    for key in scratch.touched.drain(..) {
        scratch.vertex_of[key] = u32::MAX;
    }
    mesh
}

/// The vertex where the field crosses the iso-value on the grid edge between two samples
/// (position, field): one probe of the tree at the linear interpolation of the samples gives
/// the field there, its exact gradient (the normal) and the primitives' blended pattern
/// coordinates, and one Newton step along the edge with that gradient moves the vertex onto
/// the surface. It is kept off the edge's ends, so that vertices of different edges never
/// coincide.
fn surface_vertex(tree: &Node, ends: [(DVec3, f64); 2]) -> Vertex {
    let [(pa, fa), (pb, fb)] = ends;
    let edge = pb - pa;
    let guess = ((ISO - fa) / (fb - fa)).clamp(1e-3, 1.0 - 1e-3);
    let Probe {
        field,
        gradient,
        paint,
    } = tree.probe(pa + edge * guess);
    let newton = guess - (field - ISO) / gradient.dot(edge);
    let t = if newton.is_finite() {
        newton.clamp(1e-3, 1.0 - 1e-3)
    } else {
        guess
    };
    let p = pa + edge * t;
    let normal = (-gradient)
        .try_normalize()
        .unwrap_or(edge.normalize() * -(fb - fa).signum());
    let surface = if paint.inner {
        Surface::Inner
    } else {
        Surface::Outer
    };
    Vertex::new(p, normal, paint.coordinates(), surface)
}

/// Chunks along each side of the blocks the whole tree is culled to before their chunks are
/// culled from that: culling a chunk from the whole tree costs more than sampling it.
const CULLED_CHUNKS: u32 = 4;

/// Every chunk of `tree` at growth step `step`, meshed and joined: the whole surface at once.
pub fn polygonize(tree: &Node, grid: &Grid, step: u32) -> Mesh {
    let mut scratch = Scratch::default();
    let mut seams = Seams::default();
    let mut mesh = Mesh::default();
    let mut blocks: Vec<Vec<ChunkIndex>> = Vec::new();
    let mut block_of = HashMap::new();
    for chunk in grid.chunks_touching(&tree.bounds) {
        let block = chunk.map(|c| c / CULLED_CHUNKS);
        let n = *block_of.entry(block).or_insert_with(|| {
            blocks.push(Vec::new());
            blocks.len() - 1
        });
        blocks[n].push(chunk);
    }
    for chunks in blocks {
        let mut region = Bounds::EMPTY;
        for &chunk in &chunks {
            region = region.union(&grid.region(chunk));
        }
        // As wide as the culls of its chunks reach (see `sample`).
        let Some(tree) = tree.cull(&region.padded(grid.voxel), step) else {
            continue;
        };
        for chunk in chunks {
            mesh.append(&mesh_chunk(
                &tree,
                grid,
                chunk,
                step,
                &mut scratch,
                Memory::Seams(&mut seams),
            ));
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forms::murex::whorl::whorl;
    use crate::presets::presets;
    use crate::spec::form::Form;

    /// The whole Murex's tree and its last growth step.
    fn murex() -> (Node, u32) {
        let preset = presets().iter().find(|p| p.id == "murex-cabritii");
        let preset = preset.expect("the Murex preset");
        let Form::Implicit(spec) = &preset.spec.form else {
            panic!("the Murex is implicit");
        };
        let rows = preset.spec.growth.rows as usize;
        let shell = whorl(spec, &preset.spec.pattern, preset.spec.seed, rows).expect("a whorl");
        (shell.tree, shell.instances - 1)
    }

    #[test]
    fn chunks_handing_on_their_faces_mesh_as_chunks_meshed_alone() {
        let (tree, step) = murex();
        let grid = Grid::new(&tree.bounds, 64);
        let whole = polygonize(&tree, &grid, step);
        let (mut scratch, mut alone) = (Scratch::default(), Mesh::default());
        for chunk in grid.chunks_touching(&tree.bounds) {
            // A cache left by nothing: every sample and vertex is computed.
            let mut cache = ChunkCache::default();
            let memory = Memory::Cache {
                cache: &mut cache,
                changed: &tree.bounds,
            };
            alone.append(&mesh_chunk(&tree, &grid, chunk, step, &mut scratch, memory));
        }
        assert!(
            whole.triangle_count() > 10_000,
            "{}",
            whole.triangle_count()
        );
        assert_eq!(whole.triangle_count(), alone.triangle_count());
        assert_eq!(whole.content_hash(), alone.content_hash());
    }

    #[test]
    fn samples_are_exact_or_proven_on_their_side_and_many_are_proven() {
        let (tree, step) = murex();
        let tree = &tree;
        let grid = Grid::new(&tree.bounds, 64);
        let (mut field, mut evaluated, mut proven, mut meshed) = (Vec::new(), 0, 0, 0);
        for chunk in grid.chunks_touching(&tree.bounds) {
            if sample(tree, &grid, chunk, step, &mut field, |_| {}).is_none() {
                continue;
            }
            meshed += 1;
            let first = Grid::first_sample(chunk);
            for (i, &f) in field.iter().enumerate() {
                let at = at_local(i);
                let p = grid.sample(std::array::from_fn(|k| first[k] + at[k] as i64));
                let exact = tree.field(p);
                if f.is_finite() {
                    assert_eq!(f.to_bits(), exact.to_bits(), "the sample at {p}");
                    evaluated += 1;
                } else {
                    assert_eq!(f > 0.0, exact >= ISO, "the side of {p} ({exact})");
                    proven += 1;
                }
            }
        }
        assert!(meshed > 100, "{meshed} chunks meshed");
        // At 64 voxels a spine is a voxel or two thick; at 256 most samples are proven.
        assert!(
            3 * proven > evaluated,
            "{proven} samples proven, {evaluated} evaluated"
        );
    }
}
