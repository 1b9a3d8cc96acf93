//! The map of a shell's parameter space: tiles spaced as the axes say, each the pattern (or, over
//! a parameter of the form, the shell) of the spec its link reopens, computed deterministically,
//! with tiles that cannot be integrated or grown refused with their reason while the others
//! fill.

use seashells_core::forms::sweep::raup::Raup;
use seashells_core::presets::preset;
use seashells_core::share::link::{decode, flatten};
use seashells_core::spec::fields::field;
use seashells_core::spec::form::Form;
use seashells_core::variation::parameter_map::{
    Axis, PATIENCE_S, PHONE_SIDE, ParameterMap, SIDE, first_axes, parameters, side_for,
};
use seashells_core::variation::tile::Tile;

fn value(spec: &seashells_core::spec::ShellSpec, key: &str) -> f64 {
    flatten(&serde_json::to_value(spec).unwrap())[key]
        .as_f64()
        .unwrap()
}

/// Checks that `tile` can grow, has the values of its axes, and that its link reopens it as it
/// is, with nothing to say.
fn grown_and_reopened(tile: &Tile, values: [(&str, f64); 2]) {
    assert_eq!(tile.failure, None);
    for (key, v) in values {
        assert_eq!(value(&tile.spec, key), v, "{key}");
    }
    let opened = decode(&tile.link);
    assert!(opened.problems.is_empty(), "{:?}", opened.problems);
    assert_eq!(opened.spec, tile.spec, "the link reopens the tile's shell");
}

fn filled(map: &mut ParameterMap) {
    let mut steps = 0;
    while !map.finished() {
        map.work(|| {
            steps += 1;
            steps % 100 != 0
        });
    }
}

#[test]
fn axes_step_evenly_or_by_equal_ratios_clamp_to_their_range_and_refuse_what_cannot_span_a_map() {
    let linear = Axis::new("sweep", "pattern.model.d_a", 0.01, 0.03, 5).unwrap();
    assert_eq!(linear.values, [0.01, 0.015, 0.02, 0.025, 0.03]);
    let ratios = Axis::new("sweep", "pattern.model.sigma", 0.0001, 0.01, 3).unwrap();
    assert_eq!(ratios.values, [0.0001, 0.001, 0.01]);
    for (key, from, to, count, why) in [
        ("pattern.model.d_a", 0.9, 1.5, 8, "lies beyond it"),
        ("pattern.model.d_a", 0.01, 0.01, 8, "two different numbers"),
        ("pattern.cells", 10.0, 20.0, 8, "not a parameter"),
        (
            "form.chamber.ratio",
            1.0,
            1.2,
            8,
            "not a parameter of a sweep",
        ),
        ("form.curve.closed", 0.0, 1.0, 8, "not a parameter"),
        ("pattern.model.d_a", 0.01, 0.02, 1, "at least two values"),
    ] {
        let e = Axis::new("sweep", key, from, to, count).unwrap_err();
        assert!(e.contains(why), "{key}: {e}");
    }
    // A range beyond the field's is spread within it, and says so.
    let whorls = Axis::new("sweep", "form.spiral.whorls", 1.0, 40.0, 3).unwrap();
    assert_eq!(whorls.values, [1.0, 15.5, 30.0]);
    let note = whorls.note.unwrap();
    assert!(
        note.contains("runs from 0.05 to 30") && note.contains("1 to 40 was clamped to 1 to 30"),
        "{note}"
    );
    assert_eq!(linear.note, None);
    let d_a = field("sweep", "pattern.model.d_a").unwrap();
    assert_eq!(
        Axis::around("sweep", d_a, 0.015, 3).unwrap().values,
        [0.0075, 0.01875, 0.03]
    );
    assert_eq!(
        Axis::around("sweep", d_a, 0.0, 2).unwrap().values,
        [0.0, 0.125]
    );
    let lambda = field("sweep", "form.spiral.lambda_r").unwrap();
    let ratios = Axis::around("sweep", lambda, 1.007, 3).unwrap().values;
    let per_whorl = |l: f64| l.powi(36);
    assert!(
        (per_whorl(ratios[0]).ln() * 2.0 - per_whorl(1.007).ln()).abs() < 0.05
            && (per_whorl(ratios[2]).ln() / 2.0 - per_whorl(1.007).ln()).abs() < 0.05,
        "a growth ratio spans half to twice its logarithm (rounded as the panel shows it): \
         {ratios:?}"
    );
    let apexes = Axis::new("chambers", "form.mouth.apexes", 3.0, 12.0, 4).unwrap();
    assert_eq!(apexes.values, [3.0, 6.0, 9.0, 12.0], "whole numbers");
    assert!(apexes.shapes() && !linear.shapes());
}

