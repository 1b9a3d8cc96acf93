//! The vector cellular automaton for shell pigmentation (the 1/6-8/5 rule family): each cell
//! of the growing edge holds a prepigment count x and an activity p ∈ {0, 1}; the daughter
//! cell's state is f(p, m), g(p, m) of her mother's activity and the prepigment sum m of her
//! mother and two aunts (eq 2). The edge is a ring (or, with zero-flux ends, the end cell is
//! its own missing aunt). It starts from a few special cells with prepigment in an otherwise
//! empty, inactive edge.

use super::automaton_rule::{MAX_COUNT, Rule};
use super::edge_growth::insert_copy;
use super::edge_model::{EdgeModel, PatternError};
use super::noise::Noise;
use crate::spec::pattern::{Automaton as Params, Boundary, ColourBy, PatternSpec};

pub struct Automaton {
    rule: Rule,
    x: Vec<u32>,
    p: Vec<u8>,
    next_x: Vec<u32>,
    next_p: Vec<u8>,
    recorded: Vec<f32>,
    generations: u32,
    boundary: Boundary,
    colour_by: ColourBy,
}

/// The rule a spec names or gives.
pub fn rule_of(p: &Params) -> Result<Rule, String> {
    if p.rule == "custom" {
        Rule::tables(&p.f, &p.g)
    } else if p.f.is_empty() && p.g.is_empty() {
        Rule::named(&p.rule)
    } else {
        Err(format!(
            "rule '{}' is named, so tables f and g must be empty (or name the rule \"custom\")",
            p.rule
        ))
    }
}

impl Automaton {
    pub fn new(p: &Params, spec: &PatternSpec, seed: u64) -> Result<Self, PatternError> {
        let rule = rule_of(p).map_err(PatternError)?;
        let cells = spec.cells as usize;
        if p.start_value > MAX_COUNT {
            return Err(PatternError(format!(
                "a start holds at most {MAX_COUNT} prepigment, not {}",
                p.start_value
            )));
        }
        let mut x = vec![0; cells];
        let mut activity = vec![0u8; cells];
        let mut noise = Noise::new(seed, 2);
        let random = (0..p.random_starts).map(|_| noise.below(cells));
        for i in p.start_cells.iter().map(|&s| s as usize).chain(random) {
            let i = i.min(cells - 1); // cells ≥ 1, checked by `pattern::build`.
            x[i] = p.start_value;
            activity[i] = u8::from(p.start_activity > 0);
        }
        Ok(Self {
            rule,
            recorded: x.iter().map(|&v| v as f32).collect(),
            next_x: x.clone(),
            next_p: activity.clone(),
            x,
            p: activity,
            generations: spec.iterations.max(1),
            boundary: spec.boundary,
            colour_by: p.colour_by,
        })
    }

    /// The activities of the cells.
    pub fn activity(&self) -> &[u8] {
        &self.p
    }

    fn generation(&mut self) {
        let n = self.x.len();
        for i in 0..n {
            let (left, right) = match self.boundary {
                Boundary::Periodic => (self.x[(i + n - 1) % n], self.x[(i + 1) % n]),
                Boundary::ZeroFlux => (
                    self.x[i.checked_sub(1).unwrap_or(i)],
                    self.x[if i + 1 < n { i + 1 } else { i }],
                ),
            };
            let m = (left + self.x[i] + right) as usize;
            let p = usize::from(self.p[i]);
            self.next_x[i] = self.rule.f[p][m];
            self.next_p[i] = self.rule.g[p][m] as u8;
        }
        std::mem::swap(&mut self.x, &mut self.next_x);
        std::mem::swap(&mut self.p, &mut self.next_p);
    }
}

impl EdgeModel for Automaton {
    fn advance_row(&mut self) -> Result<(), PatternError> {
        for _ in 0..self.generations {
            self.generation();
        }
        for (r, &x) in self.recorded.iter_mut().zip(&self.x) {
            *r = x as f32;
        }
        Ok(())
    }

    /// The prepigment counts.
    fn recorded(&self) -> &[f32] {
        &self.recorded
    }

    /// The daughter is a copy of its mother: counts and activity are not means.
    fn divide(&mut self, cell: usize, _noise: &mut Noise) {
        insert_copy(&mut self.x, cell);
        insert_copy(&mut self.p, cell);
        insert_copy(&mut self.recorded, cell);
        self.next_x.push(0);
        self.next_p.push(0);
    }

    /// By prepigment (mapped from low..high), by activity, or both: active cells full
    /// pigment, inactive ones their prepigment up to 60 %.
    fn pigment(&self, low: f64, high: f64, out: &mut [f32]) {
        for ((out, &x), &p) in out.iter_mut().zip(&self.recorded).zip(&self.p) {
            let pre = ((f64::from(x) - low) / (high - low)).clamp(0.0, 1.0) as f32;
            *out = match self.colour_by {
                ColourBy::Prepigment => pre,
                ColourBy::Activity => f32::from(p),
                ColourBy::Both if p > 0 => 1.0,
                ColourBy::Both => 0.6 * pre,
            };
        }
    }
}
