//! Kawaguchi's chamber stack as a growing mesh: the first step lays the apex base (nothing to
//! show yet), and every later step adds one chamber, its sides joined to the ring below band by
//! band, and moves the cap that closes the mouth (the transient edge mesh). The result is one closed
//! solid, outward-facing, whatever the look, handedness or position of the top base.
//!
//! A walled stack is hollow, as a cephalopod's shell is: each chamber holds a cavity, its side
//! the chamber's drawn in by the wall, and a septum as thick as the wall parts it from the
//! next. A siphuncle pierces every septum, so the cavities join one another and the last,
//! which opens at the mouth: the solid stays one closed surface (one body, no voids a printer
//! would have to guess at), and the mouth shows the last septum inside. The edge mesh is then
//! the top of the last cavity and the lip around it.
//!
//! The pigmentation paints it as it paints a sweep: a chamber stack is a sweep of N-gon rims,
//! so apex j sits at position j/N along the growing edge and chamber c spans the rows from
//! c·ρ to (c + 1)·ρ, ρ = (rows − 1)/chambers. A pattern with as many cells as apexes and one
//! row more than chambers gives each facet a cell of its own.

use super::chamber_stack::{ChamberStack, RingKind, SIPHUNCLE};
use crate::forms::kawaguchi::facet::Facet;
use crate::mesh::{Bounds, Capacity, Mesh, Surface, Vertex};
use crate::shape::{GrowingShape, LineGrid, ShapeError};
use crate::spec::form::chambers::{ChambersSpec, Look};
use glam::{DAffine3, DVec3};

/// One ring as grown: its apexes (shell space, before mirroring), the direction of growth
/// through it, and its pattern row.
struct Ring {
    points: Vec<DVec3>,
    growth: DVec3,
    row: f64,
}

/// A [`ChamberStack`] grown chamber by chamber.
pub struct ChamberMesh {
    stack: ChamberStack,
    look: Look,
    capacity: (Capacity, Capacity),
    rows_per_chamber: f64,
    /// Whether quads taken as (ring below j, j + 1; ring above j + 1, j) face inwards.
    inward: bool,
    /// The frame of the next chamber to grow.
    frame: DAffine3,
    /// The frame of the last chamber grown, whose cavity a hollow stack's next septum closes.
    grown: Option<DAffine3>,
    /// The last ring grown and the one before it (smooth normals look across them).
    last: Option<Ring>,
    before_last: Option<Ring>,
    done: usize,
}

/// Sizes of the fully grown mesh of `spec`: the permanent mesh (chamber sides and the apex
/// cap) and the mouth cap. Validation checks the same count against the vertex cap.
pub fn mesh_capacity(spec: &ChambersSpec) -> (Capacity, Capacity) {
    let n = spec.mouth.apexes as usize;
    let chambers = spec.chambers as usize;
    let rings = chambers * (1 + usize::from(spec.septa)) + 1;
    let bands = rings.saturating_sub(1);
    let band_vertices = match spec.look {
        Look::Faceted => 4 * n,
        Look::Smooth => 2 * (n + 1),
    };
    let cap = Capacity {
        vertices: n + 1,
        indices: 3 * n,
    };
    let band = Capacity {
        vertices: band_vertices,
        indices: 6 * n,
    };
    let annulus = Capacity {
        vertices: 4 * n,
        indices: 6 * n,
    };
    let sum = |parts: &[(usize, Capacity)]| Capacity {
        vertices: parts.iter().map(|(k, c)| k * c.vertices).sum(),
        indices: parts.iter().map(|(k, c)| k * c.indices).sum(),
    };
    if spec.wall > 0.0 {
        // Besides the outside: each chamber's cavity side, the first cavity's floor, and
        // every later septum's two faces with the siphuncle between them. The mouth: the
        // last cavity's top and the lip.
        let septa = chambers.saturating_sub(1);
        let sides = sum(&[
            (bands + chambers + septa, band),
            (2, cap),
            (2 * septa, annulus),
        ]);
        (sides, sum(&[(1, band), (1, annulus)]))
    } else {
        (sum(&[(bands, band), (1, cap)]), cap)
    }
}

