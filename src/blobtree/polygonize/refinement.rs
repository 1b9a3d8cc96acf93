//! Adaptive refinement: each chunk of the grid is meshed at its own level, its voxels halved
//! that many times (up to [`MAX_LEVEL`]), so that parts thinner than a voxel are shown where
//! they stand while the rest of the surface keeps the grid's resolution. A chunk of level ℓ is
//! meshed as the 8^ℓ chunks of the grid of level ℓ it holds, its *pieces*, each as costly as a
//! chunk of level 0, so a growth step stays one piece's meshing.
//!
//! Where chunks of different levels meet, the meshes must join without cracks. The rule:
//! a sample on the boundary of a chunk coarser than its own takes, instead of the field, the
//! piecewise-linear interpolation of the coarser grid's samples over the Kuhn triangle (or
//! edge) of that grid it lies in, the coarsest level among the chunks holding it deciding.
//! On such a face both sides then see the same linear function: the zero line through each
//! coarse triangle is one straight segment, the coarse side's triangle edge, which the finer
//! side crosses in several steps. A vertex on a finer edge lying along a coarser grid edge is
//! that edge's own vertex, computed from its ends, so both sides share it bit for bit; the
//! coarse side splits its triangle edge at the finer side's vertices inside the coarse
//! triangle (`chunk.rs`), so that every edge of the joined mesh has two faces. Samples held
//! by chunks of different levels are never flipped as part of a speck (`sample.rs`): each
//! side would judge them by other neighbours.

use super::grid::{CHUNK, ChunkIndex, Grid};
use super::vertex::surface_vertex;
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::mesh::{Bounds, Vertex};
use glam::DVec3;

/// The most times a chunk's voxels are halved. The rule holds for any level, but on the
/// Murex, whose thin parts cover most of its last whorls, halving twice nearly tripled the
/// triangles once more for spines already standing at half a voxel.
pub const MAX_LEVEL: u32 = 1;

/// Samples of the finest level along one cell: a piece of the finest level, the unit in which
/// levels are decided.
const CELL: i64 = CHUNK as i64;

/// One chunk of the grid of its level: a whole chunk of level 0, or a piece of a chunk
/// refined to level ℓ, 2^−ℓ of its side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Piece {
    pub level: u32,
    /// Its chunk in the grid of its level.
    pub chunk: ChunkIndex,
}

/// The grid of level 0 and the level each part of it is meshed at: an octree of pieces over
/// each chunk, a piece split in eight while a part inside it needs a finer level, its level
/// stored in each cell (piece of the finest level) it covers.
#[derive(Clone, Debug, PartialEq)]
pub struct Refinement {
    grid: Grid,
    /// Cells along x, y and z.
    cells: [u32; 3],
    /// The level of the piece holding each cell, x fastest.
    levels: Vec<u8>,
}

impl Refinement {
    /// Every chunk of `grid` at level 0.
    pub fn uniform(grid: Grid) -> Self {
        let cells = grid.at_level(MAX_LEVEL).chunks;
        Self {
            levels: vec![0; cells.iter().map(|&c| c as usize).product()],
            cells,
            grid,
        }
    }

    /// `grid` refined so that every part of `parts` (its box and the level that shows it,
    /// capped at [`MAX_LEVEL`]) is meshed at least at its level: a piece is split while a
    /// cell inside it needs a finer level than its own.
    pub fn new(grid: Grid, parts: &[(Bounds, u32)]) -> Self {
        let mut refinement = Self::uniform(grid);
        let finest = grid.at_level(MAX_LEVEL);
        let mut needs = vec![0u8; refinement.levels.len()];
        let side = finest.voxel * f64::from(CHUNK);
        let origin = finest.sample([0; 3]);
        for (bounds, level) in parts {
            // The cells the box overlaps (a cell's samples include its faces).
            let range = |k: usize| {
                let at = |x: f64| ((x - origin[k]) / side).floor();
                let last = f64::from(refinement.cells[k] - 1);
                let lo = at(bounds.min[k]).clamp(0.0, last) as u32;
                let hi = at(bounds.max[k]).clamp(0.0, last) as u32;
                lo..=hi
            };
            for z in range(2) {
                for y in range(1) {
                    for x in range(0) {
                        let n = &mut needs[finest.linear([x, y, z])];
                        *n = (*n).max((*level).min(MAX_LEVEL) as u8);
                    }
                }
            }
        }
        // The most any cell of each piece needs, level by level from the finest.
        let mut most = vec![needs];
        for level in (0..MAX_LEVEL).rev() {
            let (finer, grid) = (&most[0], grid.at_level(level));
            let mut coarser = vec![0u8; grid.chunk_count()];
            let fine_grid = grid.at_level(level + 1);
            for (n, &need) in finer.iter().enumerate() {
                let child = fine_grid.chunk_at(n);
                let parent = grid.linear(child.map(|c| c / 2));
                coarser[parent] = coarser[parent].max(need);
            }
            most.insert(0, coarser);
        }
        for (n, l) in refinement.levels.iter_mut().enumerate() {
            let cell = finest.chunk_at(n);
            *l = (0..MAX_LEVEL)
                .find(|&level| {
                    let piece = cell.map(|c| c >> (MAX_LEVEL - level));
                    u32::from(most[level as usize][grid.at_level(level).linear(piece)]) <= level
                })
                .unwrap_or(MAX_LEVEL) as u8;
        }
        refinement
    }

