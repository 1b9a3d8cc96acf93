//! A pattern being grown: the model, the colours, every row so far as RGBA (the texture and
//! the planar view), and a hash of the recorded values that is the same on every platform
//! for the same spec.
//!
//! On a growing edge (see [`super::edge_growth`]) a row has as many cells as the rim has
//! room for, fewer than the last row's; its RGBA is still as wide as the last row's, each
//! cell stretched over its share of the row, so that position x along the rim (in [0, 1])
//! finds the cell there on every row, as the texture and the files read it.

use super::edge_growth::{Divisions, cell_counts};
use super::{EdgeModel, PatternError, build};
use crate::fnv::Fnv;
use crate::spec::ShellSpec;
use crate::spec::colour::Rgb;
use crate::spec::pattern::{EdgeGrowth, Model};

/// The pattern of one shell, row by row.
pub struct PatternRun {
    model: Box<dyn EdgeModel>,
    ground: Rgb,
    pigment: Rgb,
    low: f64,
    high: f64,
    cells: usize,
    rows: usize,
    /// Cells of each row recorded (all `cells` on a fixed edge).
    widths: Vec<u32>,
    growth: Option<Box<Growth>>,
    rgba: Vec<u8>,
    shade: Vec<f32>,
    hash: Fnv,
}

/// How a growing edge divides its cells: computed cells on each row, and which divide.
struct Growth {
    counts: Vec<usize>,
    divisions: Divisions,
}

impl PatternRun {
    /// The pattern a spec asks for, with its first row (the starting state) recorded; `None`
    /// when the spec has no pattern model. `rim` gives the rim's length on each row, which a
    /// growing edge follows; `None` where the form has no one growing edge.
    pub fn new(
        spec: &ShellSpec,
        rim: impl Fn(usize) -> Option<f64>,
    ) -> Result<Option<Self>, PatternError> {
        let (pattern, counts) = match spec.pattern.edge_growth {
            EdgeGrowth::Off => (spec.pattern.clone(), None),
            _ if spec.pattern.model == Model::None => (spec.pattern.clone(), None),
            EdgeGrowth::Uniform => {
                let rows = spec.growth.rows_grown();
                let rims = (0..rows).map(&rim).collect::<Option<Vec<f64>>>().ok_or_else(|| {
                    PatternError(
                        "pattern.edge_growth: this form has no one growing edge whose cells could divide (swept shells and chambers have); set it to off".into(),
                    )
                })?;
                let counts = cell_counts(spec.pattern.cells, spec.pattern.apex_cells, &rims)?;
                let mut first = spec.pattern.clone();
                first.cells = counts[0];
                // The automaton's starting cells are positions along the last row's edge.
                if let Model::Automaton(a) = &mut first.model {
                    for c in &mut a.start_cells {
                        let at = u64::from(*c) * u64::from(counts[0]);
                        *c = (at / u64::from(spec.pattern.cells.max(1))) as u32;
                    }
                }
                (first, Some(counts))
            }
        };
        let Some(model) = build(&pattern, spec.seed)? else {
            return Ok(None);
        };
        // Cells the model computes per cell of the spec: the refinement k of a
        // reaction-diffusion model, 1 for the automaton.
        let per_cell = model.recorded().len() / pattern.cells.max(1) as usize;
        let cells = spec.pattern.cells as usize * per_cell;
        let growth = counts.map(|counts| {
            Box::new(Growth {
                counts: counts.iter().map(|&n| n as usize * per_cell).collect(),
                divisions: Divisions::new(spec.seed),
            })
        });
        let mut run = Self {
            model,
            ground: spec.colours.ground,
            pigment: spec.colours.pigment,
            low: spec.pattern.low,
            high: spec.pattern.high,
            cells,
            rows: 0,
            widths: Vec::with_capacity(spec.growth.rows as usize),
            growth,
            rgba: Vec::with_capacity(cells * 4 * spec.growth.rows as usize),
            shade: Vec::with_capacity(cells),
            hash: Fnv::default(),
        };
        run.record();
        Ok(Some(run))
    }

