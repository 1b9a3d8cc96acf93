//! The page's copy of a shell growing on a worker: the permanent mesh, the edge, the pattern's
//! rows, where growth stands, and the hashes, kept up to date from the [`Delta`]s a worker
//! sends. Each delta is taken in only if it continues exactly what the copy holds. When the
//! shell is finished apart, the meshes of the pieces' groups come back from any workers in any
//! order and are joined once all are in, in the order of the groups: the mesh is then the one a single
//! thread finishing the shell would have made, bit for bit, whatever the number of workers.

use super::message::{Delta, Progress, ShellInfo, WholeShell};
use super::slotted_edge::SlottedEdge;
use crate::export::paint::PatternImage;
use crate::export::shell::Grown;
use crate::generator::{Advance, EdgeRuns};
use crate::mesh::{Bounds, Mesh};
use crate::pattern::run::planar_rows;
use crate::shape::Pieces;
use std::fmt;
use std::ops::Range;

/// A delta that does not continue the copy (a bug: each worker answers in order).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutOfStep {
    /// What did not follow on.
    pub key: &'static str,
    pub expected: usize,
    pub got: usize,
}

impl fmt::Display for OutOfStep {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "a worker's {} start at {} where the page holds {}",
            self.key, self.got, self.expected
        )
    }
}

impl std::error::Error for OutOfStep {}

/// Pieces being made apart, and the meshes of those in so far.
struct Joining {
    pieces: Pieces,
    /// The hash of the mesh without the pieces.
    hash: u64,
    /// The mesh of each group, once in.
    made: Vec<Option<Mesh>>,
}

/// The page's copy of a growing shell.
pub struct Replica {
    session: u32,
    /// What the shell is, once its worker has built it.
    shell: Option<ShellInfo>,
    mesh: Mesh,
    edge: SlottedEdge,
    rgba: Vec<u8>,
    /// Cells computed on each pattern row (see [`crate::pattern::run::PatternRun::widths`]).
    widths: Vec<u32>,
    rows_grown: usize,
    grown: Bounds,
    progress: Progress,
    joining: Option<Joining>,
}

impl Replica {
    /// The copy of session `session`, empty until its worker says it is built.
    pub fn new(session: u32) -> Self {
        Self {
            session,
            shell: None,
            mesh: Mesh::default(),
            edge: SlottedEdge::default(),
            rgba: Vec::new(),
            widths: Vec::new(),
            rows_grown: 0,
            grown: Bounds::EMPTY,
            progress: Progress::default(),
            joining: None,
        }
    }

    /// The copy of a shell grown whole on a worker (a gallery picture): grown, edge included
    /// in its mesh. No worker holds it, so its session is 0, which no pool gives out (see
    /// [`super::pool::Pool::open_session`]).
    pub fn whole(whole: WholeShell) -> Self {
        let rows = whole.shell.rows;
        let mut grown = Bounds::EMPTY;
        grown.include_vertices(&whole.mesh.vertices);
        let mesh_hash = whole.mesh.content_hash();
        Self {
            session: 0,
            shell: Some(whole.shell),
            mesh: whole.mesh,
            edge: SlottedEdge::default(),
            rgba: whole.rgba,
            widths: whole.widths,
            rows_grown: rows as usize,
            grown,
            progress: Progress {
                rows_done: rows,
                caught_up: true,
                done: true,
                mesh_hash: Some(mesh_hash),
                ..Progress::default()
            },
            joining: None,
        }
    }

    pub fn session(&self) -> u32 {
        self.session
    }

    /// What the shell is, once built.
    pub fn shell(&self) -> Option<&ShellInfo> {
        self.shell.as_ref()
    }

    /// The shell is built: what it is, and its first delta. The copy's meshes take the room
    /// the shape expects at once, as the generator's do, so that no frame stops to move the
    /// whole mesh grown so far into a larger one.
    pub fn loaded(&mut self, shell: ShellInfo, delta: Delta) -> Result<Advance, OutOfStep> {
        self.mesh.reserve_total(shell.capacity.0);
        self.edge.reserve_total(shell.capacity.1);
        self.shell = Some(shell);
        self.apply(delta)
    }

    /// Takes in what a request added; the ranges it added, for the GPU.
    pub fn apply(&mut self, delta: Delta) -> Result<Advance, OutOfStep> {
        let check = |key, expected: usize, got: u32| {
            if expected == got as usize {
                Ok(())
            } else {
                Err(OutOfStep {
                    key,
                    expected,
                    got: got as usize,
                })
            }
        };
        check("vertices", self.mesh.vertices.len(), delta.first_vertex)?;
        check("indices", self.mesh.indices.len(), delta.first_index)?;
        check("pattern rows", self.rows_grown, delta.rows.start)?;
        let (v0, i0) = (self.mesh.vertices.len(), self.mesh.indices.len());
        self.mesh.vertices.extend_from_slice(&delta.vertices);
        self.mesh.indices.extend_from_slice(&delta.indices);
        self.rgba.extend_from_slice(&delta.rgba);
        self.widths.extend_from_slice(&delta.widths);
        self.rows_grown = delta.rows.end as usize;
        let edge = delta.edge.map(|writes| self.edge.apply(&writes));
        self.grown = delta.grown;
        self.progress = delta.progress;
        Ok(Advance {
            vertices: v0..self.mesh.vertices.len(),
            indices: i0..self.mesh.indices.len(),
            edge,
            rows: delta.rows.start as usize..delta.rows.end as usize,
        })
    }

