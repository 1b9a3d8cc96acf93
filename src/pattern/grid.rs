//! The growing edge's discretisation shared by all continuous models: how many cells, how many
//! time steps per displayed row, and the step Δt.
//!
//! Meinhardt ran his models with Δt = Δx = 1. Refining by k puts k cells where there was one,
//! so a diffusion constant D becomes D·k² per step; to keep the same stability condition the
//! time step becomes 1/k² (k² steps per former step). The physical model is unchanged, so a
//! refined run converges to the same pattern, which the tests check.

use crate::spec::pattern::{Boundary, PatternSpec};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Cells actually computed: the spec's cells × refinement.
    pub cells: usize,
    /// Cells per cell of the unrefined edge.
    pub refinement: u32,
    /// Time steps per displayed row: iterations × refinement².
    pub steps_per_row: u32,
    /// Δt = 1 / refinement².
    pub dt: f64,
    pub boundary: Boundary,
}

impl Grid {
    pub fn new(spec: &PatternSpec) -> Self {
        let k = spec.refinement.max(1);
        Self {
            cells: spec.cells as usize * k as usize,
            refinement: k,
            steps_per_row: spec.iterations.max(1) * k * k,
            dt: 1.0 / f64::from(k * k),
            boundary: spec.boundary,
        }
    }

    /// The per-step diffusion weight of a constant D given per unrefined cell and step: D·k²·Δt,
    /// which is D itself.
    pub fn diffusion(&self, d: f64) -> f64 {
        d * f64::from(self.refinement * self.refinement) * self.dt
    }

    /// Rates per unit time (a rate per cell) as amounts per step: each times Δt, rounded once to
    /// single precision, so that the step's arithmetic does not multiply by Δt again.
    pub fn per_step<R: Into<f64>>(&self, rates: impl IntoIterator<Item = R>) -> Vec<f32> {
        rates
            .into_iter()
            .map(|r| (r.into() * self.dt) as f32)
            .collect()
    }

    /// Position of cell i in unrefined cells (its centre).
    pub fn position(&self, i: usize) -> f64 {
        (i as f64 + 0.5) / f64::from(self.refinement)
    }
}
