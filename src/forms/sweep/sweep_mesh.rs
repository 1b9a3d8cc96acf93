//! The swept surface as a growing mesh (Fowler et al. 1992, §2.4): each step adds one rim of
//! n + 1 points and the band of quads joining it to the previous rim.
//!
//! With a wall thickness the shell is a closed solid: an inner surface under the outer one,
//! joined by a lip strip at the growing edge (rewritten each step), by caps at the apex, and for
//! an open generating curve by side strips along its two ends. A closed curve repeats its first
//! point as its last (the same position, bit for bit) so that the pattern coordinate can run
//! from 0 to 1 while the solid stays watertight.

use super::drawn_size::{RimThinning, half_pixel, points_per_rim};
use super::helico_spiral::SpiralWalk;
use super::surface::{Rim, Sweep};
use crate::mesh::{Bounds, Capacity, Mesh, Surface, Vertex};
use crate::shape::{GrowingShape, LineGrid, ShapeError};
use crate::spec::form::sweep::SweepSpec;
use glam::DVec3;
use std::f64::consts::TAU;

/// Where the previous rim's vertices start in the mesh.
#[derive(Clone, Copy, Debug)]
struct RimBase {
    outer: u32,
    inner: u32,
    sides: u32,
}

/// A [`Sweep`] grown rim by rim.
pub struct SweepMesh {
    sweep: Sweep,
    walk: SpiralWalk,
    scale: f64,
    done: usize,
    rows_per_rim: f64,
    previous: Option<RimBase>,
    /// In a picture, which of the full mesh's rims it keeps (see [`super::drawn_size`]).
    thinning: Option<RimThinning>,
    /// In a picture, the spec's own surface with all its points per rim: the rims' lengths,
    /// which a pattern on a growing edge follows, are measured on it, so that the picture
    /// shows the shell's own pattern.
    measured: Option<Sweep>,
}

impl SweepMesh {
    pub fn new(spec: &SweepSpec, rows: usize) -> Result<Self, ShapeError> {
        let sweep = Sweep::new(spec)?;
        let [lr, lz, _] = sweep.lambda();
        let walk = SpiralWalk::new(spec.spiral.r0, spec.spiral.z0, lr, lz, sweep.step());
        let rows_per_rim = (rows - 1) as f64 / (sweep.rims() - 1) as f64;
        Ok(Self {
            sweep,
            walk,
            scale: 1.0,
            done: 0,
            rows_per_rim,
            previous: None,
            thinning: None,
            measured: None,
        })
    }

    /// The mesh of a picture `pixels` wide: of the full mesh's rims those that keep it
    /// within half a pixel, with as few points per rim as keep it so ([`super::drawn_size`]).
    pub fn drawn_at(spec: &SweepSpec, rows: usize, pixels: u32) -> Result<Self, ShapeError> {
        let full = Self::new(spec, rows)?;
        let tolerance = half_pixel(full.bounds().radius(), pixels);
        let mut coarse = spec.clone();
        coarse.curve.segments = points_per_rim(spec, &full.sweep, tolerance)?;
        Ok(Self {
            thinning: Some(RimThinning::new(tolerance)),
            measured: Some(full.sweep),
            ..Self::new(&coarse, rows)?
        })
    }

    /// Pushes the vertices of `rim` (outer ring, inner ring, side points) to `mesh`.
    fn rings(&self, mesh: &mut Mesh, rim: &Rim) -> RimBase {
        let wall = self.sweep.has_wall();
        RimBase {
            outer: self.push_ring(mesh, Self::outer(rim), rim, Surface::Outer),
            inner: if wall {
                self.push_ring(mesh, Self::inner(rim), rim, Surface::Inner)
            } else {
                0
            },
            sides: if wall && !self.sweep.is_closed() {
                self.push_sides(mesh, rim)
            } else {
                0
            },
        }
    }

    /// The band of quads joining two rims' vertices in `mesh` (`count` points a ring): the
    /// outer surface, the inner one, and an open curve's sides.
    fn stitch(&self, mesh: &mut Mesh, prev: RimBase, base: RimBase, count: u32) {
        let wall = self.sweep.has_wall();
        let (outer_flip, inner_flip) = (self.flip(true), self.flip(false));
        for j in 0..count - 1 {
            let (a, b) = (prev.outer + j, base.outer + j);
            mesh.quad([a, a + 1, b + 1, b], outer_flip);
            if wall {
                let (a, b) = (prev.inner + j, base.inner + j);
                mesh.quad([a, a + 1, b + 1, b], inner_flip);
            }
        }
        if wall && !self.sweep.is_closed() {
            // Start side (facing −s) then end side (facing +s).
            for (k, outwards) in [(0, true), (2, false)] {
                let (a, b) = (prev.sides + k, base.sides + k);
                mesh.quad([a, b, b + 1, a + 1], self.flip(outwards));
            }
        }
    }

