//! The link codec: decode(encode(spec)) == spec for every valid spec, encoding is canonical,
//! and every kind of bad link gets a specific message while still giving a shell.

use proptest::prelude::*;
use seashells_core::generator::Generator;
use seashells_core::presets::{DEFAULT_PRESET, preset, presets};

use seashells_core::share::link::{MAX_LINK, decode, encode, flatten};
use seashells_core::share::presentation::{Presentation, Ui};
use seashells_core::share::repair::repair;
use seashells_core::spec::fields::{FORM_KINDS, Field, Kind, Section, field, fields};
use seashells_core::spec::material::Drawing;
use seashells_core::spec::{Problem, ShellSpec};
use serde_json::Value;

/// A random valid spec: a preset with some fields set to random values in their ranges.
fn perturbed(preset: usize, changes: &[(usize, f64)]) -> Option<(usize, ShellSpec)> {
    let preset = preset % presets().len();
    let base = &presets()[preset].spec;
    let mut value = serde_json::to_value(base).unwrap();
    let table: Vec<&Field> = fields(base.form.kind()).collect();
    for &(i, x) in changes {
        let field = table[i % table.len()];
        if field.key.ends_with(".kind") {
            continue;
        }
        let slot = field
            .key
            .split('.')
            .try_fold(&mut value, |v, part| v.as_object_mut()?.get_mut(part));
        let Some(slot) = slot else { continue };
        *slot = match field.kind {
            Kind::Real { min, max, .. } => serde_json::json!(min + x * (max - min)),
            Kind::Integer { min, max } => {
                let span = (max - min).min(1 << 40) as f64;
                serde_json::json!(min + (x * span) as u64)
            }
            Kind::Flag => Value::Bool(x < 0.5),
            Kind::Choice(options) => {
                Value::String(options[(x * options.len() as f64) as usize % options.len()].into())
            }
            Kind::Colour => Value::String(format!("{:06x}", (x * 16_777_215.0) as u32)),
            Kind::List { .. } | Kind::Table | Kind::Text => continue,
        };
    }
    let mut spec: ShellSpec = serde_json::from_value(value).ok()?;
    repair(&mut spec, base);
    Some((preset, spec))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn decode_inverts_encode(preset in 0usize..1000, changes in prop::collection::vec((0usize..1000, 0.0f64..1.0), 0..12)) {
        if let Some((preset, spec)) = perturbed(preset, &changes) {
            let preset = &presets()[preset];
            let link = encode(preset, &spec);
            let decoded = decode(&link);
            // Nothing is repaired again; what repair still says of the spec (whorls that
            // overlap, which it shows as asked) is all the link says.
            let mut again = spec.clone();
            let still = repair(&mut again, &preset.spec);
            prop_assert_eq!(&again, &spec);
            prop_assert_eq!(&decoded.problems, &still, "{}", link);
            prop_assert_eq!(&decoded.spec, &spec);
            prop_assert_eq!(encode(decoded.preset, &decoded.spec), link);
        }
    }

    #[test]
    fn any_text_gives_a_shell_and_never_panics(text in ".{0,200}") {
        let decoded = decode(&text);
        prop_assert!(Generator::new(&decoded.spec).is_ok());
        let again = decode(&encode(decoded.preset, &decoded.spec));
        prop_assert!(again.problems.is_empty());
        prop_assert_eq!(again.spec, decoded.spec);
    }
}

#[test]
fn a_preset_alone_encodes_to_its_name_and_version() {
    for preset in presets() {
        assert_eq!(
            encode(preset, &preset.spec),
            format!("v=1&preset={}", preset.id)
        );
    }
}

#[test]
fn the_canonical_form_sorts_and_deduplicates() {
    let messy = "#preset=turbinate&form.spiral.whorls=5.0&v=1&seed=7";
    let decoded = decode(messy);
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    assert_eq!(
        encode(decoded.preset, &decoded.spec),
        "v=1&preset=turbinate&form.spiral.whorls=5&seed=7"
    );
}

