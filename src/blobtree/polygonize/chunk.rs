//! Meshing one chunk (a piece of its level) by marching tetrahedra: a voxel's tetrahedra
//! (Kuhn's six, or a coned voxel's) hold zero, one or two triangles each; a vertex sits where
//! the field crosses the iso-value on an edge of a tetrahedron (`vertex.rs`). A piece meshes the voxels of its own
//! level only; a whole voxel beside a halved one is coned from its centre to meet it
//! (`transition.rs`, `refinement.rs`).

use super::grid::{CHUNK, Grid, SIDE, at_local, local};
use super::memory::{Known, Memory};
use super::refinement::{Piece, Refinement};
use super::sample::{Culled, FineClasses, class, octant_of, one_side, sample};
use super::tetrahedra::{CUTS, DIRECTIONS, EDGES, TETRAHEDRA, edge_key, edge_of, offset};
use super::transition::{Point, coned, cut};
use super::vertex::surface_vertex;
use crate::blobtree::blob_tree::Node;
use crate::mesh::{Bounds, Mesh, Vertex};

/// Buffers reused from chunk to chunk.
#[derive(Default)]
pub struct Scratch {
    pub(super) field: Vec<f64>,
    /// Whether each sample counts as inside.
    inside: Vec<bool>,
    /// Vertex of each (sample, direction) edge met so far in this chunk, or `u32::MAX`.
    vertex_of: Vec<u32>,
    touched: Vec<usize>,
    /// Vertices taken over from a [`Memory`].
    known: Known,
    /// What a chunk beside halved voxels knows of the points of the finest lattice.
    judged: Vec<u8>,
}

