//! The incremental generator: one spec in, new pattern rows and new rims out, a few at a time,
//! on a growth clock measured in pattern rows (row 0 is the starting state at the apex, row
//! `rows − 1` the opening). The cost of a call depends on the rows it adds, never on the age
//! of the shell.

use crate::forms::{has_one_growing_edge, picture_shape_for, shape_for};
use crate::mesh::{Bounds, Capacity, Mesh};
use crate::pattern::PatternError;
use crate::pattern::run::PatternRun;
use crate::shape::{EdgePart, GrowingShape, LineGrid, Pieces, ShapeError};
use crate::spec::ShellSpec;
use crate::spec::form::Form;
use crate::spec::pattern::EdgeGrowth;
use glam::DVec3;
use std::ops::Range;

/// Milliseconds of a frame that the page's growth may take, so no speed freezes the tab.
pub const GROWTH_BUDGET_MS: f64 = 12.0;

/// A `keep_going` for [`Generator::advance_while`] that spends at most `budget_ms` from now
/// on the clock `now` (milliseconds): it stops before a step that would end past the budget if
/// it took as long as the longest step lately. `longest` carries that estimate from frame to
/// frame, since a step far longer than most (meshing a chunk thick with spines, showing a
/// finished section) comes once in many frames; it fades by [`LONGEST_FADE`] every frame so
/// that one slow step does not slow growth for long.
pub fn within<'a>(
    now: impl Fn() -> f64 + 'a,
    budget_ms: f64,
    longest: &'a mut f64,
) -> impl FnMut() -> bool + 'a {
    let start = now();
    *longest *= LONGEST_FADE;
    let (deadline, mut last) = (start + budget_ms, start);
    move || {
        let t = now();
        *longest = longest.max(t - last);
        last = t;
        t + *longest < deadline
    }
}

/// What is left of the longest step's time after a frame (see [`within`]).
pub const LONGEST_FADE: f64 = 0.9;

/// What one call to [`Generator::advance`] added.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Advance {
    /// New vertices of the permanent mesh.
    pub vertices: Range<usize>,
    /// New indices of the permanent mesh.
    pub indices: Range<usize>,
    /// When the transient edge mesh was rewritten: the ranges of it written anew (the GPU
    /// keeps the rest as it holds it).
    pub edge: Option<EdgeRuns>,
    /// The pattern rows added (their RGBA is [`PatternRun::rgba`] over this range).
    pub rows: Range<usize>,
}

/// Ranges of a transient edge mesh written anew, as its holder lays it out: all of it from a
/// generator, the parts a step changed from the page's copy ([`crate::work::slotted_edge`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeRuns {
    pub vertices: Vec<Range<usize>>,
    pub indices: Vec<Range<usize>>,
}

impl EdgeRuns {
    /// All of `edge`.
    pub fn whole(edge: &Mesh) -> Self {
        let (vertices, indices) = (0..edge.vertices.len(), 0..edge.indices.len());
        Self {
            vertices: vec![vertices],
            indices: vec![indices],
        }
    }
}

/// A shell growing from its spec.
pub struct Generator {
    shape: Box<dyn GrowingShape>,
    pattern: Option<PatternRun>,
    mesh: Mesh,
    edge: Mesh,
    rows: usize,
    rows_done: usize,
    failure: Option<String>,
    /// The content hash of the shell as it stands, once asked for.
    hash: std::cell::OnceCell<u64>,
}

/// Why a generator cannot be built from a spec.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BuildError {
    /// The form cannot be built.
    Shape(ShapeError),
    /// The pattern model cannot start.
    Pattern(PatternError),
}

impl std::fmt::Display for BuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BuildError::Shape(e) => e.fmt(f),
            BuildError::Pattern(e) => write!(f, "the pattern cannot be computed: {e}"),
        }
    }
}

impl std::error::Error for BuildError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BuildError::Shape(e) => Some(e),
            BuildError::Pattern(e) => Some(e),
        }
    }
}

/// The rim's length on every row of one form grown in a number of rows, kept for the next
/// pattern of the same form and rows: a preview redrawn at every step of a pattern's slider,
/// or a parameter map's tiles over two values of the pattern, build the form once.
#[derive(Default)]
pub struct RimLengths {
    of: Option<(Form, usize)>,
    lengths: Vec<Option<f64>>,
}

