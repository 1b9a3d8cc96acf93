//! The shell forms, one folder per paper's model, and the one place that dispatches on
//! [`Form`]: which [`GrowingShape`] a spec grows, how its form is repaired, and how many
//! pattern rows make one whorl.
//!
//! - [`sweep`]: a generating curve swept along a helico-spiral (Fowler, Meinhardt &
//!   Prusinkiewicz 1992, §2).
//! - [`kawaguchi`]: accumulated chambers and branching forms (Kawaguchi 1982).
//! - [`murex`]: generating surfaces of skeletal primitives blended along a helico-spiral and
//!   polygonized (Galbraith, Prusinkiewicz & Wyvill), built on the [`blobtree`](crate::blobtree)
//!   engine.

pub mod kawaguchi;
pub mod murex;
pub mod sweep;

use crate::shape::{GrowingShape, ShapeError};
use crate::spec::ShellSpec;
use crate::spec::form::Form;
use crate::spec::pattern::PatternSpec;
use crate::spec::problem::Problem;
use kawaguchi::branching::branching_mesh::BranchingMesh;
use kawaguchi::chambers::chamber_mesh::ChamberMesh;
use kawaguchi::chambers::chamber_stack::{ChamberStack, turn_per_chamber};
use murex::implicit_mesh::ImplicitMesh;
pub use murex::implicit_mesh::PieceMaker;
use sweep::sweep_mesh::SweepMesh;

/// The growing shape a spec's form describes; `rows` (at least 2) is the length of the pattern
/// in rows: the first step lies on row 0, the last on row `rows − 1`. Random choices of the
/// form come from the spec's seed.
pub fn shape_for(spec: &ShellSpec, rows: usize) -> Result<Box<dyn GrowingShape>, ShapeError> {
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

/// The growing shape of a picture of `spec` `pixels` wide: a swept shell's mesh no finer than
/// the picture shows ([`SweepMesh::drawn_at`]); any other form's own.
pub fn picture_shape_for(
    spec: &ShellSpec,
    rows: usize,
    pixels: u32,
) -> Result<Box<dyn GrowingShape>, ShapeError> {
    match &spec.form {
        Form::Sweep(sweep) => Ok(Box::new(SweepMesh::drawn_at(sweep, rows, pixels)?)),
        Form::Chambers(_) | Form::Branching(_) | Form::Implicit(_) => shape_for(spec, rows),
    }
}

/// What makes the pieces of the growth of `spec` (`rows` long) that its shape's
/// [`GrowingShape::finish_apart`] leaves out, apart from that shape; `None` for a form whose
/// growth does not split.
pub fn piece_maker(spec: &ShellSpec, rows: usize) -> Result<Option<PieceMaker>, ShapeError> {
    match &spec.form {
        Form::Implicit(implicit) => {
            PieceMaker::new(implicit, &spec.pattern, spec.seed, rows).map(Some)
        }
        Form::Sweep(_) | Form::Chambers(_) | Form::Branching(_) => Ok(None),
    }
}

/// Whether the growth of `form` ends in pieces meshed apart ([`piece_maker`] makes them): such
/// a shell, grown whole, is remeshed whole rather than grown again when a value changes, and is
/// finished before a file is written of it. Each form says, so that a new one must.
pub fn meshed_in_pieces(form: &Form) -> bool {
    match form {
        Form::Implicit(_) => true,
        Form::Sweep(_) | Form::Chambers(_) | Form::Branching(_) => false,
    }
}

/// Whether `form` grows one edge whose length a pattern's dividing cells can follow
/// ([`GrowingShape::rim_length`] gives it): a swept shell's rim and a chamber stack's mouth
/// have one; the Murex's sections and a tree's many branches have not. Each form says.
pub fn has_one_growing_edge(form: &Form) -> bool {
    match form {
        Form::Sweep(_) | Form::Chambers(_) => true,
        Form::Implicit(_) | Form::Branching(_) => false,
    }
}

/// Repairs what `form` asks that its model cannot build, or that breaks a cap, from
/// `fallback` (a form of the same kind), and says what was done in `problems`.
pub(crate) fn repair(
    form: &mut Form,
    fallback: &Form,
    pattern: &PatternSpec,
    seed: u64,
    problems: &mut Vec<Problem>,
) {
    match (form, fallback) {
        (Form::Sweep(s), Form::Sweep(f)) => sweep::repair::repair(s, f, problems),
        (Form::Chambers(c), Form::Chambers(f)) => {
            kawaguchi::chambers::repair::repair(c, f, problems)
        }
        (Form::Branching(b), Form::Branching(f)) => {
            kawaguchi::branching::repair::repair(b, f, seed, problems)
        }
        (Form::Implicit(i), Form::Implicit(f)) => murex::repair::repair(i, f, pattern, problems),
        _ => unreachable!("the fallback is a form of the same kind"),
    }
}

/// Why `form`, though the page shows it, is no solid a file may carry: whorls of a chamber
/// stack that pass through one another. None for a form that builds a solid.
pub fn self_overlap(form: &Form) -> Option<Problem> {
    match form {
        Form::Chambers(c) => ChamberStack::new(c)
            .ok()
            .as_ref()
            .and_then(kawaguchi::chambers::repair::overlap_problem),
        Form::Sweep(_) | Form::Branching(_) | Form::Implicit(_) => None,
    }
}

/// Pattern rows per turn of the shell, for shading depth inside the opening.
pub fn rows_per_whorl(spec: &ShellSpec) -> f64 {
    let rows = f64::from(spec.growth.rows);
    let whorls = match &spec.form {
        Form::Sweep(s) => s.spiral.whorls,
        Form::Chambers(c) => {
            f64::from(c.chambers) * turn_per_chamber(&c.chamber) / std::f64::consts::TAU
        }
        Form::Implicit(i) => i.turns(),
        // No whorls: the whole growth counts as one.
        Form::Branching(_) => return rows,
    };
    rows / whorls.max(1e-3)
}