    /// Records the model's row: its values in the hash, and its colours stretched to the
    /// row's whole width (cell i of n has its centre at texel (i + ½)·cells/n).
    fn record(&mut self) {
        let recorded = self.model.recorded();
        for x in recorded {
            self.hash.write(&x.to_bits().to_le_bytes());
        }
        let n = recorded.len();
        self.shade.resize(n, 0.0);
        self.model.pigment(self.low, self.high, &mut self.shade);
        let start = self.rgba.len();
        self.rgba.resize(start + self.cells * 4, 255);
        let row = self.rgba[start..].chunks_exact_mut(4);
        if n == self.cells {
            for (pixel, &p) in row.zip(&self.shade) {
                pixel[..3].copy_from_slice(&self.ground.mix(self.pigment, p).0);
            }
        } else {
            // Each texel's centre in cells, its pigment interpolated between the two nearest
            // cells' centres: a cell's colour stays on its part of the rim without the steps
            // a row of few wide cells would draw each time one divides.
            let scale = n as f32 / self.cells as f32;
            for (k, pixel) in row.enumerate() {
                let at = ((k as f32 + 0.5) * scale - 0.5).clamp(0.0, (n - 1) as f32);
                let i = (at as usize).min(n.saturating_sub(2));
                let f = at - i as f32;
                let next = self.shade[(i + 1).min(n - 1)];
                let p = self.shade[i] + (next - self.shade[i]) * f;
                pixel[..3].copy_from_slice(&self.ground.mix(self.pigment, p).0);
            }
        }
        self.widths.push(n as u32);
        self.rows += 1;
    }

    /// Computes and records the next row: on a growing edge its cells divide first, to as
    /// many as the rim has room for there.
    pub fn advance(&mut self) -> Result<(), PatternError> {
        if let Some(g) = &mut self.growth {
            let target = g.counts[self.rows.min(g.counts.len() - 1)];
            g.divisions.divide_to(self.model.as_mut(), target);
        }
        self.model
            .advance_row()
            .map_err(|e| PatternError(format!("at row {}, {e}", self.rows)))?;
        self.record();
        Ok(())
    }

    /// Cells per row of the RGBA: the last row's cells.
    pub fn cells(&self) -> usize {
        self.cells
    }

    /// The rows as the planar view shows them (see [`planar_rows`]).
    pub fn planar(&self) -> Vec<u8> {
        planar_rows(&self.rgba, &self.widths, self.cells)
    }

    /// Cells the model computed on each row recorded: `cells` on a fixed edge, fewer before
    /// the last rows on a growing one.
    pub fn widths(&self) -> &[u32] {
        &self.widths
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

/// Rows of `cells` RGBA texels as the planar view shows them, each row's `widths[r]` cells one
/// texel each, the row centred, the texels beyond its ends transparent: a growing edge's
/// pattern widens as a fan (rows as wide as `cells` are as they are). Cell i of a row of n is
/// the texel (2i + 1)·cells / 2n of its stretched row, the one nearest its centre (see
/// [`PatternRun::rgba`]).
pub fn planar_rows(rgba: &[u8], widths: &[u32], cells: usize) -> Vec<u8> {
    let mut out = vec![0u8; rgba.len()];
    let row_bytes = cells * 4;
    for ((row, stretched), &n) in out
        .chunks_exact_mut(row_bytes)
        .zip(rgba.chunks_exact(row_bytes))
        .zip(widths)
    {
        let n = (n as usize).clamp(1, cells);
        if n == cells {
            row.copy_from_slice(stretched);
            continue;
        }
        let offset = (cells - n) / 2;
        for i in 0..n {
            let k = ((2 * i + 1) * cells) / (2 * n);
            let at = 4 * (offset + i);
            row[at..at + 4].copy_from_slice(&stretched[4 * k..4 * k + 4]);
        }
    }
    out
}