#[test]
fn every_tile_is_the_pattern_of_its_own_link_and_the_map_is_the_same_every_time() {
    let oliva = preset("oliva-porphyria").unwrap();
    let spec = &oliva.spec;
    let offered = parameters(spec);
    let names: Vec<&str> = offered.iter().map(|(f, _)| f.key).collect();
    assert!(names.contains(&"pattern.model.d_a") && names.contains(&"pattern.model.nu"));
    assert!(names.contains(&"form.spiral.lambda_r") && names.contains(&"form.curve.segments"));
    assert!(
        names.iter().all(|k| ["pattern.model.", "form.", "raup."]
            .iter()
            .any(|p| k.starts_with(p))),
        "{names:?}"
    );
    let (x, y) = first_axes(&offered);
    assert_eq!(
        (names[x], names[y]),
        ("pattern.model.d_a", "pattern.model.sigma")
    );
    assert_eq!(offered[x].1, 0.015, "with the shell's value");
    let map = || {
        let x = Axis::new("sweep", "pattern.model.d_a", 0.005, 0.04, 3).unwrap();
        let y = Axis::new("sweep", "pattern.model.nu", 0.005, 0.03, 3).unwrap();
        let mut map = ParameterMap::new(oliva, spec, x, y);
        assert!(!map.shells(), "a table of patterns");
        filled(&mut map);
        map
    };
    let (a, b) = (map(), map());
    assert_eq!(a.rows, 400, "as many rows as cells");
    let mut distinct = Vec::new();
    for (j, &ny) in a.y.values.iter().enumerate() {
        for (i, &dx) in a.x.values.iter().enumerate() {
            let tile = a.tile(i, j);
            grown_and_reopened(tile, [("pattern.model.d_a", dx), ("pattern.model.nu", ny)]);
            let picture = tile.picture.as_ref().unwrap();
            assert_eq!(
                (picture.width, picture.height),
                (100, 100),
                "400 cells averaged by 4"
            );
            assert_eq!(
                Some(picture),
                b.tile(i, j).picture.as_ref(),
                "deterministic"
            );
            if !distinct.contains(&picture.rgba) {
                distinct.push(picture.rgba.clone());
            }
        }
    }
    assert_eq!(
        distinct.len(),
        9,
        "every pair of values draws its own pattern"
    );
}

#[test]
fn tiles_that_cannot_be_integrated_say_why_and_the_others_fill() {
    let stripes = preset("stripes").unwrap();
    // D_a with μ = 0.01 is stable up to (2 − μ)/4 = 0.4975.
    let x = Axis::new("sweep", "pattern.model.d_a", 0.002, 0.5, 2).unwrap();
    let y = Axis::new("sweep", "pattern.model.d_s", 0.1, 0.4, 2).unwrap();
    let mut map = ParameterMap::new(stripes, &stripes.spec, x, y);
    filled(&mut map);
    for j in 0..2 {
        assert!(map.tile(0, j).picture.is_some());
        let refused = map.tile(1, j);
        assert!(refused.picture.is_none());
        let why = refused.failure.as_deref().unwrap();
        assert!(why.contains("D_a") && why.contains("stabl"), "{why}");
    }
}