/// The mesh of the surface of `tree` at growth step `step` inside one piece of the grid
/// `refinement` refines; empty when the piece is proven to hold none of it. Samples and
/// vertices that `memory` holds are taken over instead of computed.
pub fn mesh_chunk(
    tree: &Node,
    refinement: &Refinement,
    piece: Piece,
    step: u32,
    scratch: &mut Scratch,
    mut memory: Memory,
) -> Mesh {
    let grid = &refinement.grid_at(piece.level);
    let chunk = piece.chunk;
    let first = Grid::first_sample(chunk);
    let global = |i: [usize; 3]| std::array::from_fn(|k| first[k] + i[k] as i64);
    let whole = piece.level == 0;
    // Whether voxels of the other level stand in the piece or beside it: only then is a
    // voxel's level asked.
    let around = whole.then(|| refinement.halved_around(chunk)).flatten();
    let mixed = if whole {
        around.is_some()
    } else {
        refinement.halved_in_cell(chunk) != u64::MAX
    };
    // The grid edge with key `key` and the box it spans: a vertex looks at the field there only.
    let edge = |key: usize| {
        let (lo, direction) = edge_of(key);
        let hi = std::array::from_fn(|k| lo[k] + DIRECTIONS[direction][k]);
        (lo, hi)
    };
    let received = match &mut memory {
        Memory::Seams(seams) => seams.take(piece),
        _ => Vec::new(),
    };
    scratch.known.clear();
    // What is known already: the cache's samples and vertices outside the changed boxes, or
    // what the neighbours handed over.
    match &memory {
        Memory::Cache { cache, changed } if !cache.field.is_empty() => {
            let unchanged = |(lo, hi): ([usize; 3], [usize; 3])| {
                let reach = Bounds {
                    min: grid.sample(global(lo)),
                    max: grid.sample(global(hi)),
                };
                !changed.iter().any(|b| b.intersects(&reach))
            };
            scratch.known.extend(
                (cache.vertices.iter())
                    .filter(|(key, _)| unchanged(edge(**key)))
                    .map(|(key, v)| (*key, *v)),
            );
        }
        _ => {
            for face in &received {
                scratch.known.extend(face.vertices.iter().copied());
            }
        }
    }
    let culled = sample(
        tree,
        grid,
        chunk,
        step,
        &mut scratch.field,
        whole && mixed,
        |field| match &memory {
            Memory::Cache { cache, changed } if !cache.field.is_empty() => {
                for (i, (f, old)) in field.iter_mut().zip(&cache.field).enumerate() {
                    let at = grid.sample(global(at_local(i)));
                    if old.is_finite() && !changed.iter().any(|b| b.contains(at)) {
                        *f = *old;
                    }
                }
            }
            _ => {
                for &(i, f) in received.iter().flat_map(|face| &face.samples) {
                    field[i] = f;
                }
            }
        },
    );
    let Some(culled) = culled else {
        match memory {
            Memory::Cache { cache, .. } => {
                cache.field.clear();
                cache.vertices.clear();
                cache.judged.clear();
            }
            Memory::Seams(seams) => {
                seams.hand_over(grid, piece, &scratch.field, std::iter::empty());
            }
        }
        return Mesh::default();
    };
    let mut fine = (whole && mixed).then(|| {
        let at = (grid, chunk);
        let buffer = std::mem::take(&mut scratch.judged);
        let mut fine = FineClasses::new(
            (tree, step),
            refinement,
            at,
            (&culled, &scratch.field),
            buffer,
        );
        if let Memory::Cache { cache, changed } = &memory {
            fine.take_over(&cache.judged, changed);
        }
        fine
    });
    class(
        (tree, step),
        grid,
        chunk,
        &scratch.field,
        &mut scratch.inside,
        whole.then_some(refinement),
        fine.as_mut(),
    );
    scratch.vertex_of.resize(EDGES, u32::MAX);
    let cell = if whole {
        0
    } else {
        refinement.halved_in_cell(chunk)
    };
    let mut mesh = Mesh::default();
    for z in 0..CHUNK as usize {
        for y in 0..CHUNK as usize {
            for x in 0..CHUNK as usize {
                if let Some(around) = &around {
                    let v = global([x, y, z]);
                    if around.is_halved(v) {
                        continue;
                    }
                    let tetrahedra = around.beside(v).then(|| coned(v, &|w| around.is_halved(w)));
                    if let Some(tetrahedra) = tetrahedra.flatten() {
                        // A coned voxel's samples and vertices take the octant's tree too;
                        // an octant without one is proven on one side.
                        if let Some(tree) = &culled.octants[octant_of([x, y, z])] {
                            // A voxel whose field is proven on the side its corners all take
                            // holds no surface: every point of it takes that side, in a
                            // component larger than a speck.
                            let corners = (0..8).map(|c| {
                                let o = offset(c);
                                scratch.inside[local([x + o[0], y + o[1], z + o[2]])]
                            });
                            let side = corners.clone().all(|c| c) || !corners.clone().any(|c| c);
                            let region = Bounds {
                                min: grid.sample(v),
                                max: grid.sample(v.map(|c| c + 1)),
                            };
                            let inside = scratch.inside[local([x, y, z])];
                            if side && one_side(tree, &region) == Some(inside) {
                                continue;
                            }
                            let fine = fine
                                .as_mut()
                                .expect("judged in a chunk beside halved voxels");
                            let at = Coned {
                                tree,
                                refinement,
                                first,
                            };
                            at.mesh(&tetrahedra, scratch, fine, &mut mesh);
                        }
                        continue;
                    }
                } else if mixed {
                    // A voxel of the cell whose whole voxel is not halved is meshed whole.
                    let bit = (x / 2) + 4 * (y / 2) + 16 * (z / 2);
                    if cell & 1 << bit == 0 {
                        continue;
                    }
                }
                kuhn_voxel([x, y, z], &culled, grid, global, scratch, &mut mesh);
            }
        }
    }
    let judged = fine.map(|fine| {
        let judged = fine.judged();
        scratch.judged = fine.into_buffer();
        judged
    });
    let made = scratch
        .touched
        .iter()
        .map(|&key| (key, mesh.vertices[scratch.vertex_of[key] as usize]));
    match memory {
        Memory::Cache { cache, .. } => {
            cache.vertices.clear();
            cache.vertices.extend(made);
            std::mem::swap(&mut cache.field, &mut scratch.field);
            cache.judged = judged.unwrap_or_default();
        }
        Memory::Seams(seams) => seams.hand_over(grid, piece, &scratch.field, made),
    }
    for key in scratch.touched.drain(..) {
        scratch.vertex_of[key] = u32::MAX;
    }
    mesh
}

/// Meshes the voxel whose lowest sample is `[x, y, z]` (in the chunk) as Kuhn's six
/// tetrahedra.
fn kuhn_voxel(
    [x, y, z]: [usize; 3],
    culled: &Culled,
    grid: &Grid,
    global: impl Fn([usize; 3]) -> [i64; 3],
    scratch: &mut Scratch,
    mesh: &mut Mesh,
) {
    let corner = |c: usize| {
        let o = offset(c);
        [x + o[0], y + o[1], z + o[2]]
    };
    let mask = (0..8)
        .filter(|&c| scratch.inside[local(corner(c))])
        .fold(0, |m, c| m | 1 << c);
    if mask == 0 || mask == 0xff {
        return;
    }
    // The octant's tree holds every primitive that reaches this voxel (an octant without one
    // is proven on one side, so none of its voxels gets here).
    let tree = culled.octants[octant_of([x, y, z])]
        .as_ref()
        .unwrap_or(&culled.chunk);
    for (tet, cuts) in TETRAHEDRA.iter().zip(&CUTS) {
        let inside = (0..4).filter(|&i| mask & 1 << tet[i] != 0);
        let cut = &cuts[inside.fold(0, |m, i| m | 1 << i)];
        let mut made = [0; 4];
        for (slot, edge) in made.iter_mut().zip(&cut.edges[..cut.edge_count]) {
            let (lo, hi) = (corner(edge.lo), corner(edge.hi));
            let ends = [lo, hi].map(|i| (grid.sample(global(i)), scratch.field[local(i)]));
            let key = edge_key(local(lo), edge.direction);
            *slot = grid_vertex(scratch, mesh, key, || surface_vertex(tree, ends));
        }
        for triangle in &cut.triangles[..cut.triangle_count] {
            mesh.triangle(triangle.map(|i| made[i]), false);
        }
    }
}