    /// Takes in a delta after which the shell is grown but for `pieces`, made apart; `hash` is
    /// the hash of the mesh without them.
    pub fn apart(&mut self, delta: Delta, pieces: Pieces, hash: u64) -> Result<Advance, OutOfStep> {
        let advance = self.apply(delta)?;
        self.joining = Some(Joining {
            made: vec![None; pieces.groups.len()],
            pieces,
            hash,
        });
        Ok(advance)
    }

    /// The pieces being made apart, when the shell waits for them.
    pub fn pieces(&self) -> Option<&Pieces> {
        self.joining.as_ref().map(|j| &j.pieces)
    }

    /// The mesh of group `group` of the pieces has come (with its hash; a group that came
    /// already is ignored); once every group is in, they are joined and the ranges added are
    /// returned.
    pub fn made(&mut self, group: usize, mesh: Mesh, hash: u64) -> Option<Advance> {
        let joining = self.joining.as_mut()?;
        match joining.made.get_mut(group) {
            Some(slot @ None) => *slot = Some(mesh),
            _ => return None,
        }
        joining.hash = joining.hash.wrapping_add(hash);
        if joining.made.iter().any(Option::is_none) {
            return None;
        }
        let joining = self.joining.take()?;
        let (v0, i0) = (self.mesh.vertices.len(), self.mesh.indices.len());
        Pieces::join(&mut self.mesh, joining.made.into_iter().flatten().collect());
        self.grown.include_vertices(&self.mesh.vertices[v0..]);
        self.progress.mesh_hash = Some(joining.hash);
        Some(Advance {
            vertices: v0..self.mesh.vertices.len(),
            indices: i0..self.mesh.indices.len(),
            edge: None,
            rows: self.rows_grown..self.rows_grown,
        })
    }

    /// Everything held, as one advance: what a fresh upload must write.
    pub fn everything(&self) -> Advance {
        Advance {
            vertices: 0..self.mesh.vertices.len(),
            indices: 0..self.mesh.indices.len(),
            edge: Some(EdgeRuns::whole(self.edge.mesh())),
            rows: 0..self.rows_grown,
        }
    }

    /// The permanent mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The transient mesh closing the growing edge, each of its parts in a slot.
    pub fn edge(&self) -> &SlottedEdge {
        &self.edge
    }

    /// The shell as it stands, edge included: what an export writes.
    pub fn snapshot(&self) -> Mesh {
        let mut mesh = self.mesh.clone();
        mesh.append(&self.edge.joined());
        mesh
    }

    /// The shell as it stands, for an export to read, once its worker has built it.
    pub fn for_export(&self) -> Option<Grown<'_>> {
        let shell = self.shell.as_ref()?;
        Some(Grown {
            mesh: self.snapshot(),
            failure: self.failure(),
            front: shell.front,
            pattern: (self.cells() > 0).then(|| PatternImage {
                cells: self.cells(),
                rows: self.rgba.len() / (self.cells() * 4),
                rgba: &self.rgba,
            }),
        })
    }

    /// Bounds of what has grown, edge included.
    pub fn grown(&self) -> &Bounds {
        &self.grown
    }

    /// The pattern's rows so far, `cells() × 4` bytes each.
    pub fn rgba(&self) -> &[u8] {
        &self.rgba
    }

    /// Rows `rows` of the pattern as the planar view shows them, each as long as its cells
    /// (see [`planar_rows`]).
    pub fn planar(&self, rows: Range<usize>) -> Vec<u8> {
        let row = self.cells() * 4;
        let rgba = &self.rgba[rows.start * row..rows.end * row];
        planar_rows(rgba, &self.widths[rows], self.cells())
    }

    /// Cells of a pattern row, 0 without a pattern (or before the shell is built).
    pub fn cells(&self) -> usize {
        self.shell.as_ref().map_or(0, |s| s.cells as usize)
    }

    /// Total rows from apex to opening, once built.
    pub fn rows(&self) -> usize {
        self.shell.as_ref().map_or(0, |s| s.rows as usize)
    }

    pub fn rows_done(&self) -> usize {
        self.progress.rows_done as usize
    }

    pub fn steps_done(&self) -> usize {
        self.progress.steps_done as usize
    }

    /// Whether the shape stands exactly at the rows grown.
    pub fn caught_up(&self) -> bool {
        self.progress.caught_up && self.joining.is_none()
    }

    /// Whether growth has ended (grown whole, pieces joined, or stopped by a failure).
    pub fn is_done(&self) -> bool {
        self.progress.done && self.joining.is_none()
    }

    /// Why growth stopped early, in words.
    pub fn failure(&self) -> Option<&str> {
        self.progress.failure.as_deref()
    }

    pub fn pattern_hash(&self) -> Option<u64> {
        self.progress.pattern_hash
    }

    /// The hash of the whole mesh (edge included), once growth has ended.
    pub fn mesh_hash(&self) -> Option<u64> {
        self.progress.mesh_hash.filter(|_| self.is_done())
    }
}