#[test]
fn a_map_over_the_forms_parameters_is_a_grid_of_shells_each_reopened_by_its_link() {
    let plain = preset("turbinate").unwrap();
    let offered = parameters(&plain.spec);
    assert!(
        offered
            .iter()
            .all(|(f, _)| f.key.starts_with("form.") || f.key.starts_with("raup.")),
        "no pattern"
    );
    let lambda_r = Axis::new("sweep", "form.spiral.lambda_r", 1.002, 1.02, 4).unwrap();
    let whorls = Axis::new("sweep", "form.spiral.whorls", 1.0, 6.0, 3).unwrap();
    let mut map = ParameterMap::new(plain, &plain.spec, lambda_r, whorls);
    assert!(map.shells(), "tiles show shells, drawn by the page");
    assert_eq!(
        map.current, None,
        "8 whorls lie beyond 6 by more than half a step"
    );
    assert_eq!(map.to_compute().len(), 12);
    assert_eq!(map.work(|| true), 0..0, "no pattern is computed here");
    for (j, &w) in map.y.values.clone().iter().enumerate() {
        for (i, &l) in map.x.values.clone().iter().enumerate() {
            let tile = map.tile(i, j);
            grown_and_reopened(
                tile,
                [("form.spiral.lambda_r", l), ("form.spiral.whorls", w)],
            );
        }
    }
    let around = ParameterMap::new(
        plain,
        &plain.spec,
        Axis::new("sweep", "form.spiral.lambda_r", 1.002, 1.02, 4).unwrap(),
        Axis::new("sweep", "form.spiral.whorls", 2.0, 9.0, 3).unwrap(),
    );
    assert_eq!(
        around.current,
        Some(2 * 4 + 1),
        "λᵣ 1.007 by 1.008, 8 whorls by 9"
    );
    let fast = Axis::new("sweep", "form.spiral.lambda_r", 1.02, 1.05, 2).unwrap();
    let whorls = Axis::new("sweep", "form.spiral.lambda_z", 1.0, 1.001, 2).unwrap();
    let repaired = ParameterMap::new(plain, &plain.spec, fast, whorls);
    let tile = repaired.tile(1, 0);
    assert_eq!(tile.failure, None, "the values of its axes can grow");
    assert!(value(&tile.spec, "form.spiral.whorls") < 8.0);
    let note = tile.note.as_deref().unwrap();
    assert!(note.starts_with("form.spiral.whorls:"), "{note}");
    let refused = ParameterMap::new(
        plain,
        &plain.spec,
        Axis::new("sweep", "form.spiral.lambda_r", 1.02, 1.05, 2).unwrap(),
        Axis::new("sweep", "form.spiral.whorls", 1.0, 30.0, 2).unwrap(),
    );
    let why = refused.tile(1, 1).failure.as_deref().unwrap();
    assert!(why.starts_with("form.spiral.whorls:"), "{why}");
    map.shown(0, Ok(()));
    map.shown(1, Err("the curve leaves the axis".into()));
    assert_eq!(map.to_compute().len(), 10);
    for index in map.to_compute() {
        map.shown(index, Ok(()));
    }
    assert!(map.finished());
    assert_eq!(
        map.tile(1, 0).failure.as_deref(),
        Some("the curve leaves the axis")
    );
}