    /// The grid of `level`.
    pub fn grid_at(&self, level: u32) -> Grid {
        self.grid.at_level(level)
    }

    /// The share of the grid's volume meshed at a finer level than 0.
    pub fn refined_share(&self) -> f64 {
        let refined = self.levels.iter().filter(|&&l| l > 0).count();
        refined as f64 / self.levels.len().max(1) as f64
    }

    /// The level of the piece holding cell `c`, `None` beyond the grid.
    fn level_at(&self, c: [i64; 3]) -> Option<u32> {
        let within = (0..3).all(|k| (0..i64::from(self.cells[k])).contains(&c[k]));
        within.then(|| {
            let n = c[0] + i64::from(self.cells[0]) * (c[1] + i64::from(self.cells[1]) * c[2]);
            u32::from(self.levels[n as usize])
        })
    }

    /// The first cell of a piece and how many cells it spans along each side.
    fn cells_of(piece: Piece) -> ([i64; 3], i64) {
        let span = 1i64 << (MAX_LEVEL - piece.level);
        (piece.chunk.map(|c| i64::from(c) * span), span)
    }

    /// Whether `piece` is meshed: its level is the one its cells hold.
    fn is_meshed(&self, piece: Piece) -> bool {
        self.level_at(Self::cells_of(piece).0) == Some(piece.level)
    }

    /// The pieces meshed, each at its level, whose samples reach into `b`.
    pub fn pieces_touching(&self, b: &Bounds) -> Vec<Piece> {
        self.pieces_near(b, 0.0)
    }

    /// The pieces meshed, each at its level, whose samples come within `voxels` voxels of
    /// their level of `b`.
    pub(super) fn pieces_near(&self, b: &Bounds, voxels: f64) -> Vec<Piece> {
        (0..=MAX_LEVEL)
            .flat_map(move |level| {
                let grid = self.grid_at(level);
                (grid
                    .chunks_touching(&b.padded(voxels * grid.voxel))
                    .into_iter())
                .map(move |chunk| Piece { level, chunk })
                .filter(|&p| self.is_meshed(p))
            })
            .collect()
    }

    /// A number for each piece: those of level 0 first, as [`Grid::linear`] numbers them,
    /// then level by level.
    pub fn id(&self, piece: Piece) -> u32 {
        let before: usize = (0..piece.level)
            .map(|l| self.grid.chunk_count() << (3 * l))
            .sum();
        (before + self.grid_at(piece.level).linear(piece.chunk)) as u32
    }

    /// The piece with number `id`: the inverse of [`Refinement::id`].
    pub fn piece(&self, id: u32) -> Piece {
        let mut n = id as usize;
        let mut level = 0;
        while level < MAX_LEVEL && n >= self.grid.chunk_count() << (3 * level) {
            n -= self.grid.chunk_count() << (3 * level);
            level += 1;
        }
        Piece {
            level,
            chunk: self.grid_at(level).chunk_at(n),
        }
    }

    /// Whether a piece of another level holds a sample of `piece`: only then may its
    /// samples be interpolated, its vertices shared with coarser edges or its triangles split.
    pub(super) fn borders_other_levels(&self, piece: Piece) -> bool {
        let (first, span) = Self::cells_of(piece);
        let near = |k: usize| first[k] - 1..=first[k] + span;
        near(2).any(|z| {
            near(1).any(|y| {
                near(0).any(|x| self.level_at([x, y, z]).is_some_and(|l| l != piece.level))
            })
        })
    }

    /// The level of the piece across the plane of a piece's face at `axis` (above it when
    /// `high`) from the voxel face whose lowest corner is `corner` (finest index), when it is
    /// finer than `level`.
    pub(super) fn finer_across(
        &self,
        corner: [i64; 3],
        axis: usize,
        high: bool,
        level: u32,
    ) -> Option<u32> {
        let cell = std::array::from_fn(|k| {
            let c = corner[k].div_euclid(CELL);
            if k == axis && !high { c - 1 } else { c }
        });
        self.level_at(cell).filter(|&l| l > level)
    }

