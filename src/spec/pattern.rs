//! The pigmentation part of a [`ShellSpec`](super::ShellSpec): the growing edge (cells,
//! iterations per row, ends), how the recorded quantity becomes pigment, and the model.

use serde::{Deserialize, Serialize};

/// The pattern computed on the growing edge.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PatternSpec {
    /// Cells along the growing edge.
    pub cells: u32,
    /// Model iterations (Δt = 1) per displayed row.
    pub iterations: u32,
    /// Refinement k: k cells per cell and k² steps per iteration, the same model resolved
    /// more finely (1: as Meinhardt ran it).
    pub refinement: u32,
    /// What happens at the two ends of the edge.
    pub boundary: Boundary,
    /// Whether the edge's cells divide as the rim lengthens (beyond the paper, which keeps
    /// their number fixed: "we ignore the effect of the gradual increase of polygon size
    /// resulting from the rim's growth", §3). `cells` are then those of the last row.
    pub edge_growth: EdgeGrowth,
    /// The fewest cells a growing edge has (at most `cells`): its first rows, at the apex,
    /// hold this many however short the rim is there, as a mollusc's mantle edge holds many
    /// cells from the start; they divide once the rim has room for more. A model whose waves
    /// need room to travel (fig 14's) dies out on an edge of one or two cells.
    pub apex_cells: u32,
    /// Recorded value shown as no pigment.
    pub low: f64,
    /// Recorded value shown as full pigment.
    pub high: f64,
    pub model: Model,
}

impl Default for PatternSpec {
    /// No pattern.
    fn default() -> Self {
        Self {
            cells: 256,
            iterations: 1,
            refinement: 1,
            boundary: Boundary::ZeroFlux,
            edge_growth: EdgeGrowth::Off,
            apex_cells: 1,
            low: 0.0,
            high: 1.0,
            model: Model::None,
        }
    }
}

/// Ends of the growing edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Boundary {
    /// Nothing diffuses out of either end.
    ZeroFlux,
    /// The edge is a ring: the last cell neighbours the first.
    Periodic,
}

/// How the number of cells follows the rim's growth.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EdgeGrowth {
    /// As many cells on every row: each cell widens as the rim grows (the paper's models).
    Off,
    /// As many cells on a row as keep every cell the same length: cells divide as the rim
    /// lengthens, evenly along it, each daughter taking the mean of its neighbours.
    Uniform,
}

/// The pattern model.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Model {
    /// No pigmentation: the shell is painted in its ground colour.
    None,
    /// Activator and substrate (Fowler et al. 1992, eq 8).
    ActivatorSubstrate(ActivatorSubstrate),
    /// Activator and inhibitor regulated by a hormone (Fowler et al. 1992, eq 9).
    ActivatorInhibitor(ActivatorInhibitor),
    /// A spreading reaction switched off by a second reaction-diffusion system (the triangles
    /// of *Conus marmoreus*, fig 15).
    Coupled(Coupled),
    /// The vector cellular automaton of prepigment and activity (the 1/6-8/5 rule family).
    Automaton(Automaton),
}

/// What colours the shell under the automaton.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ColourBy {
    /// The prepigment count, mapped from `low..high`.
    Prepigment,
    /// The activity: active cells are pigmented.
    Activity,
    /// Active cells fully pigmented, the others by their prepigment.
    Both,
}

/// Parameters of the vector cellular automaton: x(i, t+1) = f(p, m), p(i, t+1) = g(p, m),
/// m = x(i−1, t) + x(i, t) + x(i+1, t) (eqs 2–4).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Automaton {
    /// A rule "a/b-c/d" (zeros in f's and g's rows), or "custom" for the tables below.
    pub rule: String,
    /// A custom table f: two rows (mother inactive, active) of daughter prepigment by sum m.
    #[serde(default)]
    pub f: Vec<Vec<u32>>,
    /// A custom table g: two rows of daughter activity (0 or 1) by sum m.
    #[serde(default)]
    pub g: Vec<Vec<u32>>,
    /// Cells that start with prepigment, by position along the edge.
    pub start_cells: Vec<u32>,
    /// Further starting cells placed by the seed.
    pub random_starts: u32,
    /// Prepigment of a starting cell.
    pub start_value: u32,
    /// Activity of a starting cell (0 or 1).
    pub start_activity: u32,
    pub colour_by: ColourBy,
}

