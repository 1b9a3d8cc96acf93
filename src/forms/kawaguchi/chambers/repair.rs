//! The chamber stack's cross-field checks: a mouth that does not fold over itself, a growth
//! from first to last chamber that a file can hold, chambers whose top base stays above their
//! bottom base, and a mesh within the vertex cap.

use super::chamber_mesh::mesh_capacity;
use super::chamber_stack::{ChamberStack, check_growth, most_chambers};
use super::mouth::mouth_polygon;
use super::overlap::whorls_overlap;
use crate::mesh::MAX_VERTICES;
use crate::spec::form::chambers::ChambersSpec;
use crate::spec::problem::Problem;

/// A chamber stack must build (a mouth that does not fold over itself, no more chambers than
/// its ratio allows, chambers whose top base stays above their bottom base) and fit the
/// vertex cap.
pub(crate) fn repair(c: &mut ChambersSpec, f: &ChambersSpec, problems: &mut Vec<Problem>) {
    if let Err(e) = mouth_polygon(&c.mouth) {
        problems.push(e.repaired("the preset's protuberances"));
        c.mouth.protuberances = f.mouth.protuberances.clone();
        if mouth_polygon(&c.mouth).is_err() {
            c.mouth = f.mouth.clone();
        }
    }
    if let Err(e) = check_growth(c.chambers, c.chamber.ratio) {
        let most = most_chambers(c.chamber.ratio);
        problems.push(e.repaired(&most.to_string()));
        c.chambers = most;
    }
    let stack = ChamberStack::new(c).or_else(|e| {
        problems.push(e.repaired("the preset's chamber"));
        c.chamber = f.chamber.clone();
        ChamberStack::new(c).or_else(|_| {
            *c = f.clone();
            ChamberStack::new(c)
        })
    });
    if let Some(problem) = stack.ok().as_ref().and_then(overlap_problem) {
        problems.push(problem);
    }
    let vertices = mesh_capacity(c).0.vertices as u64;
    if vertices > MAX_VERTICES {
        problems.push(Problem::new(
            "form.chambers",
            format!(
                "{} chambers of {} apexes would make {vertices} vertices, more than the cap of {MAX_VERTICES}; used the preset's {} chambers of {} apexes",
                c.chambers, c.mouth.apexes, f.chambers, f.mouth.apexes
            ),
        ));
        c.chambers = f.chambers;
        c.mouth.apexes = f.mouth.apexes;
    }
}

/// Whorls that pass through one another, said with the fix; the stack is left as asked, since
/// the page shows it well, but no file is written of it.
pub(crate) fn overlap_problem(stack: &ChamberStack) -> Option<Problem> {
    whorls_overlap(stack).map(|d| {
        Problem::shown(
            "form.chamber.ratio",
            format!(
                "whorls overlap: each chamber passes through the one {d} chambers later, so no file is written of this shell; raise the growth ratio r, or move the position (Tx, Ty) to open the coil"
            ),
        )
    })
}