    /// The index on the finest level of the sample with global index `i` on `level`.
    pub(super) fn finest(i: [i64; 3], level: u32) -> [i64; 3] {
        i.map(|c| c << (MAX_LEVEL - level))
    }

    /// The position of the sample with finest index `q`.
    pub(super) fn point(&self, q: [i64; 3]) -> DVec3 {
        self.grid_at(MAX_LEVEL).sample(q)
    }

    /// The lowest and highest levels of the pieces whose samples include every point of
    /// `points` (finest indices).
    fn levels_holding(&self, points: &[[i64; 3]]) -> (u32, u32) {
        let along = |k: usize| {
            let mut range = (i64::MIN, i64::MAX);
            for q in points {
                let c = q[k].div_euclid(CELL);
                let low = if q[k].rem_euclid(CELL) == 0 { c - 1 } else { c };
                range = (range.0.max(low), range.1.min(c));
            }
            range
        };
        let ranges = [along(0), along(1), along(2)];
        let (mut lo, mut hi) = (MAX_LEVEL, 0);
        for z in ranges[2].0..=ranges[2].1 {
            for y in ranges[1].0..=ranges[1].1 {
                for x in ranges[0].0..=ranges[0].1 {
                    if let Some(level) = self.level_at([x, y, z]) {
                        (lo, hi) = (lo.min(level), hi.max(level));
                    }
                }
            }
        }
        (lo, hi)
    }

    /// Whether pieces of different levels hold the sample with finest index `q`: its class
    /// is then never flipped as part of a speck.
    pub(super) fn is_shared_across_levels(&self, q: [i64; 3]) -> bool {
        let (lo, hi) = self.levels_holding(&[q]);
        lo < hi
    }

    /// The level whose grid the sample with finest index `q` is interpolated on, `None` when
    /// it takes the field itself: it lies on the grid of the coarsest piece holding it.
    fn interpolated_on(&self, q: [i64; 3]) -> Option<u32> {
        let (lo, hi) = self.levels_holding(&[q]);
        let step = 1 << (MAX_LEVEL - lo);
        (lo < hi && q.iter().any(|c| c % step != 0)).then_some(lo)
    }

    /// The value a sample with finest index `q` takes in place of the field of `tree`, when it
    /// takes another (see the module's rule).
    pub(super) fn interpolated(&self, tree: &Node, q: [i64; 3]) -> Option<f64> {
        let level = self.interpolated_on(q)?;
        // Kuhn's interpolation over the voxel of that level holding `q`: walk from its lowest
        // corner adding one axis at a time, the axis of largest fraction first; on a face
        // (or an edge) of the voxel the walk stays in it.
        let step = 1i64 << (MAX_LEVEL - level);
        let mut corner = q.map(|c| c.div_euclid(step) * step);
        let t: [f64; 3] = std::array::from_fn(|k| (q[k] - corner[k]) as f64 / step as f64);
        let mut axes: Vec<usize> = (0..3).filter(|&k| t[k] > 0.0).collect();
        axes.sort_by(|&a, &b| t[b].total_cmp(&t[a]).then(a.cmp(&b)));
        let mut v = (1.0 - t[axes[0]]) * self.value(tree, corner);
        for (n, &a) in axes.iter().enumerate() {
            corner[a] += step;
            let next = axes.get(n + 1).map_or(0.0, |&b| t[b]);
            v += (t[a] - next) * self.value(tree, corner);
        }
        Some(v)
    }

    /// The value of the sample with finest index `q`: the field of `tree`, or its
    /// interpolation where the rule asks for one.
    pub(super) fn value(&self, tree: &Node, q: [i64; 3]) -> f64 {
        self.interpolated(tree, q)
            .unwrap_or_else(|| tree.field(self.point(q)))
    }

