//! Checks that involve several fields at once, and the caps that keep any spec within memory
//! and time: each violation is repaired (from a fallback spec, usually the preset's own
//! values) and reported as a [`Problem`] naming the key, the cap and what was used.

use super::ShellSpec;
use super::branching::BranchingSpec;
use super::chambers::ChambersSpec;
use super::form::{CurveSpec, Form, SweepSpec};
use super::implicit::{ImplicitSpec, Placement};
use super::link::Problem;
use super::pattern::{Automaton, Model, PatternSpec};
use crate::growing_shape::GeometryError;
use crate::growth::branching_mesh::BranchingMesh;
use crate::growth::chamber_mesh::mesh_capacity;
use crate::growth::chamber_stack::ChamberStack;
use crate::growth::mouth::mouth_polygon;
use crate::implicit::implicit_whorl;
use crate::pattern::automaton::rule_of;
use crate::pattern::diffusions;
use crate::species;
use crate::texture_layout::TextureLayout;

/// Most vertices a shell's mesh may have (72 MB of vertex data).
pub const MAX_VERTICES: u64 = 2_000_000;
/// Most cell updates (cells × rows × iterations) one pattern may take.
pub const MAX_CELL_UPDATES: u64 = 4_000_000_000;

/// Vertices of a sweep's mesh: rims × points per rim, doubled with a wall.
fn sweep_vertices(s: &SweepSpec) -> u64 {
    let rims = (s.spiral.whorls * 360.0 / s.spiral.delta_theta * f64::from(s.spiral.subdivisions))
        .round() as u64
        + 1;
    let points = u64::from(s.curve.segments) + 1;
    rims * points * if s.wall.thickness > 0.0 { 2 } else { 1 }
}

/// Whether the curve has the number of control points its closedness needs.
fn curve_fits(curve: &CurveSpec) -> bool {
    let n = curve.points.len();
    if curve.closed {
        n >= 3 && n.is_multiple_of(3)
    } else {
        n >= 4 && n % 3 == 1
    }
}

/// The form to repair `form` from: `fallback`'s when it is of the same kind, else that of the
/// first preset of the kind (a link that switched kinds starts from that preset too).
fn same_kind<'a>(form: &Form, fallback: &'a Form) -> &'a Form {
    let kind = std::mem::discriminant(form);
    if std::mem::discriminant(fallback) == kind {
        return fallback;
    }
    species::presets()
        .iter()
        .map(|p| &p.spec.form)
        .find(|f| std::mem::discriminant(*f) == kind)
        .expect("every form kind has a preset")
}

/// A shape error ("key: what") as a problem, saying what was used instead.
fn shape_problem(error: GeometryError, used: &str) -> Problem {
    let (key, message) = error.0.split_once(": ").unwrap_or(("form", &error.0));
    Problem::new(key, format!("{message}; used {used}"))
}

/// Repairs every cross-field violation of `spec` from `fallback` and says what was done.
pub fn repair(spec: &mut ShellSpec, fallback: &ShellSpec) -> Vec<Problem> {
    let mut problems = Vec::new();
    let fallback_form = same_kind(&spec.form, &fallback.form);
    match (&mut spec.form, fallback_form) {
        (Form::Sweep(s), Form::Sweep(f)) => repair_sweep(s, f, &mut problems),
        (Form::Chambers(c), Form::Chambers(f)) => repair_chambers(c, f, &mut problems),
        (Form::Branching(b), Form::Branching(f)) => {
            repair_branching(b, f, spec.seed, &mut problems)
        }
        (Form::Implicit(i), Form::Implicit(f)) => repair_implicit(i, f, &mut problems),
        _ => unreachable!("same_kind gives a fallback of the form's kind"),
    }
    repair_pattern(spec, fallback, &mut problems);
    if let Form::Implicit(i) = &mut spec.form {
        let varices = &mut i.varices;
        if varices.placement == Placement::Pattern
            && !varices.spines.is_empty()
            && matches!(spec.pattern.model, Model::None)
        {
            varices.placement = Placement::Table;
            problems.push(Problem::new(
                "form.varices.placement",
                "spines placed by the pattern need a pattern model; used the table",
            ));
        }
    }
    problems
}

