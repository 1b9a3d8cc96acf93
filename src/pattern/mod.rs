//! Pigmentation patterns computed on the growing edge (Fowler, Meinhardt & Prusinkiewicz 1992,
//! §3): every model implements [`EdgeModel`], "advance the growing edge by one row", and the
//! rows stacked in time are the pattern.

pub mod activator_inhibitor;
pub mod activator_substrate;
pub mod automaton;
pub mod automaton_rule;
pub mod coupled;
pub mod diffusion;
pub mod grid;
pub mod noise;
pub mod run;
pub mod starts;

use crate::spec::pattern::{Model, PatternSpec};

/// Why a pattern cannot go on: a message in words, naming the parameters that matter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PatternError(pub String);

impl std::fmt::Display for PatternError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// A model of the growing edge.
pub trait EdgeModel {
    /// Advances by one displayed row (the model's own number of time steps).
    fn advance_row(&mut self) -> Result<(), PatternError>;

    /// The quantity the pattern records, one value per cell: the activator concentration, or
    /// the prepigment count of the automaton.
    fn recorded(&self) -> &[f64];

    /// Pigment density in [0, 1] per cell, from the recorded value mapped from `low..high`.
    fn pigment(&self, low: f64, high: f64, out: &mut [f32]) {
        for (p, &x) in out.iter_mut().zip(self.recorded()) {
            *p = ((x - low) / (high - low)).clamp(0.0, 1.0) as f32;
        }
    }
}

/// Checks that explicit Euler can integrate diffusion `d` (per step) together with a linear
/// decay `decay` (per step): the shortest wave is damped only while 4d + decay ≤ 2.
pub fn check_stability(d: (&str, f64), decay: (&str, f64)) -> Result<(), PatternError> {
    let (dn, d) = d;
    let (mn, m) = decay;
    if !(0.0..=crate::spec::fields::MAX_DIFFUSION).contains(&d) {
        return Err(PatternError(format!(
            "{dn} = {d} cannot be integrated stably: explicit Euler with Δt = Δx = 1 needs 0 ≤ {dn} ≤ 0.5"
        )));
    }
    if 4.0 * d + m > 2.0 {
        return Err(PatternError(format!(
            "{dn} = {d} with {mn} = {m} cannot be integrated stably: explicit Euler with Δt = Δx = 1 needs 4·{dn} + {mn} ≤ 2, here {}",
            4.0 * d + m
        )));
    }
    Ok(())
}

/// The model a pattern spec describes, or `None` for a shell without pattern.
pub fn build(spec: &PatternSpec, seed: u64) -> Result<Option<Box<dyn EdgeModel>>, PatternError> {
    if spec.cells == 0 && spec.model != Model::None {
        return Err(PatternError(
            "the growing edge needs at least one cell".into(),
        ));
    }
    Ok(match &spec.model {
        Model::None => None,
        Model::ActivatorSubstrate(p) => Some(Box::new(
            activator_substrate::ActivatorSubstrate::new(p, spec, seed)?,
        )),
        Model::ActivatorInhibitor(p) => Some(Box::new(
            activator_inhibitor::ActivatorInhibitor::new(p, spec, seed)?,
        )),
        Model::Coupled(p) => Some(Box::new(coupled::Coupled::new(p, spec, seed)?)),
        Model::Automaton(p) => Some(Box::new(automaton::Automaton::new(p, spec, seed)?)),
    })
}

/// Refuses concentrations that are no longer numbers, or that left any sensible range.
pub fn check_finite(name: &str, values: &[f64], hint: &str) -> Result<(), PatternError> {
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
