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

mod chunk;
mod grid;
mod memory;
mod sample;
#[cfg(test)]
mod test_shell;
mod tetrahedra;

pub use chunk::{Scratch, mesh_chunk};
pub use grid::{CHUNK, ChunkIndex, Grid};
pub use memory::{ChunkCache, Memory, Seams};
pub use sample::surface_box;

use crate::blobtree::blob_tree::Node;
use crate::mesh::{Bounds, Mesh};
use std::collections::HashMap;

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
    use super::test_shell::test_shell;
    use super::*;

    #[test]
    fn chunks_handing_on_their_faces_mesh_as_chunks_meshed_alone() {
        let (tree, step) = test_shell();
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
}