/// A chamber stack must build (a mouth that does not fold over itself, chambers whose top
/// base stays above their bottom base) and fit the vertex cap.
fn repair_chambers(c: &mut ChambersSpec, f: &ChambersSpec, problems: &mut Vec<Problem>) {
    if let Err(e) = mouth_polygon(&c.mouth) {
        problems.push(shape_problem(e, "the preset's protuberances"));
        c.mouth.protuberances = f.mouth.protuberances.clone();
        if mouth_polygon(&c.mouth).is_err() {
            c.mouth = f.mouth.clone();
        }
    }
    if let Err(e) = ChamberStack::new(c) {
        problems.push(shape_problem(e, "the preset's chamber"));
        c.chamber = f.chamber.clone();
        if ChamberStack::new(c).is_err() {
            *c = f.clone();
        }
    }
    let vertices = mesh_capacity(c).0.vertices as u64;
    if vertices > MAX_VERTICES {
        problems.push(Problem::new(
            "form.chambers",
            format!(
                "{} chambers of {} apexes would make {vertices} vertices, more than the cap of {MAX_VERTICES}; used the preset's {} chambers of {} apexes",
                c.chambers, c.mouth.apexes, f.chambers, f.mouth.apexes
            ),
        ));
        c.chambers = f.chambers;
        c.mouth.apexes = f.mouth.apexes;
    }
}

/// A branching form must build (limits in order, the count of trunks within its cap) and fit
/// the vertex cap.
fn repair_branching(
    b: &mut BranchingSpec,
    f: &BranchingSpec,
    seed: u64,
    problems: &mut Vec<Problem>,
) {
    if b.knot.k0 >= b.knot.k1 {
        problems.push(Problem::new(
            "form.knot.k0",
            format!(
                "the lower limit k₀ ({}°) must be below the upper limit k₁ ({}°); used the preset's {}° and {}°",
                b.knot.k0, b.knot.k1, f.knot.k0, f.knot.k1
            ),
        ));
        b.knot.k0 = f.knot.k0;
        b.knot.k1 = f.knot.k1;
    }
    let vertices = match BranchingMesh::new(b, seed, 2) {
        Ok(mesh) => mesh.total_capacity().vertices as u64,
        Err(e) => {
            problems.push(shape_problem(e, "the preset's form"));
            *b = f.clone();
            return;
        }
    };
    if vertices > MAX_VERTICES {
        problems.push(Problem::new(
            "form.trunk.sides",
            format!(
                "{} sides would make {vertices} vertices, more than the cap of {MAX_VERTICES}; used the preset's form",
                b.trunk.sides
            ),
        ));
        *b = f.clone();
    }
}

/// An implicit shell must build: a spiral that grows, positive sizes, bends its cones can
/// take, parts that its controlled blending names, a resolution within the cap, spines and
/// an opening within theirs.
fn repair_implicit(i: &mut ImplicitSpec, f: &ImplicitSpec, problems: &mut Vec<Problem>) {
    if let Err(e) = implicit_whorl::check(i) {
        let key = e.0.split_once(": ").map_or("form", |(k, _)| k);
        let used = if key == "form.resolution" {
            i.resolution = f.resolution;
            format!("the preset's resolution {}", f.resolution)
        } else if key.starts_with("form.generator") {
            i.generator = f.generator.clone();
            "the preset's generating surface".into()
        } else if key.starts_with("form.varices") {
            i.varices = f.varices.clone();
            "the preset's varices".into()
        } else if key.starts_with("form.canal_spines") {
            i.canal_spines = f.canal_spines.clone();
            "the preset's canal spines".into()
        } else if key.starts_with("form.opening") {
            i.opening = f.opening.clone();
            "the preset's opening".into()
        } else {
            "the preset's form".into()
        };
        problems.push(shape_problem(e, &used));
        if implicit_whorl::check(i).is_err() {
            *i = f.clone();
        }
    }
}

