//! A branching form as a growing mesh in which every branch is one closed tube, from the base
//! where it leaves its parent (inside the parent's knot: bodies may overlap, as slicers expect,
//! but no face coincides with another) to its tip. Each step adds one segment of the
//! [`BranchingTree`] — a trunk and the knot after it — to the tube of its branch: the bands
//! from the branch's last ring to the trunk's top base and on across the knot, the base's cap
//! where a branch starts, the tip's cap where it ends. A branch still growing is closed by a
//! cap over its last ring in the transient edge mesh, one slot of a cap per open branch, which
//! a step rewrites in place (or adds, or swaps out when the branch ends), so a step costs what
//! it adds whatever the number of branches. The form is a set of closed, outward-facing
//! tubes, one per branch, at every stage. Steps follow the tree's order, generation by
//! generation, so every branch tip grows at once.
//!
//! The look: `faceted` gives every facet its own normal, creased at each knot, as Kawaguchi's
//! polyhedral trunks; `smooth` shares each ring between the bands on either side and averages
//! across them, so a tube bends smoothly through its knots.

use super::branching_tree::{Base, BranchingTree, Segment};
use crate::forms::kawaguchi::facet::Facet;
use crate::mesh::{Bounds, Capacity, Mesh, Surface, Vertex};
use crate::shape::{GrowingShape, LineGrid, ShapeError};
use crate::spec::form::branching::BranchingSpec;
use crate::spec::form::chambers::Look;
use glam::DVec3;

/// Below this distance (relative to the trunk's diameter) an apex of the ring after a knot is
/// taken to be the apex of the top base it lies on: the point K where the knot's bases touch.
const TOUCHING: f64 = 1e-6;

/// One ring of a tube: its apexes, the first of its vertices when it is shared by the bands
/// on either side (smooth look), and its pattern row.
#[derive(Clone, Debug)]
struct Ring {
    points: Vec<DVec3>,
    start: u32,
    row: f64,
}

/// A branch whose tip is still growing: its last segment and last ring. Its cap is slot
/// `i` of the edge mesh, where `i` is its place in [`BranchingMesh::open`].
#[derive(Clone, Debug)]
struct OpenTip {
    segment: usize,
    ring: Ring,
}

/// A [`BranchingTree`] grown segment by segment.
pub struct BranchingMesh {
    tree: BranchingTree,
    sides: usize,
    look: Look,
    slenderness: f64,
    rows_per_generation: f64,
    /// The branches whose tip is open, in the order of their caps in the edge mesh.
    open: Vec<OpenTip>,
    /// For each segment grown whose branch goes on, its place in `open`.
    slot_of: Vec<usize>,
    capacity: Capacity,
    edge_capacity: Capacity,
    done: usize,
}

impl BranchingMesh {
    pub fn new(spec: &BranchingSpec, seed: u64, rows: usize) -> Result<Self, ShapeError> {
        let tree = BranchingTree::new(spec, seed)?;
        let sides = spec.trunk.sides as usize;
        let (capacity, edge_capacity) = capacities(&tree.segments, sides, spec.look);
        Ok(Self {
            rows_per_generation: (rows - 1) as f64 / tree.generations().max(1) as f64,
            sides,
            look: spec.look,
            slenderness: spec.trunk.slenderness,
            open: Vec::new(),
            slot_of: vec![usize::MAX; tree.segments.len()],
            tree,
            capacity,
            edge_capacity,
            done: 0,
        })
    }

    /// The whole form's permanent mesh size (the edge is empty once every branch has ended).
    pub fn total_capacity(&self) -> Capacity {
        self.capacity
    }

    /// The apexes of `base`; where `touching` gives the top base before a knot, an apex that
    /// lies on the same apex of it (K, where the knot's bases touch) is made that very point,
    /// so that the two weld and the quad between them becomes a triangle.
    fn ring_points(&self, base: &Base, touching: Option<&[DVec3]>) -> Vec<DVec3> {
        let mut points = base.ring(self.sides);
        if let Some(before) = touching {
            for (p, q) in points.iter_mut().zip(before) {
                let close = (*p - *q).length() < TOUCHING * base.diameter;
                if close || p.as_vec3() == q.as_vec3() {
                    *p = *q;
                }
            }
        }
        points
    }

    /// The normal at apex j of `ring`, from the rings on either side: around the ring × along
    /// the tube, which faces outwards for rings counter-clockwise about the axis.
    fn smooth_normal(below: &[DVec3], ring: &[DVec3], above: &[DVec3], j: usize) -> DVec3 {
        let n = ring.len();
        let around = ring[(j + 1) % n] - ring[(j + n - 1) % n];
        around.cross(above[j] - below[j]).normalize_or_zero()
    }