    /// Adds `rim` to the mesh, joined to the rim added before it, and closes the growing edge
    /// there.
    fn add(&mut self, mesh: &mut Mesh, edge: &mut Mesh, rim: &Rim) {
        let wall = self.sweep.has_wall();
        let base = self.rings(mesh, rim);
        match self.previous {
            None if self.sweep.is_closed() => {
                self.apex_caps(mesh, rim, base.outer, wall.then_some(base.inner));
            }
            None if wall => self.edge_band(mesh, rim, false),
            None => {}
            Some(prev) => self.stitch(mesh, prev, base, rim.points.len() as u32),
        }
        edge.clear();
        if wall {
            self.edge_band(edge, rim, true);
        }
        self.previous = Some(base);
    }

    /// A picture's growing edge while rims are held back: the band from the last rim kept to
    /// the newest rim, closed by the lip there, so that the shell as it stands reaches the
    /// rim it has grown to (the band passes within the tolerance of the rims between).
    fn open_band(&self, edge: &mut Mesh, kept: &Rim, newest: &Rim) {
        edge.clear();
        let from = self.rings(edge, kept);
        let to = self.rings(edge, newest);
        self.stitch(edge, from, to, newest.points.len() as u32);
        if self.sweep.has_wall() {
            self.edge_band(edge, newest, true);
        }
    }

    fn vertex(&self, p: DVec3, n: DVec3, j: usize, row: f64, surface: Surface) -> Vertex {
        Vertex::new(
            self.sweep.handedness().mirror(p),
            self.sweep.handedness().mirror(n),
            [self.sweep.edge_coordinate(j), row],
            surface,
        )
    }

    /// Whether triangles whose geometric normal is ∂P/∂s × ∂P/∂t-like must be reversed to face
    /// `outwards` (true) or inwards; mirroring reverses everything once more.
    fn flip(&self, outwards: bool) -> bool {
        ((self.sweep.orientation() < 0.0) == outwards) != self.sweep.handedness().is_sinistral()
    }

    /// Pushes a ring of rim points (outer or inner). On a closed curve the last point is
    /// sampled at s = 0 again (see [`Sweep`]), so the seam closes bit for bit.
    fn push_ring(
        &self,
        mesh: &mut Mesh,
        ring: impl Iterator<Item = (DVec3, DVec3)>,
        rim: &Rim,
        surface: Surface,
    ) -> u32 {
        let base = mesh.next_index();
        let row = rim.t / self.sweep.step() * self.rows_per_rim;
        for (j, (p, n)) in ring.enumerate() {
            mesh.vertices.push(self.vertex(p, n, j, row, surface));
        }
        base
    }

    fn outer(rim: &Rim) -> impl Iterator<Item = (DVec3, DVec3)> + '_ {
        rim.points.iter().map(|p| (p.position, p.normal))
    }

    fn inner(rim: &Rim) -> impl Iterator<Item = (DVec3, DVec3)> + '_ {
        (0..rim.points.len()).map(|j| (rim.inner(j), -rim.points[j].normal))
    }

    /// A strip of edge quads joining two rows of vertices a and b (each `count` long).
    fn strip(mesh: &mut Mesh, a: u32, b: u32, count: u32, flip: bool) {
        for j in 0..count - 1 {
            mesh.quad([a + j, a + j + 1, b + j + 1, b + j], flip);
        }
    }

    /// The lip (facing +t) or apex strip (facing −t) joining outer and inner rim points, with
    /// its own vertices so that it is shaded as a face of its own.
    fn edge_band(&self, mesh: &mut Mesh, rim: &Rim, forwards: bool) {
        let sign = if forwards { 1.0 } else { -1.0 };
        let row = rim.t / self.sweep.step() * self.rows_per_rim;
        let outer_base = mesh.next_index();
        for (j, p) in rim.points.iter().enumerate() {
            mesh.vertices
                .push(self.vertex(p.position, p.along_t * sign, j, row, Surface::Edge));
        }
        let inner_base = mesh.next_index();
        for (j, p) in rim.points.iter().enumerate() {
            mesh.vertices
                .push(self.vertex(rim.inner(j), p.along_t * sign, j, row, Surface::Edge));
        }
        let count = rim.points.len() as u32;
        Self::strip(mesh, outer_base, inner_base, count, self.flip(forwards));
    }

    /// Fans closing the apex of a closed curve: outer cap facing back, inner cap facing into
    /// the cavity.
    fn apex_caps(&self, mesh: &mut Mesh, rim: &Rim, outer: u32, inner: Option<u32>) {
        let n = rim.points.len() as u32 - 1;
        let rings = [(outer, Surface::Edge, true)]
            .into_iter()
            .chain(inner.map(|i| (i, Surface::Inner, false)));
        for (ring, surface, backwards) in rings {
            let points: Vec<DVec3> = (0..n)
                .map(|j| DVec3::from(mesh.vertices[(ring + j) as usize].position.map(f64::from)))
                .collect();
            let centre = points.iter().sum::<DVec3>() / f64::from(n);
            let facing = rim.points[0].along_t * if backwards { -1.0 } else { 1.0 };
            let c = mesh.next_index();
            mesh.vertices.push(Vertex::new(
                centre,
                self.sweep.handedness().mirror(facing),
                [0.5, 0.0],
                surface,
            ));
            // The centre is already in mirrored space; only the facing needed mirroring.
            for j in 0..n {
                mesh.triangle([c, ring + j, ring + j + 1], self.flip(!backwards));
            }
        }
    }

    /// Side strip vertices at the two ends of an open curve: outer and inner copies facing
    /// away from the curve.
    fn push_sides(&self, mesh: &mut Mesh, rim: &Rim) -> u32 {
        let base = mesh.next_index();
        let row = rim.t / self.sweep.step() * self.rows_per_rim;
        let last = rim.points.len() - 1;
        for (j, sign) in [(0, -1.0), (last, 1.0)] {
            let facing = rim.points[j].along_s * sign;
            mesh.vertices
                .push(self.vertex(rim.points[j].position, facing, j, row, Surface::Edge));
            mesh.vertices
                .push(self.vertex(rim.inner(j), facing, j, row, Surface::Edge));
        }
        base
    }
}