/// The vertex on the grid edge with key `key`: the one made already in this chunk, else the
/// one known, else `make`'s.
fn grid_vertex(
    scratch: &mut Scratch,
    mesh: &mut Mesh,
    key: usize,
    make: impl FnOnce() -> Vertex,
) -> u32 {
    if scratch.vertex_of[key] == u32::MAX {
        scratch.vertex_of[key] = mesh.next_index();
        scratch.touched.push(key);
        mesh.vertices
            .push(scratch.known.get(key).unwrap_or_else(make));
    }
    scratch.vertex_of[key]
}

/// A whole voxel of a chunk of level 0 coned to meet halved neighbours.
struct Coned<'a> {
    /// The tree of the voxel's octant.
    tree: &'a Node,
    refinement: &'a Refinement,
    /// The chunk's first sample (global index of level 0).
    first: [i64; 3],
}

impl Coned<'_> {
    /// The chunk's sample at the finest point `q`, when `q` is one (a corner of a whole voxel).
    fn sample_of(&self, q: Point) -> Option<[usize; 3]> {
        let i: [i64; 3] = std::array::from_fn(|k| q[k].div_euclid(2) - self.first[k]);
        let on_grid = q.iter().all(|c| c.rem_euclid(2) == 0);
        (on_grid && i.iter().all(|c| (0..SIDE as i64).contains(c))).then(|| i.map(|c| c as usize))
    }

    /// The field at `q` and whether it counts as inside: a corner's sample and class, as the
    /// chunk decided them (the field evaluated where its block was proven one-sided), or the
    /// field evaluated at another point of the finest lattice and the class `fine` judges
    /// there, as every voxel holding the point judges it.
    fn value(&self, q: Point, scratch: &Scratch, fine: &mut FineClasses) -> (f64, bool) {
        let evaluate = || self.tree.field(self.refinement.point(q));
        match self.sample_of(q) {
            Some(i) => {
                let f = scratch.field[local(i)];
                (
                    if f.is_finite() { f } else { evaluate() },
                    scratch.inside[local(i)],
                )
            }
            None => (evaluate(), fine.class(q)),
        }
    }

    /// Meshes the voxel's `tetrahedra`, whose points are the 3³ points of the finest lattice
    /// in it.
    fn mesh(
        &self,
        tetrahedra: &[[Point; 4]],
        scratch: &mut Scratch,
        fine: &mut FineClasses,
        mesh: &mut Mesh,
    ) {
        let base = tetrahedra[0][3].map(|c| c - 1);
        let slot =
            |q: Point| ((q[0] - base[0]) + 3 * (q[1] - base[1]) + 9 * (q[2] - base[2])) as usize;
        let mut values: [Option<(f64, bool)>; 27] = [None; 27];
        // The vertices made on edges that are not grid edges, by their ends in order.
        let mut between: Vec<((Point, Point), u32)> = Vec::new();
        for tet in tetrahedra {
            let at =
                tet.map(|q| *values[slot(q)].get_or_insert_with(|| self.value(q, scratch, fine)));
            for triangle in cut(tet, at.map(|(_, inside)| inside)) {
                let t = triangle.map(|(a, b)| {
                    // In one order, whichever voxel meets the edge.
                    let (lo, hi) = if tet[a] < tet[b] { (a, b) } else { (b, a) };
                    let ends = [lo, hi].map(|i| (self.refinement.point(tet[i]), at[i].0));
                    let make = || surface_vertex(self.tree, ends);
                    let key = (tet[lo], tet[hi]);
                    match self.grid_edge(key.0, key.1) {
                        Some(edge) => grid_vertex(scratch, mesh, edge, make),
                        None => match between.iter().find(|(k, _)| *k == key) {
                            Some(&(_, v)) => v,
                            None => {
                                mesh.vertices.push(make());
                                between.push((key, mesh.next_index() - 1));
                                mesh.next_index() - 1
                            }
                        },
                    }
                });
                mesh.triangle(t, false);
            }
        }
    }

    /// The key of the chunk's grid edge from `lo` to `hi` (finest points), when it is one.
    fn grid_edge(&self, lo: Point, hi: Point) -> Option<usize> {
        let (a, b) = (self.sample_of(lo)?, self.sample_of(hi)?);
        let d: [usize; 3] = std::array::from_fn(|k| b[k].wrapping_sub(a[k]));
        let direction = DIRECTIONS.iter().position(|&e| e == d)?;
        Some(edge_key(local(a), direction))
    }
}
