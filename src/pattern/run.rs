//! A pattern being grown: the model, the colours, every row so far as RGBA (the texture and
//! the planar view), and a hash of the recorded values that is the same on every platform
//! for the same spec.

use super::{EdgeModel, PatternError, build};
use crate::fnv::Fnv;
use crate::spec::ShellSpec;
use crate::spec::colour::Rgb;

/// The pattern of one shell, row by row.
pub struct PatternRun {
    model: Box<dyn EdgeModel>,
    ground: Rgb,
    pigment: Rgb,
    low: f64,
    high: f64,
    cells: usize,
    rows: usize,
    rgba: Vec<u8>,
    shade: Vec<f32>,
    hash: Fnv,
}

impl PatternRun {
    /// The pattern a spec asks for, with its first row (the starting state) recorded; `None`
    /// when the spec has no pattern model.
    pub fn new(spec: &ShellSpec) -> Result<Option<Self>, PatternError> {
        let Some(model) = build(&spec.pattern, spec.seed)? else {
            return Ok(None);
        };
        let cells = model.recorded().len();
        let mut run = Self {
            model,
            ground: spec.colours.ground,
            pigment: spec.colours.pigment,
            low: spec.pattern.low,
            high: spec.pattern.high,
            cells,
            rows: 0,
            rgba: Vec::with_capacity(cells * 4 * spec.growth.rows as usize),
            shade: vec![0.0; cells],
            hash: Fnv::default(),
        };
        run.record();
        Ok(Some(run))
    }

    fn record(&mut self) {
        for x in self.model.recorded() {
            self.hash.write(&x.to_bits().to_le_bytes());
        }
        self.model.pigment(self.low, self.high, &mut self.shade);
        let start = self.rgba.len();
        self.rgba.resize(start + self.cells * 4, 255);
        for (pixel, &p) in self.rgba[start..].chunks_exact_mut(4).zip(&self.shade) {
            pixel[..3].copy_from_slice(&self.ground.mix(self.pigment, p).0);
        }
        self.rows += 1;
    }

    /// Computes and records the next row.
    pub fn advance(&mut self) -> Result<(), PatternError> {
        self.model
            .advance_row()
            .map_err(|e| PatternError(format!("at row {}, {e}", self.rows)))?;
        self.record();
        Ok(())
    }

    /// Cells per row.
    pub fn cells(&self) -> usize {
        self.cells
    }

    /// Rows recorded so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// All rows so far, `cells × 4` bytes each.
    pub fn rgba(&self) -> &[u8] {
        &self.rgba
    }

    /// The recorded values of the latest row.
    pub fn recorded(&self) -> &[f32] {
        self.model.recorded()
    }

    /// Hash of every recorded value so far, bit for bit.
    pub fn hash(&self) -> u64 {
        self.hash.value()
    }
}
