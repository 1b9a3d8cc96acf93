//! One file being written from a shell, in any format: the writers' steps (see
//! [`super::steps`]) behind one interface that the page drives a frame's budget at a time and
//! the command line runs to the end.

use super::error::ExportError;
use super::png::PatternPng;
use super::shell::Shell;
use super::steps::{Writer, run};
use super::{MeshFormat, glb, obj, ply, stl, three_mf};

/// One file being written from a shell.
pub struct Export {
    writer: Box<dyn Writer>,
}

impl Export {
    /// Starts writing `shell` in `format`; a shell without triangles is refused.
    pub fn new(format: MeshFormat, shell: Shell) -> Result<Self, ExportError> {
        if shell.mesh.triangle_count() == 0 {
            return Err(ExportError::Empty);
        }
        let writer: Box<dyn Writer> = match format {
            MeshFormat::Glb => Box::new(glb::Glb::new(shell)),
            MeshFormat::Ply => Box::new(ply::Ply::new(shell)),
            MeshFormat::ThreeMf => Box::new(three_mf::ThreeMf::new(shell)),
            MeshFormat::Obj => Box::new(obj::Obj::new(shell.mesh)),
            MeshFormat::Stl => Box::new(stl::Stl::new(shell.mesh)),
        };
        Ok(Self { writer })
    }

    /// Starts writing the pattern's planar representation (`cells × rows` RGBA texels) as PNG.
    pub fn pattern(cells: usize, rows: usize, rgba: Vec<u8>) -> Self {
        Self {
            writer: Box::new(PatternPng::new(cells, rows, rgba)),
        }
    }

    /// Works while `keep_going` allows (at least one step); returns the file once it is whole.
    pub fn work(
        &mut self,
        mut keep_going: impl FnMut() -> bool,
    ) -> Result<Option<Vec<u8>>, ExportError> {
        loop {
            if let Some(bytes) = self.writer.step()? {
                return Ok(Some(bytes));
            }
            if !keep_going() {
                return Ok(None);
            }
        }
    }

    /// How much of the file is written, from 0 to 1.
    pub fn progress(&self) -> f64 {
        self.writer.progress()
    }

    /// Writes the whole file at once.
    pub fn run(mut self) -> Result<Vec<u8>, ExportError> {
        run(self.writer.as_mut())
    }
}
