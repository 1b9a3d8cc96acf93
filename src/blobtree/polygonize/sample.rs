//! Sampling a chunk's field with interval culling: blocks that bounds on the field keep on one
//! side of the iso-value are marked proven and never evaluated, the rest split in eight down
//! to a few voxels; each octant is sampled with the tree culled to it. Samples alone in their
//! class among their neighbours (pinholes) take their neighbours' class.

use super::grid::{CHUNK, ChunkIndex, Grid, SIDE, at_local, local};
use super::refinement::Refinement;
use super::tetrahedra::{DIRECTIONS, offset};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::mesh::Bounds;

/// Which side of the iso-value the field of `tree` is proven to keep throughout `region`, by
/// the bounds [`Node::range`] gives over the ball around it: `Some(true)` inside, `Some(false)`
/// outside, `None` when the bounds allow both.
fn one_side(tree: &Node, region: &Bounds) -> Option<bool> {
    let (lo, hi) = tree.range(region.center(), (region.max - region.min).length() * 0.5);
    // A margin for the rounding of the bounds themselves.
    const MARGIN: f64 = 1e-9;
    if lo > ISO + MARGIN {
        Some(true)
    } else if hi < ISO - MARGIN {
        Some(false)
    } else {
        None
    }
}

/// What a sample proven inside (outside) by [`one_side`] holds instead of its field, which is
/// never computed: +∞ (−∞). Only its side matters: a grid edge the surface crosses has both
/// its ends outside every proven block, since a proven block holds no crossing.
fn proven(inside: bool) -> f64 {
    if inside {
        f64::INFINITY
    } else {
        f64::NEG_INFINITY
    }
}

/// Blocks of at most this many voxels along a side are sampled whole; larger ones are proven
/// one-sided or split in eight.
const SAMPLED_BLOCK: usize = 2;
/// Voxels along each side of a chunk's octant: each octant is sampled and meshed with the
/// tree culled to it, smaller and cheaper to evaluate than the chunk's.
const OCTANT: usize = CHUNK as usize / 2;

/// The octant of a chunk that voxel `v` of it lies in, numbered as voxel corners are.
pub(super) fn octant_of(v: [usize; 3]) -> usize {
    (0..3).map(|k| (v[k] / OCTANT) << k).sum()
}

/// The samples of one chunk, filled block by block.
struct Sampler<'a> {
    grid: &'a Grid,
    /// Global index of the chunk's first sample.
    first: [i64; 3],
    /// The chunk's samples; NaN where not yet filled.
    field: &'a mut [f64],
}

impl Sampler<'_> {
    /// The box of the block of `size` voxels whose first sample is `at` (in the chunk).
    fn region(&self, at: [usize; 3], size: usize) -> Bounds {
        let corner = |d: usize| {
            self.grid
                .sample(std::array::from_fn(|k| self.first[k] + (at[k] + d) as i64))
        };
        Bounds {
            min: corner(0),
            max: corner(size),
        }
    }

    /// Fills the samples of the block of `size` voxels at `at`: marked [`proven`] when the
    /// range of `tree` keeps it on one side, else split in eight, down to blocks of
    /// [`SAMPLED_BLOCK`] whose samples are evaluated, but for those known already. Near a
    /// surface most blocks hold none of it, and so most samples of a chunk the surface passes
    /// through are never evaluated.
    fn block(&mut self, tree: &Node, at: [usize; 3], size: usize) {
        if let Some(inside) = one_side(tree, &self.region(at, size)) {
            self.mark(at, size, inside);
        } else if size > SAMPLED_BLOCK {
            let half = size / 2;
            for octant in 0..8 {
                let o = offset(octant);
                self.block(tree, std::array::from_fn(|k| at[k] + o[k] * half), half);
            }
        } else {
            let (grid, first) = (self.grid, self.first);
            self.each(at, size, |i, f| {
                if !f.is_finite() {
                    *f = tree.field(grid.sample(std::array::from_fn(|k| first[k] + i[k] as i64)));
                }
            });
        }
    }

    /// Marks the samples of a block not filled yet as [`proven`] on one side.
    fn mark(&mut self, at: [usize; 3], size: usize, inside: bool) {
        self.each(at, size, |_, f| {
            if f.is_nan() {
                *f = proven(inside);
            }
        });
    }

    /// Calls `f` with the index and the sample of every sample of the block of `size` voxels
    /// at `at`, its faces included.
    fn each(&mut self, at: [usize; 3], size: usize, mut f: impl FnMut([usize; 3], &mut f64)) {
        for z in at[2]..=at[2] + size {
            for y in at[1]..=at[1] + size {
                for x in at[0]..=at[0] + size {
                    f([x, y, z], &mut self.field[local([x, y, z])]);
                }
            }
        }
    }
}