impl RimLengths {
    /// The rim's length on each of the `rows` rows of `spec`'s form; all `None` for a form
    /// without one growing edge, which is not built for it.
    pub(crate) fn of(
        &mut self,
        spec: &ShellSpec,
        rows: usize,
    ) -> Result<&[Option<f64>], ShapeError> {
        if !matches!(&self.of, Some((form, r)) if *form == spec.form && *r == rows) {
            self.lengths = if has_one_growing_edge(&spec.form) {
                let shape = shape_for(spec, rows)?;
                (0..rows).map(|row| shape.rim_length(row)).collect()
            } else {
                vec![None; rows]
            };
            self.of = Some((spec.form.clone(), rows));
        }
        Ok(&self.lengths)
    }
}

/// The pattern of `spec` without its mesh (a preview, a map of parameters). Its form is built
/// only for a growing edge, whose cells follow the rim, and only when `rims` does not hold its
/// rim's lengths already.
pub fn pattern_alone(
    spec: &ShellSpec,
    rims: &mut RimLengths,
) -> Result<Option<PatternRun>, BuildError> {
    let lengths: &[Option<f64>] = match spec.pattern.edge_growth {
        EdgeGrowth::Off => &[],
        EdgeGrowth::Uniform => rims
            .of(spec, spec.growth.rows_grown())
            .map_err(BuildError::Shape)?,
    };
    PatternRun::new(spec, |row| lengths.get(row).copied().flatten()).map_err(BuildError::Pattern)
}

impl Generator {
    pub fn new(spec: &ShellSpec) -> Result<Self, BuildError> {
        let rows = spec.growth.rows_grown();
        Self::with_shape(spec, rows, shape_for(spec, rows))
    }

    /// The growth of a picture of `spec` `pixels` wide: the same pattern, on a mesh no finer
    /// than the picture shows ([`picture_shape_for`]).
    pub fn picture(spec: &ShellSpec, pixels: u32) -> Result<Self, BuildError> {
        let rows = spec.growth.rows_grown();
        Self::with_shape(spec, rows, picture_shape_for(spec, rows, pixels))
    }

    /// The growth of `spec`, `rows` long, on `shape`.
    fn with_shape(
        spec: &ShellSpec,
        rows: usize,
        shape: Result<Box<dyn GrowingShape>, ShapeError>,
    ) -> Result<Self, BuildError> {
        let shape = shape.map_err(BuildError::Shape)?;
        let pattern =
            PatternRun::new(spec, |row| shape.rim_length(row)).map_err(BuildError::Pattern)?;
        let mut generator = Self {
            mesh: Mesh::default(),
            edge: Mesh::default(),
            shape,
            pattern,
            rows,
            rows_done: 1,
            failure: None,
            hash: std::cell::OnceCell::new(),
        };
        generator.grow_shape();
        Ok(generator)
    }

    /// Total rows from apex to opening.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Rows grown so far.
    pub fn rows_done(&self) -> usize {
        self.rows_done
    }

    /// Whether growth has ended: fully grown, or stopped by a failure, the shape grown to the row
    /// where the pattern stopped.
    pub fn is_done(&self) -> bool {
        (self.failure.is_some() || self.rows_done >= self.rows)
            && self.shape.steps_done() >= self.target_step()
    }

    /// Why growth stopped early (the pattern diverged), in words.
    pub fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    /// Whether the shape has grown as far as the rows (within a call of
    /// [`Self::advance_while`] it may lag behind them): the shell then stands exactly at
    /// [`Self::rows_done`], as a frame-exact recording needs.
    pub fn caught_up(&self) -> bool {
        self.shape.steps_done() >= self.target_step()
    }

    /// The pattern, when the shell has one.
    pub fn pattern(&self) -> Option<&PatternRun> {
        self.pattern.as_ref()
    }

    /// Buffer sizes of the fully grown mesh and of the edge.
    pub fn capacity(&self) -> (Capacity, Capacity) {
        (self.shape.capacity(), self.shape.edge_capacity())
    }

