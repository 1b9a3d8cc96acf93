//! The pattern's cross-field checks and caps: a pattern that fits its texture and the
//! cell-update cap, diffuses stably, shows a range of values, and (for the automaton) has a
//! rule that parses. Each violation is repaired and reported.

use super::automaton::rule_of;
use super::stability::diffusions;
use super::texture_layout::TextureLayout;
use crate::spec::pattern::{Automaton, Model, PatternSpec};
use crate::spec::problem::Problem;

/// Most cell updates (cells × rows × iterations) one pattern may take.
pub const MAX_CELL_UPDATES: u64 = 4_000_000_000;

/// The pattern must fit its texture and the cell-update cap, diffuse stably, and (for the
/// automaton) have a rule that parses.
pub(crate) fn repair(
    pattern: &mut PatternSpec,
    rows: &mut u32,
    fallback: &PatternSpec,
    problems: &mut Vec<Problem>,
) {
    if pattern.model != Model::None {
        let most = super::texture_layout::MAX_SIDE / pattern.refinement.max(1);
        if pattern.cells > most {
            problems.push(Problem::new(
                "pattern.cells",
                format!(
                    "{} cells refined {} times make {} columns, more than the pattern texture's 2048; used {most} cells",
                    pattern.cells,
                    pattern.refinement,
                    pattern.cells * pattern.refinement
                ),
            ));
            pattern.cells = most;
        }
        let cells = pattern.cells * pattern.refinement.max(1);
        if TextureLayout::new(cells, *rows).is_none() {
            let fit = TextureLayout::max_rows(cells);
            problems.push(Problem::new(
                "growth.rows",
                format!(
                    "{cells} cells × {} rows do not fit the pattern texture (2048 × 2048 texels); used {fit} rows",
                    *rows
                ),
            ));
            *rows = fit;
        }
        // Refinement k computes k² steps per iteration on k× the cells (`cells` counts them).
        let k = u64::from(pattern.refinement.max(1));
        let per_iteration = u64::from(cells) * u64::from(*rows) * k * k;
        let updates = per_iteration * u64::from(pattern.iterations);
        if updates > MAX_CELL_UPDATES {
            let fit = (MAX_CELL_UPDATES / per_iteration).max(1) as u32;
            problems.push(Problem::new(
                "pattern.iterations",
                format!(
                    "cells × rows × iterations (× refinement³) = {updates} cell updates, more than the cap of {MAX_CELL_UPDATES}; used {fit} iterations per row"
                ),
            ));
            pattern.iterations = fit;
        }
        for d in diffusions(&mut pattern.model) {
            if let Some(problem) = d.problem() {
                let used = d.limit();
                problems.push(Problem::new(d.key, format!("{problem}; used {used}")));
                *d.value = used;
            }
        }
        problems.extend(repair_automaton(pattern, fallback));
        if pattern.low >= pattern.high {
            problems.push(Problem::new(
                "pattern.low",
                format!(
                    "the value shown as no pigment ({}) must be below the one shown as full pigment ({}); used the preset's {} and {}",
                    pattern.low, pattern.high, fallback.low, fallback.high
                ),
            ));
            pattern.low = fallback.low;
            pattern.high = fallback.high;
        }
    }
}

/// The automaton's rule must parse, its starting cells lie on the edge, and, being discrete,
/// it has no refinement.
fn repair_automaton(pattern: &mut PatternSpec, fallback: &PatternSpec) -> Vec<Problem> {
    let mut problems = Vec::new();
    let cells = pattern.cells;
    if !matches!(pattern.model, Model::Automaton(_)) {
        return problems;
    }
    if pattern.refinement != 1 {
        problems.push(Problem::new(
            "pattern.refinement",
            "the automaton is discrete and cannot be refined; used 1",
        ));
        pattern.refinement = 1;
    }
    let Model::Automaton(a) = &mut pattern.model else {
        return problems;
    };
    if let Err(e) = rule_of(a) {
        let (rule, f, g) = match &fallback.model {
            Model::Automaton(Automaton { rule, f, g, .. }) => (rule.clone(), f.clone(), g.clone()),
            _ => ("1/6-8/5".to_string(), vec![], vec![]),
        };
        problems.push(Problem::new(
            "pattern.model.rule",
            format!("{e}; used the rule {rule}"),
        ));
        (a.rule, a.f, a.g) = (rule, f, g);
    }
    if let Some(&beyond) = a.start_cells.iter().find(|&&c| c >= cells) {
        problems.push(Problem::new(
            "pattern.model.start_cells",
            format!("cell {beyond} is beyond the edge's {cells} cells; used the last cell"),
        ));
        for c in &mut a.start_cells {
            *c = (*c).min(cells.saturating_sub(1));
        }
    }
    problems
}