/// The trees a chunk the surface passes through is meshed with.
pub(super) struct Culled {
    /// Culled to the chunk and one voxel more on every side: the neighbours that decide a
    /// pinhole (see `class`).
    pub(super) chunk: Node,
    /// Culled to each octant ([`octant_of`]); `None` where the field is zero throughout it or
    /// proven on one side of the iso-value.
    pub(super) octants: [Option<Node>; 8],
}

/// Samples the field of `tree` at growth step `step` at a chunk's corners into `field`, and
/// gives the trees culled to the chunk and its octants; `None` when the surface does not pass
/// through it (proven by the culled tree or the field's range, or seen in the samples).
/// `known` first fills in the samples known already (exact, or left NaN), given the tree
/// culled to the chunk. Samples in blocks proven one-sided hold [`proven`] values; `field`
/// is left empty when none was sampled.
pub(super) fn sample(
    tree: &Node,
    grid: &Grid,
    chunk: ChunkIndex,
    step: u32,
    field: &mut Vec<f64>,
    known: impl FnOnce(&Node, &mut [f64]),
) -> Option<Culled> {
    field.clear();
    let region = grid.region(chunk);
    let tree = tree.cull(&region.padded(2.0 * grid.voxel), step)?;
    one_side(&tree, &region).is_none().then_some(())?;
    field.resize(SIDE * SIDE * SIDE, f64::NAN);
    known(&tree, field);
    let mut sampler = Sampler {
        grid,
        first: Grid::first_sample(chunk),
        field,
    };
    let octants = std::array::from_fn(|octant| {
        let at = offset(octant).map(|o| o * OCTANT);
        let region = sampler.region(at, OCTANT);
        // An octant the chunk's tree keeps on one side (a third of them) is never culled.
        if let Some(inside) = one_side(&tree, &region) {
            sampler.mark(at, OCTANT, inside);
            return None;
        }
        let culled = tree.cull(&region, step);
        match &culled {
            Some(t) => sampler.block(t, at, OCTANT),
            None => sampler.mark(at, OCTANT, false),
        }
        culled
    });
    let inside = field.iter().any(|&f| f >= ISO);
    let outside = field.iter().any(|&f| f < ISO);
    (inside && outside).then_some(Culled {
        chunk: tree,
        octants,
    })
}

