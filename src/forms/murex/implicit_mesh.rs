//! An implicit shell grown like every other: each growth step adds one generating surface to
//! the BlobTree and re-meshes only the chunks whose meshes depend on what it changes: those
//! within the boxes of the parts it adds or takes away, or near enough that the classes
//! deciding their specks reach into them (`Refinement::pieces_depending_on`). A growth step
//! here is one chunk's meshing, so that a frame's time budget can stop between any two; the
//! chunks of one instance are shown together once all are meshed, so that what is on screen is
//! always one closed surface. A chunk that no later instance reaches is final and moves to the
//! permanent mesh; the others, still open to change, make up the transient edge mesh.
//! Finishing meshes every chunk not yet final once, as it ends up: those chunks are pieces that
//! other threads may mesh apart ([`PieceMaker`]) group by group, joined in the groups' order.

use super::whorl::{Whorl, whorl};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::polygonize::{
    ChunkCache, ChunkWork, Grid, Memory, Piece, Refinement, Scratch, block_of, mesh_chunk,
    surface_box,
};
use crate::mesh::{Bounds, Capacity, Mesh};
use crate::shape::{EdgePart, GrowingShape, LineGrid, Pieces, ShapeError};
use crate::spec::form::implicit::ImplicitSpec;
use crate::spec::pattern::PatternSpec;
use glam::DVec3;
use std::collections::{BTreeMap, BTreeSet};

/// Voxels along the longest side when the shell's extent is estimated, for framing.
const ESTIMATE_RESOLUTION: u32 = 32;

/// What meshes the pieces of an implicit shell's growth apart from it: its tree and its grid
/// refined where thin parts stand, built from the same spec. A piece is a chunk of its level,
/// numbered as [`Refinement::id`] numbers it.
pub struct PieceMaker {
    tree: Node,
    refinement: Refinement,
}

impl PieceMaker {
    /// The pieces of the shell of `spec` (see [`ImplicitMesh::new`]).
    pub fn new(
        spec: &ImplicitSpec,
        pattern: &PatternSpec,
        seed: u64,
        rows: usize,
    ) -> Result<Self, ShapeError> {
        let Whorl { tree, fine, .. } = whorl(spec, pattern, seed, rows)?;
        let refinement = Refinement::new(Grid::new(&tree.bounds, spec.resolution), &fine.boxes);
        Ok(Self { tree, refinement })
    }

    /// The work of meshing the pieces numbered `ids` (one group of [`Pieces`]) at growth step
    /// `step`.
    pub fn start(&self, step: u32, ids: &[u32]) -> ChunkWork {
        self.start_onto(Mesh::default(), step, ids)
    }

    /// As [`PieceMaker::start`], the pieces' meshes appended to `mesh`. `ids` may be several
    /// groups in turn, each of one block (as [`ImplicitMesh::finish_apart`] makes them): the
    /// work meshes a block's pieces together, so the mesh is then the groups' meshes joined
    /// in their order.
    fn start_onto(&self, mesh: Mesh, step: u32, ids: &[u32]) -> ChunkWork {
        let pieces = ids.iter().map(|&n| self.refinement.piece(n)).collect();
        ChunkWork::onto(mesh, step, pieces)
    }

    /// Meshes chunks of `work` while `keep_going` allows (at least one); says whether all are.
    pub fn work(&self, work: &mut ChunkWork, keep_going: &mut dyn FnMut() -> bool) -> bool {
        work.work(&self.tree, &self.refinement, keep_going)
    }

    /// The mesh of the pieces of finished `work`, joined in the order they were given.
    pub fn finished(&self, work: ChunkWork) -> Mesh {
        work.into_mesh()
    }
}

