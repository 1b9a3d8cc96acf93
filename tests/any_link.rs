//! No link makes a bad file: links drawn at random over the whole field table (every form and
//! pattern model, each field anywhere in the panel's range, at its ends, and several ends at
//! once) are either refused naming a key, or grow to a mesh that a file may carry. A grown mesh
//! has only finite coordinates within [`BOUND`], no edge on more than two triangles (welded
//! exactly, by float32 position, as the files weld), and is closed and consistently wound
//! wherever the form is a solid; the pattern's values are finite.
//!
//! `make test` runs [`QUICK_CASES`] cases, with the fields that only cost time (rows, the
//! implicit grid) drawn below [`QUICK_CAPS`]; `make fuzz` sets `SEASHELLS_FUZZ_CASES` and
//! draws every field over its whole range (docs/fuzzing.md says what it found).

use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence, RngSeed};
use seashells_core::generator::Generator;
use seashells_core::mesh::{Bounds, Mesh};
use seashells_core::presets::presets;
use seashells_core::share::link::{self, Decoded};
use seashells_core::spec::ShellSpec;
use seashells_core::spec::fields::{self, Field, Kind};
use seashells_core::spec::form::Form;
use std::collections::HashMap;

/// No coordinate of a grown shell lies further from the origin (in shell units, in which the
/// presets span 1 to 30): the fields' lengths reach 100 and growth is bounded at 10⁴
/// (`mesh::MAX_GROWTH_DECADES`), with a decade to spare for the coil.
const BOUND: f32 = 1e7;

/// Nor further from the origin than this many times the shell's largest side: every form is
/// built about its axis through the origin, and a shell far off it beside its size would have
/// lost its detail to float32 in the mesh itself.
const OFF_AXIS: f32 = 100.0;

/// Cases in `make test`.
const QUICK_CASES: u32 = 160;

/// The seed of `make test`'s links.
const QUICK_SEED: u64 = 1982;

/// In `make test`, the highest value drawn for fields that cost time and nothing else.
const QUICK_CAPS: &[(&str, u64)] = &[
    ("growth.rows", 600),
    ("form.resolution", 48),
    ("form.chambers", 400),
    ("pattern.cells", 400),
    ("pattern.iterations", 40),
];

/// How a field's value is drawn.
#[derive(Clone, Copy, Debug)]
enum Draw {
    Least,
    Most,
    /// Within the range, at this fraction of it (of its logarithm for a logarithmic slider).
    Inside(f64),
}

fn draw() -> impl Strategy<Value = Draw> {
    prop_oneof![
        1 => Just(Draw::Least),
        1 => Just(Draw::Most),
        2 => (0.0..=1.0f64).prop_map(Draw::Inside),
    ]
}

/// A field's value as link text, drawn as `how` says; None for fields drawn otherwise (texts,
/// tables, lists and colours have no range to draw from).
fn value(field: &Field, how: Draw, quick: bool) -> Option<String> {
    let at = |min: f64, max: f64| match how {
        Draw::Least => 0.0,
        Draw::Most => 1.0,
        Draw::Inside(u) => u,
    } * (max - min)
        + min;
    match field.kind {
        Kind::Real { min, max, log } if log => Some(at(min.ln(), max.ln()).exp().to_string()),
        Kind::Real { min, max, .. } => Some(at(min, max).to_string()),
        Kind::Integer { min, max } => {
            let cap = QUICK_CAPS.iter().find(|(k, _)| *k == field.key);
            let max = match cap {
                Some(&(_, cap)) if quick => max.min(cap.max(min)),
                _ => max,
            };
            Some(
                (at(min as f64, max as f64).round() as u64)
                    .clamp(min, max)
                    .to_string(),
            )
        }
        Kind::Flag => Some(matches!(how, Draw::Most | Draw::Inside(0.5..)).to_string()),
        Kind::Choice(options) => {
            let i = (at(0.0, options.len() as f64 - 1.0).round() as usize).min(options.len() - 1);
            Some(options[i].to_string())
        }
        _ => None,
    }
}