    /// Bounds and viewing direction of the fully grown shell.
    pub fn framing(&self) -> (Bounds, DVec3) {
        (self.shape.bounds(), self.shape.front())
    }

    /// Where a line drawing of the shape draws its lines.
    pub fn line_grid(&self) -> LineGrid {
        self.shape.line_grid()
    }

    /// The permanent mesh grown so far.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The transient mesh closing the current growing edge.
    pub fn edge(&self) -> &Mesh {
        &self.edge
    }

    /// The parts of [`Self::edge`] that change apart, in the order of their numbers.
    pub fn edge_parts(&self) -> Vec<EdgePart> {
        self.shape.edge_parts(&self.edge)
    }

    /// [`Mesh::content_hash`] of the shell as it stands, edge included: the same for the same
    /// triangles however they were grown.
    pub fn mesh_hash(&self) -> u64 {
        *self.hash.get_or_init(|| {
            self.mesh
                .content_hash()
                .wrapping_add(self.edge.content_hash())
        })
    }

    /// The shell as it stands, edge included: what an export writes.
    pub fn snapshot(&self) -> Mesh {
        let mut mesh = self.mesh.clone();
        mesh.append(&self.edge);
        mesh
    }

    /// The shape's step that the current row has reached.
    fn target_step(&self) -> usize {
        let steps = self.shape.steps();
        if steps <= 1 {
            steps
        } else {
            ((self.rows_done - 1) * (steps - 1) / (self.rows - 1) + 1).min(steps)
        }
    }

    /// Grows the shape towards the step that the current row has reached, while `keep_going`
    /// allows (at least one step); says whether the edge mesh was rewritten.
    fn grow_shape_while(&mut self, mut keep_going: impl FnMut() -> bool) -> bool {
        self.hash.take();
        let target = self.target_step();
        let mut changed = false;
        let mut first = true;
        while self.shape.steps_done() < target && (first || keep_going()) {
            changed |= self.shape.grow(&mut self.mesh, &mut self.edge);
            first = false;
        }
        changed
    }

    /// Takes the room the fully grown meshes need at once, before growing step by step, so
    /// that no step stops to move the whole mesh grown so far into a larger one. Growing to
    /// the end at once ([`Generator::finish`]) takes the room the shape asks for finishing
    /// ([`GrowingShape::finish_capacity`]) instead.
    fn reserve(&mut self) {
        self.mesh.reserve_total(self.shape.capacity());
        self.edge.reserve_total(self.shape.edge_capacity());
    }

    /// Grows the shape up to the step that the current row has reached.
    fn grow_shape(&mut self) -> bool {
        self.grow_shape_while(|| true)
    }

    /// Computes pattern rows up to row `target`, stopping at a failure.
    fn advance_pattern(&mut self, target: usize) {
        while self.failure.is_none() && self.rows_done < target {
            if let Some(Err(e)) = self.pattern.as_mut().map(PatternRun::advance) {
                self.failure = Some(format!("The pattern stopped {e}."));
                break;
            }
            self.rows_done += 1;
        }
    }

    /// Grows by up to `rows` pattern rows.
    pub fn advance(&mut self, rows: usize) -> Advance {
        self.reserve();
        let (v0, i0, r0) = (
            self.mesh.vertices.len(),
            self.mesh.indices.len(),
            self.rows_done,
        );
        self.advance_pattern((self.rows_done + rows).min(self.rows));
        let edge_changed = self.grow_shape();
        Advance {
            vertices: v0..self.mesh.vertices.len(),
            indices: i0..self.mesh.indices.len(),
            edge: edge_changed.then(|| EdgeRuns::whole(&self.edge)),
            rows: r0..self.rows_done,
        }
    }

    /// Everything grown so far, as one advance: what a fresh upload must write.
    pub fn grown(&self) -> Advance {
        Advance {
            vertices: 0..self.mesh.vertices.len(),
            indices: 0..self.mesh.indices.len(),
            edge: Some(EdgeRuns::whole(&self.edge)),
            rows: 0..self.rows_done,
        }
    }

