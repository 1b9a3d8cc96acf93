//! A branching form as a growing mesh: each step adds one segment of the [`BranchingTree`] —
//! a trunk and the knot after it — as a closed tube of its own, capped at both ends, so the
//! form is a set of closed, outward-facing solids at every stage and no step rewrites an
//! earlier one. Steps follow the tree's order, generation by generation, so every branch tip
//! grows at once.

use super::branching_tree::{Base, BranchingTree};
use crate::mesh::{Bounds, Capacity, Mesh, Surface, Vertex};
use crate::shape::{GrowingShape, LineGrid, ShapeError};
use crate::spec::form::branching::BranchingSpec;
use glam::DVec3;

/// A [`BranchingTree`] grown segment by segment.
pub struct BranchingMesh {
    tree: BranchingTree,
    sides: usize,
    rows_per_generation: f64,
    done: usize,
}

/// Vertices and indices of a segment: two bands of two rings each and two caps with a knot,
/// one band and two caps without.
fn segment_capacity(sides: usize, knot: bool) -> Capacity {
    let bands = 1 + usize::from(knot);
    Capacity {
        vertices: bands * 2 * (sides + 1) + 2 * (sides + 1),
        indices: bands * 6 * sides + 2 * 3 * sides,
    }
}

impl BranchingMesh {
    pub fn new(spec: &BranchingSpec, seed: u64, rows: usize) -> Result<Self, ShapeError> {
        let tree = BranchingTree::new(spec, seed)?;
        Ok(Self {
            rows_per_generation: (rows - 1) as f64 / tree.generations().max(1) as f64,
            sides: spec.trunk.sides as usize,
            tree,
            done: 0,
        })
    }

    /// The whole form's permanent mesh size, at most (no transient edge: every tube is
    /// closed).
    pub fn total_capacity(&self) -> Capacity {
        self.tree
            .segments
            .iter()
            .map(|s| segment_capacity(self.sides, s.next.is_some()))
            .fold(Capacity::default(), |a, b| Capacity {
                vertices: a.vertices + b.vertices,
                indices: a.indices + b.indices,
            })
    }

    /// A ring of vertices around `base`, normals pointing away from its centre.
    fn ring(&self, mesh: &mut Mesh, base: &Base, row: f64) -> u32 {
        let start = mesh.next_index();
        let points = base.ring(self.sides);
        for j in 0..=self.sides {
            let p = points[j % self.sides];
            let normal = (p - base.centre).normalize();
            let x = j as f64 / self.sides as f64;
            mesh.vertices
                .push(Vertex::new(p, normal, [x, row], Surface::Outer));
        }
        start
    }

    /// The side of a tube from base `a` to base `b`. Where a knot's bases touch at an apex
    /// (K), the quad there has collapsed to a triangle and only that triangle is kept.
    fn band(&self, mesh: &mut Mesh, (a, row_a): (&Base, f64), (b, row_b): (&Base, f64)) {
        let lo = self.ring(mesh, a, row_a);
        let hi = self.ring(mesh, b, row_b);
        let at = |mesh: &Mesh, i: u32| mesh.vertices[i as usize].position;
        for j in 0..self.sides as u32 {
            let (p, q, r, s) = (lo + j, lo + j + 1, hi + j + 1, hi + j);
            for t in [[p, q, r], [p, r, s]] {
                let [x, y, z] = t.map(|i| at(mesh, i));
                if x != y && y != z && z != x {
                    mesh.triangle(t, false);
                }
            }
        }
    }

    /// A flat cap over `base`, facing along its axis (`forwards`) or against it.
    fn cap(&self, mesh: &mut Mesh, base: &Base, row: f64, forwards: bool) {
        let facing = if forwards { base.axis() } else { -base.axis() };
        let c = mesh.next_index();
        mesh.vertices
            .push(Vertex::new(base.centre, facing, [0.5, row], Surface::Edge));
        for (j, p) in base.ring(self.sides).into_iter().enumerate() {
            let x = j as f64 / self.sides as f64;
            mesh.vertices
                .push(Vertex::new(p, facing, [x, row], Surface::Edge));
        }
        let n = self.sides as u32;
        for j in 0..n {
            mesh.triangle([c, c + 1 + j, c + 1 + (j + 1) % n], !forwards);
        }
    }
}

impl GrowingShape for BranchingMesh {
    fn steps(&self) -> usize {
        self.tree.segments.len()
    }

    fn steps_done(&self) -> usize {
        self.done
    }

    fn capacity(&self) -> Capacity {
        self.total_capacity()
    }

    fn edge_capacity(&self) -> Capacity {
        Capacity::default()
    }

    fn bounds(&self) -> Bounds {
        let mut bounds = Bounds::EMPTY;
        for s in &self.tree.segments {
            for base in [s.base, s.base.lifted(s.height)].iter().chain(&s.next) {
                for p in base.ring(self.sides) {
                    bounds.include(p);
                }
            }
        }
        bounds
    }

    /// The tubes' edges: side j of n at x = j / n, and the bases, which lie half a
    /// generation apart (a trunk's bottom and top, then the knot's top).
    fn line_grid(&self) -> LineGrid {
        LineGrid {
            across: self.sides as f64,
            rows: self.rows_per_generation / 2.0,
        }
    }

    fn front(&self) -> DVec3 {
        DVec3::NEG_Y
    }

    fn grow(&mut self, mesh: &mut Mesh, _edge: &mut Mesh) -> bool {
        let Some(segment) = self.tree.segments.get(self.done) else {
            return false;
        };
        let row = |level: f64| (segment.generation as f64 + level) * self.rows_per_generation;
        let top = segment.base.lifted(segment.height);
        self.cap(mesh, &segment.base, row(0.0), false);
        self.band(mesh, (&segment.base, row(0.0)), (&top, row(0.5)));
        match &segment.next {
            Some(next) => {
                self.band(mesh, (&top, row(0.5)), (next, row(1.0)));
                self.cap(mesh, next, row(1.0), true);
            }
            None => self.cap(mesh, &top, row(0.5), true),
        }
        self.done += 1;
        false
    }
}