impl ChamberMesh {
    pub fn new(spec: &ChambersSpec, rows: usize) -> Result<Self, ShapeError> {
        let stack = ChamberStack::new(spec)?;
        let first = stack.first_frame();
        let (bottom, top) = (
            stack.ring(&first, RingKind::Bottom),
            stack.ring(&first, RingKind::Top),
        );
        let centre = bottom.iter().sum::<DVec3>() / bottom.len() as f64;
        let outward: f64 = (0..bottom.len())
            .map(|j| {
                let next = bottom[(j + 1) % bottom.len()];
                (next - bottom[j])
                    .cross(top[j] - bottom[j])
                    .dot(bottom[j] - centre)
            })
            .sum();
        Ok(Self {
            rows_per_chamber: (rows - 1) as f64 / stack.chambers() as f64,
            look: spec.look,
            capacity: mesh_capacity(spec),
            inward: outward < 0.0,
            frame: first,
            grown: None,
            stack,
            last: None,
            before_last: None,
            done: 0,
        })
    }

    fn vertex(&self, p: DVec3, n: DVec3, x: f64, row: f64, surface: Surface) -> Vertex {
        Vertex::new(
            self.stack.handedness().mirror(p),
            self.stack.handedness().mirror(n),
            [x, row],
            surface,
        )
    }

    fn ring(&self, frame: &DAffine3, chamber: usize, kind: RingKind) -> Ring {
        Ring {
            points: self.stack.ring(frame, kind),
            growth: self.stack.growth_direction(frame, kind),
            row: (chamber as f64 + ChamberStack::level(kind)) * self.rows_per_chamber,
        }
    }

    /// A ring of chamber `chamber`'s cavity at `level` of its width, drawn in further by
    /// `scale` (see [`ChamberStack::cavity_ring`]).
    fn cavity_ring(&self, frame: &DAffine3, chamber: usize, level: f64, scale: f64) -> Ring {
        Ring {
            points: self.stack.cavity_ring(frame, level, scale),
            growth: self.stack.growth_direction(frame, RingKind::Bottom),
            row: (chamber as f64 + level) * self.rows_per_chamber,
        }
    }

    /// Normal of the surface at apex j of `ring`, from the rings on either side (itself at the
    /// ends of the stack): around the ring × along the growth, turned away from the material
    /// (outwards, or into the cavity when `cavity`).
    fn smooth_normal(&self, [below, ring, above]: [&Ring; 3], j: usize, cavity: bool) -> DVec3 {
        let n = ring.points.len();
        let around = ring.points[(j + 1) % n] - ring.points[(j + n - 1) % n];
        let along = above.points[j] - below.points[j];
        let normal = around.cross(along).normalize_or_zero();
        if self.inward != cavity {
            -normal
        } else {
            normal
        }
    }

    /// The band of quads from ring `a` up to ring `b`, given the ring before `a` and the one
    /// after `b` (each the ring itself at an end of the stack), facing outwards, or into the
    /// stack's axis when it is the side of a `cavity` (or of the siphuncle).
    fn band(
        &self,
        mesh: &mut Mesh,
        [below_a, a, b, above_b]: [&Ring; 4],
        surface: Surface,
        cavity: bool,
    ) {
        let n = a.points.len();
        let inward = self.inward != cavity;
        // Mirroring reverses the winding once more.
        let flip = inward != self.stack.handedness().is_sinistral();
        let x = |j: usize| j as f64 / n as f64;
        match self.look {
            Look::Faceted => {
                for j in 0..n {
                    let facet = Facet::new([&a.points, &b.points], [a.row, b.row], j);
                    let face = facet.face;
                    let normal = if inward { -face } else { face }.normalize_or_zero();
                    let base = mesh.next_index();
                    for (p, [u, row]) in facet.corners.into_iter().zip(facet.pattern) {
                        mesh.vertices.push(self.vertex(p, normal, u, row, surface));
                    }
                    mesh.quad([base, base + 1, base + 2, base + 3], flip);
                }
            }
            Look::Smooth => {
                let mut starts = [0u32; 2];
                for (start, (ring, below, above)) in
                    starts.iter_mut().zip([(a, below_a, b), (b, a, above_b)])
                {
                    *start = mesh.next_index();
                    for j in 0..=n {
                        let normal = self.smooth_normal([below, ring, above], j % n, cavity);
                        let p = ring.points[j % n];
                        mesh.vertices
                            .push(self.vertex(p, normal, x(j), ring.row, surface));
                    }
                }
                let [lo, hi] = starts;
                for j in 0..n as u32 {
                    mesh.quad([lo + j, lo + j + 1, hi + j + 1, hi + j], flip);
                }
            }
        }
    }