/// Each bad link, the key its problem must name, and words the message must contain.
const BAD_LINKS: &[(&str, &str, &str)] = &[
    (
        "v=1&preset=turbinate&form.spiral.whorlz=3",
        "form.spiral.whorlz",
        "not a key",
    ),
    (
        "v=1&preset=turbinate&form.spiral.whorls=many",
        "form.spiral.whorls",
        "not a number",
    ),
    (
        "v=1&preset=turbinate&form.spiral.whorls=",
        "form.spiral.whorls",
        "not a number",
    ),
    (
        "v=1&preset=turbinate&form.spiral.whorls=NaN",
        "form.spiral.whorls",
        "not a finite number",
    ),
    (
        "v=1&preset=turbinate&form.spiral.whorls=1e9",
        "form.spiral.whorls",
        "used 30",
    ),
    (
        "v=1&preset=turbinate&form.curve.segments=-4",
        "form.curve.segments",
        "whole number",
    ),
    (
        "v=1&preset=turbinate&form.curve.points=1,2",
        "form.curve.points",
        "not 3",
    ),
    (
        "v=1&preset=turbinate&form.curve.points=0,0,0;1,1,0",
        "form.curve.points",
        "needs 3k points",
    ),
    (
        "v=1&preset=turbinate&form.spiral.handedness=upside",
        "form.spiral.handedness",
        "not one of",
    ),
    (
        "v=1&preset=turbinate&colours.ground=%3Cscript%3E",
        "colours.ground",
        "not a colour",
    ),
    ("v=1&preset=turbi", "preset", "no preset 'turbi'"),
    (
        "v=1&preset=turbinate&form.spiral.whorls",
        "form.spiral.whorls",
        "key=value",
    ),
    (
        "v=1&preset=turbinate&seed=1&seed=2",
        "seed",
        "more than once",
    ),
    (
        "v=9&preset=turbinate&form.spiral.whorls=3",
        "v",
        "newer version",
    ),
    ("preset=turbinate", "v", "no version"),
    (
        "v=1&preset=turbinate&form.spiral.whorls=30&form.spiral.subdivisions=16&form.curve.segments=512",
        "form",
        "cap",
    ),
    (
        "v=1&preset=turbinate&<img src=x onerror=alert(1)>=1",
        "<img src",
        "not a key",
    ),
    ("nonsense-preset", "preset", "no preset"),
    (
        "v=1&preset=oliva-porphyria&pattern.model.d_a=0.9",
        "pattern.model.d_a",
        "used 0.475",
    ),
    (
        "v=1&preset=stripes&pattern.model.d_s=0.5&pattern.model.nu=0.4",
        "pattern.model.d_s",
        "4·D_s + ν ≤ 2",
    ),
];

#[test]
fn bad_links_get_specific_messages_and_still_give_a_shell() {
    for &(link, key, words) in BAD_LINKS {
        let decoded = decode(link);
        let problem = decoded
            .problems
            .iter()
            .find(|p| p.key == key)
            .unwrap_or_else(|| panic!("{link}: no problem about {key} in {:?}", decoded.problems));
        assert!(
            problem.message.contains(words),
            "{link}: '{}' lacks '{words}'",
            problem.message
        );
        let again = decode(&encode(decoded.preset, &decoded.spec));
        assert!(
            again.problems.is_empty(),
            "{link} repaired into an invalid spec: {:?}",
            again.problems
        );
        if let Err(e) = Generator::new(&decoded.spec) {
            panic!("{link} was repaired into a spec that cannot be built: {e}");
        }
    }
}

#[test]
fn the_interface_rides_beside_the_spec_and_an_unknown_one_opens_the_full_page() {
    for ui in Ui::ALL {
        let link = format!(
            "v=1&preset=oliva-porphyria&pattern.model.d_a=0.02&ui={}",
            ui.name()
        );
        let decoded = decode(&link);
        assert_eq!(decoded.presentation.ui, ui, "{link}");
        assert!(
            decoded.problems.is_empty(),
            "{link}: {:?}",
            decoded.problems
        );
        assert_eq!(
            encode(decoded.preset, &decoded.spec),
            "v=1&preset=oliva-porphyria&pattern.model.d_a=0.02",
            "the interface is not part of the shell's link"
        );
        let mut written = encode(decoded.preset, &decoded.spec);
        decoded.presentation.write(&mut written);
        assert_eq!(
            written,
            if ui == Ui::Full {
                "v=1&preset=oliva-porphyria&pattern.model.d_a=0.02".to_string()
            } else {
                link.clone()
            }
        );
    }
    let decoded = decode("v=1&preset=murex-cabritii&ui=sidebar");
    assert_eq!(decoded.presentation, Presentation::default());
    assert_eq!(decoded.preset.id, "murex-cabritii");
    assert_eq!(decoded.problems.len(), 1, "{:?}", decoded.problems);
    assert_eq!(decoded.problems[0].key, "ui");
    assert!(
        decoded.problems[0]
            .message
            .contains("opened the full interface"),
        "{}",
        decoded.problems[0]
    );
    assert_eq!(decode("v=1&preset=turbinate").presentation.ui, Ui::Full);
}

