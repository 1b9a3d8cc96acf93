//! The voxel grid a BlobTree is polygonized on: cubic voxels over a box, cut into chunks of
//! [`CHUNK`]³ voxels, and the numbering of the samples inside a chunk. A grid of level ℓ
//! halves the voxels of level 0 ℓ times over the same box: the halved voxels are meshed in
//! chunks of that grid (see `refinement.rs`).

use crate::mesh::Bounds;
use glam::DVec3;

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
    /// Times the voxels of level 0 are halved.
    pub level: u32,
    /// Edge length of a voxel of level 0.
    base: f64,
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
            level: 0,
            base: voxel,
        }
    }

    /// The grid of `level` over the same box: voxels halved `level` times, chunks as many
    /// times doubled along each side. A sample of level 0 is the same point, bit for bit, as
    /// the sample of every finer level at the same place.
    pub fn at_level(&self, level: u32) -> Self {
        let scale = 1 << level;
        Self {
            origin: self.origin,
            voxel: self.base / f64::from(scale),
            chunks: self.chunks.map(|c| (c >> self.level) * scale),
            level,
            base: self.base,
        }
    }

    /// The grid of level 0 whose voxels are this one's halved, from the same origin: what a
    /// grid every voxel of which is halved must mesh alike.
    #[cfg(test)]
    pub(super) fn halved(&self) -> Self {
        let voxel = self.voxel / 2.0;
        Self {
            origin: self.origin,
            voxel,
            chunks: self.chunks.map(|c| c * 2),
            level: 0,
            base: voxel,
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
    pub(super) fn sample(&self, i: [i64; 3]) -> DVec3 {
        // Dividing by a power of two is exact, so that the samples of every level shared
        // with a coarser one are the same point.
        let scale = f64::from(1u32 << self.level);
        self.origin + DVec3::new(i[0] as f64, i[1] as f64, i[2] as f64) / scale * self.base
    }

    /// Global index of a chunk's first sample.
    pub(super) fn first_sample(chunk: ChunkIndex) -> [i64; 3] {
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

/// Samples along each side of a chunk: the corners of its voxels.
pub(super) const SIDE: usize = CHUNK as usize + 1;

/// The index in a chunk of its sample `i` (x fastest).
pub(super) fn local(i: [usize; 3]) -> usize {
    i[0] + SIDE * (i[1] + SIDE * i[2])
}

/// The sample with index `n` in a chunk: the inverse of [`local`].
pub(super) fn at_local(n: usize) -> [usize; 3] {
    [n % SIDE, n / SIDE % SIDE, n / (SIDE * SIDE)]
}
