//! Sampling a chunk's field with interval culling: blocks that bounds on the field keep on one
//! side of the iso-value are marked proven and never evaluated, the rest split in eight down
//! to a few voxels; each octant is sampled with the tree culled to it. Small components of
//! one class (specks the grid, not the model, makes) take the other class.

use super::grid::{CHUNK, ChunkIndex, Grid, SIDE, at_local, local};
use super::refinement::{MAX_LEVEL, Refinement};
use super::tetrahedra::{DIRECTIONS, offset};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::mesh::Bounds;
use std::collections::{HashMap, HashSet};

/// Which side of the iso-value the field of `tree` is proven to keep throughout `region`, by
/// the bounds [`Node::range`] gives over the ball around it: `Some(true)` inside, `Some(false)`
/// outside, `None` when the bounds allow both.
pub(super) fn one_side(tree: &Node, region: &Bounds) -> Option<bool> {
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
    /// Culled to the chunk.
    pub(super) chunk: Node,
    /// Culled to each octant ([`octant_of`]); `None` where the field is zero throughout it or
    /// proven on one side of the iso-value.
    pub(super) octants: [Option<Node>; 8],
}

/// Samples the field of `tree` at growth step `step` at a chunk's corners into `field`, and
/// gives the trees culled to the chunk and its octants; `None` when the surface does not pass
/// through it (proven by the culled tree or the field's range, or seen in the samples, unless
/// it may pass `between` them: a chunk with coned voxels meshes points the samples are not).
/// `known` first fills in the samples known already (exact, or left NaN). Samples in blocks
/// proven one-sided hold [`proven`] values; `field` is left empty when none was sampled.
pub(super) fn sample(
    tree: &Node,
    grid: &Grid,
    chunk: ChunkIndex,
    step: u32,
    field: &mut Vec<f64>,
    between: bool,
    known: impl FnOnce(&mut [f64]),
) -> Option<Culled> {
    field.clear();
    let region = grid.region(chunk);
    let tree = tree.cull(&region, step)?;
    one_side(&tree, &region).is_none().then_some(())?;
    field.resize(SIDE * SIDE * SIDE, f64::NAN);
    known(field);
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
    (between || inside && outside).then_some(Culled {
        chunk: tree,
        octants,
    })
}

/// Most samples a piece of one class holds for the grid, not the model, to have made it: a
/// component of inside (or outside) samples, joined along the edges of the Kuhn
/// triangulation, no larger than this is a speck, and takes the other class. A field that
/// dips below the iso-value (or rises above it) at a sample or two, in the crease where two
/// parts meet as in a union, would give a closed bubble far smaller than a voxel; the thin
/// end of a wedge that a difference leaves (the wall between the opening and the previous
/// whorl tapering to nothing) is caught by a grid as a row of inside samples the row beside
/// it misses, a separate sliver. Either would be a separate piece of the mesh. Twelve
/// samples is a row eleven voxels long (under a chunk and a half), or a blob under three
/// voxels across: any part of a model that small is below what the grid can draw.
pub(crate) const SPECK: usize = 12;

/// Voxels beyond its chunk that the classes deciding a chunk's specks reach: a speck's
/// samples lie within [`SPECK`] of the chunk.
pub(super) const REACH: f64 = SPECK as f64;

/// The neighbours within its chunk of the chunk's sample `i`, along the edges of the Kuhn
/// triangulation.
fn neighbours_within(i: usize) -> impl Iterator<Item = usize> {
    let at = at_local(i);
    DIRECTIONS.iter().flat_map(move |d| {
        let up = (0..3).all(|k| at[k] + d[k] < SIDE);
        let down = (0..3).all(|k| at[k] >= d[k]);
        let step = local(*d);
        [up.then(|| i + step), down.then(|| i - step)]
            .into_iter()
            .flatten()
    })
}