#[test]
fn an_overlong_link_is_refused_as_a_whole() {
    let link = format!("v=1&preset=turbinate&seed={}", "9".repeat(MAX_LINK));
    let decoded = decode(&link);
    assert_eq!(decoded.preset.id, DEFAULT_PRESET);
    assert_eq!(decoded.problems.len(), 1);
    assert!(decoded.problems[0].message.contains("more than"));
}

#[test]
fn every_leaf_of_every_preset_is_described_in_its_forms_field_table() {
    for preset in presets() {
        let kind = preset.spec.form.kind();
        let value = serde_json::to_value(&preset.spec).unwrap();
        assert_eq!(value["form"]["kind"], kind, "{}", preset.id);
        assert!(FORM_KINDS.contains(&kind), "{kind}");
        for leaf in flatten(&value).into_keys() {
            assert!(
                field(kind, &leaf).is_some(),
                "{}: {leaf} has no description among the {kind} fields",
                preset.id
            );
        }
    }
}

#[test]
fn every_field_of_a_form_is_a_key_of_its_presets_and_shows_in_one_section_per_concept() {
    for kind in FORM_KINDS {
        let mut leaves = std::collections::BTreeSet::new();
        for preset in presets().iter().filter(|p| p.spec.form.kind() == *kind) {
            leaves.extend(flatten(&serde_json::to_value(&preset.spec).unwrap()).into_keys());
        }
        assert!(!leaves.is_empty(), "no preset of the {kind} form");
        let table: Vec<&Field> = fields(kind).collect();
        // Pattern parameters belong to the models a form's presets may not use.
        for f in table
            .iter()
            .filter(|f| !f.key.starts_with("pattern.model."))
        {
            assert!(
                leaves.contains(f.key),
                "{kind}: {} is described but no preset of the form has it",
                f.key
            );
        }
        let mut seen: Vec<Section> = Vec::new();
        for f in &table {
            if seen.last() != Some(&f.section) {
                assert!(
                    !seen.contains(&f.section),
                    "{kind}: the section {} comes twice (again at {})",
                    f.section.title(),
                    f.key
                );
                seen.push(f.section);
            }
        }
    }
    // A key two forms share has each form's own range: an implicit shell's R₀ must be > 0.
    let Some(Kind::Real { min, .. }) = field("implicit", "form.spiral.r0").map(|f| f.kind) else {
        panic!("R₀ of the implicit form is a real number");
    };
    assert!(min > 0.0);
    let Some(Kind::Real { min, .. }) = field("sweep", "form.spiral.r0").map(|f| f.kind) else {
        panic!("r₀ of the sweep is a real number");
    };
    assert_eq!(min, 0.0);
    assert!(field("implicit", "form.curve.points").is_none());
}

#[test]
fn a_panel_edit_is_read_like_a_link_value() {
    use seashells_core::share::link::with;
    use seashells_core::spec::pattern::Model;
    let oliva = seashells_core::presets::preset("oliva-porphyria").unwrap();
    let edited = with(oliva, &oliva.spec, "pattern.model.d_a", "0.02");
    assert!(edited.problems.is_empty());
    assert_eq!(
        encode(oliva, &edited.spec),
        "v=1&preset=oliva-porphyria&pattern.model.d_a=0.02"
    );
    let Model::ActivatorInhibitor(m) = &edited.spec.pattern.model else {
        panic!("eq 9")
    };
    assert_eq!(m.d_a, 0.02);
    assert_eq!(edited.spec.seed, oliva.spec.seed, "an edit keeps the seed");

    let clamped = with(oliva, &edited.spec, "pattern.model.d_a", "3");
    assert_eq!(
        clamped.problems.len(),
        1,
        "one message per key: {:?}",
        clamped.problems
    );
    let message = &clamped.problems[0].message;
    assert!(
        message.contains("used 0.5, then") && message.ends_with("used 0.475"),
        "{message}"
    );

    let switched = with(oliva, &edited.spec, "pattern.model.kind", "automaton");
    assert!(switched.problems.is_empty(), "{:?}", switched.problems);
    assert!(matches!(switched.spec.pattern.model, Model::Automaton(_)));
    assert_eq!(decode(&encode(oliva, &switched.spec)).spec, switched.spec);
}