impl GrowingShape for SweepMesh {
    fn steps(&self) -> usize {
        self.sweep.rims()
    }

    fn steps_done(&self) -> usize {
        self.done
    }

    fn capacity(&self) -> Capacity {
        let rims = self.sweep.rims();
        let points = self.sweep.points_per_rim();
        let quads = points - 1;
        let (mut vertices, mut indices) = (rims * points, (rims - 1) * quads * 6);
        if self.sweep.has_wall() {
            vertices *= 2;
            indices *= 2;
            if self.sweep.is_closed() {
                vertices += 2;
                indices += 2 * quads * 3;
            } else {
                vertices += rims * 4 + 2 * points;
                indices += (rims - 1) * 12 + quads * 6;
            }
        } else if self.sweep.is_closed() {
            vertices += 1;
            indices += quads * 3;
        }
        Capacity { vertices, indices }
    }

    /// The lip, and in a picture the open band to the newest rim ([`Self::open_band`]).
    fn edge_capacity(&self) -> Capacity {
        let points = self.sweep.points_per_rim();
        let wall = self.sweep.has_wall();
        let mut capacity = if wall {
            Capacity {
                vertices: 2 * points,
                indices: (points - 1) * 6,
            }
        } else {
            Capacity::default()
        };
        if self.thinning.is_some() {
            let surfaces = if wall { 2 } else { 1 };
            let sides = if wall && !self.sweep.is_closed() {
                4
            } else {
                0
            };
            capacity.vertices += 2 * (surfaces * points + sides);
            capacity.indices += surfaces * (points - 1) * 6 + sides * 3;
        }
        capacity
    }

    fn bounds(&self) -> Bounds {
        let mut bounds = Bounds::EMPTY;
        let t_max = self.sweep.t_max();
        let samples = 64;
        let from = (t_max - 1.25 * TAU).max(0.0);
        let ts = (0..=samples).map(|i| from + (t_max - from) * i as f64 / samples as f64);
        for t in std::iter::once(0.0).chain(ts) {
            let rim = self.sweep.rim_at(t);
            for p in &rim.points {
                bounds.include(self.sweep.handedness().mirror(p.position));
            }
        }
        bounds
    }

    fn line_grid(&self) -> LineGrid {
        let rows_per_whorl = TAU / self.sweep.step() * self.rows_per_rim;
        LineGrid::sparse(rows_per_whorl, Some(self.rows_per_rim))
    }

    /// The generating curve's length on the rim at that row, sculpture and lip included.
    fn rim_length(&self, row: usize) -> Option<f64> {
        let sweep = self.measured.as_ref().unwrap_or(&self.sweep);
        let t = row as f64 / self.rows_per_rim * sweep.step();
        let rim = sweep.rim_at(t.min(sweep.t_max()));
        let points = rim.points.windows(2);
        Some(points.map(|p| p[0].position.distance(p[1].position)).sum())
    }

    fn front(&self) -> DVec3 {
        let rim = self.sweep.rim_at(self.sweep.t_max());
        let facing: DVec3 = rim.points.iter().map(|p| p.along_t).sum();
        self.sweep.handedness().mirror(facing)
    }

    fn grow(&mut self, mesh: &mut Mesh, edge: &mut Mesh) -> bool {
        if self.done >= self.sweep.rims() {
            return false;
        }
        let at = self.walk.next().expect("the walk is endless");
        let rim = self.sweep.rim(at, self.scale);
        self.scale *= self.sweep.lambda()[2];
        self.done += 1;
        let Some(thinning) = &mut self.thinning else {
            self.add(mesh, edge, &rim);
            return true;
        };
        let added = thinning.take(rim, self.done == self.sweep.rims());
        for rim in &added {
            self.add(mesh, edge, rim);
        }
        if let Some((kept, newest)) = self.thinning.as_ref().and_then(RimThinning::open) {
            self.open_band(edge, kept, newest);
        }
        true
    }
}
