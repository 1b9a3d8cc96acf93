//! Pigmentation patterns computed on the growing edge (Fowler, Meinhardt & Prusinkiewicz 1992,
//! §3): every model implements [`EdgeModel`], "advance the growing edge by one row", and the
//! rows stacked in time are the pattern.

pub(crate) mod activator_inhibitor;
pub(crate) mod activator_substrate;
pub mod automaton;
pub(crate) mod automaton_rule;
pub(crate) mod coupled;
pub(crate) mod diffusion;
pub(crate) mod edge_growth;
pub(crate) mod edge_model;
pub(crate) mod grid;
pub(crate) mod noise;
pub(crate) mod repair;
pub mod run;
pub(crate) mod stability;
pub(crate) mod starts;
pub mod texture_layout;

use crate::spec::pattern::{Model, PatternSpec};
pub use edge_model::{EdgeModel, PatternError};
use stability::{Diffusion, diffusions};

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
