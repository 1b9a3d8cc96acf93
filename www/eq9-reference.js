// The reference the benchmark sets beside the wasm solvers: eq 9 of Fowler, Meinhardt &
// Prusinkiewicz 1992 (activator a, inhibitor h, hormone c) written as a JavaScript user would
// write it, in double precision on typed arrays: explicit Euler with the inhibitor's decay ν/c
// taken implicitly, zero-flux ends, one pass per time step. Its starts and fluctuations come
// from a simple generator of its own, so its pattern is like, not equal to, the Rust model's;
// the work per cell and step is the same.

/**
 * A solver of eq 9 on `cells` cells with the parameters `p` of a pattern spec's model and the
 * time step `dt` (1, or 1/k² on an edge refined k times, where diffusion per step is unchanged).
 */
export function eq9(p, cells, dt) {
  let seed = 1;
  const random = () => {
    seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
    return seed / 4294967296;
  };
  let a = new Float64Array(cells).fill(p.a_init);
  let h = new Float64Array(cells).fill(p.h_init);
  let nextA = new Float64Array(cells);
  let nextH = new Float64Array(cells);
  const rho = new Float64Array(cells);
  for (let i = 0; i < cells; i++) rho[i] = p.rho * (1 + p.rho_noise * (2 * random() - 1));
  for (let s = 0; s < p.starts; s++) a[Math.floor(random() * cells)] = p.start_level;
  let c = p.c_init;

  function step() {
    let sum = 0;
    for (let i = 0; i < cells; i++) sum += a[i];
    const keep = p.nu === 0 ? 1 : c / (c + dt * p.nu);
    for (let i = 0; i < cells; i++) {
      const ai = a[i];
      const hi = h[i];
      const left = i > 0 ? i - 1 : i;
      const right = i < cells - 1 ? i + 1 : i;
      const lapA = a[left] - 2 * ai + a[right];
      const lapH = h[left] - 2 * hi + h[right];
      const auto = (ai * ai) / (1 + p.kappa * ai * ai);
      nextA[i] = ai + dt * ((rho[i] / (hi + p.h0)) * (auto + p.rho0) - p.mu * ai) + p.d_a * lapA;
      nextH[i] = (hi + dt * (p.sigma + rho[i] * auto) + p.d_h * lapH) * keep;
    }
    [a, nextA] = [nextA, a];
    [h, nextH] = [nextH, h];
    c += dt * (p.rho_c * (sum / cells) - p.eta * c);
  }

  return {
    /** Advances `steps` time steps. */
    advance(steps) {
      for (let k = 0; k < steps; k++) step();
    },
    /** The activator along the edge. */
    activator: () => a,
  };
}
