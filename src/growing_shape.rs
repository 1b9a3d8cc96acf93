//! The one interface between a shell form and everything that shows or exports it: a shape
//! that grows one step at a time, appending to a permanent mesh and rewriting a small transient
//! mesh that closes its current growing edge (the lip of a thick wall). A step's cost depends
//! only on what it adds, never on how much has grown already.

use crate::geometry::sweep_mesh::SweepMesh;
use crate::growth::branching_mesh::BranchingMesh;
use crate::growth::chamber_mesh::ChamberMesh;
use crate::implicit::implicit_mesh::ImplicitMesh;
use crate::mesh::{Bounds, Capacity, Mesh};
use crate::spec::ShellSpec;
use crate::spec::form::Form;
use glam::DVec3;

/// Why a shape cannot be built from its spec, in words that name the key concerned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GeometryError(pub String);

/// A shape grown step by step.
pub trait GrowingShape {
    /// Steps from the first to the fully grown shape.
    fn steps(&self) -> usize;
    /// Steps grown so far.
    fn steps_done(&self) -> usize;
    /// Sizes of the permanent mesh when fully grown.
    fn capacity(&self) -> Capacity;
    /// The largest the transient edge mesh ever gets.
    fn edge_capacity(&self) -> Capacity;
    /// Bounding box of the fully grown shape.
    fn bounds(&self) -> Bounds;
    /// The direction the fully grown shape is best seen from (where its opening faces).
    fn front(&self) -> DVec3;
    /// Grows one step: appends to `mesh`, and may replace `edge` with the geometry that closes
    /// the new growing edge; says whether it did.
    fn grow(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> bool;
    /// Grows every remaining step (a form may know a shorter way to the end than step by step).
    fn finish(&mut self, mesh: &mut Mesh, edge: &mut Mesh) {
        while self.steps_done() < self.steps() {
            self.grow(mesh, edge);
        }
    }
}

/// The growing shape a spec's form describes; `rows` (at least 2) is the length of the pattern
/// in rows: the first step lies on row 0, the last on row `rows − 1`. Random choices of the
/// form come from the spec's seed.
pub fn shape_for(spec: &ShellSpec, rows: usize) -> Result<Box<dyn GrowingShape>, GeometryError> {
    match &spec.form {
        Form::Sweep(sweep) => Ok(Box::new(SweepMesh::new(sweep, rows)?)),
        Form::Chambers(chambers) => Ok(Box::new(ChamberMesh::new(chambers, rows)?)),
        Form::Branching(branching) => Ok(Box::new(BranchingMesh::new(branching, spec.seed, rows)?)),
        Form::Implicit(implicit) => Ok(Box::new(ImplicitMesh::new(
            implicit,
            &spec.pattern,
            spec.seed,
            rows,
        )?)),
    }
}
