//! Exports as resumable steps. Writing a large shell (the Murex at its own resolution: 180,000
//! vertices) takes longer than a frame, so every writer is a state machine that does one small
//! unit of work per [`Writer::step`] (a few thousand vertices or triangles, a few dozen rows
//! of an image) and keeps everything else in itself: the page calls [`Export::work`] within
//! its frame budget, frame after frame (or, later, a Web Worker calls it), the command line
//! runs it to the end, and both get the same bytes.

use super::error::ExportError;
use super::png::PatternPng;
use super::shell::Shell;
use super::{MeshFormat, glb, obj, ply, stl, three_mf};
use std::ops::Range;

/// One writer's work, a unit per step.
pub(crate) trait Writer {
    /// Does one unit of work; returns the file once it is whole.
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError>;

    /// How much of the work is done, from 0 to 1.
    fn progress(&self) -> f64;
}

/// A walk over `len` items, a unit at a time.
#[derive(Clone, Debug, Default)]
pub(crate) struct Cursor {
    at: usize,
    len: usize,
}

impl Cursor {
    pub fn new(len: usize) -> Self {
        Self { at: 0, len }
    }

    /// The next `unit` items (fewer at the end; empty once done).
    pub fn next(&mut self, unit: usize) -> Range<usize> {
        let start = self.at;
        self.at = (self.at + unit).min(self.len);
        start..self.at
    }

    pub fn done(&self) -> bool {
        self.at >= self.len
    }

    /// The share of the items walked.
    pub fn fraction(&self) -> f64 {
        if self.len == 0 {
            1.0
        } else {
            self.at as f64 / self.len as f64
        }
    }
}

/// Progress through stages of given weights (their shares of the work): all of the stages
/// before `stage`, and `fraction` of it.
pub(crate) fn progress(weights: &[f64], stage: usize, fraction: f64) -> f64 {
    let total: f64 = weights.iter().sum();
    let before: f64 = weights[..stage.min(weights.len())].iter().sum();
    let current = weights.get(stage).map_or(0.0, |w| w * fraction);
    ((before + current) / total).clamp(0.0, 1.0)
}

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

    /// Runs `writer`.
    pub(crate) fn from_writer(writer: Box<dyn Writer>) -> Self {
        Self { writer }
    }

    /// Starts writing the pattern's planar representation (`cells × rows` RGBA texels) as PNG.
    pub fn pattern(cells: usize, rows: usize, rgba: Vec<u8>) -> Self {
        Self::from_writer(Box::new(PatternPng::new(cells, rows, rgba)))
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
        loop {
            if let Some(bytes) = self.work(|| true)? {
                return Ok(bytes);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cursor_walks_every_item_once_in_units() {
        let mut c = Cursor::new(10);
        assert_eq!(c.next(4), 0..4);
        assert_eq!(c.fraction(), 0.4);
        assert_eq!(c.next(4), 4..8);
        assert!(!c.done());
        assert_eq!(c.next(4), 8..10);
        assert!(c.done());
        assert_eq!(c.next(4), 10..10);
        assert!(Cursor::new(0).done());
    }

    #[test]
    fn progress_counts_earlier_stages_whole() {
        let w = [1.0, 2.0, 1.0];
        assert_eq!(progress(&w, 0, 0.0), 0.0);
        assert_eq!(progress(&w, 1, 0.5), 0.5);
        assert_eq!(progress(&w, 3, 0.0), 1.0);
    }
}
