//! Exports as resumable steps. Writing a large shell (the Murex at its own resolution: 180,000
//! vertices) takes longer than a frame, so every writer is a state machine that does one small
//! unit of work per [`Writer::step`] (a few thousand vertices or triangles, a few dozen rows
//! of an image) and keeps everything else in itself: the page calls
//! [`Export::work`](super::job::Export::work) within its frame budget, frame after frame (or,
//! later, a Web Worker calls it), the command line runs it to the end, and both get the same
//! bytes.

use super::error::ExportError;
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

/// Runs `writer` to its end: the whole file at once.
pub(crate) fn run(writer: &mut dyn Writer) -> Result<Vec<u8>, ExportError> {
    loop {
        if let Some(bytes) = writer.step()? {
            return Ok(bytes);
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