    /// A flat cap over `ring` facing along `facing`: the apex (backwards), the mouth, or the
    /// first cavity's floor.
    fn cap(&self, mesh: &mut Mesh, ring: &Ring, facing: DVec3, surface: Surface) {
        let n = ring.points.len();
        let centre = ring.points.iter().sum::<DVec3>() / n as f64;
        let c = mesh.next_index();
        mesh.vertices
            .push(self.vertex(centre, facing, 0.5, ring.row, surface));
        for (j, &p) in ring.points.iter().enumerate() {
            let x = j as f64 / n as f64;
            mesh.vertices
                .push(self.vertex(p, facing, x, ring.row, surface));
        }
        let area: DVec3 = (0..n)
            .map(|j| (ring.points[j] - centre).cross(ring.points[(j + 1) % n] - centre))
            .sum();
        let flip = (area.dot(facing) < 0.0) != self.stack.handedness().is_sinistral();
        for j in 0..n as u32 {
            mesh.triangle([c, c + 1 + j, c + 1 + (j + 1) % n as u32], flip);
        }
    }

    /// A flat ring of quads from `outer` in to `inner` (a ring in the same plane, drawn in
    /// towards its centre), each facing along `facing`: a septum's face around the siphuncle,
    /// or the lip around the open mouth.
    fn annulus(
        &self,
        mesh: &mut Mesh,
        [outer, inner]: [&Ring; 2],
        facing: DVec3,
        surface: Surface,
    ) {
        let n = outer.points.len();
        for j in 0..n {
            let facet = Facet::new([&outer.points, &inner.points], [outer.row, inner.row], j);
            let flip = (facet.face.dot(facing) < 0.0) != self.stack.handedness().is_sinistral();
            let base = mesh.next_index();
            for (p, [u, row]) in facet.corners.into_iter().zip(facet.pattern) {
                mesh.vertices.push(self.vertex(p, facing, u, row, surface));
            }
            mesh.quad([base, base + 1, base + 2, base + 3], flip);
        }
    }

    /// Chamber `c`'s cavity, whose frame is `frame`, up to where the septum above it will
    /// begin: the septum below it (the first cavity's floor, or the faces of the septum
    /// between it and the cavity of the chamber before, whose frame is `previous`, the
    /// siphuncle through them) and its side.
    fn hollow_chamber(
        &self,
        mesh: &mut Mesh,
        previous: Option<&DAffine3>,
        frame: &DAffine3,
        c: usize,
    ) {
        let s = self.stack.septum();
        let floor = self.cavity_ring(frame, c, s, 1.0);
        if let Some(previous) = previous {
            let roof = self.cavity_ring(previous, c - 1, 1.0 - s, 1.0);
            let roof_hole = self.cavity_ring(previous, c - 1, 1.0 - s, SIPHUNCLE);
            let floor_hole = self.cavity_ring(frame, c, s, SIPHUNCLE);
            self.annulus(mesh, [&roof, &roof_hole], -roof.growth, Surface::Inner);
            let tube = [&roof_hole, &roof_hole, &floor_hole, &floor_hole];
            self.band(mesh, tube, Surface::Inner, true);
            self.annulus(mesh, [&floor, &floor_hole], floor.growth, Surface::Inner);
        } else {
            self.cap(mesh, &floor, floor.growth, Surface::Inner);
        }
        let ceiling = self.cavity_ring(frame, c, 1.0 - s, 1.0);
        self.band(
            mesh,
            [&floor, &floor, &ceiling, &ceiling],
            Surface::Inner,
            true,
        );
    }

