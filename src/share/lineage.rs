//! A lineage of shells bred by choosing among offspring (see `breeding`), as a link carries it:
//! the choices made from a first shell and the mutation rate each generation was bred at
//! (`breed=0.4/3,0.4/7,0.5`: the third offspring at rate 0.4, then the seventh, and the next
//! offspring at 0.5). Reading one never fails: what cannot be read ends it, said in a problem.

use crate::spec::Problem;
use crate::spec::fields::display;

/// The link key of a lineage.
pub const KEY: &str = "breed";
/// Offspring of each generation.
pub const OFFSPRING: usize = 8;
/// The mutation rate a lineage starts at, and the least and most it may be: the standard
/// deviation of a step, in halves of the span the parameter map gives the value.
pub const RATE: f64 = 0.4;
pub const RATES: (f64, f64) = (0.05, 1.0);
/// Most choices a lineage follows: each is replayed on the page's thread when its link opens.
pub const MAX_CHOICES: usize = 100;
/// The choices made from a first shell: each the rate a generation was bred at and the
/// offspring chosen from it (1 to [`OFFSPRING`]); and the rate of the generation shown.
#[derive(Clone, Debug, PartialEq)]
pub struct Lineage {
    pub chosen: Vec<(f64, usize)>,
    pub rate: f64,
}

impl Default for Lineage {
    fn default() -> Self {
        Self {
            chosen: Vec::new(),
            rate: RATE,
        }
    }
}

impl Lineage {
    /// Reads a link's value, as far as it can be read: a rate outside [`RATES`] is clamped, and
    /// the choices stop before the first that cannot be read; each said in a problem.
    pub fn parse(text: &str) -> (Self, Vec<Problem>) {
        let mut problems = Vec::new();
        let rate = |text: &str, problems: &mut Vec<Problem>| match text.trim().parse::<f64>() {
            Ok(r) if r.is_finite() => {
                let kept = r.clamp(RATES.0, RATES.1);
                if kept != r {
                    problems.push(Problem::new(
                        KEY,
                        format!(
                            "a mutation rate of {} is outside {} to {}; used {}",
                            display(r),
                            display(RATES.0),
                            display(RATES.1),
                            display(kept)
                        ),
                    ));
                }
                Some(kept)
            }
            _ => {
                problems.push(Problem::new(
                    KEY,
                    format!("'{text}' is not a mutation rate; the lineage stops before it"),
                ));
                None
            }
        };
        let mut lineage = Self::default();
        let items: Vec<&str> = text.split(',').collect();
        for (i, item) in items.iter().enumerate() {
            let last = i + 1 == items.len();
            if lineage.chosen.len() == MAX_CHOICES && !last {
                problems.push(Problem::new(
                    KEY,
                    format!("the lineage has more than {MAX_CHOICES} choices; followed the first {MAX_CHOICES}"),
                ));
                break;
            }
            match item.split_once('/') {
                Some((r, child)) => {
                    let Some(r) = rate(r, &mut problems) else {
                        break;
                    };
                    match child.trim().parse::<usize>() {
                        Ok(c) if (1..=OFFSPRING).contains(&c) => lineage.chosen.push((r, c)),
                        _ => {
                            problems.push(Problem::new(
                                KEY,
                                format!(
                                    "'{child}' is not an offspring (1 to {OFFSPRING}); the \
                                     lineage stops before it"
                                ),
                            ));
                            lineage.rate = r;
                            break;
                        }
                    }
                    lineage.rate = r;
                }
                None if last => {
                    if let Some(r) = rate(item, &mut problems) {
                        lineage.rate = r;
                    }
                }
                None => {
                    problems.push(Problem::new(
                        KEY,
                        format!(
                            "'{item}' is not a choice (rate/offspring); the lineage stops before it"
                        ),
                    ));
                    break;
                }
            }
        }
        (lineage, problems)
    }

    /// The link's value (`0.4/3,0.4/7,0.5`).
    pub fn write(&self) -> String {
        let mut parts: Vec<String> = self
            .chosen
            .iter()
            .map(|(r, c)| format!("{r}/{c}"))
            .collect();
        parts.push(format!("{}", self.rate));
        parts.join(",")
    }

    /// With offspring `child` (1 to 8) of the generation shown chosen.
    pub fn choose(&self, child: usize) -> Self {
        let mut next = self.clone();
        next.chosen.push((self.rate, child));
        next
    }

    /// The generation before, at the rate it was bred at; none at the first.
    pub fn back(&self) -> Option<Self> {
        let mut before = self.clone();
        let (rate, _) = before.chosen.pop()?;
        before.rate = rate;
        Some(before)
    }

    /// The generation shown, bred at `rate` (clamped to [`RATES`]).
    pub fn at_rate(&self, rate: f64) -> Self {
        Self {
            rate: rate.clamp(RATES.0, RATES.1),
            ..self.clone()
        }
    }
}
