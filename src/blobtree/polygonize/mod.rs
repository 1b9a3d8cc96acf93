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

/// The block of chunks that `chunk` is culled with.
pub fn block_of(chunk: ChunkIndex) -> [u32; 3] {
    chunk.map(|c| c / CULLED_CHUNKS)
}

/// Every chunk of `tree` at growth step `step`, meshed and joined: the whole surface at once.
pub fn polygonize(tree: &Node, grid: &Grid, step: u32) -> Mesh {
    let mut work = ChunkWork::new(step, grid.chunks_touching(&tree.bounds));
    work.work(tree, grid, &mut || true);
    let mut mesh = Mesh::default();
    for (_, m) in work.into_meshes() {
        mesh.append(&m);
    }
    mesh
}

/// Chunks meshed one after another from one tree at one growth step, a few at a time if need
/// be: grouped by block (in the order each block first appears), each block's tree culled
/// once, and every chunk handing the samples and vertices on its faces to the neighbours met
/// after it ([`Seams`]). A chunk's mesh is the same, bit for bit, whichever other chunks are
/// meshed with it, so the chunks of a surface may be shared out among workers and their meshes
/// joined in a fixed order.
pub struct ChunkWork {
    step: u32,
    chunks: Vec<ChunkIndex>,
    next: usize,
    /// The block being meshed and its tree, `None` where nothing of the tree reaches it.
    block: Option<([u32; 3], Option<Node>)>,
    seams: Seams,
    scratch: Scratch,
    meshes: Vec<(ChunkIndex, Mesh)>,
}

impl ChunkWork {
    /// The work of meshing `chunks` at growth step `step`.
    pub fn new(step: u32, chunks: Vec<ChunkIndex>) -> Self {
        let mut order: Vec<[u32; 3]> = Vec::new();
        let mut of_block: HashMap<[u32; 3], Vec<ChunkIndex>> = HashMap::new();
        for chunk in chunks {
            let block = block_of(chunk);
            of_block
                .entry(block)
                .or_insert_with(|| {
                    order.push(block);
                    Vec::new()
                })
                .push(chunk);
        }
        let chunks = order
            .iter()
            .flat_map(|b| of_block.remove(b).unwrap_or_default())
            .collect();
        Self {
            step,
            chunks,
            next: 0,
            block: None,
            seams: Seams::default(),
            scratch: Scratch::default(),
            meshes: Vec::new(),
        }
    }

    /// Meshes chunks of `tree` on `grid` while `keep_going` allows (at least one); says
    /// whether all are meshed.
    pub fn work(&mut self, tree: &Node, grid: &Grid, keep_going: &mut dyn FnMut() -> bool) -> bool {
        let mut first = true;
        while self.next < self.chunks.len() && (first || keep_going()) {
            first = false;
            let chunk = self.chunks[self.next];
            let block = block_of(chunk);
            if self.block.as_ref().is_none_or(|(b, _)| *b != block) {
                let mut region = Bounds::EMPTY;
                for &c in self.chunks[self.next..]
                    .iter()
                    .take_while(|&&c| block_of(c) == block)
                {
                    region = region.union(&grid.region(c));
                }
                // As wide as the culls of its chunks reach (see `sample`).
                let culled = tree.cull(&region.padded(grid.voxel), self.step);
                self.block = Some((block, culled));
            }
            self.next += 1;
            let Some((_, Some(tree))) = &self.block else {
                continue;
            };
            let mesh = mesh_chunk(
                tree,
                grid,
                chunk,
                self.step,
                &mut self.scratch,
                Memory::Seams(&mut self.seams),
            );
            if !mesh.indices.is_empty() {
                self.meshes.push((chunk, mesh));
            }
        }
        self.is_done()
    }

    /// Whether every chunk is meshed.
    pub fn is_done(&self) -> bool {
        self.next >= self.chunks.len()
    }

    /// The meshes of the chunks that hold part of the surface, in the order they were meshed.
    pub fn into_meshes(self) -> Vec<(ChunkIndex, Mesh)> {
        self.meshes
    }
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
