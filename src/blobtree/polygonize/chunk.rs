//! Meshing one chunk (a piece of its level) by marching tetrahedra: each voxel's six
//! tetrahedra hold zero, one or two triangles; a vertex sits where the field crosses the
//! iso-value on a grid edge (`vertex.rs`). Where the piece meets pieces of another level, it
//! follows the refinement's rule (`refinement.rs`) and splits its triangles at a finer
//! neighbour's vertices.

use super::grid::{CHUNK, Grid, at_local, local};
use super::memory::{Known, Memory};
use super::refinement::{Piece, Refinement};
use super::sample::{class, octant_of, sample};
use super::tetrahedra::{CUTS, DIRECTIONS, EDGES, TETRAHEDRA, edge_key, edge_of, offset};
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
}

/// The mesh of the surface of `tree` at growth step `step` inside one piece of the grid
/// `refinement` refines; empty when the piece is proven to hold none of it. Samples and
/// vertices that `memory` holds are taken over instead of computed. Where the piece meets
/// pieces of other levels, it follows the refinement's rule (see `refinement.rs`).
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
    let finest = |i: [usize; 3]| Refinement::finest(global(i), piece.level);
    let border = refinement.borders_other_levels(piece).then_some(refinement);
    // The samples another level fixes take their values, whatever was known of them.
    let fix_border = |tree: &Node, field: &mut [f64]| {
        if let Some(r) = border {
            for (i, f) in field.iter_mut().enumerate() {
                if let Some(v) = r.interpolated(tree, finest(at_local(i))) {
                    *f = v;
                }
            }
        }
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
    // what the neighbours handed over; then the samples another level fixes.
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
        |culled, field| {
            match &memory {
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
            }
            fix_border(culled, field);
        },
    );
    let Some(culled) = culled else {
        match memory {
            Memory::Cache { cache, .. } => {
                cache.field.clear();
                cache.vertices.clear();
            }
            Memory::Seams(seams) => {
                seams.hand_over(grid, piece, &scratch.field, std::iter::empty());
            }
        }
        return Mesh::default();
    };
    class(
        tree,
        step,
        grid,
        chunk,
        &scratch.field,
        &mut scratch.inside,
        refinement,
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
                    let mut ends = [([0; 3], [0; 3]); 4];
                    for (edge_index, (slot, edge)) in made
                        .iter_mut()
                        .zip(&cut.edges[..cut.edge_count])
                        .enumerate()
                    {
                        let (lo, hi) = (corner(edge.lo), corner(edge.hi));
                        let key = edge_key(local(lo), edge.direction);
                        if scratch.vertex_of[key] == u32::MAX {
                            scratch.vertex_of[key] = mesh.next_index();
                            scratch.touched.push(key);
                            // An edge along a coarser one takes that edge's vertex.
                            let coarser = border.and_then(|r| {
                                let (a, b) = r.coarser_edge(finest(lo), finest(hi), piece.level)?;
                                Some(r.vertex(&culled.chunk, a, b))
                            });
                            mesh.vertices.push(match (coarser, scratch.known.get(key)) {
                                (Some(v), _) | (None, Some(v)) => v,
                                (None, None) => surface_vertex(
                                    tree,
                                    [
                                        (grid.sample(global(lo)), scratch.field[local(lo)]),
                                        (grid.sample(global(hi)), scratch.field[local(hi)]),
                                    ],
                                ),
                            });
                        }
                        *slot = scratch.vertex_of[key];
                        ends[edge_index] = (lo, hi);
                    }
                    for triangle in &cut.triangles[..cut.triangle_count] {
                        let t = triangle.map(|i| made[i]);
                        let Some(r) = border else {
                            mesh.triangle(t, false);
                            continue;
                        };
                        // Its sides on a face with a finer piece take that piece's vertices.
                        let e = triangle.map(|i| ends[i]);
                        let inserts = std::array::from_fn(|i| {
                            let sides = [e[i], e[(i + 1) % 3]];
                            (finer_crossings(r, &culled.chunk, piece.level, sides, &finest))
                                .into_iter()
                                .map(|v| {
                                    mesh.vertices.push(v);
                                    mesh.next_index() - 1
                                })
                                .collect()
                        });
                        split_triangle(&mut mesh, t, inserts);
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
        Memory::Seams(seams) => seams.hand_over(grid, piece, &scratch.field, made),
    }
    for key in scratch.touched.drain(..) {
        scratch.vertex_of[key] = u32::MAX;
    }
    mesh
}

/// The vertices of a finer piece across a face of this piece (of `level`) at which its mesh
/// crosses the triangle of this piece's grid that the grid edges `sides` (local samples; a
/// triangle side runs between their vertices) lie in, in order from the first side's vertex:
/// none unless both lie in a face whose piece across is finer.
fn finer_crossings(
    refinement: &Refinement,
    tree: &Node,
    level: u32,
    sides: [([usize; 3], [usize; 3]); 2],
    finest: &dyn Fn([usize; 3]) -> [i64; 3],
) -> Vec<Vertex> {
    let points = [sides[0].0, sides[0].1, sides[1].0, sides[1].1];
    let face = (0..3).find_map(|axis| {
        let c = points[0][axis];
        let on_face = points.iter().all(|p| p[axis] == c) && (c == 0 || c == CHUNK as usize);
        on_face.then_some((axis, c != 0))
    });
    let Some((axis, high)) = face else {
        return Vec::new();
    };
    let corner = std::array::from_fn(|k| points.iter().map(|&p| finest(p)[k]).min().unwrap_or(0));
    let Some(finer) = refinement.finer_across(corner, axis, high, level) else {
        return Vec::new();
    };
    let ends = sides.map(|(lo, hi)| [finest(lo), finest(hi)]);
    refinement.crossings(tree, ends, axis, [level, finer])
}

/// Pushes triangle `t`, its edge from `t[i]` to `t[i + 1]` split at the vertices `inserts[i]`
/// (in order along it): a fan from the opposite corner for the first edge split, then the same
/// for the others in the triangles of the fan that hold them. Winding is kept.
fn split_triangle(mesh: &mut Mesh, t: [u32; 3], inserts: [Vec<u32>; 3]) {
    let Some(i) = (0..3).find(|&i| !inserts[i].is_empty()) else {
        mesh.triangle(t, false);
        return;
    };
    let [a, b, c] = [t[i], t[(i + 1) % 3], t[(i + 2) % 3]];
    let [mut along, mut next, mut back] = {
        let mut inserts = inserts;
        [i, (i + 1) % 3, (i + 2) % 3].map(|k| std::mem::take(&mut inserts[k]))
    };
    let chain: Vec<u32> = std::iter::once(a)
        .chain(along.drain(..))
        .chain(std::iter::once(b))
        .collect();
    let last = chain.len() - 2;
    for (n, pair) in chain.windows(2).enumerate() {
        // The first triangle of the fan holds the edge c → a, the last the edge b → c.
        let rest = [
            Vec::new(),
            if n == last {
                std::mem::take(&mut next)
            } else {
                Vec::new()
            },
            if n == 0 {
                std::mem::take(&mut back)
            } else {
                Vec::new()
            },
        ];
        split_triangle(mesh, [pair[0], pair[1], c], rest);
    }
}
