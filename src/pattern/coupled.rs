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

use super::diffusion;
use super::edge_growth;
use super::edge_model::{EdgeModel, PatternError, check_finite, check_nonnegative};
use super::grid::Grid;
use super::noise::Noise;
use super::starts;
use crate::spec::pattern::{Coupled as Params, PatternSpec};

pub struct Coupled {
    p: Params,
    grid: Grid,
    a: Vec<f32>,
    e: Vec<f32>,
    f: Vec<f32>,
    /// Δt·ρ per cell (ρ fluctuates by ±`rho_noise`).
    rho_dt: Vec<f32>,
    /// The next step's values, swapped in after each step.
    next_a: Vec<f32>,
    next_e: Vec<f32>,
    next_f: Vec<f32>,
}

impl Coupled {
    pub fn new(p: &Params, spec: &PatternSpec, seed: u64) -> Result<Self, PatternError> {
        let grid = Grid::new(spec);
        let rho_dt = grid.per_step(Noise::new(seed, 1).fluctuating(p.rho, p.rho_noise, grid.cells));
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
            next_a: vec![0.0; grid.cells],
            next_e: vec![0.0; grid.cells],
            next_f: vec![0.0; grid.cells],
            rho_dt,
            grid,
        })
    }

    fn step(&mut self) {
        let p = &self.p;
        let (dt, n) = (self.grid.dt, self.grid.cells);
        let (da, de) = (self.grid.diffusion(p.d_a), self.grid.diffusion(p.d_e));
        // The weights of a cell's own value (see `diffusion`): x′ = w x + D (x₋ + x₊) + …
        let [w_a, w_e, w_f] = [
            1.0 - 2.0 * da - dt * p.mu,
            1.0 - 2.0 * de - dt * p.mu_e,
            1.0 - dt * p.nu_f,
        ]
        .map(|w| w as f32);
        let [da, de, kappa, rho0, gamma_dt, theta] =
            [da, de, p.kappa, p.rho0, p.gamma * dt, p.theta].map(|x| x as f32);
        let [rho_e_dt, rho_e0, k_a, nu_f_dt, eps_f] =
            [p.rho_e * dt, p.rho_e0, p.k_a, p.nu_f * dt, p.eps_f].map(|x| x as f32);
        let theta4 = theta * theta * theta * theta;
        let (a, e, f, rho_dt) = (&self.a[..n], &self.e[..n], &self.f[..n], &self.rho_dt[..n]);
        let (next_a, next_e, next_f) = (
            &mut self.next_a[..n],
            &mut self.next_e[..n],
            &mut self.next_f[..n],
        );
        diffusion::step(
            [a, e],
            self.grid.boundary,
            #[inline(always)]
            |i, [near_a, near_e]| {
                // Every rate below is per step (Δt folded into its constant).
                let (a, e, f) = (a[i], e[i], f[i]);
                let (aa, e2) = (a * a, e * e);
                let extinction = gamma_dt * a * e2 * e2 / (theta4 + e2 * e2);
                let made = rho_dt[i] * (aa / (1.0 + kappa * aa) + rho0);
                let enabled = rho_e_dt * f * a / (a + k_a);
                let burst = enabled * e2 / (1.0 + e2);
                next_a[i] = diffusion::flush(w_a * a + da * near_a + made - extinction);
                next_e[i] = diffusion::flush(w_e * e + de * near_e + burst + enabled * rho_e0);
                next_f[i] = diffusion::flush(w_f * f + nu_f_dt - eps_f * burst);
            },
        );
        std::mem::swap(&mut self.a, &mut self.next_a);
        std::mem::swap(&mut self.e, &mut self.next_e);
        std::mem::swap(&mut self.f, &mut self.next_f);
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

    fn recorded(&self) -> &[f32] {
        &self.a
    }

    fn divide(&mut self, cell: usize, noise: &mut Noise) {
        edge_growth::divide(
            cell,
            [
                &mut [&mut self.a, &mut self.e, &mut self.f],
                &mut [&mut self.next_a, &mut self.next_e, &mut self.next_f],
            ],
            &mut self.rho_dt,
            (self.p.rho, self.p.rho_noise),
            &mut self.grid,
            noise,
        );
    }
}
