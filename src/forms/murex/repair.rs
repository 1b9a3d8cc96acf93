//! The implicit shell's cross-field checks: everything [`check`] asks of the numbers, each
//! violation repaired from the fallback's part it concerns (or, for whorls too many or too
//! thin, to the most whorls or the least λ allowed), and spines placed by a pattern only
//! where there is one.

use super::check::{self, check};
use super::grid_sight;
use crate::spec::form::implicit::{ImplicitSpec, Placement, Shows};
use crate::spec::pattern::{Model, PatternSpec};
use crate::spec::problem::Problem;

/// Most times one link's implicit form is repaired before the preset's form is used.
const REPAIRS: usize = 3;

/// An implicit shell must build: a spiral that grows, positive sizes, bends its cones can
/// take, parts that its controlled blending names, a resolution within the cap, spines and
/// an opening within theirs; spines placed by the pattern need a pattern model.
pub(crate) fn repair(
    i: &mut ImplicitSpec,
    f: &ImplicitSpec,
    pattern: &PatternSpec,
    problems: &mut Vec<Problem>,
) {
    // Repaired a few times over: a λ raised to be seen may allow fewer whorls.
    for _ in 0..REPAIRS {
        let Err(e) = check(i) else { break };
        let key = e.key.as_str();
        let most = check::most_whorls(i.spiral.lambda);
        let used = if key == "form.whorls" && i.whorls > most {
            i.whorls = most;
            most.to_string()
        } else if let Some(least) = (key == "form.spiral.lambda")
            .then(|| grid_sight::least_lambda_seen(i))
            .flatten()
        {
            i.spiral.lambda = least;
            format!("λ = {least}")
        } else if key == "form.resolution" {
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
        } else if key.starts_with("form.textures") {
            i.textures = f.textures.clone();
            "the preset's textures".into()
        } else {
            *i = f.clone();
            "the preset's form".into()
        };
        problems.push(e.repaired(&used));
    }
    if let Err(e) = check(i) {
        problems.push(e.repaired("the preset's form"));
        *i = f.clone();
    }
    if i.opening.shows != Shows::Shell && i.opening.inside.is_empty() {
        i.opening.shows = Shows::Shell;
        problems.push(Problem::new(
            "form.opening.shows",
            "this shell is solid, with no inside generating surface to carve an opening with; showed the shell",
        ));
    }
    let varices = &mut i.varices;
    if varices.placement == Placement::Pattern && matches!(pattern.model, Model::None) {
        varices.placement = Placement::Table;
        let message = if varices.spines.is_empty() && !i.canal_spines.spines.is_empty() {
            // No varices then, and canal spines stand below varices.
            i.canal_spines.spines.clear();
            "spines placed by the pattern need a pattern model; used the table, which is empty, so the shell has no varices and no canal spines"
        } else {
            "spines placed by the pattern need a pattern model; used the table"
        };
        problems.push(Problem::new("form.varices.placement", message));
    }
}
