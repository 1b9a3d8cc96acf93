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
//! pattern coordinates the primitives' blended coordinates.

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

/// Buffers reused from chunk to chunk.
#[derive(Default)]
pub struct Scratch {
    field: Vec<f64>,
    /// Whether each sample counts as inside.
    inside: Vec<bool>,
    /// Vertex of each (sample, direction) edge met so far in this chunk, or `u32::MAX`.
    vertex_of: Vec<u32>,
    touched: Vec<usize>,
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

fn offset(corner: usize) -> [usize; 3] {
    [corner & 1, (corner >> 1) & 1, (corner >> 2) & 1]
}

fn local(i: [usize; 3]) -> usize {
    i[0] + SIDE * (i[1] + SIDE * i[2])
}

/// Whether the field of `tree` is proven to stay on one side of the iso-value throughout
/// `region`, by the bounds [`Node::range`] gives over the ball around it. Most chunks near a
/// surface hold none of it (about two thirds of those a Murex's boxes reach at 256³), and this
/// spares sampling them.
fn one_side(tree: &Node, region: &Bounds) -> bool {
    let (lo, hi) = tree.range(region.center(), (region.max - region.min).length() * 0.5);
    // A margin for the rounding of the bounds themselves.
    const MARGIN: f64 = 1e-9;
    hi < ISO - MARGIN || lo > ISO + MARGIN
}

/// Samples the field of `tree` at growth step `step` at a chunk's corners into `field`, and
/// gives the tree culled to the chunk; `None` when the surface does not pass through it
/// (proven by the culled tree or the field's range, or seen in the samples).
fn sample(
    tree: &Node,
    grid: &Grid,
    chunk: ChunkIndex,
    step: u32,
    field: &mut Vec<f64>,
    reuse: Option<(&Bounds, &[f64])>,
) -> Option<Node> {
    let region = grid.region(chunk);
    // One voxel more on every side: the neighbours that decide a pinhole (see `class`).
    let tree = tree.cull(&region.padded(grid.voxel), step)?;
    if one_side(&tree, &region) {
        return None;
    }
    let first = Grid::first_sample(chunk);
    field.clear();
    let (mut inside, mut outside) = (false, false);
    for z in 0..SIDE {
        for y in 0..SIDE {
            for x in 0..SIDE {
                let at = [x, y, z].map(|i| i as i64);
                let p = grid.sample(std::array::from_fn(|k| first[k] + at[k]));
                let f = match reuse {
                    Some((changed, old)) if !changed.contains(p) => old[field.len()],
                    _ => tree.field(p),
                };
                inside |= f >= ISO;
                outside |= f < ISO;
                field.push(f);
            }
        }
    }
    (inside && outside).then_some(tree)
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
        if sample(tree, grid, chunk, step, &mut field, None).is_none() {
            continue;
        }
        let first = Grid::first_sample(chunk);
        for (i, f) in field.iter().enumerate() {
            if *f >= ISO {
                let at = [i % SIDE, i / SIDE % SIDE, i / (SIDE * SIDE)].map(|i| i as i64);
                inside.include(grid.sample(std::array::from_fn(|k| first[k] + at[k])));
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
/// chunk is proven to hold none of it. With `changed`, the tree differs from when `cache` was
/// left only inside that box; the cache is rewritten either way.
pub fn mesh_chunk(
    tree: &Node,
    grid: &Grid,
    chunk: ChunkIndex,
    step: u32,
    scratch: &mut Scratch,
    cache: &mut ChunkCache,
    changed: Option<&Bounds>,
) -> Mesh {
    let changed = changed.filter(|_| !cache.field.is_empty());
    let reuse = changed.map(|b| (b, cache.field.as_slice()));
    let Some(tree) = sample(tree, grid, chunk, step, &mut scratch.field, reuse) else {
        cache.field.clear();
        cache.vertices.clear();
        return Mesh::default();
    };
    let first = Grid::first_sample(chunk);
    let global = |i: [usize; 3]| std::array::from_fn(|k| first[k] + i[k] as i64);
    class(&tree, grid, first, &scratch.field, &mut scratch.inside);
    scratch
        .vertex_of
        .resize(SIDE * SIDE * SIDE * DIRECTIONS.len(), u32::MAX);
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
                for tet in TETRAHEDRA {
                    let (mut ins, mut outs) = ([0; 4], [0; 4]);
                    let (mut n_in, mut n_out) = (0, 0);
                    for c in tet {
                        if mask & 1 << c != 0 {
                            ins[n_in] = c;
                            n_in += 1;
                        } else {
                            outs[n_out] = c;
                            n_out += 1;
                        }
                    }
                    if n_in == 0 || n_out == 0 {
                        continue;
                    }
                    let (ins, outs) = (&ins[..n_in], &outs[..n_out]);
                    let mut vertex = |a: usize, b: usize| {
                        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                        let (lo, hi) = (corner(lo), corner(hi));
                        let direction = DIRECTIONS
                            .iter()
                            .position(|d| (0..3).all(|k| lo[k] + d[k] == hi[k]))
                            .expect("Kuhn edges join dominating corners");
                        let key = local(lo) * DIRECTIONS.len() + direction;
                        if scratch.vertex_of[key] == u32::MAX {
                            scratch.vertex_of[key] = mesh.next_index();
                            scratch.touched.push(key);
                            let ends = [
                                (grid.sample(global(lo)), scratch.field[local(lo)]),
                                (grid.sample(global(hi)), scratch.field[local(hi)]),
                            ];
                            // The vertex looks at the field along its edge only.
                            let reach = Bounds {
                                min: ends[0].0,
                                max: ends[1].0,
                            };
                            let kept = changed
                                .filter(|b| !b.intersects(&reach))
                                .and_then(|_| cache.vertices.get(&key));
                            mesh.vertices.push(match kept {
                                Some(v) => *v,
                                None => surface_vertex(&tree, ends),
                            });
                        }
                        scratch.vertex_of[key]
                    };
                    let inward = |p: &Mesh, t: [u32; 3]| {
                        // Whether the triangle faces from the inside corners to the outside ones.
                        let at =
                            |i: u32| DVec3::from(p.vertices[i as usize].position.map(f64::from));
                        let face = (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0]));
                        let mean = |cs: &[usize]| {
                            cs.iter()
                                .map(|&c| {
                                    let o = offset(c);
                                    DVec3::new(o[0] as f64, o[1] as f64, o[2] as f64)
                                })
                                .sum::<DVec3>()
                                / cs.len() as f64
                        };
                        face.dot(mean(outs) - mean(ins)) < 0.0
                    };
                    let (triangles, count) = match n_in {
                        1 => {
                            let t = [
                                vertex(ins[0], outs[0]),
                                vertex(ins[0], outs[1]),
                                vertex(ins[0], outs[2]),
                            ];
                            ([t, t], 1)
                        }
                        3 => {
                            let t = [
                                vertex(outs[0], ins[0]),
                                vertex(outs[0], ins[1]),
                                vertex(outs[0], ins[2]),
                            ];
                            ([t, t], 1)
                        }
                        _ => {
                            // Two in, two out: the quad a0–b0, a0–b1, a1–b1, a1–b0.
                            let q = [
                                vertex(ins[0], outs[0]),
                                vertex(ins[0], outs[1]),
                                vertex(ins[1], outs[1]),
                                vertex(ins[1], outs[0]),
                            ];
                            ([[q[0], q[1], q[2]], [q[0], q[2], q[3]]], 2)
                        }
                    };
                    for &t in &triangles[..count] {
                        let flip = inward(&mesh, t);
                        mesh.triangle(t, flip);
                    }
                }
            }
        }
    }
    cache.vertices.clear();
    for key in scratch.touched.drain(..) {
        cache
            .vertices
            .insert(key, mesh.vertices[scratch.vertex_of[key] as usize]);
        scratch.vertex_of[key] = u32::MAX;
    }
    std::mem::swap(&mut cache.field, &mut scratch.field);
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

/// Every chunk of `tree` at growth step `step`, meshed and joined in chunk order: the whole
/// surface at once.
pub fn polygonize(tree: &Node, grid: &Grid, step: u32) -> Mesh {
    let (mut scratch, mut cache) = (Scratch::default(), ChunkCache::default());
    let mut mesh = Mesh::default();
    for chunk in grid.chunks_touching(&tree.bounds) {
        mesh.append(&mesh_chunk(
            tree,
            grid,
            chunk,
            step,
            &mut scratch,
            &mut cache,
            None,
        ));
    }
    mesh
}