/// Parameters of eq 8:
/// ∂a/∂t = ρ s (a²/(1 + κa²) + ρ₀) − μa + D_a ∂²a/∂x²,
/// ∂s/∂t = σ(x) − ρ s (a²/(1 + κa²) + ρ₀) − νs + D_s ∂²s/∂x².
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActivatorSubstrate {
    /// ρ: rate of the autocatalysis.
    pub rho: f64,
    /// Relative random fluctuation of ρ from cell to cell (0.025 is ±2.5 %).
    pub rho_noise: f64,
    /// ρ₀: base production of the activator.
    pub rho0: f64,
    /// μ: decay rate of the activator.
    pub mu: f64,
    /// D_a: diffusion of the activator.
    pub d_a: f64,
    /// σ (σ_max when modulated): production of the substrate.
    pub sigma: f64,
    /// Depth of the periodic modulation of σ along the edge, 0 (none) to 1.
    pub sigma_depth: f64,
    /// Period of the modulation of σ, in cells.
    pub sigma_period: f64,
    /// ν: decay rate of the substrate.
    pub nu: f64,
    /// D_s: diffusion of the substrate.
    pub d_s: f64,
    /// κ: saturation of the autocatalysis.
    pub kappa: f64,
    /// Activator concentration at the start.
    pub a_init: f64,
    /// Substrate concentration at the start.
    pub s_init: f64,
}

/// Parameters of eq 9:
/// ∂a/∂t = ρ/(h + h₀) (a²/(1 + κa²) + ρ₀) − μa + D_a ∂²a/∂x²,
/// ∂h/∂t = σ + ρ a²/(1 + κa²) − (ν/c) h + D_h ∂²h/∂x²,
/// dc/dt = ρ′ (mean of a along the edge) − ηc.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActivatorInhibitor {
    /// ρ: rate of the autocatalysis.
    pub rho: f64,
    /// Relative random fluctuation of ρ from cell to cell.
    pub rho_noise: f64,
    /// ρ₀: base production of the activator.
    pub rho0: f64,
    /// μ: decay rate of the activator.
    pub mu: f64,
    /// D_a: diffusion of the activator.
    pub d_a: f64,
    /// σ: base production of the inhibitor.
    pub sigma: f64,
    /// ν: decay rate of the inhibitor, divided by the hormone c.
    pub nu: f64,
    /// D_h: diffusion of the inhibitor.
    pub d_h: f64,
    /// ρ′: production of the hormone per unit of mean activator.
    pub rho_c: f64,
    /// η: decay rate of the hormone.
    pub eta: f64,
    /// h₀: inhibitor level that limits the activator's production when h is small.
    pub h0: f64,
    /// κ: saturation of the autocatalysis.
    pub kappa: f64,
    /// Activator concentration at the start.
    pub a_init: f64,
    /// Inhibitor concentration at the start.
    pub h_init: f64,
    /// Hormone concentration at the start.
    pub c_init: f64,
    /// Cells, chosen at random from the seed, whose activator starts at `start_level`: the
    /// system is excitable, so waves need a start.
    pub starts: u32,
    /// Activator concentration of the starting cells.
    pub start_level: f64,
    /// Width of each start, in cells.
    pub start_width: u32,
}

/// Parameters of the coupled model of *Conus marmoreus* (our design from Fowler et al. 1992 §3.2
/// and Meinhardt's account of triangles; see `pattern::coupled`):
/// ∂a/∂t = ρ (a²/(1 + κa²) + ρ₀) − μa − γ a e⁴/(θ⁴ + e⁴) + D_a ∂²a/∂x²,
/// ∂e/∂t = ρₑ f a/(a + kₐ) (e²/(1 + e²) + ρₑ₀) − μₑ e + Dₑ ∂²e/∂x²,
/// ∂f/∂t = ν_f (1 − f) − ε_f ρₑ f a/(a + kₐ) e²/(1 + e²).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Coupled {
    /// ρ: rate of the spreading reaction's autocatalysis.
    pub rho: f64,
    /// Relative random fluctuation of ρ from cell to cell.
    pub rho_noise: f64,
    /// ρ₀: base production of the spreading reaction.
    pub rho0: f64,
    /// μ: decay of the spreading reaction.
    pub mu: f64,
    /// D_a: diffusion of the spreading reaction (sets how fast triangles widen).
    pub d_a: f64,
    /// κ: saturation of its autocatalysis.
    pub kappa: f64,
    /// ρₑ: autocatalysis of the extinguisher.
    pub rho_e: f64,
    /// ρₑ₀: base production of the extinguisher where the reaction is active (its clock).
    pub rho_e0: f64,
    /// μₑ: decay of the extinguisher.
    pub mu_e: f64,
    /// Dₑ: diffusion of the extinguisher (spreads the extinction across a triangle).
    pub d_e: f64,
    /// kₐ: activity of the reaction at which the extinguisher's production is half on.
    pub k_a: f64,
    /// γ: strength of the extinction.
    pub gamma: f64,
    /// θ: extinguisher level at which the extinction is half on.
    pub theta: f64,
    /// ν_f: recovery of the extinguisher's substrate.
    pub nu_f: f64,
    /// ε_f: use of that substrate by the extinguisher's burst.
    pub eps_f: f64,
    /// Starts of the spreading reaction, placed by the seed.
    pub starts: u32,
    /// Level of the reaction at a start.
    pub start_level: f64,
    /// Width of each start, in cells.
    pub start_width: u32,
}