/// The neighbours of a sample along the edges of the Kuhn triangulation, in or beyond a chunk.
fn neighbours(at: [i64; 3]) -> impl Iterator<Item = [i64; 3]> {
    DIRECTIONS.iter().flat_map(move |d| {
        [1i64, -1].map(|sign| -> [i64; 3] { std::array::from_fn(|k| at[k] + sign * d[k] as i64) })
    })
}

/// The classes of points of the finest lattice, judged on that lattice as a chunk of it
/// judges its samples (see [`class`]): a chunk of level 0 asks it for its samples held by
/// halved voxels too, and for the points its coned voxels add, so that every voxel holding a
/// point, of either level, gives it one class.
pub(super) struct FineClasses<'a> {
    tree: &'a Node,
    step: u32,
    refinement: &'a Refinement,
    /// The chunk's trees: a point in it is evaluated with its octant's.
    culled: &'a Culled,
    /// The side of each octant whose tree is `None`, proven one-sided.
    octant_sides: [bool; 8],
    /// The box the points asked about and their specks lie in.
    region: Bounds,
    /// The tree culled to it, once a point beyond the chunk is evaluated.
    reach: Option<Option<Node>>,
    /// The chunk's first point.
    first: [i64; 3],
    /// Each point's side of the iso-value and class in the block the chunk's specks reach,
    /// x fastest: bit 0 evaluated, bit 1 inside; bit 2 judged, bit 3 its class inside.
    points: Vec<u8>,
    /// The slots written, so that reading and clearing them costs what was judged.
    written: Vec<u32>,
}

/// Points of the finest lattice along each side of the block whose sides and classes
/// [`FineClasses`] keeps: a chunk's, and a speck's reach on either side.
const KEPT: i64 = 2 * CHUNK as i64 + 1 + 2 * (SPECK as i64 + 1);

