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
pub mod repair;
pub mod run;
pub mod starts;
pub mod texture_layout;

use crate::spec::pattern::{Model, PatternSpec};

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

    /// Pigment density in [0, 1] per cell, from the recorded value mapped from `low..high`.
    fn pigment(&self, low: f64, high: f64, out: &mut [f32]) {
        for (p, &x) in out.iter_mut().zip(self.recorded()) {
            *p = ((f64::from(x) - low) / (high - low)).clamp(0.0, 1.0) as f32;
        }
    }
}

/// One diffusion constant of a model, with the linear decay it is integrated together with.
pub struct Diffusion<'a> {
    /// Its key in links.
    pub key: &'static str,
    pub symbol: &'static str,
    pub value: &'a mut f64,
    pub decay_symbol: &'static str,
    pub decay: f64,
}

impl Diffusion<'_> {
    /// The largest value explicit Euler with Δt = Δx = 1 integrates stably together with the
    /// decay: the shortest wave is damped only while 4D + decay ≤ 2 (and D ≤ 0.5 with none).
    pub fn limit(&self) -> f64 {
        ((2.0 - self.decay) / 4.0).clamp(0.0, crate::spec::fields::MAX_DIFFUSION)
    }

    /// Why the value cannot be integrated, if it cannot.
    pub fn problem(&self) -> Option<String> {
        let (d, s) = (*self.value, self.symbol);
        if d < 0.0 {
            Some(format!("{s} = {d} is negative"))
        } else if d > self.limit() {
            Some(format!(
                "{s} = {d} with {} = {} cannot be integrated stably: explicit Euler with Δt = Δx = 1 needs 4·{s} + {} ≤ 2 and {s} ≤ 0.5",
                self.decay_symbol, self.decay, self.decay_symbol
            ))
        } else {
            None
        }
    }
}

fn diffusion<'a>(
    key: &'static str,
    symbol: &'static str,
    value: &'a mut f64,
    decay: (&'static str, f64),
) -> Diffusion<'a> {
    Diffusion {
        key,
        symbol,
        value,
        decay_symbol: decay.0,
        decay: decay.1,
    }
}

/// Every diffusion constant of a model: where explicit Euler's stability is decided, for the
/// model's refusal and for the repair of links alike.
pub fn diffusions(model: &mut Model) -> Vec<Diffusion<'_>> {
    match model {
        Model::ActivatorSubstrate(m) => {
            let (mu, nu) = (m.mu, m.nu);
            vec![
                diffusion("pattern.model.d_a", "D_a", &mut m.d_a, ("μ", mu)),
                diffusion("pattern.model.d_s", "D_s", &mut m.d_s, ("ν", nu)),
            ]
        }
        Model::ActivatorInhibitor(m) => {
            let mu = m.mu;
            vec![
                diffusion("pattern.model.d_a", "D_a", &mut m.d_a, ("μ", mu)),
                diffusion("pattern.model.d_h", "D_h", &mut m.d_h, ("its decay", 0.0)),
            ]
        }
        Model::Coupled(m) => {
            let (decay, mu_e) = (m.mu + m.gamma, m.mu_e);
            vec![
                diffusion("pattern.model.d_a", "D_a", &mut m.d_a, ("μ + γ", decay)),
                diffusion("pattern.model.d_e", "Dₑ", &mut m.d_e, ("μₑ", mu_e)),
            ]
        }
        Model::Automaton(_) | Model::None => vec![],
    }
}

/// The model a pattern spec describes, or `None` for a shell without pattern.
pub fn build(spec: &PatternSpec, seed: u64) -> Result<Option<Box<dyn EdgeModel>>, PatternError> {
    if spec.cells == 0 && spec.model != Model::None {
        return Err(PatternError(
            "the growing edge needs at least one cell".into(),
        ));
    }
    if let Some(problem) = diffusions(&mut spec.model.clone())
        .iter()
        .find_map(Diffusion::problem)
    {
        return Err(PatternError(problem));
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
