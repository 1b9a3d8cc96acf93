//! Binary little-endian PLY with vertex colours: welded positions with averaged normals, and
//! `red`, `green`, `blue` (uchar) per vertex, the page's colour there (see [`Paint::colour`]),
//! the de-facto format of coloured point and mesh tools. Where the lip meets the outer surface
//! the welded vertex takes the pattern's colour.
//!
//! [`Paint::colour`]: super::paint::Paint::colour

use super::error::ExportError;
use super::shell::Shell;
use super::steps::{Cursor, Writer, progress};
use super::weld::{Welded, Welder};
use glam::Vec3;

/// Vertices or triangles per step.
const PER_STEP: usize = 4096;
/// Shares of the work: welding, counting faces, vertices, faces.
const WEIGHTS: [f64; 4] = [0.35, 0.05, 0.35, 0.25];

#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    Weld,
    Count,
    Vertices,
    Faces,
}

/// A PLY being written.
pub(crate) struct Ply {
    shell: Shell,
    stage: Stage,
    cursor: Cursor,
    welder: Option<Welder>,
    welded: Option<Welded>,
    /// The sum of the normals of every vertex at each position.
    normals: Vec<Vec3>,
    faces: usize,
    out: Vec<u8>,
}

impl Ply {
    pub fn new(shell: Shell) -> Self {
        Self {
            cursor: Cursor::new(shell.mesh.vertices.len()),
            welder: Some(Welder::new(&shell.mesh)),
            shell,
            stage: Stage::Weld,
            welded: None,
            normals: Vec::new(),
            faces: 0,
            out: Vec::new(),
        }
    }

    fn welded(&self) -> &Welded {
        self.welded.as_ref().expect("welded")
    }

    fn header(&self) -> String {
        format!(
            "ply\nformat binary_little_endian 1.0\ncomment seashells: {}\nelement vertex {}\n\
             property float x\nproperty float y\nproperty float z\n\
             property float nx\nproperty float ny\nproperty float nz\n\
             property uchar red\nproperty uchar green\nproperty uchar blue\n\
             element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
            self.shell.title.replace('\n', " "),
            self.welded().positions.len(),
            self.faces
        )
    }
}

impl Writer for Ply {
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError> {
        let mesh = &self.shell.mesh;
        let range = self.cursor.next(PER_STEP);
        match self.stage {
            Stage::Weld => {
                let welder = self.welder.as_mut().expect("welding");
                welder.weld(mesh, range);
                if self.cursor.done() {
                    let welded = self.welder.take().expect("welding").finish();
                    self.normals = vec![Vec3::ZERO; welded.positions.len()];
                    for (v, &i) in mesh.vertices.iter().zip(&welded.index) {
                        self.normals[i as usize] += Vec3::from(v.normal);
                    }
                    self.welded = Some(welded);
                    self.stage = Stage::Count;
                    self.cursor = Cursor::new(mesh.triangle_count());
                }
            }
            Stage::Count => {
                let welded = self.welded.as_ref().expect("welded");
                self.faces += range
                    .filter(|&t| welded.triangle(mesh, t).is_some())
                    .count();
                if self.cursor.done() {
                    if self.faces == 0 {
                        return Err(ExportError::Empty);
                    }
                    let header = self.header();
                    let vertices = self.welded().positions.len();
                    self.out = Vec::with_capacity(header.len() + 27 * vertices + 13 * self.faces);
                    self.out.extend_from_slice(header.as_bytes());
                    self.stage = Stage::Vertices;
                    self.cursor = Cursor::new(vertices);
                }
            }
            Stage::Vertices => {
                let welded = self.welded.as_ref().expect("welded");
                for i in range {
                    let n = self.normals[i].normalize_or(Vec3::Z);
                    for x in welded.positions[i].iter().chain(n.to_array().iter()) {
                        self.out.extend_from_slice(&x.to_le_bytes());
                    }
                    let source = &mesh.vertices[welded.source[i] as usize];
                    self.out.extend_from_slice(&self.shell.paint.colour(source));
                }
                if self.cursor.done() {
                    self.stage = Stage::Faces;
                    self.cursor = Cursor::new(mesh.triangle_count());
                }
            }
            Stage::Faces => {
                let welded = self.welded.as_ref().expect("welded");
                for t in range.filter_map(|t| welded.triangle(mesh, t)) {
                    self.out.push(3);
                    for i in t {
                        self.out.extend_from_slice(&i.to_le_bytes());
                    }
                }
                if self.cursor.done() {
                    return Ok(Some(std::mem::take(&mut self.out)));
                }
            }
        }
        Ok(None)
    }

    fn progress(&self) -> f64 {
        // Stages are numbered in their order.
        let stage = self.stage as usize;
        progress(&WEIGHTS, stage, self.cursor.fraction())
    }
}
