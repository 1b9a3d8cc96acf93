//! The repair of a whole spec: every value that breaks another field's limit or a cap on
//! memory and time is repaired from a fallback spec (usually the preset's own values) and
//! reported as a [`Problem`] naming the key, the cap and what was used. The form's checks are
//! its own (`forms::repair`), the pattern's the pattern's (`pattern::repair`).

use crate::forms;
use crate::pattern;
use crate::presets;
use crate::spec::ShellSpec;
use crate::spec::form::Form;
use crate::spec::pattern::EdgeGrowth;
use crate::spec::problem::Problem;

/// The form to repair `form` from: `fallback`'s when it is of the same kind, else that of the
/// first preset of the kind (a link that switched kinds starts from that preset too).
fn same_kind<'a>(form: &Form, fallback: &'a Form) -> &'a Form {
    let kind = std::mem::discriminant(form);
    if std::mem::discriminant(fallback) == kind {
        return fallback;
    }
    presets::presets()
        .iter()
        .map(|p| &p.spec.form)
        .find(|f| std::mem::discriminant(*f) == kind)
        .expect("every form kind has a preset")
}

/// Repairs every cross-field violation of `spec` from `fallback` and says what was done.
pub fn repair(spec: &mut ShellSpec, fallback: &ShellSpec) -> Vec<Problem> {
    let mut problems = Vec::new();
    let fallback_form = same_kind(&spec.form, &fallback.form);
    forms::repair(
        &mut spec.form,
        fallback_form,
        &spec.pattern,
        spec.seed,
        &mut problems,
    );
    pattern::repair::repair(
        &mut spec.pattern,
        &mut spec.growth.rows,
        &fallback.pattern,
        &mut problems,
    );
    if spec.pattern.edge_growth != EdgeGrowth::Off && !forms::has_one_growing_edge(&spec.form) {
        problems.push(Problem::new(
            "pattern.edge_growth",
            "this form has no one growing edge whose cells could divide (swept shells and chambers have); used off",
        ));
        spec.pattern.edge_growth = EdgeGrowth::Off;
    }
    problems
}
