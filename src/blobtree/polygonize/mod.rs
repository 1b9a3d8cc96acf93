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
//! outside the boxes its tree changed in ([`ChunkCache`]). Voxels where thin parts stand are
//! halved, and the whole voxels beside them split to meet them, so that the surface is closed
//! across the levels with every sample the field itself ([`Refinement`]).

mod chunk;
mod grid;
mod memory;
mod refinement;
mod sample;
#[cfg(test)]
mod test_shell;
mod tetrahedra;
mod transition;
mod vertex;

pub use chunk::{Scratch, mesh_chunk};
pub use grid::{CHUNK, ChunkIndex, Grid};
pub use memory::{ChunkCache, Memory, Seams};
pub use refinement::{MAX_LEVEL, Piece, Refinement};
pub(crate) use sample::SPECK;
pub use sample::surface_box;

use crate::blobtree::blob_tree::Node;
use crate::mesh::{Bounds, Mesh};
use sample::REACH;
use std::collections::HashMap;

/// Chunks along each side of the blocks the whole tree is culled to before their chunks are
/// culled from that: culling a chunk from the whole tree costs more than sampling it.
const CULLED_CHUNKS: u32 = 4;

/// A block of pieces culled together: their level, and the block's place in that level's grid.
pub type Block = (u32, [u32; 3]);

/// The block of pieces of its level that `piece` is culled with.
pub fn block_of(piece: Piece) -> Block {
    (piece.level, piece.chunk.map(|c| c / CULLED_CHUNKS))
}

/// Every piece of `tree` at growth step `step`, meshed and joined: the whole surface at once.
pub fn polygonize(tree: &Node, refinement: &Refinement, step: u32) -> Mesh {
    let mut work = ChunkWork::new(step, refinement.pieces_touching(&tree.bounds));
    work.work(tree, refinement, &mut || true);
    work.into_mesh()
}

impl Refinement {
    /// The pieces meshed whose meshes depend on the field inside `b`: those whose samples
    /// reach into it, or whose specks' classes do (within `REACH` voxels of their level, see
    /// `sample.rs`). Growth re-meshes them when the tree changes inside `b`.
    pub fn pieces_depending_on(&self, b: &Bounds) -> Vec<Piece> {
        self.pieces_near(b, REACH)
    }
}

/// Chunks meshed one after another from one tree at one growth step, a few at a time if need
/// be: grouped by block (in the order each block first appears), each block's tree culled
/// once, and every chunk handing the samples and vertices on its faces to the neighbours met
/// after it ([`Seams`]). A chunk's mesh is the same, bit for bit, whichever other chunks are
/// meshed with it, so the chunks of a surface may be shared out among workers and their meshes
/// joined in a fixed order. Each chunk's mesh is appended to one mesh as soon as it is made,
/// so meshing holds no second copy of the surface.
pub struct ChunkWork {
    step: u32,
    chunks: Vec<Piece>,
    next: usize,
    /// The block being meshed and its tree, `None` where nothing of the tree reaches it.
    block: Option<(Block, Option<Node>)>,
    seams: Seams,
    scratch: Scratch,
    mesh: Mesh,
}

impl ChunkWork {
    /// The work of meshing the pieces `chunks` at growth step `step`, grouped by block in
    /// the order each block first appears (the order their meshes are joined in).
    pub fn new(step: u32, chunks: Vec<Piece>) -> Self {
        Self::onto(Mesh::default(), step, chunks)
    }

