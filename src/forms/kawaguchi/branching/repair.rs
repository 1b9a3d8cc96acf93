//! The branching form's cross-field checks: limits in order, trunks within their cap, and a
//! mesh within the vertex cap.

use super::branching_mesh::BranchingMesh;
use crate::mesh::MAX_VERTICES;
use crate::spec::form::branching::BranchingSpec;
use crate::spec::problem::Problem;

/// A branching form must build (limits in order, the count of trunks within its cap) and fit
/// the vertex cap.
pub(crate) fn repair(
    b: &mut BranchingSpec,
    f: &BranchingSpec,
    seed: u64,
    problems: &mut Vec<Problem>,
) {
    if b.knot.k0 >= b.knot.k1 {
        problems.push(Problem::new(
            "form.knot.k0",
            format!(
                "the lower limit k₀ ({}°) must be below the upper limit k₁ ({}°); used the preset's {}° and {}°",
                b.knot.k0, b.knot.k1, f.knot.k0, f.knot.k1
            ),
        ));
        b.knot.k0 = f.knot.k0;
        b.knot.k1 = f.knot.k1;
    }
    let vertices = match BranchingMesh::new(b, seed, 2) {
        Ok(mesh) => mesh.total_capacity().vertices as u64,
        Err(e) => {
            problems.push(e.repaired("the preset's form"));
            *b = f.clone();
            return;
        }
    };
    if vertices > MAX_VERTICES {
        problems.push(Problem::new(
            "form.trunk.sides",
            format!(
                "{} sides would make {vertices} vertices, more than the cap of {MAX_VERTICES}; used the preset's form",
                b.trunk.sides
            ),
        ));
        *b = f.clone();
    }
}
