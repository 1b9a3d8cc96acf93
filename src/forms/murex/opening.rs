//! The opening (Galbraith, Prusinkiewicz & Wyvill §3.3, eq 14): the hollow inside carved out
//! of the shell, open at every stage of growth, with a wall the grid can show.

use super::generating_surface::generating_surface;
use super::helix::Instances;
use super::sections::{Gathered, joined, sections};
use super::varix::{edge_distance, outward};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::spec::form::implicit::ImplicitSpec;
use glam::{DAffine3, DVec3};

/// Voxels the wall is at least thick where the shell is hollow.
pub const WALL_VOXELS: f64 = 2.5;
/// The smallest the hollow's generating surface is shrunk to for the wall to keep
/// [`WALL_VOXELS`]; closer to the apex, where it would have to shrink further or where the
/// shrunk instances no longer join into one tube, the shell is solid.
const SMALLEST_HOLLOW: f64 = 0.3;

/// The hollow inside of eq 14: the inside generating surface placed like the shell's, up to
/// `ahead` instances beyond the growing edge, each born `ahead` growth steps early, so that
/// the aperture is open at every stage. Where the wall it leaves would be thinner than
/// [`WALL_VOXELS`] at the spec's resolution, it is shrunk about its centre until the wall is
/// that thick, as spines are thickened, so that a coarse grid shows a whole wall, not a
/// perforated one. The paper subtracts the previous whorl from this inside whorl so that the
/// cut leaves it intact, and adds an inside wall back (eq 15) because its opening is not
/// round. Our inside surface is concentric with the body's and smaller, so it never reaches
/// the previous whorl and its aperture is already round: neither step is needed.
pub(crate) fn inside(
    spec: &ImplicitSpec,
    instances: &Instances,
    voxel: f64,
    gathered: &mut Gathered,
) -> Option<Node> {
    let o = &spec.opening;
    let hollow = generating_surface(&o.inside, 0.0, f64::INFINITY)?;
    let solid = generating_surface(&spec.generator, 0.0, f64::INFINITY)?;
    // (outer, hollow) extents in units of D, in eight directions of the generating curve.
    let extents: Vec<[f64; 2]> = (0..8)
        .filter_map(|i| {
            let d = outward(45.0 * f64::from(i));
            let at = DAffine3::IDENTITY;
            Some([
                edge_distance(&solid, &at, d)?,
                edge_distance(&hollow, &at, d)?,
            ])
        })
        .collect();
    let scale = |k: u32| {
        let wall = WALL_VOXELS * voxel / instances.size(f64::from(k));
        extents
            .iter()
            .map(|[outer, hollow]| (outer - wall) / hollow)
            .fold(1.0, f64::min)
    };
    // The hollow starts where consecutive instances join into one tube: where the fields of
    // two neighbours sum past the iso-value halfway between their centres.
    let placed = |k: u32| {
        let at = instances.placement(f64::from(k)) * DAffine3::from_scale(DVec3::splat(scale(k)));
        (at, Node::transform(at, hollow.clone()))
    };
    let joins = |k: u32| {
        let ((a, na), (b, nb)) = (placed(k), placed(k + 1));
        let middle = (a.translation + b.translation) * 0.5;
        na.field(middle) + nb.field(middle) >= ISO
    };
    let end = instances.count + o.ahead;
    let first = (0..end).find(|&k| scale(k) >= SMALLEST_HOLLOW && joins(k))?;
    let parts = sections(
        &o.inside,
        instances,
        (first..end).map(|k| (k, scale(k))),
        spec.surfaces,
        o.ahead,
        gathered,
    );
    (!parts.is_empty()).then(|| {
        joined(
            spec.blending,
            parts.into_iter().map(|s| s.1).collect(),
            Vec::new(),
        )
    })
}