    /// As [`ChunkWork::new`], the chunks' meshes appended to `mesh`.
    pub fn onto(mesh: Mesh, step: u32, chunks: Vec<Piece>) -> Self {
        let mut order: Vec<Block> = Vec::new();
        let mut of_block: HashMap<Block, Vec<Piece>> = HashMap::new();
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
            mesh,
        }
    }

    /// Meshes pieces of `tree` on the grid `refinement` refines while `keep_going` allows (at
    /// least one); says whether all are meshed.
    pub fn work(
        &mut self,
        tree: &Node,
        refinement: &Refinement,
        keep_going: &mut dyn FnMut() -> bool,
    ) -> bool {
        let mut first = true;
        while self.next < self.chunks.len() && (first || keep_going()) {
            first = false;
            let chunk = self.chunks[self.next];
            let block = block_of(chunk);
            if self.block.as_ref().is_none_or(|(b, _)| *b != block) {
                let grid = refinement.grid_at(chunk.level);
                let mut region = Bounds::EMPTY;
                for &c in self.chunks[self.next..]
                    .iter()
                    .take_while(|&&c| block_of(c) == block)
                {
                    region = region.union(&grid.region(c.chunk));
                }
                // As wide as the classes deciding its chunks' specks reach (see `sample.rs`).
                let culled = tree.cull(&region.padded(REACH * grid.voxel), self.step);
                self.block = Some((block, culled));
            }
            self.next += 1;
            let Some((_, Some(tree))) = &self.block else {
                continue;
            };
            let mesh = mesh_chunk(
                tree,
                refinement,
                chunk,
                self.step,
                &mut self.scratch,
                Memory::Seams(&mut self.seams),
            );
            self.mesh.append_sparingly(&mesh);
        }
        self.is_done()
    }

    /// Whether every chunk is meshed.
    pub fn is_done(&self) -> bool {
        self.next >= self.chunks.len()
    }

    /// The mesh the chunks were appended to, in the order they were meshed.
    pub fn into_mesh(self) -> Mesh {
        self.mesh
    }
}

#[cfg(test)]
mod tests {
    use super::test_shell::test_shell;
    use super::*;
    use crate::mesh::Bounds;

    #[test]
    fn chunks_handing_on_their_faces_mesh_as_chunks_meshed_alone() {
        let (tree, step) = test_shell();
        let refinement = Refinement::uniform(Grid::new(&tree.bounds, 64));
        let whole = polygonize(&tree, &refinement, step);
        let (mut scratch, mut alone) = (Scratch::default(), Mesh::default());
        for chunk in refinement.pieces_touching(&tree.bounds) {
            // A cache left by nothing: every sample and vertex is computed.
            let mut cache = ChunkCache::default();
            let memory = Memory::Cache {
                cache: &mut cache,
                changed: std::slice::from_ref(&tree.bounds),
            };
            alone.append(&mesh_chunk(
                &tree,
                &refinement,
                chunk,
                step,
                &mut scratch,
                memory,
            ));
        }
        assert!(
            whole.triangle_count() > 10_000,
            "{}",
            whole.triangle_count()
        );
        assert_eq!(whole.triangle_count(), alone.triangle_count());
        assert_eq!(whole.content_hash(), alone.content_hash());
    }

