//! Triangles on *Conus marmoreus* (Fowler et al. 1992, fig 15): a spreading reaction switched
//! off by a second reaction-diffusion system. The paper gives no equations; this design follows
//! its remark that the pigment process is "controlled by another reaction-diffusion process"
//! and Meinhardt's account of triangles: a slowly spreading reaction draws a triangle; once it
//! has been active for a while a second mechanism is triggered that extinguishes it; the
//! reaction survives at the flanks, from which the next spread starts; a stronger extinction
//! gives chains of smaller triangles.
//!
//! - The **spreading reaction** a is bistable (saturating autocatalysis against decay), so an
//!   active region invades its surroundings at a constant speed set by D_a: the two sides of a
//!   triangle.
//!   ∂a/∂t = ρ (a²/(1 + κa²) + ρ₀) − μa − γ a e⁴/(θ⁴ + e⁴) + D_a ∂²a/∂x²
//! - The **extinguisher** e is an autocatalytic substance that can only be made where the
//!   reaction is active (the factor a/(a + kₐ), which saturates so that a fading reaction does
//!   not starve it). Its base production ρₑ₀ is a clock: it creeps past its threshold first
//!   where the reaction has been active longest, then bursts and runs through the active region
//!   by diffusion, switching the reaction off (the steep factor e⁴/(θ⁴ + e⁴) keeps the reaction
//!   untouched until the burst). The youngest cells at the flanks, only just activated, are
//!   not yet excitable and survive.
//!   ∂e/∂t = ρₑ f a/(a + kₐ) (e²/(1 + e²) + ρₑ₀) − μₑ e + Dₑ ∂²e/∂x²
//! - The extinguisher's **substrate** f is used up by the burst and recovers slowly, so the
//!   extinguisher burns out and the region can be invaded again.
//!   ∂f/∂t = ν_f (1 − f) − ε_f ρₑ f a/(a + kₐ) e²/(1 + e²)
//!
//! Explicit Euler with Δt = Δx = 1 (unrefined), as for the paper's models.

use super::diffusion::laplacian;
use super::grid::Grid;
use super::noise::Noise;
use super::starts;
use super::{EdgeModel, PatternError, check_finite, check_nonnegative};
use crate::spec::pattern::{Coupled as Params, PatternSpec};

pub struct Coupled {
    p: Params,
    grid: Grid,
    a: Vec<f64>,
    e: Vec<f64>,
    f: Vec<f64>,
    rho: Vec<f64>,
    lap_a: Vec<f64>,
    lap_e: Vec<f64>,
}

impl Coupled {
    pub fn new(p: &Params, spec: &PatternSpec, seed: u64) -> Result<Self, PatternError> {
        let grid = Grid::new(spec);
        let rho = Noise::new(seed, 1).fluctuating(p.rho, p.rho_noise, grid.cells);
        let mut a = vec![0.0; grid.cells];
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
            e: vec![0.0; grid.cells],
            f: vec![1.0; grid.cells],
            lap_a: vec![0.0; grid.cells],
            lap_e: vec![0.0; grid.cells],
            rho,
            grid,
        })
    }

    fn step(&mut self) {
        let p = &self.p;
        let dt = self.grid.dt;
        let (da, de) = (self.grid.diffusion(p.d_a), self.grid.diffusion(p.d_e));
        laplacian(&self.a, self.grid.boundary, &mut self.lap_a);
        laplacian(&self.e, self.grid.boundary, &mut self.lap_e);
        let theta4 = p.theta * p.theta * p.theta * p.theta;
        for i in 0..self.grid.cells {
            let (a, e, f) = (self.a[i], self.e[i], self.f[i]);
            let e2 = e * e;
            let extinction = p.gamma * a * e2 * e2 / (theta4 + e2 * e2);
            let reaction =
                self.rho[i] * (a * a / (1.0 + p.kappa * a * a) + p.rho0) - p.mu * a - extinction;
            let enabled = p.rho_e * f * a / (a + p.k_a);
            let burst = enabled * e2 / (1.0 + e2);
            self.a[i] = a + dt * reaction + da * self.lap_a[i];
            self.e[i] = e + dt * (burst + enabled * p.rho_e0 - p.mu_e * e) + de * self.lap_e[i];
            self.f[i] = f + dt * (p.nu_f * (1.0 - f) - p.eps_f * burst);
        }
    }
}

impl EdgeModel for Coupled {
    fn advance_row(&mut self) -> Result<(), PatternError> {
        for _ in 0..self.grid.steps_per_row {
            self.step();
        }
        let hint = "lower ρ or ρₑ, or raise κ, μ or μₑ";
        check_finite("reaction", &self.a, hint)?;
        check_finite("extinguisher", &self.e, hint)?;
        check_nonnegative("extinguisher's substrate", &self.f, "lower ε_f or ρₑ")
    }

    fn recorded(&self) -> &[f64] {
        &self.a
    }
}
