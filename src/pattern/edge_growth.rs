//! A growing edge whose cells divide as the rim lengthens. Fowler, Meinhardt & Prusinkiewicz
//! keep the number of cells fixed: "We ignore the effect of the gradual increase of polygon
//! size resulting from the rim's growth" (§3, after eqs 8–9), so every cell widens with the
//! shell and a pattern's wavelength grows with it. Meinhardt's own account of the growing edge
//! (*The Algorithmic Beauty of Sea Shells*) inserts cells instead: the number of cells follows
//! the rim's length, so each cell keeps its size, diffusion acts over a constant length, the
//! pattern keeps its wavelength in absolute size, and new stripes appear between old ones
//! where the edge has room for them.
//!
//! Here the count on each row is the last row's times the rim's length there over its length
//! at the last row, never fewer than the apex's cells (`pattern.apex_cells`, at least one) and
//! never fewer than the row before: cells do not die. Nor more than the last row's: a rim
//! longer before than at the end (a generating curve that shrinks, λ_c < 1) keeps the last
//! row's cells from the apex on, as a fixed edge would, instead of the millions its first
//! rows would ask for.
//! A cell divides by putting a daughter after itself, whose concentrations are the mean of its
//! two neighbours' (the automaton's discrete counts: a copy of the mother's), with its own
//! fluctuation of ρ drawn from the seed. Uniform growth spreads the divisions evenly along the
//! edge and over time: the m-th division splits the cell at the fraction m/φ (mod 1) of the
//! edge, a sequence that never clusters.

use super::edge_model::{EdgeModel, PatternError};
use super::grid::Grid;
use super::noise::Noise;
use crate::spec::pattern::Boundary;

/// Cells on each row for a last row of `last` cells and at least `apex` (clamped to 1..=last),
/// given the rim's length on each row (`rims[r]`, shell units): never more than `last`.
pub(crate) fn cell_counts(last: u32, apex: u32, rims: &[f64]) -> Result<Vec<u32>, PatternError> {
    let end = *rims
        .last()
        .ok_or_else(|| PatternError("no rows to grow".into()))?;
    if let Some(r) = rims.iter().position(|&l| !(l.is_finite() && l > 0.0)) {
        return Err(PatternError(format!(
            "the rim at row {r} has no length ({}), so edge growth cannot follow it",
            rims[r]
        )));
    }
    let last = last.max(1);
    let mut most = apex.clamp(1, last);
    Ok(rims
        .iter()
        .map(|&l| {
            let n = (f64::from(last) * l / end)
                .round()
                .clamp(1.0, f64::from(last)) as u32;
            most = most.max(n);
            most
        })
        .collect())
}

/// The divisions of one growing edge: which cell divides next (the m-th division splits the
/// cell at frac(m/φ) of the edge), and the seed's stream that gives each daughter its ρ.
pub(crate) struct Divisions {
    made: u64,
    noise: Noise,
}

impl Divisions {
    /// 1/φ, the golden ratio's inverse: its multiples mod 1 spread most evenly over [0, 1).
    const STRIDE: f64 = 0.618_033_988_749_894_9;
    /// The stream of the seed that gives daughter cells their fluctuation of ρ.
    const DAUGHTERS: u64 = 7;

    pub fn new(seed: u64) -> Self {
        Self {
            made: 0,
            noise: Noise::new(seed, Self::DAUGHTERS),
        }
    }

    /// The cell of an edge of `n` cells that divides next.
    fn next(&mut self, n: usize) -> usize {
        self.made += 1;
        let at = (self.made as f64 * Self::STRIDE).fract();
        ((at * n as f64) as usize).min(n - 1)
    }

    /// Divides `model`'s cells, one after another, until it has `cells`.
    pub fn divide_to(&mut self, model: &mut dyn EdgeModel, cells: usize) {
        while model.recorded().len() < cells {
            let cell = self.next(model.recorded().len());
            model.divide(cell, &mut self.noise);
        }
    }
}

