//! Meshing one chunk by marching tetrahedra: each voxel's six tetrahedra hold zero, one or two
//! triangles; a vertex sits where the field crosses the iso-value on a grid edge, placed by one
//! Newton step, with the field's exact gradient as its normal and the primitives' blended
//! pattern coordinates.

use super::grid::{CHUNK, ChunkIndex, Grid, at_local, local};
use super::memory::{Known, Memory};
use super::sample::{class, octant_of, sample};
use super::tetrahedra::{CUTS, DIRECTIONS, EDGES, TETRAHEDRA, edge_key, edge_of, offset};
use crate::blobtree::blob_tree::{Node, Probe};
use crate::blobtree::falloff::ISO;
use crate::mesh::{Bounds, Mesh, Surface, Vertex};
use glam::DVec3;

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
/// the field there, its exact gradient (the normal) and the primitives' blended textures, and
/// one Newton step along the edge with that gradient moves the vertex onto the surface. It is
/// kept off the edge's ends, so that vertices of different edges never coincide.
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
    Vertex::new(p, normal, paint.coordinates(), surface).tinted(paint.tint())
}