/// The link of preset `preset` with the fields `picks` (indices into the fields that preset's
/// spec has) drawn as they say.
fn link_of(preset: usize, picks: &[(usize, Draw)], quick: bool) -> String {
    let preset = &presets()[preset % presets().len()];
    let keys = link::flatten(&serde_json::to_value(&preset.spec).unwrap());
    let drawable: Vec<&Field> = fields::fields(preset.spec.form.kind())
        .filter(|f| f.key.ends_with(".kind") || keys.contains_key(f.key))
        .filter(|f| value(f, Draw::Least, quick).is_some())
        .collect();
    let mut link = format!("v=1&preset={}", preset.id);
    if quick && keys.contains_key("form.resolution") {
        // The implicit grid only costs time: the quick run meshes coarsely unless it draws it.
        link.push_str("&form.resolution=48");
    }
    for &(i, how) in picks {
        let field = drawable[i % drawable.len()];
        if let Some(v) = value(field, how, quick) {
            link.push_str(&format!("&{}={v}", field.key));
        }
    }
    link
}

/// Every key a problem may name: the table's keys, their parents (a problem about a whole
/// group), and the link as a whole.
fn names_a_key(key: &str) -> bool {
    key == "link"
        || key == "v"
        || fields::FORM_KINDS
            .iter()
            .flat_map(|k| fields::fields(k))
            .any(|f| f.key == key || f.key.starts_with(&format!("{key}.")))
}

/// Whether the grown form is a solid (everything but a sweep without a wall).
fn solid(spec: &ShellSpec) -> bool {
    !matches!(&spec.form, Form::Sweep(s) if s.wall.thickness <= 0.0)
}

/// What is wrong with `mesh` as the content of a file, if anything.
fn fault(mesh: &Mesh, solid: bool) -> Option<String> {
    if let Some(v) = mesh
        .vertices
        .iter()
        .find(|v| v.position.iter().chain(&v.normal).any(|c| !c.is_finite()))
    {
        return Some(format!("a vertex is not finite: {v:?}"));
    }
    if let Some(v) = mesh
        .vertices
        .iter()
        .find(|v| v.position.iter().any(|c| c.abs() > BOUND))
    {
        return Some(format!("a vertex lies beyond {BOUND}: {:?}", v.position));
    }
    if mesh.triangle_count() == 0 {
        return Some("the shell grew to nothing, and the link does not say why".into());
    }
    let mut bounds = Bounds::EMPTY;
    bounds.include_vertices(&mesh.vertices);
    let side = (bounds.max - bounds.min).max_element() as f32;
    let far = bounds.min.abs().max(bounds.max.abs()).max_element() as f32;
    if far > OFF_AXIS * side {
        return Some(format!(
            "the shell lies {far} from its axis, {} times its largest side {side}",
            far / side
        ));
    }
    let key = |i: u32| mesh.vertices[i as usize].position.map(f32::to_bits);
    let mut directed: HashMap<([u32; 3], [u32; 3]), usize> = HashMap::new();
    for (t, c) in mesh.indices.chunks_exact(3).enumerate() {
        if mesh.collapsed(t) {
            continue;
        }
        for (a, b) in [(c[0], c[1]), (c[1], c[2]), (c[2], c[0])] {
            *directed.entry((key(a), key(b))).or_insert(0) += 1;
        }
    }
    for (&(a, b), &n) in &directed {
        let back = directed.get(&(b, a)).copied().unwrap_or(0);
        if n + back > 2 {
            return Some(format!("an edge is on {} triangles", n + back));
        }
        if solid && (n != 1 || back != 1) {
            return Some(format!(
                "a solid's edge is used {n} times one way and {back} the other (a hole or a winding fault)"
            ));
        }
    }
    None
}