/// The growing implicit shell.
pub struct ImplicitMesh {
    maker: PieceMaker,
    front: DVec3,
    bounds: Bounds,
    resolution: u32,
    /// (instance, piece) in growth order.
    jobs: Vec<(u32, Piece)>,
    /// The last instance reaching each piece, by its number.
    last_reach: BTreeMap<u32, u32>,
    /// Meshes of the pieces some later instance will change, by number.
    live: BTreeMap<u32, Mesh>,
    /// Meshes of the instance being meshed, shown once all its pieces are done.
    pending: Vec<(u32, Mesh)>,
    /// What meshing each live piece left behind, for meshing it again.
    caches: BTreeMap<u32, ChunkCache>,
    /// The boxes of what each growth step changes, by step.
    reach: Vec<Vec<Bounds>>,
    done: usize,
    /// The last instance shown.
    shown: Option<u32>,
    scratch: Scratch,
    line_grid: LineGrid,
}

impl ImplicitMesh {
    /// The shell of `spec`; spines placed by the pattern read `pattern` seeded by `seed`.
    pub fn new(
        spec: &ImplicitSpec,
        pattern: &PatternSpec,
        seed: u64,
        rows: usize,
    ) -> Result<Self, ShapeError> {
        let Whorl {
            tree,
            instances,
            reach,
            front,
            fine,
            ..
        } = whorl(spec, pattern, seed, rows)?;
        let refinement = Refinement::new(Grid::new(&tree.bounds, spec.resolution), &fine.boxes);
        let mut last_reach = BTreeMap::new();
        let mut jobs = Vec::new();
        for (k, boxes) in reach.iter().enumerate() {
            let ids: BTreeSet<u32> = (boxes.iter())
                .filter(|b| !b.is_empty())
                .flat_map(|b| refinement.pieces_depending_on(b))
                .map(|piece| refinement.id(piece))
                .collect();
            for id in ids {
                jobs.push((k as u32, refinement.piece(id)));
                last_reach.insert(id, k as u32);
            }
        }
        let bounds = surface_box(
            &tree,
            &Grid::new(&tree.bounds, ESTIMATE_RESOLUTION),
            instances.saturating_sub(1),
        );
        Ok(Self {
            maker: PieceMaker { tree, refinement },
            front,
            bounds,
            resolution: spec.resolution,
            jobs,
            last_reach,
            live: BTreeMap::new(),
            pending: Vec::new(),
            caches: BTreeMap::new(),
            reach,
            done: 0,
            shown: None,
            scratch: Scratch::default(),
            line_grid: LineGrid::sparse(rows as f64 / spec.turns().max(1e-3), None),
        })
    }

    /// Moves the meshes of `instance` into view: final chunks to `mesh`, the rest into the
    /// live set, which `edge` then shows.
    fn publish(&mut self, instance: u32, mesh: &mut Mesh, edge: &mut Mesh) {
        for (chunk, m) in self.pending.drain(..) {
            if self.last_reach.get(&chunk) == Some(&instance) {
                self.live.remove(&chunk);
                mesh.append(&m);
            } else {
                self.live.insert(chunk, m);
            }
        }
        edge.clear();
        for m in self.live.values() {
            edge.append(m);
        }
        self.shown = Some(instance);
    }
}

impl GrowingShape for ImplicitMesh {
    fn steps(&self) -> usize {
        self.jobs.len()
    }

    fn steps_done(&self) -> usize {
        self.done
    }

    fn capacity(&self) -> Capacity {
        // Enough for the shells we know (grown, the Murex at r voxels has about 20 r²
        // vertices before welding, with 1.75 triangles each; a plain whorl 15 r²), so that
        // growth never stops to move a large mesh: the renderer's buffers and the meshes still
        // grow when a shell needs more. Refined where its spines and bumps stand, the Murex
        // has up to 65 r² (measured at 112–256 voxels with whole chunks refined): its thin
        // parts cover most of its last whorls, and the guess is full once a quarter of the
        // grid's voxels are halved.
        let refined = self.maker.refinement.refined_share();
        let per_r2 = 20.0 + 45.0 * (4.0 * refined).min(1.0);
        let r2 = f64::from(self.resolution).powi(2);
        let vertices = (per_r2 * r2) as usize;
        Capacity {
            vertices,
            indices: vertices * 27 / 5,
        }
    }

    fn edge_capacity(&self) -> Capacity {
        self.capacity()
    }

