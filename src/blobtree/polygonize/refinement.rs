//! Adaptive refinement, voxel by voxel: each voxel of the grid is meshed whole (level 0) or
//! halved (level [`MAX_LEVEL`]), as the hints of the parts standing there ask, so that parts
//! thinner than a voxel are shown where they stand while the rest of the surface keeps the
//! grid's resolution. The voxels of one level are meshed in *pieces*, each a chunk of that
//! level's grid: a chunk of level 0 meshes its whole voxels and a chunk of level 1 (a *cell*,
//! an eighth of a chunk of level 0) its halved ones, each piece as costly as a chunk, so a
//! growth step stays one piece's meshing.
//!
//! Where whole and halved voxels meet, the mesh conforms by construction: every sample is the
//! field itself, on the lattice of the halved voxels, and the tetrahedra of both sides share
//! their faces (`transition.rs`). The eight halves of a halved voxel are split as every voxel
//! is, into Kuhn's six tetrahedra; a whole voxel beside one is split to meet it, coned from its
//! centre. Nothing is interpolated and no triangle is split after the fact. Samples that
//! voxels of both levels hold are judged specks or not on the finest lattice by every chunk
//! holding them (`sample.rs`), so that both sides give them one class.

use super::grid::{CHUNK, ChunkIndex, Grid};
use crate::mesh::Bounds;
use glam::DVec3;

/// The most times a voxel is halved. The rule of `transition.rs` meets halved voxels with
/// whole ones, one level apart; on the Murex, whose thin parts cover most of its last whorls,
/// halving twice nearly tripled the triangles once more for spines already standing at half a
/// voxel.
pub const MAX_LEVEL: u32 = 1;

/// Whole voxels along each side of a cell, a piece of the finest level: 4, so that which of a
/// cell's voxels are halved is one word.
const CELL: i64 = (CHUNK >> MAX_LEVEL) as i64;
const _: () = assert!(CELL * CELL * CELL == 64);

/// One chunk of the grid of its level: a chunk of level 0, meshing its whole voxels, or a
/// cell, meshing its halved ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Piece {
    pub level: u32,
    /// Its chunk in the grid of its level.
    pub chunk: ChunkIndex,
}

/// The grid of level 0 and which of its voxels are halved.
#[derive(Clone, Debug, PartialEq)]
pub struct Refinement {
    grid: Grid,
    /// Cells along x, y and z.
    cells: [u32; 3],
    /// For each cell (x fastest), its halved voxels (bit x + 4y + 16z of the voxel in the
    /// cell); empty when no voxel is halved.
    halved: Vec<u64>,
}

impl Refinement {
    /// Every voxel of `grid` whole.
    pub fn uniform(grid: Grid) -> Self {
        Self {
            cells: grid.at_level(MAX_LEVEL).chunks,
            halved: Vec::new(),
            grid,
        }
    }

    /// `grid` with every voxel that a part of `parts` (its box and the level that shows it)
    /// overlaps halved, where the part needs a finer level than 0.
    pub fn new(grid: Grid, parts: &[(Bounds, u32)]) -> Self {
        let mut refinement = Self::uniform(grid);
        let origin = grid.sample([0; 3]);
        let voxels = refinement.cells.map(|c| i64::from(c) * CELL);
        for (bounds, _) in parts
            .iter()
            .filter(|(b, level)| *level > 0 && !b.is_empty())
        {
            let range = |k: usize| {
                let at = |x: f64| ((x - origin[k]) / grid.voxel).floor();
                let last = (voxels[k] - 1) as f64;
                let lo = at(bounds.min[k]).clamp(0.0, last) as i64;
                let hi = at(bounds.max[k]).clamp(0.0, last) as i64;
                lo..=hi
            };
            if refinement.halved.is_empty() {
                refinement.halved = vec![0; grid.at_level(MAX_LEVEL).chunk_count()];
            }
            for z in range(2) {
                for y in range(1) {
                    for x in range(0) {
                        let (cell, bit) = refinement.cell_and_bit([x, y, z]);
                        refinement.halved[cell] |= 1 << bit;
                    }
                }
            }
        }
        refinement
    }

    /// The grid of `level`.
    pub fn grid_at(&self, level: u32) -> Grid {
        self.grid.at_level(level)
    }

    /// The share of the grid's voxels halved.
    pub fn refined_share(&self) -> f64 {
        let halved: u32 = self.halved.iter().map(|m| m.count_ones()).sum();
        f64::from(halved) / (self.cells.iter().map(|&c| f64::from(c)).product::<f64>() * 64.0)
    }

    /// The cell holding voxel `v` (of level 0, within the grid) and the voxel's bit in it.
    fn cell_and_bit(&self, v: [i64; 3]) -> (usize, u32) {
        let c = v.map(|i| i / CELL);
        let cells = self.cells.map(i64::from);
        let cell = c[0] + cells[0] * (c[1] + cells[1] * c[2]);
        let b = v.map(|i| i % CELL);
        (cell as usize, (b[0] + CELL * (b[1] + CELL * b[2])) as u32)
    }