#[test]
fn a_shell_grows_like_another_that_differs_in_its_material_alone() {
    let spec = preset("oliva-porphyria").unwrap().spec.clone();
    let mut glossy = spec.clone();
    glossy.material.gloss = 1.0;
    glossy.material.drawing = Drawing::Lines;
    assert!(spec.grows_like(&glossy) && glossy.grows_like(&spec));
    let mut reseeded = glossy.clone();
    reseeded.seed += 1;
    assert!(
        !spec.grows_like(&reseeded),
        "another seed grows another pattern"
    );
    let mut painted = spec.clone();
    painted.colours.ground.0[0] ^= 1;
    assert!(
        !spec.grows_like(&painted),
        "the ground colour is in the pattern's pixels"
    );
}

/// Bad links, each with words of the message line the page shows for it (the session says
/// [`Problem::report`] of what the link's reading found); the page test opens a few of them
/// and checks that the message is shown as text, the shell still grows, and nothing of the
/// link became HTML.
const PAGE_BAD_LINKS: &[(&str, &str)] = &[
    (
        "v=1&preset=turbinate&form.spiral.whorlz=3",
        "form.spiral.whorlz: is not a key",
    ),
    (
        "v=1&preset=turbinate&form.spiral.whorls=many",
        "'many' is not a number",
    ),
    ("v=1&preset=turbinate&form.spiral.whorls=1e9", "used 30"),
    (
        "v=1&preset=oliva-porphyria&pattern.model.d_a=0.9",
        "used 0.5",
    ),
    ("v=1&preset=turbinate&form.curve.points=1,2", "not 3"),
    ("v=1&preset=turbi", "no preset 'turbi'"),
    ("v=1&preset=turbinate&form.spiral.whorls", "key=value"),
    ("v=7&preset=turbinate", "newer version"),
    (
        "v=1&preset=oliva-porphyria&pattern.cells=2048&growth.rows=20000",
        "pattern texture",
    ),
    (
        "v=1&preset=turbinate&form.spiral.whorls=30&form.spiral.subdivisions=16&form.curve.segments=512",
        "cap",
    ),
    (
        "v=1&preset=ca-waves&pattern.model.rule=1/6-8",
        "not of the form a/b-c/d",
    ),
    (
        "v=1&preset=%3Cimg%20src=x%20onerror=alert(1)%3E",
        "no preset",
    ),
    (
        "v=1&preset=kawaguchi-shell&form.mouth.protuberances=0,-1.5",
        "fold the mouth polygon over itself",
    ),
    (
        "v=1&preset=kawaguchi-shell&form.mouth.apexes=2",
        "outside the range 3 to 256",
    ),
    (
        "v=1&preset=kawaguchi-shell&form.chamber.ratio=0",
        "outside the range 0.5 to 2",
    ),
    (
        "v=1&preset=kawaguchi-shell&form.mouth.apexes=256&form.chambers=2000&form.septa=true&form.chamber.ratio=1.001",
        "cap of 2000000",
    ),
    (
        "v=1&preset=kawaguchi-shell&form.chambers=2000",
        "at most 267 at this ratio",
    ),
    (
        "v=1&preset=kawaguchi-ammonite&form.chamber.ratio=1",
        "Shown as asked, but: form.chamber.ratio: whorls overlap",
    ),
    (
        "v=1&preset=implicit-whorl&form.spiral.lambda=1.01",
        "too thin for the grid of 96 voxels",
    ),
    (
        "v=1&preset=kawaguchi-shell&form.chamber.translation.x=0.1&form.chamber.translation.y=0.2&form.chamber.translation.z=0.15",
        "Read as today's keys: form.chamber.translation",
    ),
];

#[test]
fn the_pages_message_for_each_bad_link_says_what_is_wrong() {
    let seed = format!("v=1&preset=turbinate&seed={}", "9".repeat(20_000));
    let links = PAGE_BAD_LINKS
        .iter()
        .copied()
        .chain([(seed.as_str(), "more than the 16384")]);
    for (link, words) in links {
        let decoded = decode(link);
        let said = Problem::report(&decoded.problems).unwrap_or_default();
        assert!(
            said.contains(words),
            "{}: the page says '{said}', without '{words}'",
            &link[..link.len().min(80)]
        );
    }
}
