//! The activator-substrate model, eq 8 of Fowler et al. 1992 (Meinhardt 1984):
//!
//! ∂a/∂t = ρ s (a²/(1 + κa²) + ρ₀) − μa + D_a ∂²a/∂x²
//! ∂s/∂t = σ(x) − ρ s (a²/(1 + κa²) + ρ₀) − νs + D_s ∂²s/∂x²
//!
//! integrated with explicit Euler (Δt = Δx = 1 unrefined) as Meinhardt did, except the
//! substrate's consumption and decay, which are linear in s and taken implicitly,
//! s ← (s + Δt σ + D_s ∂²s/∂x²)/(1 + Δt (ρ(a²/(1 + κa²) + ρ₀) + ν)), and the activator is made
//! from that new s. Explicit Euler drives s below zero once ρa²/(1 + κa²) exceeds 1, and fig
//! 11's stripes (κ = 0, a up to 10, ρ = 0.01 ± 2.5 %) come within a few per cent of that; the
//! implicit step cannot overshoot, and keeps the uniform steady state exactly. ρ fluctuates from
//! cell to cell by ±`rho_noise` (seeded), which starts pattern formation; σ may be modulated
//! along the edge, σ(x) = σ_max (1 − depth (1 − cos 2πx/period)/2), for the wavy lines of
//! *Amoria* and the stripes with waves of *Volutoconus*.

use super::diffusion;
use super::edge_growth;
use super::edge_model::{EdgeModel, PatternError, check_finite, check_nonnegative};
use super::grid::Grid;
use super::noise::Noise;
use crate::spec::pattern::{ActivatorSubstrate as Params, PatternSpec};
use std::f64::consts::TAU;

pub struct ActivatorSubstrate {
    p: Params,
    grid: Grid,
    a: Vec<f32>,
    s: Vec<f32>,
    /// Δt·ρ per cell (ρ fluctuates by ±`rho_noise`).
    rho_dt: Vec<f32>,
    /// Δt·σ(x) per cell: the substrate's supply per step.
    sigma_dt: Vec<f32>,
    /// The next step's values, swapped in after each step.
    next_a: Vec<f32>,
    next_s: Vec<f32>,
}

impl ActivatorSubstrate {
    pub fn new(p: &Params, spec: &PatternSpec, seed: u64) -> Result<Self, PatternError> {
        let grid = Grid::new(spec);
        let rho_dt = grid.per_step(Noise::new(seed, 1).fluctuating(p.rho, p.rho_noise, grid.cells));
        let sigma_dt = grid.per_step((0..grid.cells).map(|i| {
            let phase = TAU * grid.position(i) / p.sigma_period;
            p.sigma * (1.0 - p.sigma_depth * (1.0 - libm::cos(phase)) / 2.0)
        }));
        Ok(Self {
            p: p.clone(),
            a: vec![p.a_init as f32; grid.cells],
            s: vec![p.s_init as f32; grid.cells],
            next_a: vec![0.0; grid.cells],
            next_s: vec![0.0; grid.cells],
            rho_dt,
            sigma_dt,
            grid,
        })
    }

    fn step(&mut self) {
        let p = &self.p;
        let (dt, n) = (self.grid.dt, self.grid.cells);
        let (da, ds) = (self.grid.diffusion(p.d_a), self.grid.diffusion(p.d_s));
        // The weights of a cell's own value (see `diffusion`): a′ = w_a a + D_a (a₋ + a₊) + …,
        // and the substrate's supply w_s s + D_s (s₋ + s₊) + Δt σ.
        let [w_a, w_s] = [1.0 - 2.0 * da - dt * p.mu, 1.0 - 2.0 * ds].map(|w| w as f32);
        let [da, ds, kappa, rho0, kept] =
            [da, ds, p.kappa, p.rho0, 1.0 + dt * p.nu].map(|x| x as f32);
        let (a, s) = (&self.a[..n], &self.s[..n]);
        let (rho_dt, sigma_dt) = (&self.rho_dt[..n], &self.sigma_dt[..n]);
        let (next_a, next_s) = (&mut self.next_a[..n], &mut self.next_s[..n]);
        diffusion::step(
            [a, s],
            self.grid.boundary,
            #[inline(always)]
            |i, [near_a, near_s]| {
                // With q = 1 + κa² and made = Δtρ(a² + ρ₀q), the gain per unit substrate in a
                // step is made/q; the implicit substrate s′ = supply/(1 + made/q + Δtν) is
                // supply·q/(q(1 + Δtν) + made), and the production made/q · s′ has the same
                // denominator: one division for both.
                let (a, s) = (a[i], s[i]);
                let aa = a * a;
                let q = 1.0 + kappa * aa;
                let made = rho_dt[i] * (aa + rho0 * q);
                let supply = w_s * s + ds * near_s + sigma_dt[i];
                let per = supply / (q * kept + made);
                next_a[i] = diffusion::flush(w_a * a + da * near_a + made * per);
                next_s[i] = diffusion::flush(q * per);
            },
        );
        std::mem::swap(&mut self.a, &mut self.next_a);
        std::mem::swap(&mut self.s, &mut self.next_s);
    }
}

impl EdgeModel for ActivatorSubstrate {
    fn advance_row(&mut self) -> Result<(), PatternError> {
        for _ in 0..self.grid.steps_per_row {
            self.step();
        }
        let hint = "the autocatalysis outran its decay; raise κ (saturation) or μ, or lower ρ";
        check_finite("activator", &self.a, hint)?;
        check_finite("substrate", &self.s, hint)?;
        check_nonnegative(
            "substrate",
            &self.s,
            "its production σ, its modulation or its start is negative; all must be ≥ 0",
        )
    }

    fn recorded(&self) -> &[f32] {
        &self.a
    }

    fn divide(&mut self, cell: usize, noise: &mut Noise) {
        edge_growth::divide(
            cell,
            [
                &mut [&mut self.a, &mut self.s, &mut self.sigma_dt],
                &mut [&mut self.next_a, &mut self.next_s],
            ],
            &mut self.rho_dt,
            (self.p.rho, self.p.rho_noise),
            &mut self.grid,
            noise,
        );
    }
}