    /// Whether voxel `v` of level 0 (its global index, its lowest sample's) is halved; a voxel
    /// beyond the grid is not.
    pub(super) fn is_halved(&self, v: [i64; 3]) -> bool {
        let within = (0..3).all(|k| (0..i64::from(self.cells[k]) * CELL).contains(&v[k]));
        within && !self.halved.is_empty() && {
            let (cell, bit) = self.cell_and_bit(v);
            self.halved[cell] & 1 << bit != 0
        }
    }

    /// The halved voxels of cell `c` (a piece of level 1), as bits.
    pub(super) fn halved_in_cell(&self, c: ChunkIndex) -> u64 {
        if self.halved.is_empty() {
            return 0;
        }
        let cells = self.cells;
        self.halved[(c[0] + cells[0] * (c[1] + cells[1] * c[2])) as usize]
    }

    /// Which voxels of a chunk of level 0, and of the voxels around it, are halved, read once;
    /// `None` when none is: only then may its voxels be skipped or coned.
    pub(super) fn halved_around(&self, chunk: ChunkIndex) -> Option<HalvedAround> {
        if self.halved.is_empty() {
            return None;
        }
        let first = Grid::first_sample(chunk).map(|c| c - 1);
        let flags: Vec<bool> = (0..AROUND * AROUND * AROUND)
            .map(|n| {
                let at = [n % AROUND, n / AROUND % AROUND, n / (AROUND * AROUND)];
                self.is_halved(std::array::from_fn(|k| first[k] + at[k]))
            })
            .collect();
        flags
            .contains(&true)
            .then_some(HalvedAround { first, flags })
    }

    /// Whether `piece` has voxels to mesh: whole ones for a chunk of level 0, halved ones for
    /// a cell.
    fn is_meshed(&self, piece: Piece) -> bool {
        if piece.level == MAX_LEVEL {
            return self.halved_in_cell(piece.chunk) != 0;
        }
        let first = piece.chunk.map(|c| c * 2);
        (0..8).any(|n| {
            let o = [n & 1, n >> 1 & 1, n >> 2 & 1];
            self.halved_in_cell(std::array::from_fn(|k| first[k] + o[k])) != u64::MAX
        })
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

    /// Whether voxels of both levels hold the sample with finest index `q` (a corner, or a
    /// point of an edge or a face, of each): its class is then judged on the finest lattice.
    pub(super) fn is_shared_across_levels(&self, q: [i64; 3]) -> bool {
        if self.halved.is_empty() {
            return false;
        }
        // Along each axis, the voxels whose closed extent holds `q`: one, or two where it lies
        // on a face between them.
        let along = |k: usize| {
            let v = q[k].div_euclid(2);
            if q[k].rem_euclid(2) == 0 {
                v - 1..=v
            } else {
                v..=v
            }
        };
        let voxels = self.cells.map(|c| i64::from(c) * CELL);
        let (mut whole, mut halved) = (false, false);
        for z in along(2) {
            for y in along(1) {
                for x in along(0) {
                    let v = [x, y, z];
                    if (0..3).all(|k| (0..voxels[k]).contains(&v[k])) {
                        if self.is_halved(v) {
                            halved = true;
                        } else {
                            whole = true;
                        }
                    }
                }
            }
        }
        whole && halved
    }

    /// The index on the finest level of the sample with global index `i` on `level`.
    pub(super) fn finest(i: [i64; 3], level: u32) -> [i64; 3] {
        i.map(|c| c << (MAX_LEVEL - level))
    }

    /// The position of the sample with finest index `q`.
    pub(super) fn point(&self, q: [i64; 3]) -> DVec3 {
        self.grid_at(MAX_LEVEL).sample(q)
    }
}

/// Voxels along each side of a chunk with the voxels around it.
const AROUND: i64 = CHUNK as i64 + 2;

/// Which voxels of a chunk of level 0 and around it are halved ([`Refinement::halved_around`]).
pub(super) struct HalvedAround {
    /// The lowest voxel held.
    first: [i64; 3],
    flags: Vec<bool>,
}

impl HalvedAround {
    /// Whether voxel `v` (global index of level 0, in the chunk or beside it) is halved.
    pub(super) fn is_halved(&self, v: [i64; 3]) -> bool {
        let at: [i64; 3] = std::array::from_fn(|k| v[k] - self.first[k]);
        (at.iter().all(|c| (0..AROUND).contains(c)))
            && self.flags[(at[0] + AROUND * (at[1] + AROUND * at[2])) as usize]
    }

    /// Whether a voxel beside voxel `v` of the chunk (sharing a face, an edge or a corner) is
    /// halved: only then may `v` be coned.
    pub(super) fn beside(&self, v: [i64; 3]) -> bool {
        (0..27).any(|n| {
            let o = [n % 3 - 1, n / 3 % 3 - 1, n / 9 - 1];
            self.is_halved(std::array::from_fn(|k| v[k] + o[k]))
        })
    }
}