/// Decodes `link` and checks it: refused naming keys, and the shell the page would show of it
/// (repaired) grows to a mesh a file may carry, or stops saying why.
fn check(link: &str) -> Result<(), String> {
    let Decoded { spec, problems, .. } = link::decode(link);
    if let Some(p) = problems.iter().find(|p| !names_a_key(&p.key)) {
        return Err(format!("a problem names no key: {p}"));
    }
    let mut generator =
        Generator::new(&spec).map_err(|e| format!("the repaired spec does not build: {e}"))?;
    generator.finish();
    if let Some(why) = generator.failure() {
        return if why.trim().is_empty() {
            Err("growth stopped without a word".into())
        } else {
            Ok(())
        };
    }
    if let Some(run) = generator.pattern()
        && run.recorded().iter().any(|x| !x.is_finite())
    {
        return Err("a pattern value is not finite".into());
    }
    let overlaps = seashells_core::forms::self_overlap(&spec.form).is_some();
    if overlaps
        != problems
            .iter()
            .any(|p| p.message.contains("whorls overlap"))
    {
        return Err("whorls overlap and the link does not say so".into());
    }
    match fault(&generator.snapshot(), solid(&spec) && !overlaps) {
        Some(fault) => Err(fault),
        None => Ok(()),
    }
}

/// The cases to run, whether they are the quick run's, and the seed they are drawn from: fixed
/// in `make test` (the same links in every run, so a run fails only for a change), random in
/// `make fuzz` unless `SEASHELLS_FUZZ_SEED` repeats one.
fn cases() -> (u32, bool, RngSeed) {
    let seed = std::env::var("SEASHELLS_FUZZ_SEED")
        .ok()
        .map(|s| RngSeed::Fixed(s.parse().expect("SEASHELLS_FUZZ_SEED is a number")));
    match std::env::var("SEASHELLS_FUZZ_CASES") {
        Ok(n) => (
            n.parse().expect("SEASHELLS_FUZZ_CASES is a number"),
            false,
            seed.unwrap_or(RngSeed::Random),
        ),
        Err(_) => (
            QUICK_CASES,
            true,
            seed.unwrap_or(RngSeed::Fixed(QUICK_SEED)),
        ),
    }
}

#[test]
fn every_link_within_the_panels_ranges_is_refused_by_name_or_makes_a_good_file() {
    let (cases, quick, rng_seed) = cases();
    let config = Config {
        cases,
        rng_seed,
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..Config::default()
    };
    proptest!(config, |(
        preset in 0usize..1000,
        picks in prop::collection::vec((any::<usize>(), draw()), 1..7),
    )| {
        let link = link_of(preset, &picks, quick);
        if let Err(e) = check(&link) {
            return Err(TestCaseError::fail(format!("{link}: {e}")));
        }
    });
}

/// Links the property test found making files that were not closed: a sculpted sweep on a
/// closed curve whose inner wall's seam was one float32 step apart (the last point's neighbour
/// along the curve wrapped to the first's give or take a step).
#[test]
fn the_sculpted_walls_the_property_test_found_open_are_closed() {
    for link in [
        "v=1&preset=rapa-rapa&form.spiral.subdivisions=16&form.sculpture.growth_ribs.amplitude=-0.20451421882402976",
        "v=1&preset=epitonium-scalare&form.sculpture.curve_ribs.sharpness=0.25",
        "v=1&preset=spiral-ribs&form.orientation.rotate_e2=84.91718583844181",
        "v=1&preset=lattice&form.sculpture.curve_ribs.frequency_change=5&form.spiral.lambda_z=0.8",
    ] {
        check(link).unwrap_or_else(|e| panic!("{link}: {e}"));
    }
}

/// Links `make fuzz` found making bad files or nothing: the tentacles' branches, wider than
/// their knot, started back to back on its axis at −90°, a base on a base (65 edges on four
/// triangles); the implicit whorl at λ = 1.01 grew to nothing without a word (its whorls beads
/// the grid drops). Each now starts off the axis, and the thin whorl is refused naming λ.
#[test]
fn the_links_make_fuzz_found_make_good_files_or_are_refused_by_name() {
    for link in [
        "v=1&preset=kawaguchi-tentacles&form.branches.angle=-90",
        "v=1&preset=implicit-whorl&form.spiral.lambda=1.01",
    ] {
        check(link).unwrap_or_else(|e| panic!("{link}: {e}"));
    }
    let thin = link::decode("v=1&preset=implicit-whorl&form.spiral.lambda=1.01");
    assert!(
        thin.problems
            .iter()
            .any(|p| p.key == "form.spiral.lambda" && p.message.contains("too thin for the grid")),
        "{:?}",
        thin.problems
    );
}