    /// None: the capacity is a guess for growth step by step, and finishing appends each
    /// chunk's mesh as it is made, taking room an eighth at a time (`Mesh::append_sparingly`).
    fn finish_capacity(&self) -> Capacity {
        Capacity::default()
    }

    /// Each live piece is a part: a step changes the few it re-meshes. The edge joins them in
    /// the order of their numbers (`publish`), so each lies where those before it end.
    fn edge_parts(&self, _edge: &Mesh) -> Vec<EdgePart> {
        let (mut v0, mut i0) = (0, 0);
        (self.live.iter())
            .map(|(&id, m)| {
                let part = EdgePart {
                    id,
                    vertices: v0..v0 + m.vertices.len(),
                    indices: i0..i0 + m.indices.len(),
                };
                (v0, i0) = (part.vertices.end, part.indices.end);
                part
            })
            .collect()
    }

    fn bounds(&self) -> Bounds {
        self.bounds
    }

    fn line_grid(&self) -> LineGrid {
        self.line_grid
    }

    /// None: the implicit surface grows by whole sections, with no one rim.
    fn rim_length(&self, _row: usize) -> Option<f64> {
        None
    }

    fn front(&self) -> DVec3 {
        self.front
    }

    fn grow(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> bool {
        let Some(&(instance, piece)) = self.jobs.get(self.done) else {
            return false;
        };
        let linear = self.maker.refinement.id(piece);
        let mut cache = self.caches.remove(&linear).unwrap_or_default();
        let m = mesh_chunk(
            &self.maker.tree,
            &self.maker.refinement,
            piece,
            instance,
            &mut self.scratch,
            Memory::Cache {
                cache: &mut cache,
                changed: &self.reach[instance as usize],
            },
        );
        if self.last_reach.get(&linear) != Some(&instance) {
            self.caches.insert(linear, cache);
        }
        self.pending.push((linear, m));
        self.done += 1;
        let last_of_instance = self.jobs.get(self.done).is_none_or(|j| j.0 != instance);
        if last_of_instance {
            self.publish(instance, mesh, edge);
        }
        last_of_instance
    }

    /// Meshes every chunk not yet final once, as it ends up, skipping the stages between.
    fn finish(&mut self, mesh: &mut Mesh, edge: &mut Mesh) {
        if let Some(pieces) = self.finish_apart(mesh, edge) {
            // One work over all the blocks, so that they hand their faces on to each other too,
            // appending each piece to the mesh as it is made: the groups in turn, as
            // `Pieces::join` joins them, since each group is one block.
            debug_assert!({
                let block = |n: &u32| block_of(self.maker.refinement.piece(*n));
                let blocks: BTreeSet<_> = pieces.groups.iter().map(|g| block(&g[0])).collect();
                blocks.len() == pieces.groups.len()
                    && (pieces.groups.iter()).all(|g| g.iter().all(|n| block(n) == block(&g[0])))
            });
            let ids = pieces.groups.concat();
            let mut work = self
                .maker
                .start_onto(std::mem::take(mesh), pieces.step, &ids);
            self.maker.work(&mut work, &mut || true);
            *mesh = self.maker.finished(work);
        }
    }

    /// The chunks not yet final, grouped by the blocks their tree is culled to: each is meshed
    /// once, as it ends up, at the last growth step.
    fn finish_apart(&mut self, _mesh: &mut Mesh, edge: &mut Mesh) -> Option<Pieces> {
        let &(last, _) = self.jobs.last()?;
        if self.done == self.jobs.len() {
            return None;
        }
        let mut groups: Vec<Vec<u32>> = Vec::new();
        let mut group_of = BTreeMap::new();
        for (&id, &reach) in &self.last_reach {
            if self.shown.is_none_or(|shown| reach > shown) {
                let block = block_of(self.maker.refinement.piece(id));
                let n = *group_of.entry(block).or_insert_with(|| {
                    groups.push(Vec::new());
                    groups.len() - 1
                });
                groups[n].push(id);
            }
        }
        self.pending.clear();
        self.live.clear();
        self.caches.clear();
        edge.clear();
        self.shown = Some(last);
        self.done = self.jobs.len();
        Some(Pieces { step: last, groups })
    }
}