/// A daughter after cell `c` of `v`: the mean of `c` and the cell after it (the ring's first
/// after the last on a periodic edge; `c` itself after the last on a zero-flux edge).
fn insert_mean(v: &mut Vec<f32>, c: usize, boundary: Boundary) {
    let next = match boundary {
        _ if c + 1 < v.len() => v[c + 1],
        Boundary::Periodic => v[0],
        Boundary::ZeroFlux => v[c],
    };
    v.insert(c + 1, (v[c] + next) * 0.5);
}

/// A daughter after cell `c` of `v`, a copy of its mother.
pub(crate) fn insert_copy<T: Copy>(v: &mut Vec<T>, c: usize) {
    v.insert(c + 1, v[c]);
}

/// Cell `cell` of a reaction-diffusion model divides: a daughter after it in each of its
/// `fields` takes the mean of its neighbours; its Δt·ρ in `rho_dt` is drawn from `noise` with
/// ρ's fluctuation `(ρ, fraction)`, as each cell's is at the start (see
/// [`Noise::fluctuating`]); each next-step buffer in `next` and the `grid` grow by one cell.
pub(crate) fn divide(
    cell: usize,
    [fields, next]: [&mut [&mut Vec<f32>]; 2],
    rho_dt: &mut Vec<f32>,
    (rho, fraction): (f64, f64),
    grid: &mut Grid,
    noise: &mut Noise,
) {
    for field in fields {
        insert_mean(field, cell, grid.boundary);
    }
    for buffer in next {
        buffer.push(0.0);
    }
    rho_dt.insert(
        cell + 1,
        grid.per_step(noise.fluctuating(rho, fraction, 1))[0],
    );
    grid.cells += 1;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_count_follows_the_rim_never_falls_and_ends_at_the_last_rows() {
        let rims = [1.0, 2.0, 4.0, 3.9, 8.0];
        assert_eq!(cell_counts(64, 1, &rims).unwrap(), [8, 16, 32, 32, 64]);
        assert_eq!(cell_counts(64, 1, &[1e-9, 1.0]).unwrap(), [1, 64]);
        assert!(cell_counts(64, 1, &[0.0, 1.0]).is_err());
        assert!(cell_counts(64, 1, &[f64::NAN, 1.0]).is_err());
    }

    #[test]
    fn the_apex_holds_its_cells_until_the_rim_has_room_for_more() {
        let rims = [1.0, 2.0, 4.0, 3.9, 8.0];
        assert_eq!(cell_counts(64, 20, &rims).unwrap(), [20, 20, 32, 32, 64]);
        assert_eq!(cell_counts(64, 0, &rims).unwrap(), [8, 16, 32, 32, 64]);
        assert_eq!(cell_counts(64, 500, &rims).unwrap(), [64; 5]);
    }

    #[test]
    fn a_rim_longer_before_than_at_the_end_keeps_the_last_rows_cells() {
        // A shrinking generating curve: the apex's rim is 4,800 times the lip's.
        let rims: Vec<f64> = (0..40).map(|r| 0.8f64.powi(r)).collect();
        assert_eq!(cell_counts(64, 1, &rims).unwrap(), [64; 40]);
        assert_eq!(cell_counts(64, 1, &[0.5, 2.0, 1.0]).unwrap(), [32, 64, 64]);
    }

    #[test]
    fn divisions_spread_evenly_along_the_edge() {
        let mut d = Divisions::new(1);
        let mut hits = [0u32; 10];
        for _ in 0..1000 {
            hits[d.next(10)] += 1;
        }
        assert!(hits.iter().all(|&h| (95..=105).contains(&h)), "{hits:?}");
    }

    #[test]
    fn a_daughter_takes_the_mean_of_its_neighbours() {
        let mut v = vec![1.0, 3.0, 5.0];
        insert_mean(&mut v, 0, Boundary::ZeroFlux);
        assert_eq!(v, [1.0, 2.0, 3.0, 5.0]);
        insert_mean(&mut v, 3, Boundary::ZeroFlux);
        assert_eq!(v, [1.0, 2.0, 3.0, 5.0, 5.0]);
        insert_mean(&mut v, 4, Boundary::Periodic);
        assert_eq!(v, [1.0, 2.0, 3.0, 5.0, 5.0, 3.0]);
        let mut counts = vec![1u32, 7];
        insert_copy(&mut counts, 1);
        assert_eq!(counts, [1, 7, 7]);
    }
}
