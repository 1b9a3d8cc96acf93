//! Binary STL: an 80-byte header, the triangle count, then per triangle its facet normal and
//! three corners.

use super::error::ExportError;
use super::steps::{Cursor, Writer, progress, run};
use super::weld::{Welded, Welder};
use crate::mesh::Mesh;
use glam::Vec3;

/// Vertices or triangles per step.
const PER_STEP: usize = 4096;
/// Shares of the work: welding, triangles.
const WEIGHTS: [f64; 2] = [0.4, 0.6];

/// The mesh as binary STL, at once; refused when no triangle has an area.
pub fn write(mesh: &Mesh) -> Result<Vec<u8>, ExportError> {
    run(&mut Stl::new(mesh.clone()))
}

/// An STL being written.
pub(crate) struct Stl {
    mesh: Mesh,
    cursor: Cursor,
    welder: Option<Welder>,
    welded: Option<Welded>,
    out: Vec<u8>,
    count: u32,
}

impl Stl {
    pub fn new(mesh: Mesh) -> Self {
        let text = b"seashells: a shell grown from the Fowler, Meinhardt & Prusinkiewicz model";
        let mut out = Vec::with_capacity(84 + 50 * mesh.triangle_count());
        out.extend_from_slice(text);
        out.resize(80, b' ');
        // The triangle count, once known.
        out.extend_from_slice(&[0; 4]);
        Self {
            cursor: Cursor::new(mesh.vertices.len()),
            welder: Some(Welder::new(&mesh)),
            mesh,
            welded: None,
            out,
            count: 0,
        }
    }
}

impl Writer for Stl {
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError> {
        let range = self.cursor.next(PER_STEP);
        if let Some(welder) = &mut self.welder {
            welder.weld(&self.mesh, range);
            if self.cursor.done() {
                self.welded = self.welder.take().map(Welder::finish);
                self.cursor = Cursor::new(self.mesh.triangle_count());
            }
            return Ok(None);
        }
        let welded = self.welded.as_ref().expect("welded");
        for t in range.filter_map(|t| welded.triangle(&self.mesh, t)) {
            let [a, b, c] = t.map(|i| Vec3::from(welded.positions[i as usize]));
            let normal = (b - a).cross(c - a).normalize_or_zero();
            for v in [normal, a, b, c] {
                for x in v.to_array() {
                    self.out.extend_from_slice(&x.to_le_bytes());
                }
            }
            self.out.extend_from_slice(&0u16.to_le_bytes());
            self.count += 1;
        }
        if !self.cursor.done() {
            return Ok(None);
        }
        if self.count == 0 {
            return Err(ExportError::Empty);
        }
        self.out[80..84].copy_from_slice(&self.count.to_le_bytes());
        Ok(Some(std::mem::take(&mut self.out)))
    }

    fn progress(&self) -> f64 {
        let stage = usize::from(self.welder.is_none());
        progress(&WEIGHTS, stage, self.cursor.fraction())
    }
}
