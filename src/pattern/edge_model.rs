//! What every pattern model is to the rest of the crate: an [`EdgeModel`] that advances the
//! growing edge by one row, the [`PatternError`] that stops it, and the checks that refuse
//! concentrations explicit Euler has driven out of range.

use super::noise::Noise;

/// Why a pattern cannot go on: a message in words, naming the parameters that matter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PatternError(pub String);

impl std::fmt::Display for PatternError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for PatternError {}

/// A model of the growing edge.
pub trait EdgeModel {
    /// Advances by one displayed row (the model's own number of time steps).
    fn advance_row(&mut self) -> Result<(), PatternError>;

    /// The quantity the pattern records, one value per cell: the activator concentration, or
    /// the prepigment count of the automaton. Single precision: the models' statistics (stripe
    /// spacing, wave counts, periods) hold in it, and it halves the work of every step.
    fn recorded(&self) -> &[f32];

    /// Cell `cell` divides (see [`super::edge_growth`]): a daughter after it takes the mean of
    /// its neighbours' concentrations, and its own fluctuation of ρ from `noise`.
    fn divide(&mut self, cell: usize, noise: &mut Noise);

    /// Pigment density in [0, 1] per cell, from the recorded value mapped from `low..high`.
    fn pigment(&self, low: f64, high: f64, out: &mut [f32]) {
        for (p, &x) in out.iter_mut().zip(self.recorded()) {
            *p = ((f64::from(x) - low) / (high - low)).clamp(0.0, 1.0) as f32;
        }
    }
}

/// Refuses concentrations that explicit Euler drove below zero.
pub fn check_nonnegative(name: &str, values: &[f32], hint: &str) -> Result<(), PatternError> {
    // The test is folded over every value without an early exit, so the compiler vectorizes
    // it; the position is looked for only when something is wrong.
    if values.iter().fold(true, |ok, &v| ok & (v >= -1e-9)) {
        return Ok(());
    }
    match values.iter().position(|&v| v < -1e-9) {
        None => Ok(()),
        Some(i) => Err(PatternError(format!(
            "the {name} became negative in cell {i}: {hint}"
        ))),
    }
}

/// Refuses concentrations that are no longer numbers, or that left any sensible range.
pub fn check_finite(name: &str, values: &[f32], hint: &str) -> Result<(), PatternError> {
    // As in `check_nonnegative`: a vectorized fold first (|v| ≤ 10¹² is false for NaN and ±∞).
    if values.iter().fold(true, |ok, &v| ok & (v.abs() <= 1e12)) {
        return Ok(());
    }
    match values.iter().position(|v| !v.is_finite() || v.abs() > 1e12) {
        None => Ok(()),
        Some(i) => Err(PatternError(format!(
            "the {name} concentration became {} in cell {i}: {hint}",
            if values[i].is_finite() {
                "too large"
            } else {
                "infinite or undefined"
            }
        ))),
    }
}
