//! Where explicit Euler's stability is decided: every diffusion constant of a model with the
//! linear decay it is integrated together with, for the model's refusal and the repair of
//! links alike.

use crate::spec::pattern::Model;

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