    /// The open mouth of a hollow stack whose last chamber's frame is `frame`: the top of the
    /// last cavity, and the lip from the top base in to it.
    fn open_mouth(&self, edge: &mut Mesh, frame: &DAffine3, c: usize) {
        let s = self.stack.septum();
        let ceiling = self.cavity_ring(frame, c, 1.0 - s, 1.0);
        let rim = self.cavity_ring(frame, c, 1.0, 1.0);
        self.band(edge, [&ceiling, &ceiling, &rim, &rim], Surface::Inner, true);
        let top = self.ring(frame, c, RingKind::Top);
        self.annulus(edge, [&top, &rim], top.growth, Surface::Edge);
    }

    /// Adds chamber `c`'s rings, each joined to the ring below by a band, and its cavity when
    /// the stack is hollow.
    fn grow_chamber(&mut self, mesh: &mut Mesh, c: usize) {
        let frame = self.frame;
        let next_frame = self.stack.next_frame(&frame);
        let kinds: Vec<RingKind> = self.stack.rings_above_bottom().collect();
        // Smooth normals at the last ring look at the next chamber's first ring.
        let smooth = self.look == Look::Smooth;
        let following = (smooth && c + 1 < self.stack.chambers()).then(|| {
            let kind = self
                .stack
                .rings_above_bottom()
                .next()
                .expect("a chamber has rings");
            self.ring(&next_frame, c + 1, kind)
        });
        let rings: Vec<Ring> = kinds.iter().map(|&k| self.ring(&frame, c, k)).collect();
        let mut rings = kinds.into_iter().zip(rings).peekable();
        while let Some((kind, ring)) = rings.next() {
            let below = self.last.take().expect("the apex ring is grown first");
            let surface = match kind {
                RingKind::Suture => Surface::Edge,
                _ => Surface::Outer,
            };
            {
                let below_below = self.before_last.as_ref().unwrap_or(&below);
                let above = rings
                    .peek()
                    .map(|(_, r)| r)
                    .or(following.as_ref())
                    .unwrap_or(&ring);
                self.band(mesh, [below_below, &below, &ring, above], surface, false);
            }
            self.before_last = Some(below);
            self.last = Some(ring);
        }
        let previous = self.grown.replace(frame);
        if self.stack.hollow() {
            self.hollow_chamber(mesh, previous.as_ref(), &frame, c);
        }
        self.frame = next_frame;
    }
}

impl GrowingShape for ChamberMesh {
    fn steps(&self) -> usize {
        self.stack.chambers() + 1
    }

    fn steps_done(&self) -> usize {
        self.done
    }

    fn capacity(&self) -> Capacity {
        self.capacity.0
    }

    fn edge_capacity(&self) -> Capacity {
        self.capacity.1
    }

    fn bounds(&self) -> Bounds {
        self.stack.bounds()
    }

    /// The chambers' edges: apex j of N at x = j / N, a base every chamber.
    fn line_grid(&self) -> LineGrid {
        LineGrid {
            across: self.stack.apexes() as f64,
            rows: self.rows_per_chamber,
        }
    }

    /// The mouth polygon's perimeter, grown by r every chamber (continuously between).
    fn rim_length(&self, row: usize) -> Option<f64> {
        let chambers = row as f64 / self.rows_per_chamber;
        Some(self.stack.perimeter() * self.stack.ratio().powf(chambers))
    }

    fn front(&self) -> DVec3 {
        let last = self.stack.frame(self.stack.chambers() - 1);
        self.stack
            .handedness()
            .mirror(self.stack.growth_direction(&last, RingKind::Top))
    }

    fn grow(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> bool {
        if self.done > self.stack.chambers() {
            return false;
        }
        edge.clear();
        if self.done == 0 {
            // The apex base alone has no volume: it is shown with the first chamber.
            self.last = Some(self.ring(&self.frame, 0, RingKind::Bottom));
        } else {
            if self.done == 1 {
                let apex = self.last.as_ref().expect("the apex ring is laid first");
                self.cap(mesh, apex, -apex.growth, Surface::Edge);
            }
            let (frame, c) = (self.frame, self.done - 1);
            self.grow_chamber(mesh, c);
            if self.stack.hollow() {
                self.open_mouth(edge, &frame, c);
            } else {
                let mouth = self.last.as_ref().expect("a ring is grown");
                self.cap(edge, mouth, mouth.growth, Surface::Edge);
            }
        }
        self.done += 1;
        true
    }
}
