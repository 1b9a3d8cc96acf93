//! The incremental generator: one spec in, new rims (and later new pattern rows) out, a few
//! at a time, on a growth clock measured in pattern rows. The cost of a call depends on the
//! rows it adds, never on the age of the shell.

use crate::growing_shape::{GrowingShape, shape_for};
use crate::mesh::{Bounds, Capacity, Mesh};
use crate::spec::ShellSpec;
use glam::DVec3;
use std::ops::Range;

/// What one call to [`Generator::advance`] added.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Advance {
    /// New vertices of the permanent mesh.
    pub vertices: Range<usize>,
    /// New indices of the permanent mesh.
    pub indices: Range<usize>,
    /// Whether the transient edge mesh was rewritten.
    pub edge_changed: bool,
    /// Pattern rows now grown, before and after.
    pub rows: Range<usize>,
}

/// A shell growing from its spec.
pub struct Generator {
    shape: Box<dyn GrowingShape>,
    mesh: Mesh,
    edge: Mesh,
    rows: usize,
    rows_done: usize,
}

/// Why a generator cannot be built from a spec.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BuildError(pub String);

impl std::fmt::Display for BuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl Generator {
    pub fn new(spec: &ShellSpec) -> Result<Self, BuildError> {
        let rows = spec.growth.rows.max(1) as usize;
        let shape = shape_for(&spec.form, rows).map_err(|e| BuildError(e.0))?;
        let mut generator = Self {
            mesh: Mesh::with_capacity(shape.capacity()),
            edge: Mesh::with_capacity(shape.edge_capacity()),
            shape,
            rows,
            rows_done: 0,
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

    pub fn is_done(&self) -> bool {
        self.rows_done >= self.rows && self.shape.steps_done() >= self.shape.steps()
    }

    /// Buffer sizes of the fully grown mesh and of the edge.
    pub fn capacity(&self) -> (Capacity, Capacity) {
        (self.shape.capacity(), self.shape.edge_capacity())
    }

    /// Bounds and viewing direction of the fully grown shell.
    pub fn framing(&self) -> (Bounds, DVec3) {
        (self.shape.bounds(), self.shape.front())
    }

    /// The permanent mesh grown so far.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The transient mesh closing the current growing edge.
    pub fn edge(&self) -> &Mesh {
        &self.edge
    }

    /// The shell as it stands, edge included: what an export writes.
    pub fn snapshot(&self) -> Mesh {
        let mut mesh = self.mesh.clone();
        mesh.append(&self.edge);
        mesh
    }

    /// Grows the shape up to the step that the current row has reached.
    fn grow_shape(&mut self) -> bool {
        let steps = self.shape.steps();
        let target = if steps <= 1 {
            steps
        } else {
            (self.rows_done * (steps - 1) / self.rows + 1).min(steps)
        };
        let mut changed = false;
        while self.shape.steps_done() < target {
            self.shape.grow(&mut self.mesh, &mut self.edge);
            changed = true;
        }
        changed
    }

    /// Grows by up to `rows` pattern rows.
    pub fn advance(&mut self, rows: usize) -> Advance {
        let (v0, i0, r0) = (
            self.mesh.vertices.len(),
            self.mesh.indices.len(),
            self.rows_done,
        );
        self.rows_done = (self.rows_done + rows).min(self.rows);
        let edge_changed = self.grow_shape();
        Advance {
            vertices: v0..self.mesh.vertices.len(),
            indices: i0..self.mesh.indices.len(),
            edge_changed,
            rows: r0..self.rows_done,
        }
    }

    /// Everything grown so far, as one advance: what a fresh upload must write.
    pub fn grown(&self) -> Advance {
        Advance {
            vertices: 0..self.mesh.vertices.len(),
            indices: 0..self.mesh.indices.len(),
            edge_changed: true,
            rows: 0..self.rows_done,
        }
    }

    /// Grows to the end.
    pub fn finish(&mut self) {
        self.advance(self.rows);
    }
}
