//! Wavefront OBJ: welded positions, one normal per original vertex (creases stay sharp). OBJ
//! has no standard way to carry colours; GLB, PLY and 3MF do.

use super::error::ExportError;
use super::steps::{Cursor, Writer, progress, run};
use super::weld::{Welded, Welder};
use crate::mesh::Mesh;
use std::fmt::Write;

/// Vertices, normals or triangles per step.
const PER_STEP: usize = 2048;
/// Shares of the work: welding, positions, normals, faces.
const WEIGHTS: [f64; 4] = [0.1, 0.3, 0.3, 0.3];

/// The mesh as OBJ, at once; refused when no triangle has an area.
pub fn write(mesh: &Mesh) -> Result<Vec<u8>, ExportError> {
    run(&mut Obj::new(mesh.clone()))
}

/// An OBJ being written.
pub(crate) struct Obj {
    mesh: Mesh,
    stage: usize,
    cursor: Cursor,
    welder: Option<Welder>,
    welded: Option<Welded>,
    out: String,
    faces: usize,
}

impl Obj {
    pub fn new(mesh: Mesh) -> Self {
        // More than the lines take (see `Download::estimate`), so the text is never moved.
        let capacity = 84 * mesh.vertices.len() + 44 * mesh.triangle_count();
        let mut out = String::with_capacity(capacity);
        out.push_str(
            "# seashells: a shell grown from the Fowler, Meinhardt & Prusinkiewicz model\n",
        );
        Self {
            cursor: Cursor::new(mesh.vertices.len()),
            welder: Some(Welder::new(&mesh)),
            mesh,
            stage: 0,
            welded: None,
            faces: 0,
            out,
        }
    }
}

impl Writer for Obj {
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError> {
        let range = self.cursor.next(PER_STEP);
        let out = &mut self.out;
        match self.stage {
            0 => self
                .welder
                .as_mut()
                .expect("welding")
                .weld(&self.mesh, range),
            1 => {
                let welded = self.welded.as_ref().expect("welded");
                for [x, y, z] in &welded.positions[range] {
                    writeln!(out, "v {x} {y} {z}").expect("write to string");
                }
            }
            2 => {
                for v in &self.mesh.vertices[range] {
                    let [x, y, z] = v.normal;
                    writeln!(out, "vn {x} {y} {z}").expect("write to string");
                }
            }
            _ => {
                let welded = self.welded.as_ref().expect("welded");
                for t in range {
                    let Some(p) = welded.triangle(&self.mesh, t) else {
                        continue;
                    };
                    let n = [0, 1, 2].map(|k| self.mesh.indices[3 * t + k] + 1);
                    let p = p.map(|i| i + 1);
                    writeln!(
                        out,
                        "f {}//{} {}//{} {}//{}",
                        p[0], n[0], p[1], n[1], p[2], n[2]
                    )
                    .expect("write to string");
                    self.faces += 1;
                }
            }
        }
        if self.cursor.done() {
            self.stage += 1;
            match self.stage {
                1 => {
                    let welded = self.welder.take().expect("welding").finish();
                    self.cursor = Cursor::new(welded.positions.len());
                    self.welded = Some(welded);
                }
                2 => self.cursor = Cursor::new(self.mesh.vertices.len()),
                3 => self.cursor = Cursor::new(self.mesh.triangle_count()),
                _ if self.faces == 0 => return Err(ExportError::Empty),
                _ => return Ok(Some(std::mem::take(&mut self.out).into_bytes())),
            }
        }
        Ok(None)
    }

    fn progress(&self) -> f64 {
        progress(&WEIGHTS, self.stage, self.cursor.fraction())
    }
}