impl<'a> FineClasses<'a> {
    /// The judge of the points of the finest lattice about `chunk` of `grid` (of level 0),
    /// from `tree` at growth step `step`, the chunk's samples `field` and trees `culled`;
    /// `points` is a buffer to keep what is known of the points in, all zeros (as
    /// [`Self::into_buffer`] leaves it).
    pub(super) fn new(
        (tree, step): (&'a Node, u32),
        refinement: &'a Refinement,
        (grid, chunk): (&Grid, ChunkIndex),
        (culled, field): (&'a Culled, &[f64]),
        mut points: Vec<u8>,
    ) -> Self {
        points.resize((KEPT * KEPT * KEPT) as usize, 0);
        let octant_sides = std::array::from_fn(|octant| {
            let corner = offset(octant).map(|o| o * OCTANT);
            field.get(local(corner)).is_some_and(|&f| f >= ISO)
        });
        Self {
            tree,
            step,
            refinement,
            culled,
            octant_sides,
            region: grid.region(chunk).padded(REACH * grid.voxel),
            reach: None,
            first: Refinement::finest(Grid::first_sample(chunk), grid.level),
            points,
            written: Vec::new(),
        }
    }

    /// Sets `bits` in the record of slot `slot`.
    fn write(&mut self, slot: usize, bits: u8) {
        if self.points[slot] == 0 {
            self.written.push(slot as u32);
        }
        self.points[slot] |= bits;
    }

    /// Takes over what meshing the same chunk judged before (`judged`, from [`Self::judged`])
    /// where the tree did not change since: a point's side outside the boxes `changed`, its
    /// class where no point within a speck's reach of it is in one.
    pub(super) fn take_over(&mut self, judged: &[(u32, u8)], changed: &[Bounds]) {
        let fine_voxel = self.refinement.grid_at(MAX_LEVEL).voxel;
        let reach = (SPECK as f64 + 1.0) * fine_voxel;
        for &(slot, record) in judged {
            let n = i64::from(slot);
            let at = [n % KEPT, n / KEPT % KEPT, n / (KEPT * KEPT)];
            let q = std::array::from_fn(|k| at[k] + self.first[k] - (SPECK as i64 + 1));
            let point = self.refinement.point(q);
            if changed.iter().any(|b| b.contains(point)) {
                continue;
            }
            let around = Bounds {
                min: point,
                max: point,
            }
            .padded(reach);
            let kept = if changed.iter().any(|b| b.intersects(&around)) {
                record & 3
            } else {
                record
            };
            self.write(slot as usize, kept);
        }
    }

    /// What was judged of the points, by slot, for [`Self::take_over`].
    pub(super) fn judged(&self) -> Vec<(u32, u8)> {
        (self.written.iter())
            .map(|&slot| (slot, self.points[slot as usize]))
            .filter(|&(_, record)| record != 0)
            .collect()
    }

    /// The buffer handed to [`Self::new`], all zeros again, for the next chunk.
    pub(super) fn into_buffer(mut self) -> Vec<u8> {
        for &slot in &self.written {
            self.points[slot as usize] = 0;
        }
        self.points
    }

    /// The slot of the point `q` (finest index) in the block kept, if it lies in it.
    fn slot(&self, q: [i64; 3]) -> Option<usize> {
        let at: [i64; 3] = std::array::from_fn(|k| q[k] - self.first[k] + SPECK as i64 + 1);
        (at.iter().all(|c| (0..KEPT).contains(c)))
            .then(|| (at[0] + KEPT * (at[1] + KEPT * at[2])) as usize)
    }

    /// The side of the iso-value the field at the point `q` (finest index) lies on.
    fn side(&mut self, q: [i64; 3]) -> bool {
        let slot = self.slot(q);
        if let Some(known) = slot.map(|i| self.points[i]).filter(|&p| p & 1 != 0) {
            return known & 2 != 0;
        }
        let point = self.refinement.point(q);
        let fine_side = 2 * CHUNK as i64;
        let within: [i64; 3] = std::array::from_fn(|k| q[k] - self.first[k]);
        let side = if within.iter().all(|c| (0..=fine_side).contains(c)) {
            let octant = (0..3)
                .map(|k| usize::from(within[k] >= fine_side / 2) << k)
                .sum::<usize>();
            match &self.culled.octants[octant] {
                Some(tree) => tree.field(point) >= ISO,
                None => self.octant_sides[octant],
            }
        } else {
            let (tree, region, step) = (self.tree, self.region, self.step);
            let reach = self.reach.get_or_insert_with(|| tree.cull(&region, step));
            reach.as_ref().is_some_and(|t| t.field(point) >= ISO)
        };
        if let Some(i) = slot {
            self.write(i, 1 | u8::from(side) << 1);
        }
        side
    }

    /// The class of the point `q` (finest index): its side, or the other one where it lies
    /// in a speck of the finest lattice.
    pub(super) fn class(&mut self, q: [i64; 3]) -> bool {
        let slot = self.slot(q);
        if let Some(known) = slot.map(|i| self.points[i]).filter(|&p| p & 4 != 0) {
            return known & 8 != 0;
        }
        let mine = self.side(q);
        // The component, up to one point more than a speck holds.
        let mut found = [q; SPECK + 1];
        let (mut count, mut next) = (1, 0);
        while next < count && count <= SPECK {
            for n in neighbours(found[next]) {
                if count <= SPECK && !found[..count].contains(&n) && self.side(n) == mine {
                    found[count] = n;
                    count += 1;
                }
            }
            next += 1;
        }
        let class = mine != (count <= SPECK);
        if let Some(i) = slot {
            self.write(i, 4 | u8::from(class) << 3);
        }
        class
    }
}

/// Classifies a chunk's samples (`field`) as inside or outside the surface, into `inside`:
/// each by its own side of the iso-value, but for specks (see [`SPECK`]), which take the
/// other class. A speck may cross the chunk's faces: samples beyond the chunk are evaluated
/// from `tree` at growth step `step` (culled [`REACH`] voxels wider than the chunk, once a
/// chunk needs them), so every chunk holding part of a speck decides alike. In a chunk of
/// level 0 (`levels` given) a component holding a sample that halved voxels hold too is not
/// flipped, in every such chunk alike, since its neighbours beyond may hold one; a chunk
/// beside halved voxels hands over `fine`, and those samples are judged on the finest
/// lattice, as the halved voxels' chunks judge them.
pub(super) fn class(
    (tree, step): (&Node, u32),
    grid: &Grid,
    chunk: ChunkIndex,
    field: &[f64],
    inside: &mut Vec<bool>,
    levels: Option<&Refinement>,
    fine: Option<&mut FineClasses>,
) {
    let first = Grid::first_sample(chunk);
    let global = |n: [i64; 3]| -> [i64; 3] { std::array::from_fn(|k| first[k] + n[k]) };
    let finest = |n: [i64; 3]| Refinement::finest(global(n), grid.level);
    inside.clear();
    inside.extend(field.iter().map(|&f| f >= ISO));
    let within = |n: &[i64; 3]| n.iter().all(|&i| (0..SIDE as i64).contains(&i));
    let index = |n: [i64; 3]| local(n.map(|i| i as usize));
    let fixed = |n: [i64; 3]| levels.is_some_and(|r| r.is_shared_across_levels(finest(n)));
    // The classes of samples beyond the chunk, evaluated once each.
    let mut reach: Option<Option<Node>> = None;
    let mut beyond: HashMap<[i64; 3], bool> = HashMap::new();
    let mut class_beyond = |n: [i64; 3]| {
        *beyond.entry(n).or_insert_with(|| {
            let reach = reach.get_or_insert_with(|| {
                tree.cull(&grid.region(chunk).padded(REACH * grid.voxel), step)
            });
            let f = reach
                .as_ref()
                .map_or(0.0, |tree| tree.field(grid.sample(global(n))));
            f >= ISO
        })
    };
    let mut seen = vec![false; inside.len()];
    let mut flip = vec![false; inside.len()];
    let mut members = Vec::new();
    for start in 0..inside.len() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mine = inside[start];
        // The component within the chunk.
        members.clear();
        members.push(start);
        let mut next = 0;
        while next < members.len() {
            for n in neighbours_within(members[next]) {
                if !seen[n] && inside[n] == mine {
                    seen[n] = true;
                    members.push(n);
                }
            }
            next += 1;
        }
        if members.len() > SPECK {
            continue;
        }
        // Where it reaches the chunk's faces, the rest of it beyond them (and back in the
        // chunk), up to one sample more than a speck holds.
        let mut found: Vec<[i64; 3]> = (members.iter())
            .map(|&i| at_local(i).map(|c| c as i64))
            .collect();
        let mut component: HashSet<[i64; 3]> = found.iter().copied().collect();
        let mut next = 0;
        while next < found.len() && component.len() <= SPECK {
            for n in neighbours(found[next]) {
                let alike = if within(&n) {
                    inside[index(n)] == mine
                } else {
                    class_beyond(n) == mine
                };
                if alike && component.insert(n) {
                    found.push(n);
                }
            }
            next += 1;
        }
        if component.len() <= SPECK && !component.iter().any(|&n| fixed(n)) {
            for n in component.into_iter().filter(within) {
                flip[index(n)] = true;
            }
        }
    }
    for (class, flip) in inside.iter_mut().zip(flip) {
        *class ^= flip;
    }
    if let Some(fine) = fine {
        for (i, class) in inside.iter_mut().enumerate() {
            let n = at_local(i).map(|c| c as i64);
            // A sample in a block proven one-sided lies in a component larger than a speck.
            if field[i].is_finite() && fixed(n) {
                *class = fine.class(finest(n));
            }
        }
    }
}

/// The box of the grid samples inside the surface of `tree` at growth step `step`, grown by
/// one voxel: the surface's extent, to the grid's resolution.
pub fn surface_box(tree: &Node, grid: &Grid, step: u32) -> Bounds {
    let mut field = Vec::new();
    let mut inside = Bounds::EMPTY;
    for chunk in grid.chunks_touching(&tree.bounds) {
        if sample(tree, grid, chunk, step, &mut field, false, |_| {}).is_none() {
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
            if sample(tree, &grid, chunk, step, &mut field, false, |_| {}).is_none() {
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
