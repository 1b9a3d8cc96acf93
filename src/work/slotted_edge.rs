//! The transient edge mesh as the page holds it: each part of the shape's edge
//! ([`crate::shape::EdgePart`]) in a slot of one mesh, with room to spare between slots whose
//! indices are all 0 (degenerate triangles, drawn as nothing). A part that a growth step
//! changes is rewritten in its own slot and nothing else moves, so that a reply carries, and
//! the GPU takes, only the parts that changed: the refined Murex's edge is megabytes, a step
//! changes a few of its hundreds of parts. The host keeps the same copy to know what the page
//! holds ([`super::edge_slots`]); both change it only through [`SlottedEdge::apply`].

use crate::generator::EdgeRuns;
use crate::mesh::{Capacity, Mesh, Vertex};
use serde::{Deserialize, Serialize};
use std::ops::Range;

/// Where one part lies in the slotted mesh: its number, its vertices, its indices (which name
/// vertices of the slotted mesh).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Slot {
    pub id: u32,
    pub vertices: Range<u32>,
    pub indices: Range<u32>,
}

/// Vertices and indices written at their places in the slotted mesh.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EdgeRun {
    pub first_vertex: u32,
    #[serde(with = "crate::pod_bytes")]
    pub vertices: Vec<Vertex>,
    pub first_index: u32,
    #[serde(with = "crate::pod_bytes")]
    pub indices: Vec<u32>,
}

/// What turns the slotted edge the page holds into the next one.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EdgeWrites {
    /// The page drops what it holds first (a host's first edge, or slots laid out anew): the
    /// runs then cover all of the new edge.
    pub fresh: bool,
    /// The slotted mesh's vertices and indices, gaps included.
    pub vertex_count: u32,
    pub index_count: u32,
    /// Every part's slot, in the order of the parts' numbers.
    pub slots: Vec<Slot>,
    pub runs: Vec<EdgeRun>,
}

/// The edge as the page holds it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SlottedEdge {
    mesh: Mesh,
    slots: Vec<Slot>,
}

impl SlottedEdge {
    /// The slotted mesh, gaps included: what the GPU draws.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// Every part's slot, in the order of the parts' numbers.
    pub fn slots(&self) -> &[Slot] {
        &self.slots
    }

    /// Whether no part is held.
    pub fn is_empty(&self) -> bool {
        self.slots.is_empty()
    }

    /// Takes the room `capacity` at once (see [`Mesh::reserve_total`]).
    pub fn reserve_total(&mut self, capacity: Capacity) {
        self.mesh.reserve_total(capacity);
    }

    /// Vertices of the parts, gaps left out.
    pub fn vertex_count(&self) -> usize {
        (self.slots.iter())
            .map(|s| (s.vertices.end - s.vertices.start) as usize)
            .sum()
    }

    /// Triangles of the parts.
    pub fn triangle_count(&self) -> usize {
        (self.slots.iter())
            .map(|s| (s.indices.end - s.indices.start) as usize / 3)
            .sum()
    }

    /// The parts joined in the order of their numbers, gaps left out: the shape's own edge,
    /// bit for bit.
    pub fn joined(&self) -> Mesh {
        let mut joined = Mesh::default();
        joined.reserve_total(Capacity {
            vertices: self.vertex_count(),
            indices: self.triangle_count() * 3,
        });
        for slot in &self.slots {
            let base = joined.vertices.len() as u32;
            joined
                .vertices
                .extend_from_slice(&self.mesh.vertices[range(&slot.vertices)]);
            joined.indices.extend(
                self.mesh.indices[range(&slot.indices)]
                    .iter()
                    .map(|i| i - slot.vertices.start + base),
            );
        }
        joined
    }

    /// Takes in `writes` (whose runs and slots lie within its counts, as
    /// [`super::message`] checks when it reads them); the ranges written, for the GPU.
    pub fn apply(&mut self, writes: &EdgeWrites) -> EdgeRuns {
        if writes.fresh {
            self.mesh.clear();
        }
        (self.mesh.vertices).resize(writes.vertex_count as usize, Vertex::default());
        (self.mesh.indices).resize(writes.index_count as usize, 0);
        let mut runs = EdgeRuns::default();
        for run in &writes.runs {
            let vertices =
                run.first_vertex as usize..run.first_vertex as usize + run.vertices.len();
            let indices = run.first_index as usize..run.first_index as usize + run.indices.len();
            self.mesh.vertices[vertices.clone()].copy_from_slice(&run.vertices);
            self.mesh.indices[indices.clone()].copy_from_slice(&run.indices);
            if !vertices.is_empty() {
                runs.vertices.push(vertices);
            }
            if !indices.is_empty() {
                runs.indices.push(indices);
            }
        }
        self.slots.clone_from(&writes.slots);
        runs
    }
}

/// A slot's range as indices into the mesh's arrays.
pub(crate) fn range(r: &Range<u32>) -> Range<usize> {
    r.start as usize..r.end as usize
}