/// A sweep's curve must have the control points its closedness needs, and its mesh fit the
/// vertex cap.
fn repair_sweep(s: &mut SweepSpec, f: &SweepSpec, problems: &mut Vec<Problem>) {
    if !curve_fits(&s.curve) {
        let n = s.curve.points.len();
        let need = if s.curve.closed {
            "3k points (k ≥ 1)"
        } else {
            "3k + 1 points (k ≥ 1)"
        };
        problems.push(Problem::new(
            "form.curve.points",
            format!(
                "a {} curve needs {need}, not {n}; used the preset's curve",
                if s.curve.closed { "closed" } else { "open" }
            ),
        ));
        s.curve.points = f.curve.points.clone();
        s.curve.closed = f.curve.closed;
    }
    let vertices = sweep_vertices(s);
    if vertices > MAX_VERTICES {
        s.spiral.whorls = f.spiral.whorls;
        s.spiral.delta_theta = f.spiral.delta_theta;
        s.spiral.subdivisions = f.spiral.subdivisions;
        s.curve.segments = f.curve.segments;
        problems.push(Problem::new(
            "form",
            format!(
                "the mesh would have {vertices} vertices, more than the cap of {MAX_VERTICES}; used the preset's whorls, angular step, rims per step and segments"
            ),
        ));
    }
}

/// The pattern must fit its texture and the cell-update cap, diffuse stably, and (for the
/// automaton) have a rule that parses.
fn repair_pattern(spec: &mut ShellSpec, fallback: &ShellSpec, problems: &mut Vec<Problem>) {
    if spec.pattern.model != Model::None {
        let most = crate::texture_layout::MAX_SIDE / spec.pattern.refinement.max(1);
        if spec.pattern.cells > most {
            problems.push(Problem::new(
                "pattern.cells",
                format!(
                    "{} cells refined {} times make {} columns, more than the pattern texture's 2048; used {most} cells",
                    spec.pattern.cells,
                    spec.pattern.refinement,
                    spec.pattern.cells * spec.pattern.refinement
                ),
            ));
            spec.pattern.cells = most;
        }
        let cells = spec.pattern.cells * spec.pattern.refinement.max(1);
        if TextureLayout::new(cells, spec.growth.rows).is_none() {
            let fit = TextureLayout::max_rows(cells);
            problems.push(Problem::new(
                "growth.rows",
                format!(
                    "{cells} cells × {} rows do not fit the pattern texture (2048 × 2048 texels); used {fit} rows",
                    spec.growth.rows
                ),
            ));
            spec.growth.rows = fit;
        }
        // Refinement k computes k² steps per iteration on k× the cells (`cells` counts them).
        let k = u64::from(spec.pattern.refinement.max(1));
        let per_iteration = u64::from(cells) * u64::from(spec.growth.rows) * k * k;
        let updates = per_iteration * u64::from(spec.pattern.iterations);
        if updates > MAX_CELL_UPDATES {
            let fit = (MAX_CELL_UPDATES / per_iteration).max(1) as u32;
            problems.push(Problem::new(
                "pattern.iterations",
                format!(
                    "cells × rows × iterations (× refinement³) = {updates} cell updates, more than the cap of {MAX_CELL_UPDATES}; used {fit} iterations per row"
                ),
            ));
            spec.pattern.iterations = fit;
        }
        for d in diffusions(&mut spec.pattern.model) {
            if let Some(problem) = d.problem() {
                let used = d.limit();
                problems.push(Problem::new(d.key, format!("{problem}; used {used}")));
                *d.value = used;
            }
        }
        problems.extend(repair_automaton(&mut spec.pattern, &fallback.pattern));
        if spec.pattern.low >= spec.pattern.high {
            problems.push(Problem::new(
                "pattern.low",
                format!(
                    "the value shown as no pigment ({}) must be below the one shown as full pigment ({}); used the preset's {} and {}",
                    spec.pattern.low, spec.pattern.high, fallback.pattern.low, fallback.pattern.high
                ),
            ));
            spec.pattern.low = fallback.pattern.low;
            spec.pattern.high = fallback.pattern.high;
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
