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

use super::diffusion;
use super::edge_growth;
use super::edge_model::{EdgeModel, PatternError, check_finite};
use super::grid::Grid;
use super::noise::Noise;
use super::starts;
use crate::spec::pattern::{ActivatorInhibitor as Params, PatternSpec};

pub struct ActivatorInhibitor {
    p: Params,
    grid: Grid,
    a: Vec<f32>,
    h: Vec<f32>,
    c: f64,
    /// Δt·ρ per cell (ρ fluctuates by ±`rho_noise`): the production per step.
    rho_dt: Vec<f32>,
    /// The next step's values, swapped in after each step.
    next_a: Vec<f32>,
    next_h: Vec<f32>,
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
        let rho_dt = grid.per_step(Noise::new(seed, 1).fluctuating(p.rho, p.rho_noise, grid.cells));
        let mut a = vec![p.a_init as f32; grid.cells];
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
            h: vec![p.h_init as f32; grid.cells],
            c: p.c_init,
            next_a: vec![0.0; grid.cells],
            next_h: vec![0.0; grid.cells],
            rho_dt,
            grid,
        })
    }

    fn step(&mut self) {
        let p = &self.p;
        let (dt, n) = (self.grid.dt, self.grid.cells);
        let (da, dh) = (self.grid.diffusion(p.d_a), self.grid.diffusion(p.d_h));
        let mean = f64::from(mean(&self.a));
        // Decay factor 1/(1 + Δt ν/c), written so that c = 0 gives 0 rather than a division.
        let keep = if p.nu == 0.0 {
            1.0
        } else {
            (self.c / (self.c + dt * p.nu)) as f32
        };
        // The weights of a cell's own value (see `diffusion`): a′ = w_a a + D_a (a₋ + a₊) + …,
        // h′ = (w_h h + D_h (h₋ + h₊) + …)·keep.
        let [w_a, w_h] = [1.0 - 2.0 * da - dt * p.mu, 1.0 - 2.0 * dh].map(|w| w as f32);
        let [da, dh, kappa, h0, rho0, sigma_dt] =
            [da, dh, p.kappa, p.h0, p.rho0, p.sigma * dt].map(|x| x as f32);
        let (a, h, rho_dt) = (&self.a[..n], &self.h[..n], &self.rho_dt[..n]);
        let (next_a, next_h) = (&mut self.next_a[..n], &mut self.next_h[..n]);
        diffusion::step(
            [a, h],
            self.grid.boundary,
            #[inline(always)]
            |i, [near_a, near_h]| {
                // With q = 1 + κa² and g = h + h₀, the saturated autocatalysis a²/q and the
                // inhibited production ρ(a²/q + ρ₀)/g share the denominator qg: one division.
                let (a, h) = (a[i], h[i]);
                let aa = a * a;
                let (q, g) = (1.0 + kappa * aa, h + h0);
                let per = rho_dt[i] / (q * g);
                let made = per * (aa + rho0 * q);
                let auto = per * g * aa;
                next_a[i] = diffusion::flush(w_a * a + da * near_a + made);
                next_h[i] = diffusion::flush((w_h * h + dh * near_h + sigma_dt + auto) * keep);
            },
        );
        std::mem::swap(&mut self.a, &mut self.next_a);
        std::mem::swap(&mut self.h, &mut self.next_h);
        self.c += dt * (p.rho_c * mean - p.eta * self.c);
    }
}

/// The mean of `v`, summed in eight interleaved partial sums (cell i into sum i mod 8) that
/// are then added pairwise: a fixed order, so every target gives the same bits, and one the
/// compiler can run as vectors instead of a chain of dependent additions.
fn mean(v: &[f32]) -> f32 {
    let mut sums = [0.0f32; 8];
    let chunks = v.chunks_exact(8);
    for (sum, &x) in sums.iter_mut().zip(chunks.remainder()) {
        *sum += x;
    }
    for chunk in chunks {
        for (sum, &x) in sums.iter_mut().zip(chunk) {
            *sum += x;
        }
    }
    let [s0, s1, s2, s3, s4, s5, s6, s7] = sums;
    (((s0 + s1) + (s2 + s3)) + ((s4 + s5) + (s6 + s7))) / v.len() as f32
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
        check_finite("hormone", &[self.c as f32], hint)?;
        Ok(())
    }

    fn recorded(&self) -> &[f32] {
        &self.a
    }

    fn divide(&mut self, cell: usize, noise: &mut Noise) {
        edge_growth::divide(
            cell,
            [
                &mut [&mut self.a, &mut self.h],
                &mut [&mut self.next_a, &mut self.next_h],
            ],
            &mut self.rho_dt,
            (self.p.rho, self.p.rho_noise),
            &mut self.grid,
            noise,
        );
    }
}