    /// Adds `points` as a ring of shared vertices (smooth look) with normals from the rings
    /// `below` and `above`; in the faceted look a band makes its own vertices and the ring
    /// adds none.
    fn ring(
        &self,
        mesh: &mut Mesh,
        points: Vec<DVec3>,
        row: f64,
        [below, above]: [&[DVec3]; 2],
    ) -> Ring {
        let start = mesh.next_index();
        if self.look == Look::Smooth {
            for j in 0..=self.sides {
                let normal = Self::smooth_normal(below, &points, above, j % self.sides);
                let x = j as f64 / self.sides as f64;
                mesh.vertices.push(Vertex::new(
                    points[j % self.sides],
                    normal,
                    [x, row],
                    Surface::Outer,
                ));
            }
        }
        Ring { points, start, row }
    }

    /// The side of a tube from ring `a` up to ring `b`. Where the two touch (at K), the quad
    /// there has collapsed to a triangle and only that triangle is kept.
    fn band(&self, mesh: &mut Mesh, a: &Ring, b: &Ring) {
        for j in 0..self.sides {
            let facet = Facet::new([&a.points, &b.points], [a.row, b.row], j);
            let indices = match self.look {
                Look::Smooth => {
                    let (j, k) = (j as u32, j as u32 + 1);
                    [a.start + j, a.start + k, b.start + k, b.start + j]
                }
                Look::Faceted => {
                    let normal = facet.face.normalize_or_zero();
                    let base = mesh.next_index();
                    for (p, at) in facet.corners.into_iter().zip(facet.pattern) {
                        mesh.vertices
                            .push(Vertex::new(p, normal, at, Surface::Outer));
                    }
                    [base, base + 1, base + 2, base + 3]
                }
            };
            for t in [[0, 1, 2], [0, 2, 3]] {
                let [p, q, r] = t.map(|i| facet.corners[i]);
                if p != q && q != r && r != p {
                    mesh.triangle(t.map(|i| indices[i]), false);
                }
            }
        }
    }

    /// A flat cap over `ring` (of `base`), facing along the base's axis (`forwards`) or
    /// against it: a fan from its first apex, with no vertex at its centre, since several
    /// branches may start from the same centre and must not share a point.
    fn cap(&self, mesh: &mut Mesh, base: &Base, ring: &Ring, forwards: bool) {
        let c = mesh.next_index();
        mesh.vertices
            .extend(cap_vertices(base, ring, forwards, self.sides));
        for j in 1..self.sides as u32 - 1 {
            mesh.triangle([c, c + j, c + j + 1], !forwards);
        }
    }

    /// Writes the cap over an open tip's last ring into slot `slot` of the edge mesh, which is
    /// either taken (its triangles stay) or the next one.
    fn edge_cap(&self, edge: &mut Mesh, slot: usize, base: &Base, ring: &Ring) {
        let per = cap_size(self.sides).vertices;
        if slot * per == edge.vertices.len() {
            self.cap(edge, base, ring, true);
        } else {
            let vertices = cap_vertices(base, ring, true, self.sides);
            for (v, new) in edge.vertices[slot * per..].iter_mut().zip(vertices) {
                *v = new;
            }
        }
    }

    /// Makes `edge` the caps of the open branches if it is not (a caller that handed in
    /// another mesh than the one the last step left), and says whether it had to.
    fn restore_edge(&self, edge: &mut Mesh) -> bool {
        let (cap, open) = (cap_size(self.sides), self.open.len());
        if edge.vertices.len() == open * cap.vertices && edge.indices.len() == open * cap.indices {
            return false;
        }
        edge.clear();
        for tip in &self.open {
            let next = self.tree.segments[tip.segment]
                .next
                .expect("an open branch goes on");
            self.cap(edge, &next, &tip.ring, true);
        }
        true
    }

    /// Removes the edge cap of slot `slot`: the last slot's cap takes its place.
    fn close_slot(&mut self, edge: &mut Mesh, slot: usize) {
        let cap = cap_size(self.sides);
        let last = self.open.len() - 1;
        let per = cap.vertices;
        edge.vertices
            .copy_within(last * per..(last + 1) * per, slot * per);
        edge.vertices.truncate(last * per);
        edge.indices.truncate(last * cap.indices);
        self.open.swap_remove(slot);
        if let Some(moved) = self.open.get(slot) {
            self.slot_of[moved.segment] = slot;
        }
    }

    /// The row of a ring at `level` (0: the trunk's base, ½ its top, 1 the knot's end) of
    /// `segment`.
    fn row(&self, segment: &Segment, level: f64) -> f64 {
        (segment.generation as f64 + level) * self.rows_per_generation
    }
}