    /// Each directed edge (by welded position) with the number of triangles using it.
    fn directed_edges(mesh: &Mesh) -> HashMap<([u32; 3], [u32; 3]), usize> {
        let key = |i: u32| mesh.vertices[i as usize].position.map(f32::to_bits);
        let mut edges = HashMap::new();
        for t in mesh.indices.chunks_exact(3) {
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                *edges.entry((key(a), key(b))).or_insert(0) += 1;
            }
        }
        edges
    }

    #[test]
    fn specks_the_grid_makes_are_dropped_and_parts_it_can_draw_are_kept() {
        use crate::blobtree::falloff::support_of;
        use crate::blobtree::primitive::Primitive;
        use crate::blobtree::texture_blend::Texture;
        use glam::DVec3;
        // Voxels of side 1, samples at whole coordinates, chunk faces at 6, 14, 22, 30.
        let grid = Grid::new(
            &Bounds {
                min: DVec3::ZERO,
                max: DVec3::splat(40.0),
            },
            40,
        );
        let leaf = |primitive| Node::leaf(primitive, Texture::around(0.0));
        let ball = |centre: DVec3, radius: f64| {
            leaf(Primitive::Point {
                centre,
                radius: support_of(radius),
            })
        };
        let rod = |from: DVec3, to: DVec3| {
            leaf(Primitive::Cone {
                from,
                to,
                radii: [0.3; 2].map(support_of),
            })
        };
        // Holding one sample each: a bubble in a chunk's face, a speck at a chunk's corner
        // and one inside a chunk; a rod five samples long across a chunk's face; and a ball
        // 27 samples large, which the grid draws.
        let bubble = DVec3::new(14.0, 10.0, 10.0);
        let specks = [DVec3::splat(30.0), DVec3::new(26.0, 10.0, 27.0)];
        let (rod_from, rod_to) = (DVec3::new(20.0, 25.0, 10.0), DVec3::new(24.0, 25.0, 10.0));
        let kept = DVec3::new(30.0, 10.0, 30.0);
        let body = Node::difference(ball(DVec3::splat(10.0), 6.0), ball(bubble, 0.3));
        let parts = [body, rod(rod_from, rod_to), ball(kept, 1.8)];
        let specks_and_all = specks.iter().map(|&c| ball(c, 0.3));
        let tree = Node::union(parts.into_iter().chain(specks_and_all).collect());
        let mesh = polygonize(&tree, &Refinement::uniform(grid), 0);
        let near = |p: DVec3, reach: f64| {
            (mesh.vertices.iter())
                .any(|v| (DVec3::from(v.position.map(f64::from)) - p).length() < reach)
        };
        for p in [bubble, rod_from, (rod_from + rod_to) * 0.5, rod_to]
            .into_iter()
            .chain(specks)
        {
            assert!(!near(p, 1.0), "a speck at {p} is drawn");
        }
        assert!(near(kept, 2.0), "the ball at {kept} is not drawn");
        let edges = directed_edges(&mesh);
        assert!(
            (edges.iter()).all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1)),
            "the mesh is not closed"
        );
    }

    #[test]
    fn a_piece_meshes_alike_whatever_changes_beyond_what_it_depends_on() {
        use crate::blobtree::falloff::support_of;
        use crate::blobtree::primitive::Primitive;
        use crate::blobtree::texture_blend::Texture;
        use glam::DVec3;
        // Voxels of side 1, samples at whole coordinates, chunk faces at 6, 14, 22, 30, ….
        let grid = Grid::new(
            &Bounds {
                min: DVec3::ZERO,
                max: DVec3::splat(80.0),
            },
            80,
        );
        let refinement = Refinement::uniform(grid);
        let rod = |from: f64, to: f64| {
            let at = |x: f64| DVec3::new(x, 25.0, 10.0);
            Node::leaf(
                Primitive::Cone {
                    from: at(from),
                    to: at(to),
                    radii: [0.3; 2].map(support_of),
                },
                Texture::around(0.0),
            )
        };
        let ball = Node::leaf(
            Primitive::Point {
                centre: DVec3::splat(60.0),
                radius: support_of(8.0),
            },
            Texture::around(0.0),
        );
        // A rod five samples long across the chunk face at x = 30: a speck. A second rod,
        // ending where the first starts, makes both one part the grid draws; the box of what
        // it adds ends a chunk before the first rod's far end.
        let before = Node::union(vec![ball.clone(), rod(28.0, 32.0)]);
        let after = Node::union(vec![ball, rod(28.0, 32.0), rod(14.0, 28.0)]);
        let changed = rod(14.0, 28.0).bounds;
        let mesh = |tree: &Node, piece: Piece| {
            let mut cache = ChunkCache::default();
            let memory = Memory::Cache {
                cache: &mut cache,
                changed: std::slice::from_ref(&tree.bounds),
            };
            mesh_chunk(tree, &refinement, piece, 0, &mut Scratch::default(), memory)
        };
        let depending: Vec<Piece> = refinement.pieces_depending_on(&changed);
        let touching = refinement.pieces_touching(&changed);
        let all = refinement.pieces_touching(&after.bounds);
        let (mut independent, mut changed_beyond) = (0, 0);
        for piece in all {
            let alike = mesh(&before, piece).content_hash() == mesh(&after, piece).content_hash();
            if !depending.contains(&piece) {
                assert!(alike, "{piece:?} changed, not depending on {changed:?}");
                independent += 1;
            } else if !touching.contains(&piece) && !alike {
                changed_beyond += 1;
            }
        }
        assert!(independent > 100, "{independent} pieces independent");
        assert!(
            changed_beyond > 0,
            "no piece beyond the box changed: the speck is not where the test needs it"
        );
    }

    /// The directed edges (by welded position) used other than once, or without their
    /// reverse: none in a closed surface wound one way.
    fn unpaired(mesh: &Mesh) -> Vec<([f32; 3], [f32; 3], usize)> {
        let edges = directed_edges(mesh);
        edges
            .iter()
            .filter(|&(&(a, b), &n)| n != 1 || edges.get(&(b, a)) != Some(&1))
            .map(|(&(a, b), &n)| (a.map(f32::from_bits), b.map(f32::from_bits), n))
            .collect()
    }

    #[test]
    fn a_speck_beside_a_halved_voxel_is_judged_alike_by_every_chunk_holding_it() {
        use crate::blobtree::falloff::support_of;
        use crate::blobtree::primitive::Primitive;
        use crate::blobtree::texture_blend::Texture;
        use glam::DVec3;
        // Voxels of side 1, samples at whole coordinates, chunk faces at 6, 14, 22, 30: a rod
        // holding two samples across the chunk face at x = 14, the first a corner of a voxel
        // halved in the chunk below, the second beside no halved voxel in the chunk above,
        // which must not flip it either.
        let grid = Grid::new(
            &Bounds {
                min: DVec3::ZERO,
                max: DVec3::splat(40.0),
            },
            40,
        );
        let voxel = Bounds {
            min: DVec3::new(12.25, 10.25, 10.25),
            max: DVec3::new(12.75, 10.75, 10.75),
        };
        let refinement = Refinement::new(grid, &[(voxel, MAX_LEVEL)]);
        let leaf = |primitive| Node::leaf(primitive, Texture::around(0.0));
        let rod = leaf(Primitive::Cone {
            from: DVec3::new(13.0, 10.0, 10.0),
            to: DVec3::new(14.0, 10.0, 10.0),
            radii: [0.3; 2].map(support_of),
        });
        let ball = leaf(Primitive::Point {
            centre: DVec3::splat(30.0),
            radius: support_of(5.0),
        });
        let mesh = polygonize(&Node::union(vec![ball, rod]), &refinement, 0);
        let bad = unpaired(&mesh);
        assert!(
            mesh.triangle_count() > 100 && bad.is_empty(),
            "{} edges not paired: {:?}",
            bad.len(),
            &bad[..bad.len().min(6)]
        );
    }

    #[test]
    fn a_grid_every_voxel_of_which_is_halved_meshes_as_the_grid_of_halved_voxels() {
        let (tree, step) = test_shell();
        let grid = Grid::new(&tree.bounds, 24);
        let everything = (tree.bounds.padded(8.0 * grid.voxel), MAX_LEVEL);
        let halved = polygonize(&tree, &Refinement::new(grid, &[everything]), step);
        let fine = polygonize(&tree, &Refinement::uniform(grid.halved()), step);
        assert!(fine.triangle_count() > 10_000, "{}", fine.triangle_count());
        assert_eq!(halved.triangle_count(), fine.triangle_count());
        assert_eq!(halved.content_hash(), fine.content_hash());
    }

    /// Random levels, with `proptest` (a native test dependency).
    #[cfg(not(target_arch = "wasm32"))]
    mod random_levels {
        use super::super::test_shell::test_shell;
        use super::super::*;
        use super::unpaired;
        use crate::mesh::Bounds;

        /// Six times the volume `mesh` encloses, positive when its triangles face out.
        fn six_volumes(mesh: &Mesh) -> f64 {
            let at = |i: u32| glam::DVec3::from(mesh.vertices[i as usize].position.map(f64::from));
            (mesh.indices.chunks_exact(3))
                .map(|t| at(t[0]).dot(at(t[1]).cross(at(t[2]))))
                .sum()
        }

        proptest::proptest! {
            #![proptest_config(proptest::prelude::ProptestConfig::with_cases(12))]
            #[test]
            fn voxels_halved_at_random_join_into_one_closed_surface_facing_out(
                seed in proptest::prelude::any::<u64>(),
                share in 0.02..0.7f64,
            ) {
                use rand_core::{Rng, SeedableRng};
                let (tree, step) = test_shell();
                let grid = Grid::new(&tree.bounds, 32);
                let mut random = rand_pcg::Pcg32::seed_from_u64(seed);
                let voxels = grid.chunks.map(|c| i64::from(c * CHUNK));
                let mut parts = Vec::new();
                for z in 0..voxels[2] {
                    for y in 0..voxels[1] {
                        for x in 0..voxels[0] {
                            if f64::from(random.next_u32()) < share * 4_294_967_296.0 {
                                let centre = grid.sample([x, y, z]) + glam::DVec3::splat(grid.voxel / 2.0);
                                let box_of = Bounds { min: centre, max: centre };
                                parts.push((box_of.padded(grid.voxel / 4.0), 1));
                            }
                        }
                    }
                }
                let refinement = Refinement::new(grid, &parts);
                let mesh = polygonize(&tree, &refinement, step);
                let whole = polygonize(&tree, &Refinement::uniform(grid), step);
                let halved = polygonize(&tree, &Refinement::uniform(grid.halved()), step);
                let bad = unpaired(&mesh);
                proptest::prop_assert!(bad.is_empty(), "{} edges not paired: {:?}", bad.len(), &bad[..bad.len().min(6)]);
                // As much solid as with no voxel halved, or every one, or between (the grid
                // misses thin parts where its voxels are whole): nothing lost or doubled where
                // the levels meet.
                let v = six_volumes(&mesh);
                let ends = [six_volumes(&whole), six_volumes(&halved)];
                let (lo, hi) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
                proptest::prop_assert!(
                    v > lo * 0.995 && v < hi * 1.005,
                    "volume ×6 {} against {:?} with no voxel halved and every one", v, ends
                );
            }
        }
    }

    #[test]
    fn pieces_of_every_level_join_into_one_closed_surface() {
        let (tree, step) = test_shell();
        let grid = Grid::new(&tree.bounds, 48);
        // Voxels halved over two overlapping boxes, across chunk faces.
        let size = tree.bounds.max - tree.bounds.min;
        let part = |from: f64, to: f64| Bounds {
            min: tree.bounds.min + size * from,
            max: tree.bounds.min + size * to,
        };
        let parts = [(part(0.3, 0.6), MAX_LEVEL), (part(0.5, 0.9), 1)];
        let refinement = Refinement::new(grid, &parts);
        let mut levels = [0; MAX_LEVEL as usize + 1];
        for piece in refinement.pieces_touching(&tree.bounds) {
            levels[piece.level as usize] += 1;
        }
        assert!(
            levels.iter().all(|&n| n > 30),
            "pieces at each level: {levels:?}"
        );
        let mesh = polygonize(&tree, &refinement, step);
        let uniform = polygonize(&tree, &Refinement::uniform(grid), step);
        assert!(
            mesh.triangle_count() > uniform.triangle_count() * 3 / 2,
            "{} triangles refined, {} not",
            mesh.triangle_count(),
            uniform.triangle_count()
        );
        let bad = unpaired(&mesh);
        assert!(
            bad.is_empty(),
            "{} edges not paired: {:?}",
            bad.len(),
            &bad[..bad.len().min(6)]
        );
    }
}