    /// Grows row by row, up to `rows` rows, while `keep_going` allows (a frame's time budget):
    /// at least one row, or one step of the shape, is grown when any remains. The shape may lag
    /// behind the rows within a call and catches up in the next.
    pub fn advance_while(&mut self, rows: usize, mut keep_going: impl FnMut() -> bool) -> Advance {
        self.reserve();
        let (v0, i0, r0) = (
            self.mesh.vertices.len(),
            self.mesh.indices.len(),
            self.rows_done,
        );
        let lagging = self.shape.steps_done() < self.target_step();
        let mut edge_changed = self.grow_shape_while(&mut keep_going);
        let mut grown = 0;
        while grown < rows && !self.is_done() && ((grown == 0 && !lagging) || keep_going()) {
            if self.shape.steps_done() >= self.target_step() {
                self.advance_pattern(self.rows_done + 1);
                grown += 1;
            }
            edge_changed |= self.grow_shape_while(&mut keep_going);
        }
        Advance {
            vertices: v0..self.mesh.vertices.len(),
            indices: i0..self.mesh.indices.len(),
            edge: edge_changed.then(|| EdgeRuns::whole(&self.edge)),
            rows: r0..self.rows_done,
        }
    }

    /// Grows to the end at once: to the last row, or to the row where the pattern stopped (the
    /// shape stops there too, however growth was cut into calls before).
    pub fn finish(&mut self) {
        self.mesh.reserve_total(self.shape.finish_capacity());
        self.advance_pattern(self.rows);
        self.hash.take();
        if self.failure.is_some() {
            self.grow_shape();
        } else {
            self.shape.finish(&mut self.mesh, &mut self.edge);
        }
    }

    /// Grows to the end at once, but for the pieces of the shape's growth it returns (see
    /// [`GrowingShape::finish_apart`]): until they are made apart and joined (by the page's
    /// copy of the shell, `work::replica`), the mesh lacks them. `None` when nothing is left
    /// apart: the shell is then whole.
    pub fn finish_apart(&mut self) -> Option<Pieces> {
        self.mesh.reserve_total(self.shape.finish_capacity());
        self.advance_pattern(self.rows);
        self.hash.take();
        if self.failure.is_some() {
            self.grow_shape();
            return None;
        }
        self.shape.finish_apart(&mut self.mesh, &mut self.edge)
    }

    /// Joins the meshes of the pieces [`Self::finish_apart`] left out, made elsewhere by a
    /// [`crate::forms::PieceMaker`] of the same spec, one mesh for each of the pieces' groups in
    /// the groups' order: the shell is then whole, the same bit for bit as [`Self::finish`]
    /// grows it.
    pub fn join_apart(&mut self, made: Vec<Mesh>) {
        self.hash.take();
        Pieces::join(&mut self.mesh, made);
    }

    /// Steps of the shape grown so far.
    pub fn steps_done(&self) -> usize {
        self.shape.steps_done()
    }

    /// Grows at once to where another generator of the same spec stood: `rows` rows and
    /// `steps` steps of its shape (at most as far as those rows reach). Growth is the same bit
    /// for bit however it was cut into calls, so this one then goes on as that one would.
    pub fn catch_up(&mut self, rows: usize, steps: usize) {
        self.reserve();
        self.advance_pattern(rows.min(self.rows));
        self.hash.take();
        let target = steps.min(self.target_step());
        while self.shape.steps_done() < target {
            self.shape.grow(&mut self.mesh, &mut self.edge);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    #[test]
    fn the_budget_remembers_a_long_step_of_an_earlier_frame() {
        let clock = Cell::new(0.0);
        let now = || clock.get();
        let mut longest = 0.0;
        {
            let mut keep_going = within(now, 12.0, &mut longest);
            clock.set(8.0);
            assert!(!keep_going(), "a second 8 ms step would end at 16 ms");
        }
        // In the next frame the steps take 1 ms, but one like the 8 ms step (faded to 7.2 ms)
        // may come: the frame stops once it could no longer end in time.
        clock.set(100.0);
        let mut keep_going = within(now, 12.0, &mut longest);
        clock.set(101.0);
        assert!(keep_going());
        clock.set(104.0);
        assert!(keep_going());
        clock.set(105.0);
        assert!(!keep_going());
    }
}