/// The vertices of a cap over `ring`: its apexes, all with the base's axis (or its opposite)
/// as their normal.
fn cap_vertices<'a>(
    base: &Base,
    ring: &'a Ring,
    forwards: bool,
    sides: usize,
) -> impl Iterator<Item = Vertex> + 'a {
    let facing = if forwards { base.axis() } else { -base.axis() };
    ring.points.iter().enumerate().map(move |(j, &p)| {
        Vertex::new(
            p,
            facing,
            [j as f64 / sides as f64, ring.row],
            Surface::Edge,
        )
    })
}

/// The size of one cap: an apex a vertex, a fan of N − 2 triangles.
fn cap_size(sides: usize) -> Capacity {
    Capacity {
        vertices: sides,
        indices: 3 * (sides - 2),
    }
}

/// Sizes of the permanent mesh when fully grown, and the most the edge mesh ever holds (one
/// cap per branch growing at once).
fn capacities(segments: &[Segment], sides: usize, look: Look) -> (Capacity, Capacity) {
    let ring = sides + 1;
    let cap = cap_size(sides);
    let (mut vertices, mut indices) = (0, 0);
    let (mut open, mut most_open) = (0usize, 0usize);
    for s in segments {
        let first = s.previous.is_none();
        let knot = s.next.is_some();
        let bands = 1 + usize::from(knot);
        let rings = usize::from(first) + 1 + usize::from(knot);
        let caps = usize::from(first) + usize::from(!knot);
        vertices += caps * cap.vertices
            + match look {
                Look::Smooth => rings * ring,
                Look::Faceted => bands * 4 * sides,
            };
        indices += caps * cap.indices + bands * 6 * sides;
        match (first, knot) {
            (true, true) => open += 1,
            (false, false) => open -= 1,
            _ => {}
        }
        most_open = most_open.max(open);
    }
    let edge = Capacity {
        vertices: most_open * cap.vertices,
        indices: most_open * cap.indices,
    };
    (Capacity { vertices, indices }, edge)
}

impl GrowingShape for BranchingMesh {
    fn steps(&self) -> usize {
        self.tree.segments.len()
    }

    fn steps_done(&self) -> usize {
        self.done
    }

    fn capacity(&self) -> Capacity {
        self.capacity
    }

    fn edge_capacity(&self) -> Capacity {
        self.edge_capacity
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

    /// None: every branch has its own edge, and each narrows as it grows.
    fn rim_length(&self, _row: usize) -> Option<f64> {
        None
    }

    fn front(&self) -> DVec3 {
        DVec3::NEG_Y
    }

    /// Adds the next segment to its branch's tube. `edge` must hold what the previous step
    /// left in it: the caps of the open branches, which this step changes in place.
    fn grow(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> bool {
        let k = self.done;
        let Some(segment) = self.tree.segments.get(k).cloned() else {
            return false;
        };
        let edge_changes =
            self.restore_edge(edge) || segment.previous.is_some() || segment.next.is_some();
        let top = segment.base.lifted(segment.height);
        let top_points = top.ring(self.sides);
        let next_points = segment
            .next
            .map(|next| self.ring_points(&next, Some(&top_points)));
        // The branch's last ring: the previous segment's knot end, or a new base.
        let (below, slot) = match segment.previous {
            Some(previous) => {
                let slot = self.slot_of[previous];
                (self.open[slot].ring.clone(), Some(slot))
            }
            None => {
                let points = self.ring_points(&segment.base, None);
                let ring = self.ring(
                    mesh,
                    points.clone(),
                    self.row(&segment, 0.0),
                    [&points, &top_points],
                );
                self.cap(mesh, &segment.base, &ring, false);
                (ring, None)
            }
        };
        let above = next_points.as_deref().unwrap_or(&top_points);
        let top_ring = self.ring(
            mesh,
            top_points.clone(),
            self.row(&segment, 0.5),
            [&below.points, above],
        );
        self.band(mesh, &below, &top_ring);
        match (segment.next, next_points) {
            (Some(next), Some(points)) => {
                // The next trunk's top, for the normals of the ring it starts from.
                let next_top = next
                    .lifted(self.slenderness * next.diameter)
                    .ring(self.sides);
                let ring = self.ring(
                    mesh,
                    points,
                    self.row(&segment, 1.0),
                    [&top_points, &next_top],
                );
                self.band(mesh, &top_ring, &ring);
                let slot = slot.unwrap_or(self.open.len());
                self.edge_cap(edge, slot, &next, &ring);
                let tip = OpenTip { segment: k, ring };
                match self.open.get_mut(slot) {
                    Some(open) => *open = tip,
                    None => self.open.push(tip),
                }
                self.slot_of[k] = slot;
            }
            _ => {
                self.cap(mesh, &top, &top_ring, true);
                if let Some(slot) = slot {
                    self.close_slot(edge, slot);
                }
            }
        }
        self.done += 1;
        edge_changes
    }
}