#[test]
fn raups_map_spans_w_and_t_at_the_shells_d_each_tile_a_self_similar_shell() {
    let plain = preset("turbinate").unwrap();
    let offered = parameters(&plain.spec);
    let (x, y) = first_axes(&offered);
    assert_eq!(
        (offered[x].0.key, offered[y].0.key),
        ("raup.w", "raup.t"),
        "Raup's expansion across, translation down"
    );
    let raup = |spec: &seashells_core::spec::ShellSpec| match &spec.form {
        Form::Sweep(s) => Raup::of(s).unwrap(),
        _ => unreachable!(),
    };
    let shell = raup(&plain.spec);
    assert_eq!(offered[x].1, shell.w);
    let map = ParameterMap::new(
        plain,
        &plain.spec,
        Axis::new("sweep", "raup.w", 1.1, 3.0, 4).unwrap(),
        Axis::new("sweep", "raup.t", 0.0, 3.0, 4).unwrap(),
    );
    assert!(map.shells());
    assert_eq!(map.current, Some(2 * 4), "W 1.29 by 1.1, T 1.9 by 2");
    // The gallery's swept shells stand where their own W and T fall.
    assert!(
        map.landmarks
            .iter()
            .any(|l| (l.tile, l.preset.id) == (2 * 4, plain.id)),
        "the shell among them"
    );
    assert!(map.landmarks.len() >= 3, "{}", map.landmarks.len());
    for l in &map.landmarks {
        let (at, p) = (l.tile, l.preset);
        // The marker lies within its tile, off its centre by where its values fall between
        // the tile's and the next.
        assert!((0.0..=1.0).contains(&l.within.0) && (0.0..=1.0).contains(&l.within.1));
        let theirs = raup(&p.spec);
        let (xs, ys) = (&map.x.values, &map.y.values);
        let column = (at % 4) as f64 + l.within.0 - 0.5;
        let row = (at / 4) as f64 + l.within.1 - 0.5;
        let w = xs[0] * (xs[3] / xs[0]).powf(column / 3.0);
        let t = ys[0] + (ys[3] - ys[0]) * row / 3.0;
        assert!(
            (w / theirs.w - 1.0).abs() < 0.02,
            "{}: W {w} for {}",
            p.id,
            theirs.w
        );
        assert!(
            (t - theirs.t).abs() < 0.02,
            "{}: T {t} for {}",
            p.id,
            theirs.t
        );
        let (i, j) = (at % 4, at / 4);
        let nearest = |values: &[f64], v: f64, log: bool| {
            let d = |a: f64| {
                if log {
                    (a / v).ln().abs()
                } else {
                    (a - v).abs()
                }
            };
            (0..values.len())
                .min_by(|&a, &b| d(values[a]).total_cmp(&d(values[b])))
                .unwrap()
        };
        assert_eq!(
            i,
            nearest(&map.x.values, theirs.w, true),
            "{}: W {}",
            p.id,
            theirs.w
        );
        assert_eq!(
            j,
            nearest(&map.y.values, theirs.t, false),
            "{}: T {}",
            p.id,
            theirs.t
        );
    }
    for (j, &t) in map.y.values.iter().enumerate() {
        for (i, &w) in map.x.values.iter().enumerate() {
            let tile = map.tile(i, j);
            assert_eq!(tile.failure, None, "W {w}, T {t}");
            let got = raup(&tile.spec);
            assert!((got.w - w).abs() < 1e-6 * w, "W {w}: {got:?}");
            assert!((got.t - t).abs() < 1e-6, "T {t}: {got:?}");
            assert!((got.d - shell.d).abs() < 1e-9, "D kept: {got:?}");
            let lambda = |key| value(&tile.spec, key);
            assert_eq!(
                lambda("form.spiral.lambda_r"),
                lambda("form.spiral.lambda_z")
            );
            assert_eq!(
                lambda("form.spiral.lambda_r"),
                lambda("form.curve.lambda_c")
            );
            assert_eq!(decode(&tile.link).spec, tile.spec, "its link reopens it");
        }
    }
    let apart: Vec<bool> = map.tiles().iter().map(|t| t.apart).collect();
    assert!(!apart[0], "W 1.1, T 0: whorls on whorls");
    assert!(apart[15], "W 3, T 3: each whorl clear of the last");
    // D near 1 leaves the curve thin and far out: r₀ passes its range, and the tile says so.
    let far = ParameterMap::new(
        plain,
        &plain.spec,
        Axis::new("sweep", "raup.d", 0.1, 0.95, 2).unwrap(),
        Axis::new("sweep", "raup.t", 0.0, 1.0, 2).unwrap(),
    );
    assert_eq!(far.tile(0, 0).failure, None);
    let why = far.tile(1, 0).failure.as_deref().unwrap();
    assert!(why.contains("form.spiral.r0"), "{why}");
}

#[test]
fn a_machine_that_draws_shells_slowly_gets_fewer_tiles_within_the_patience() {
    assert_eq!(side_for(None, SIDE), SIDE, "nothing measured yet");
    assert_eq!(side_for(Some(0.18), SIDE), SIDE, "64 shells in 12 s");
    assert_eq!(side_for(Some(0.5), SIDE), 6, "36 shells in 18 s");
    assert_eq!(
        side_for(Some(3.0), SIDE),
        PHONE_SIDE,
        "never fewer than a phone's"
    );
    assert_eq!(side_for(Some(3.0), PHONE_SIDE), PHONE_SIDE);
    for s in [0.05, 0.3, 0.4, 0.6, 0.8] {
        let side = side_for(Some(s), SIDE);
        assert!(
            side == PHONE_SIDE || (side * side) as f64 * s <= PATIENCE_S,
            "{s} s a shell: {side} × {side}"
        );
    }
}
