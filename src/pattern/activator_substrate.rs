//! The activator-substrate model, eq 8 of Fowler et al. 1992 (Meinhardt 1984):
//!
//! ∂a/∂t = ρ s (a²/(1 + κa²) + ρ₀) − μa + D_a ∂²a/∂x²
//! ∂s/∂t = σ(x) − ρ s (a²/(1 + κa²) + ρ₀) − νs + D_s ∂²s/∂x²
//!
//! integrated with explicit Euler (Δt = Δx = 1 unrefined) as Meinhardt did. ρ fluctuates from
//! cell to cell by ±`rho_noise` (seeded), which starts pattern formation; σ may be modulated
//! along the edge, σ(x) = σ_max (1 − depth (1 − cos 2πx/period)/2), for the wavy lines of
//! *Amoria* and the stripes with waves of *Volutoconus*.

use super::diffusion::laplacian;
use super::grid::Grid;
use super::noise::Noise;
use super::{EdgeModel, PatternError, check_finite, check_nonnegative};
use crate::spec::pattern::{ActivatorSubstrate as Params, PatternSpec};
use std::f64::consts::TAU;

pub struct ActivatorSubstrate {
    p: Params,
    grid: Grid,
    a: Vec<f64>,
    s: Vec<f64>,
    rho: Vec<f64>,
    sigma: Vec<f64>,
    lap_a: Vec<f64>,
    lap_s: Vec<f64>,
}

impl ActivatorSubstrate {
    pub fn new(p: &Params, spec: &PatternSpec, seed: u64) -> Result<Self, PatternError> {
        let grid = Grid::new(spec);
        let rho = Noise::new(seed, 1).fluctuating(p.rho, p.rho_noise, grid.cells);
        let sigma = (0..grid.cells)
            .map(|i| {
                let phase = TAU * grid.position(i) / p.sigma_period;
                p.sigma * (1.0 - p.sigma_depth * (1.0 - libm::cos(phase)) / 2.0)
            })
            .collect();
        Ok(Self {
            p: p.clone(),
            a: vec![p.a_init; grid.cells],
            s: vec![p.s_init; grid.cells],
            lap_a: vec![0.0; grid.cells],
            lap_s: vec![0.0; grid.cells],
            rho,
            sigma,
            grid,
        })
    }

    fn step(&mut self) {
        let p = &self.p;
        let dt = self.grid.dt;
        let (da, ds) = (self.grid.diffusion(p.d_a), self.grid.diffusion(p.d_s));
        laplacian(&self.a, self.grid.boundary, &mut self.lap_a);
        laplacian(&self.s, self.grid.boundary, &mut self.lap_s);
        for i in 0..self.grid.cells {
            let (a, s) = (self.a[i], self.s[i]);
            let production = self.rho[i] * s * (a * a / (1.0 + p.kappa * a * a) + p.rho0);
            self.a[i] = a + dt * (production - p.mu * a) + da * self.lap_a[i];
            self.s[i] = s + dt * (self.sigma[i] - production - p.nu * s) + ds * self.lap_s[i];
        }
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
            "one time step consumes more than there is; lower ρ or raise κ",
        )
    }

    fn recorded(&self) -> &[f64] {
        &self.a
    }
}
