//! The one interface between a shell form and everything that shows or exports it: a shape
//! that grows one step at a time, appending to a permanent mesh and rewriting a small transient
//! mesh that closes its current growing edge (the lip of a thick wall). A step's cost depends
//! only on what it adds, never on how much has grown already.

use crate::mesh::{Bounds, Capacity, Mesh};
use crate::spec::problem::Problem;
use glam::DVec3;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::ops::Range;

/// Why a shape cannot be built from its spec: the key of the value concerned (its dotted path
/// in the serialised spec) and what is wrong with it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShapeError {
    pub key: String,
    pub message: String,
}

impl ShapeError {
    pub fn new(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            key: key.into(),
            message: message.into(),
        }
    }

    /// The same fault as a repaired problem, saying what was `used` instead.
    pub fn repaired(self, used: &str) -> Problem {
        Problem::new(self.key, format!("{}; used {used}", self.message))
    }
}

impl fmt::Display for ShapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for ShapeError {}

/// Where a line drawing of a shape draws its lines, in pattern coordinates (x along the growing
/// edge in [0, 1], y the growth time in rows): lines along the growth direction at x = k /
/// `across`, and rims every `rows` rows. A faceted form puts them on its facets' edges; a smooth
/// one on a sparse set of its rims and of its lines of growth.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LineGrid {
    pub across: f64,
    pub rows: f64,
}

impl LineGrid {
    /// Lines along the growth direction on a smooth form.
    const SPARSE_ACROSS: f64 = 16.0;
    /// Rims per whorl on a smooth form: one every 15° of turn.
    const SPARSE_RIMS_PER_WHORL: f64 = 24.0;

    /// The grid of a smooth form that has `rows_per_whorl` pattern rows a turn, its rims
    /// falling on the form's own rims when those are `rows_per_rim` apart (a multiple of them).
    pub(crate) fn sparse(rows_per_whorl: f64, rows_per_rim: Option<f64>) -> Self {
        let rows = rows_per_whorl / Self::SPARSE_RIMS_PER_WHORL;
        Self {
            across: Self::SPARSE_ACROSS,
            rows: match rows_per_rim {
                Some(rim) if rim > 0.0 => rim * (rows / rim).round().max(1.0),
                _ => rows,
            },
        }
    }
}

/// The rest of a shape's growth cut into pieces that can be made apart from the shape (on other
/// threads, by [`crate::forms::PieceMaker`], from the same spec) and joined in a fixed order:
/// each group's mesh (its pieces' meshes in the order of the group) is appended to the
/// permanent mesh in the order of the groups, so how the groups were shared out cannot change
/// a bit of the result; made in one go, the pieces of all groups in turn give the same.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Pieces {
    /// The growth step the pieces are made at.
    pub step: u32,
    /// The pieces' numbers, in groups best made together (by one worker), each ascending.
    pub groups: Vec<Vec<u32>>,
}

impl Pieces {
    /// How many pieces there are.
    pub fn count(&self) -> usize {
        self.groups.iter().map(Vec::len).sum()
    }

    /// Appends `made`, the meshes of the groups of some [`Pieces`] (one for each group, in the
    /// groups' order), to `mesh`.
    pub fn join(mesh: &mut Mesh, made: Vec<Mesh>) {
        for m in made {
            mesh.append_sparingly(&m);
        }
    }
}

/// A part of the transient edge mesh that changes apart from the rest: its number, and where
/// it lies in the edge (its indices name vertices of its own range). The edge is its parts
/// joined in the order of their numbers, so that the page can hold each part in a place of its
/// own and take only the parts a step changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EdgePart {
    pub id: u32,
    pub vertices: Range<usize>,
    pub indices: Range<usize>,
}

impl EdgePart {
    /// All of `edge` as part 0: the edge of a shape that rewrites it whole.
    pub fn whole(edge: &Mesh) -> Self {
        Self {
            id: 0,
            vertices: 0..edge.vertices.len(),
            indices: 0..edge.indices.len(),
        }
    }
}

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
    /// The room the permanent mesh takes before the shape is grown to its end at once: its
    /// capacity, unless that is only a guess the mesh may stay far below (then none, and the
    /// mesh grows as it fills).
    fn finish_capacity(&self) -> Capacity {
        self.capacity()
    }
    /// Bounding box of the fully grown shape.
    fn bounds(&self) -> Bounds;
    /// The direction the fully grown shape is best seen from (where its opening faces).
    fn front(&self) -> DVec3;
    /// Where a line drawing of the shape draws its lines.
    fn line_grid(&self) -> LineGrid;
    /// The length of the growing edge at pattern row `row` (shell units), whose growth a
    /// pattern on a growing edge follows with its number of cells; `None` for a form that
    /// has no one growing edge.
    fn rim_length(&self, row: usize) -> Option<f64>;
    /// Grows one step: appends to `mesh`, and may replace `edge` with the geometry that closes
    /// the new growing edge, or change it in place (it holds what the previous step left in
    /// it); says whether it did.
    fn grow(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> bool;
    /// The parts of `edge` (the edge this shape's growth left) that change apart, in the order
    /// of their numbers; none when the edge is empty. A shape that rewrites its edge whole has
    /// one part.
    fn edge_parts(&self, edge: &Mesh) -> Vec<EdgePart> {
        if edge.indices.is_empty() {
            Vec::new()
        } else {
            vec![EdgePart::whole(edge)]
        }
    }
    /// Grows every remaining step (a form may know a shorter way to the end than step by step).
    fn finish(&mut self, mesh: &mut Mesh, edge: &mut Mesh) {
        while self.steps_done() < self.steps() {
            self.grow(mesh, edge);
        }
    }
    /// Ends growth as [`Self::finish`] does, but leaves out the pieces it returns, to be made
    /// apart and appended to `mesh` group by group (see [`Pieces`]). A form
    /// whose rest of growth does not split finishes here and returns `None`.
    fn finish_apart(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> Option<Pieces> {
        self.finish(mesh, edge);
        None
    }
}
