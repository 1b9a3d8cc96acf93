//! The activator-inhibitor model with a global hormone, eq 9 of Fowler et al. 1992:
//!
//! ∂a/∂t = ρ/(h + h₀) (a²/(1 + κa²) + ρ₀) − μa + D_a ∂²a/∂x²
//! ∂h/∂t = σ + ρ a²/(1 + κa²) − (ν/c) h + D_h ∂²h/∂x²
//! dc/dt = ρ′ ⟨a⟩ − ηc,   ⟨a⟩ the mean activator along the edge.
//!
//! Explicit Euler as Meinhardt ran it, except the inhibitor's decay ν/c: it grows without
//! bound as the hormone c falls, so it is taken implicitly, h ← (h + Δt·gain)/(1 + Δt·ν/c),
//! which damps h towards zero for any c and can never overshoot.
//!
//! With the parameters of fig 14 the activator has a stable low state and a threshold, so the
//! system is excitable: it starts from `starts` activated cells placed by the seed, and keeps
//! its waves alive by branching when the hormone lets the inhibitor decay fast.

use super::diffusion::laplacian;
use super::grid::Grid;
use super::noise::Noise;
use super::starts;
use super::{EdgeModel, PatternError, check_finite};
use crate::spec::pattern::{ActivatorInhibitor as Params, PatternSpec};

pub struct ActivatorInhibitor {
    p: Params,
    grid: Grid,
    a: Vec<f64>,
    h: Vec<f64>,
    c: f64,
    rho: Vec<f64>,
    lap_a: Vec<f64>,
    lap_h: Vec<f64>,
}

impl ActivatorInhibitor {
    pub fn new(p: &Params, spec: &PatternSpec, seed: u64) -> Result<Self, PatternError> {
        if p.eta > 1.0 {
            return Err(PatternError(format!(
                "η = {} makes the hormone overshoot: explicit Euler needs η ≤ 1",
                p.eta
            )));
        }
        let grid = Grid::new(spec);
        let rho = Noise::new(seed, 1).fluctuating(p.rho, p.rho_noise, grid.cells);
        let mut a = vec![p.a_init; grid.cells];
        starts::place(
            &mut a,
            p.starts,
            p.start_width,
            p.start_level,
            grid.refinement,
            seed,
        );
        Ok(Self {
            p: p.clone(),
            a,
            h: vec![p.h_init; grid.cells],
            c: p.c_init,
            lap_a: vec![0.0; grid.cells],
            lap_h: vec![0.0; grid.cells],
            rho,
            grid,
        })
    }

    fn step(&mut self) {
        let p = &self.p;
        let dt = self.grid.dt;
        let (da, dh) = (self.grid.diffusion(p.d_a), self.grid.diffusion(p.d_h));
        laplacian(&self.a, self.grid.boundary, &mut self.lap_a);
        laplacian(&self.h, self.grid.boundary, &mut self.lap_h);
        let mean = self.a.iter().sum::<f64>() / self.grid.cells as f64;
        // Decay factor 1/(1 + Δt ν/c), written so that c = 0 gives 0 rather than a division.
        let keep = if p.nu == 0.0 {
            1.0
        } else {
            self.c / (self.c + dt * p.nu)
        };
        for i in 0..self.grid.cells {
            let (a, h) = (self.a[i], self.h[i]);
            let auto = a * a / (1.0 + p.kappa * a * a);
            self.a[i] = a
                + dt * (self.rho[i] / (h + p.h0) * (auto + p.rho0) - p.mu * a)
                + da * self.lap_a[i];
            self.h[i] = (h + dt * (p.sigma + self.rho[i] * auto) + dh * self.lap_h[i]) * keep;
        }
        self.c += dt * (p.rho_c * mean - p.eta * self.c);
    }
}

impl EdgeModel for ActivatorInhibitor {
    fn advance_row(&mut self) -> Result<(), PatternError> {
        for _ in 0..self.grid.steps_per_row {
            self.step();
        }
        let hint =
            "the autocatalysis outran its inhibition; raise κ (saturation), h₀ or μ, or lower ρ";
        check_finite("activator", &self.a, hint)?;
        check_finite("inhibitor", &self.h, hint)?;
        check_finite("hormone", std::slice::from_ref(&self.c), hint)?;
        Ok(())
    }

    fn recorded(&self) -> &[f64] {
        &self.a
    }
}