    /// The coarser grid edge (its ends, finest indices) that the grid edge from `lo` to `hi`
    /// of `level` lies along, when the coarsest piece holding the edge is coarser than
    /// `level`: the values along it are then linear between that edge's ends, and its vertex
    /// is that edge's.
    pub(super) fn coarser_edge(
        &self,
        lo: [i64; 3],
        hi: [i64; 3],
        level: u32,
    ) -> Option<([i64; 3], [i64; 3])> {
        let (coarsest, _) = self.levels_holding(&[lo, hi]);
        if coarsest >= level {
            return None;
        }
        let step = 1i64 << (MAX_LEVEL - coarsest);
        let mut shift = None;
        for k in 0..3 {
            if lo[k] == hi[k] {
                (lo[k] % step == 0).then_some(())?;
            } else {
                let r = lo[k].rem_euclid(step);
                if shift.is_some_and(|s| s != r) {
                    return None;
                }
                shift = Some(r);
            }
        }
        let shift = shift?;
        let from: [i64; 3] =
            std::array::from_fn(|k| lo[k] - if lo[k] == hi[k] { 0 } else { shift });
        let to = std::array::from_fn(|k| from[k] + if lo[k] == hi[k] { 0 } else { step });
        Some((from, to))
    }

    /// The vertex of the grid edge from `lo` to `hi` (finest indices), from their values.
    pub(super) fn vertex(&self, tree: &Node, lo: [i64; 3], hi: [i64; 3]) -> Vertex {
        surface_vertex(tree, [lo, hi].map(|q| (self.point(q), self.value(tree, q))))
    }

    /// The vertices of the grid of level `levels[1]` inside the triangle of the grid of level
    /// `levels[0]` in the plane across `axis` that the grid edges `from` and `to` (finest
    /// indices of their ends) are sides of, off its sides: those at which the finer side's mesh
    /// crosses the triangle, in order along the zero line from `from`'s vertex to `to`'s.
    pub(super) fn crossings(
        &self,
        tree: &Node,
        [from, to]: [[[i64; 3]; 2]; 2],
        axis: usize,
        levels: [u32; 2],
    ) -> Vec<Vertex> {
        let corners = [from[0], from[1], to[0], to[1]];
        let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
        let base: [i64; 3] =
            std::array::from_fn(|k| corners.iter().map(|c| c[k]).min().unwrap_or(0));
        let size = 1i64 << (MAX_LEVEL - levels[0]);
        let step = 1i64 << (MAX_LEVEL - levels[1]);
        let n = size / step;
        // The triangle of the voxel's face: below its diagonal (holding the corner a voxel
        // along u) or above it.
        let below = corners
            .iter()
            .any(|c| c[u] == base[u] + size && c[w] == base[w]);
        let within = |(j, l): (i64, i64)| j <= n && l <= n && if below { j >= l } else { l >= j };
        let on_side = |a: (i64, i64), b: (i64, i64)| {
            let both = |line: &dyn Fn((i64, i64)) -> bool| line(a) && line(b);
            both(&|p| p.0 == p.1)
                || if below {
                    both(&|p| p.1 == 0) || both(&|p| p.0 == n)
                } else {
                    both(&|p| p.0 == 0) || both(&|p| p.1 == n)
                }
        };
        let at = |(j, l): (i64, i64)| {
            let mut q = base;
            q[u] += j * step;
            q[w] += l * step;
            q
        };
        let side = (n + 1) as usize;
        let values: Vec<f64> = (0..side * side)
            .map(|i| ((i % side) as i64, (i / side) as i64))
            .map(|p| {
                if within(p) {
                    self.value(tree, at(p))
                } else {
                    f64::NAN
                }
            })
            .collect();
        let value = |(j, l): (i64, i64)| values[j as usize + side * l as usize];
        let mut found = Vec::new();
        for l in 0..=n {
            for j in 0..=n {
                for (dj, dl) in [(1, 0), (0, 1), (1, 1)] {
                    let (a, b) = ((j, l), (j + dj, l + dl));
                    if !within(a) || !within(b) || on_side(a, b) {
                        continue;
                    }
                    let (va, vb) = (value(a), value(b));
                    if (va >= ISO) == (vb >= ISO) {
                        continue;
                    }
                    let (pa, pb) = (self.point(at(a)), self.point(at(b)));
                    let along = pa + (pb - pa) * ((ISO - va) / (vb - va));
                    let v = surface_vertex(tree, [(pa, va), (pb, vb)]);
                    found.push((along, v));
                }
            }
        }
        // Where the zero line crosses the triangle's sides, before any Newton step moves the
        // vertices there: the crossings lie on the segment between, in order.
        let [start, end] = [from, to].map(|[a, b]| {
            let (va, vb) = (self.value(tree, a), self.value(tree, b));
            let (pa, pb) = (self.point(a), self.point(b));
            pa + (pb - pa) * ((ISO - va) / (vb - va))
        });
        let key = |p: &DVec3| (*p - start).dot(end - start);
        found.sort_by(|a, b| key(&a.0).total_cmp(&key(&b.0)));
        found.into_iter().map(|(_, v)| v).collect()
    }
}
