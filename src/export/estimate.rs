//! What each download will weigh, estimated from the shell's counts before it is written, so
//! the page can show it on the button: meshes in bytes (from each format's layout, with
//! averages measured on the presets of every form for what the counts do not tell: how many
//! vertices welding leaves, the length of numbers as text, compression), pictures in pixels.
//! Once a file is made, the page shows its exact size.

use super::{Download, MeshFormat};
use serde::{Deserialize, Serialize};

/// What the estimates are made from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Counts {
    /// Vertices and triangles of the shell as it stands, edge included.
    pub vertices: usize,
    pub triangles: usize,
    /// Cells and rows of the pattern, when there is one.
    pub pattern: Option<(usize, usize)>,
    /// The view's size in pixels.
    pub picture: (usize, usize),
}

/// A file's size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    Bytes(u64),
    Pixels(usize, usize),
}

impl Download {
    /// About what the file will weigh (within a factor of 1.5 for the presets of every form);
    /// `None` when there is nothing to download (no pattern).
    pub fn estimate(self, c: &Counts) -> Option<Size> {
        let (v, t) = (c.vertices as f64, c.triangles as f64);
        // Welded by position, a closed surface has about half as many vertices as triangles
        // (Euler), whatever copies the form made for creases and seams.
        let positions = t / 2.0;
        let texels = c.pattern.map_or(0.0, |(cells, rows)| (cells * rows) as f64);
        let bytes = match self {
            Download::Picture => return Some(Size::Pixels(c.picture.0, c.picture.1)),
            Download::Pattern => return c.pattern.map(|(w, h)| Size::Pixels(w, h)),
            // Floats for positions, normals and (on the outer half) texture coordinates on
            // fewer vertices than the form made (it repeats some exactly), three indices a
            // triangle, and the texture at about 0.6 bytes a texel.
            Download::Mesh(MeshFormat::Glb) => 2_000.0 + 24.0 * v + 12.0 * t + 0.6 * texels,
            // 27 bytes a position (six floats, three colour bytes), 13 a triangle.
            Download::Mesh(MeshFormat::Ply) => 400.0 + 27.0 * positions + 13.0 * t,
            // Deflated XML: about 14 bytes a triangle with its vertices and colours.
            Download::Mesh(MeshFormat::ThreeMf) => 1_500.0 + 14.0 * t,
            // Lines of text: about 36 bytes a position, 38 a normal, 40 a face.
            Download::Mesh(MeshFormat::Obj) => 36.0 * positions + 38.0 * v + 40.0 * t,
            Download::Mesh(MeshFormat::Stl) => 84.0 + 50.0 * t,
        };
        Some(Size::Bytes(bytes as u64))
    }
}
