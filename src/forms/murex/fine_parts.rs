//! The thin parts of a Murex — spines, ridges, canal spines, bumps — at their size in the
//! model, and the level of refinement each needs to be shown on the grid it is polygonized with
//! ([`Refinement`](crate::blobtree::polygonize::Refinement)): the voxels a part reaches are
//! halved until the part is [`THINNEST_VOXELS`] thick, up to [`MAX_LEVEL`] times. The model
//! decides what exists, the grid only how finely it is shown:
//! a part is never thinner than [`THINNEST`] of the shell's extent (a spine's tip, the
//! smallest bumps are drawn that thick, none is left out), whatever the grid, so that the
//! same BlobTree is built at every resolution of [`SHOWS_THE_MODEL`] voxels or more. Each part
//! also notes where it stands out farthest, so that tests can find it in the mesh.

use crate::blobtree::polygonize::MAX_LEVEL;
use crate::mesh::Bounds;
use glam::{DAffine3, DVec3};

/// Voxels (of the level it is meshed at) a spine, a ridge, a canal spine or a bump should be
/// thick (as a radius), so that the polygonizer shows it joined to the shell.
pub const THINNEST_VOXELS: f64 = 1.0;

/// The coarsest grid (voxels along the shell's longest side) that shows the model's least
/// sizes, a part of [`THINNEST`] and a wall of
/// [`THINNEST_WALL`](super::opening::THINNEST_WALL): on it and on every finer grid the
/// BlobTree is the same.
pub const SHOWS_THE_MODEL: u32 = 112;

/// The thinnest radius of a spine, a ridge, a canal spine or a bump, as a fraction of the
/// shell's extent (its longest side, with its longest spine): the finest voxel of a grid of
/// [`SHOWS_THE_MODEL`], 1/224, which on the 80 mm print the exporters default to is a radius
/// of 0.36 mm, a feature a 0.4 mm nozzle still draws, and in a view 900 pixels high a radius
/// of about four pixels. The model's own size, not the grid's, on any grid of 112 voxels or
/// more (a coarser one, a gallery card's, cannot show it, and draws a part at least as thick
/// as its finest voxel): `docs/models/galbraith-prusinkiewicz-wyvill.md` argues it.
pub const THINNEST: f64 = THINNEST_VOXELS / (SHOWS_THE_MODEL << MAX_LEVEL) as f64;

/// How far about a thin part's surface the grid is refined, as a multiple of its radius: its
/// field reaches on (to 2.2 radii alone), but where it adds to another part's the surface is
/// no longer thin.
const REACH: f64 = 1.5;

/// The thin parts of one instance, in its generating surface's coordinates (units of D).
pub struct FineParts {
    /// The grid's voxel in those units: what the level of refinement is chosen against.
    voxel: f64,
    /// The thinnest radius a part is drawn at in those units ([`THINNEST`] of the shell).
    floor: f64,
    parts: Vec<(Bounds, u32)>,
    /// The point of each part farthest out of the shell, with the part's radius there.
    tips: Vec<(DVec3, f64)>,
}

/// The thin parts of a whole shell, placed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Placed {
    /// The box of each and the level of refinement it needs.
    pub boxes: Vec<(Bounds, u32)>,
    /// The point of each spine, canal spine and bump farthest out of the shell, with the
    /// part's radius there: where it stands out, whatever the grid.
    pub tips: Vec<(DVec3, f64)>,
}

impl FineParts {
    /// The parts of an instance where the grid's voxel measures `voxel` units of D and the
    /// thinnest part `floor`.
    pub fn new(voxel: f64, floor: f64) -> Self {
        Self {
            voxel,
            floor,
            parts: Vec::new(),
            tips: Vec::new(),
        }
    }

    /// The level whose voxels show a part of radius `radius`.
    pub fn level(&self, radius: f64) -> u32 {
        let halvings = (THINNEST_VOXELS * self.voxel / radius).log2().ceil();
        if halvings.is_nan() || halvings <= 0.0 {
            0
        } else {
            (halvings as u32).min(MAX_LEVEL)
        }
    }

    /// A part's radius as the model draws it: never under the floor.
    pub fn thickened(&self, radius: f64) -> f64 {
        radius.max(self.floor)
    }

    /// The voxel of the grid at `level`, by which the box refined about a part is widened.
    fn margin(&self, level: u32) -> f64 {
        THINNEST_VOXELS * self.voxel / f64::from(1u32 << level)
    }

    /// Notes a part reaching over `bounds` that needs `level`.
    pub fn add(&mut self, bounds: Bounds, level: u32) {
        if level > 0 && !bounds.is_empty() {
            self.parts.push((bounds, level));
        }
    }

    /// Notes a part that needs `level` along a tube: points on its axis, each with the radius
    /// of its surface there. The refined boxes follow the tube segment by segment, each
    /// `REACH` times as wide as the surface, rather than the box of the whole curved part.
    pub fn add_tube(&mut self, axis: &[(DVec3, f64)], level: u32) {
        let margin = self.margin(level);
        let ball = |(c, r): (DVec3, f64)| {
            let reach = DVec3::splat(REACH * r + margin);
            Bounds {
                min: c - reach,
                max: c + reach,
            }
        };
        for pair in axis.windows(2) {
            self.add(ball(pair[0]).union(&ball(pair[1])), level);
        }
        if let [only] = axis {
            self.add(ball(*only), level);
        }
    }

    /// Notes where a part stands out farthest, with its radius there.
    pub fn tip(&mut self, at: DVec3, radius: f64) {
        self.tips.push((at, radius));
    }

    /// Adds the parts noted, placed by `at` (the instance's placement, scaling by `size`), to
    /// `placed`.
    pub fn place(self, at: &DAffine3, size: f64, placed: &mut Placed) {
        placed
            .boxes
            .extend(self.parts.into_iter().map(|(b, level)| {
                let mut moved = Bounds::EMPTY;
                for corner in b.corners() {
                    moved.include(at.transform_point3(corner));
                }
                (moved, level)
            }));
        (placed.tips).extend(
            (self.tips.into_iter()).map(|(p, radius)| (at.transform_point3(p), radius * size)),
        );
    }
}