/// Classifies a chunk's samples (`field`, the chunk's first sample at global index `first`)
/// as inside or outside the surface, into `inside`. A sample alone in its class among its
/// fourteen neighbours along the edges of the Kuhn triangulation is a pinhole: a field that
/// dips below the iso-value (or rises above it) at one sample only, in the crease where two
/// parts meet as in a union, would give a closed bubble far smaller than a voxel, a separate
/// piece of the mesh. Such a sample takes its neighbours' class, and so do two neighbours
/// alone in their class together (a bubble two samples long, which a refined grid shows where
/// a thin gap of the hollow ends against a coarser one). Samples beyond the chunk are
/// evaluated from `tree` (culled two voxels wider than the chunk), so both chunks sharing a
/// sample decide alike. Where chunks of other levels are near (`border`), neighbours beyond
/// the chunk take the values the refinement gives them, and samples those chunks hold too are
/// never flipped: each side would judge them by other neighbours.
pub(super) fn class(
    tree: &Node,
    grid: &Grid,
    first: [i64; 3],
    field: &[f64],
    inside: &mut Vec<bool>,
    border: Option<&Refinement>,
) {
    let global = |n: [i64; 3]| -> [i64; 3] { std::array::from_fn(|k| first[k] + n[k]) };
    let finest = |n: [i64; 3]| Refinement::finest(global(n), grid.level);
    inside.clear();
    inside.extend(field.iter().map(|&f| f >= ISO));
    let within = |n: &[i64; 3]| n.iter().all(|&i| (0..SIDE as i64).contains(&i));
    // The class of a sample, in the chunk or beyond it (two voxels at most).
    let class_of = |n: [i64; 3], inside: &[bool]| {
        if within(&n) {
            inside[local(n.map(|i| i as usize))]
        } else {
            let f = match border {
                Some(r) => r.value(tree, finest(n)),
                None => tree.field(grid.sample(global(n))),
            };
            f >= ISO
        }
    };
    let neighbours = |at: [i64; 3]| {
        DIRECTIONS.iter().flat_map(move |d| {
            [1i64, -1]
                .map(|sign| -> [i64; 3] { std::array::from_fn(|k| at[k] + sign * d[k] as i64) })
        })
    };
    let fixed = |n: [i64; 3]| border.is_some_and(|r| r.is_shared_across_levels(finest(n)));
    // The neighbours of its class, up to `most` of them; those in the chunk first: most
    // samples have one of their class there, and those beyond it cost an evaluation each.
    let alike = |at: [i64; 3], inside: &[bool], most: usize| -> Vec<[i64; 3]> {
        let mine = class_of(at, inside);
        let mut found = Vec::new();
        for n in neighbours(at)
            .filter(within)
            .chain(neighbours(at).filter(|n| !within(n)))
        {
            if class_of(n, inside) == mine {
                found.push(n);
                if found.len() > most {
                    break;
                }
            }
        }
        found
    };
    let mut flips = Vec::new();
    for z in 0..SIDE {
        for y in 0..SIDE {
            for x in 0..SIDE {
                let at = [x, y, z].map(|i| i as i64);
                if fixed(at) {
                    continue;
                }
                // Alone in its class, or one of a pair alone in theirs.
                let pinhole = match alike(at, inside, 1)[..] {
                    [] => true,
                    [other] => !fixed(other) && alike(other, inside, 1) == [at],
                    _ => false,
                };
                if pinhole {
                    flips.push(local([x, y, z]));
                }
            }
        }
    }
    for i in flips {
        inside[i] = !inside[i];
    }
}

/// The box of the grid samples inside the surface of `tree` at growth step `step`, grown by
/// one voxel: the surface's extent, to the grid's resolution.
pub fn surface_box(tree: &Node, grid: &Grid, step: u32) -> Bounds {
    let mut field = Vec::new();
    let mut inside = Bounds::EMPTY;
    for chunk in grid.chunks_touching(&tree.bounds) {
        if sample(tree, grid, chunk, step, &mut field, |_, _| {}).is_none() {
            continue;
        }
        let first = Grid::first_sample(chunk);
        for (i, f) in field.iter().enumerate() {
            if *f >= ISO {
                let at = at_local(i);
                inside.include(grid.sample(std::array::from_fn(|k| first[k] + at[k] as i64)));
            }
        }
    }
    if inside.is_empty() {
        tree.bounds
    } else {
        inside.padded(grid.voxel)
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_shell::test_shell;
    use super::*;

    #[test]
    fn samples_are_exact_or_proven_on_their_side_and_many_are_proven() {
        let (tree, step) = test_shell();
        let tree = &tree;
        let grid = Grid::new(&tree.bounds, 64);
        let (mut field, mut evaluated, mut proven, mut meshed) = (Vec::new(), 0, 0, 0);
        for chunk in grid.chunks_touching(&tree.bounds) {
            if sample(tree, &grid, chunk, step, &mut field, |_, _| {}).is_none() {
                continue;
            }
            meshed += 1;
            let first = Grid::first_sample(chunk);
            for (i, &f) in field.iter().enumerate() {
                let at = at_local(i);
                let p = grid.sample(std::array::from_fn(|k| first[k] + at[k] as i64));
                let exact = tree.field(p);
                if f.is_finite() {
                    assert_eq!(f.to_bits(), exact.to_bits(), "the sample at {p}");
                    evaluated += 1;
                } else {
                    assert_eq!(f > 0.0, exact >= ISO, "the side of {p} ({exact})");
                    proven += 1;
                }
            }
        }
        assert!(meshed > 100, "{meshed} chunks meshed");
        assert!(
            3 * proven > evaluated,
            "{proven} samples proven, {evaluated} evaluated"
        );
    }
}
