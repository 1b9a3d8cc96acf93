//! Whether the polygonizer's grid can see a shell at all. An implicit shell is drawn by
//! sampling its field on a grid of `resolution` voxels along the longest side of its box
//! (`blobtree::polygonize`), which drops pieces of a few samples as specks the grid made
//! (`polygonize::SPECK`), so a generating surface that holds no more is not drawn. Eq 3
//! makes the generating surface D = R(λ − 1)/((λ + 1) sin β) wide: as λ nears 1 the whorls
//! thin to threads, or to beads apart from one another, beside the box they coil in, and the
//! whole shell, opening included, falls between the samples and grows to nothing.

use super::generating_surface::generating_surface;
use super::helix::Instances;
use super::sections::{Gathered, sections};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::blobtree::polygonize::SPECK;
use crate::mesh::Bounds;
use crate::shape::ShapeError;
use crate::spec::fields;
use crate::spec::form::implicit::ImplicitSpec;
use glam::DVec3;

/// Across this many voxels (the box its field reaches over) the opening's generating surface
/// is surely drawn, its surface some voxels wide. Below it, [`check`] samples the field.
const SURELY_SEEN: f64 = 24.0;

/// Most samples [`opening_seen`] takes: more would cover an opening far wider than a speck.
const MOST_SAMPLES: usize = 1 << 18;

/// The voxels of the shell's grid across its opening's generating surface (the largest side
/// of the box its field reaches over), and the grid's voxel: the grid spans the box of the
/// opening's generating surface placed at every instance along the helico-spiral (eq 8), as
/// [`super::whorl::whorl`] measures the shell before spines are added (which only widen it),
/// give or take the parts early whorls lack (a wider box, a coarser voxel: the safer side).
fn voxels_across(spec: &ImplicitSpec, instances: &Instances, last: &Node) -> (f64, f64) {
    let local = last.bounds;
    let mut shell = Bounds::EMPTY;
    for k in 0..instances.count {
        let at = instances.placement(f64::from(k));
        for corner in local.corners() {
            shell.include(at.transform_point3(corner));
        }
    }
    let voxel = (shell.max - shell.min).max_element() / f64::from(spec.resolution);
    let size = instances.size(f64::from(instances.count - 1));
    ((local.max - local.min).max_element() * size / voxel, voxel)
}

/// Whether the grid sees the opening: the last two sections' generating surfaces, blended,
/// hold a component of inside samples (joined face to face) more than twice as large as the
/// specks the polygonizer drops ([`SPECK`]), on a grid of the shell's voxel (its offset may
/// differ from the shell's grid by a fraction of a voxel, hence twice). Generating surfaces
/// apart from one another, each a bead of a few samples, are all dropped.
fn opening_seen(spec: &ImplicitSpec, instances: &Instances, voxel: f64) -> bool {
    let count = instances.count;
    let from = count.saturating_sub(2 * spec.surfaces);
    let mut gathered = Gathered { reach: Vec::new() };
    let last_two = sections(
        &spec.generator,
        instances,
        (from..count).map(|k| (k, 1.0)),
        spec.surfaces,
        0,
        &mut gathered,
    );
    let blended = Node::blend(last_two.into_iter().map(|(_, s)| s).collect());
    let b = blended.bounds;
    let n = ((b.max - b.min) / voxel).ceil().as_uvec3() + 1;
    let (nx, ny, nz) = (n.x as usize, n.y as usize, n.z as usize);
    if nx * ny * nz > MOST_SAMPLES {
        return true;
    }
    let at = |i: usize| {
        let (x, y, z) = (i % nx, i / nx % ny, i / (nx * ny));
        b.min + DVec3::new(x as f64, y as f64, z as f64) * voxel
    };
    let mut inside: Vec<bool> = (0..nx * ny * nz)
        .map(|i| blended.field(at(i)) >= ISO)
        .collect();
    let steps = [1, nx, nx * ny];
    for first in 0..inside.len() {
        if !inside[first] {
            continue;
        }
        inside[first] = false;
        let (mut component, mut stack) = (0, vec![first]);
        while let Some(i) = stack.pop() {
            component += 1;
            let (x, y, z) = (i % nx, i / nx % ny, i / (nx * ny));
            let within = [(x, nx), (y, ny), (z, nz)];
            for (axis, &step) in steps.iter().enumerate() {
                let (c, size) = within[axis];
                let below = (c > 0).then(|| i - step);
                let above = (c + 1 < size).then(|| i + step);
                for j in [below, above].into_iter().flatten() {
                    if inside[j] {
                        inside[j] = false;
                        stack.push(j);
                    }
                }
            }
        }
        if component > 2 * SPECK {
            return true;
        }
    }
    false
}

/// A shell the grid cannot see is refused: it would grow to nothing.
pub(crate) fn check(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let instances = Instances::new(spec, 2);
    let last = f64::from(instances.count - 1);
    let Some(surface) = generating_surface(&spec.generator, 0.0, instances.whorl(last)) else {
        return Ok(());
    };
    let (across, voxel) = voxels_across(spec, &instances, &surface);
    if across >= SURELY_SEEN || opening_seen(spec, &instances, voxel) {
        return Ok(());
    }
    let h = &spec.spiral;
    let width = (h.lambda - 1.0) / ((h.lambda + 1.0) * h.beta.to_radians().sin());
    Err(ShapeError::new(
        "form.spiral.lambda",
        format!(
            "at λ = {} the whorls are too thin for the grid of {} voxels: the opening's generating surface, {:.3} of its radius wide (eq 3), holds no more than a speck of the grid's samples, which the grid drops, so the shell would grow to nothing; raise λ, the resolution, or the generating surface's parts",
            h.lambda, spec.resolution, width
        ),
    ))
}

/// The least λ (to a thousandth, at most the panel's most) at which the grid sees the shell of
/// `spec` ([`check`] alone; the other checks follow in the repair), everything else as it is:
/// what the page uses for a λ too small; none when even the most λ would not be seen, or λ is
/// outside the panel's range.
pub(crate) fn least_lambda_seen(spec: &ImplicitSpec) -> Option<f64> {
    let mut at = spec.clone();
    let mut seen = |lambda: f64| {
        at.spiral.lambda = lambda;
        check(&at).is_ok()
    };
    let (least, most) = fields::range("implicit", "form.spiral.lambda");
    if !(least..most).contains(&spec.spiral.lambda) {
        return None;
    }
    let (mut lo, mut hi) = (spec.spiral.lambda, most);
    if !seen(hi) {
        return None;
    }
    while hi - lo > 1e-4 {
        let mid = (lo + hi) / 2.0;
        if seen(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let rounded = (hi * 1000.0).ceil() / 1000.0;
    Some(if seen(rounded) { rounded } else { hi })
}
