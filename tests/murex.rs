//! Murex cabritii (Galbraith, Prusinkiewicz & Wyvill §3): varices whose spines follow table 1,
//! canal rows that follow table 2, spines that stand out of the body, a hollow solid,
//! determinism by seed, spines placed by the pattern, and messages for bad values.
//!
//! The paper's tables reached us with their columns run together. Our reading:
//!
//! Table 1 (relative size σ of the spines of every varix of a whorl, by angle from the
//! horizontal): each row's values are right-aligned, so a row with k values fills the last k
//! whorls. The last whorl then carries spines over −90°…80° (18 spines), whorl 6 eight
//! (−10°…60°), whorl 5 five (20°…60°), whorl 4 three (40°…60°), whorls 2 and 3 one each at 50°
//! (the shoulder, where earlier whorls show above the suture), and whorl 1 none. Every number
//! that survived is kept; the 50° row's "0.8/ 09| 15| 064|096 0.72" reads 0.8, 0.9, 1.5, 0.64,
//! 0.96, 0.72.
//!
//! Table 2 (relative size of the axial spines on the canal below the last three varices, from
//! the body down the canal): five full rows, and a sixth with two values, read left-aligned:
//! varices 1 and 2 (the earlier ones) have six spines, varix 3 (at the opening) five, which
//! matches the paper's "axial rows of 5–6 spines" (fig 9).

use crate::common;

use common::{assert_refused_and_repaired, implicit, signed_volume};
use glam::DVec3;
use seashells_core::forms::murex::helix::Instances;
use seashells_core::forms::murex::whorl::{Whorl, whorl};
use seashells_core::generator::Generator;
use seashells_core::mesh::Mesh;
use seashells_core::presets;
use seashells_core::share::link::{decode, encode};
use seashells_core::share::repair::repair;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::implicit::Placement;
use std::collections::BTreeMap;

/// Table 1 as we read it: (whorl, angle°, σ).
const TABLE_1: &[(u32, f64, f64)] = &[
    (2, 50.0, 0.8),
    (3, 50.0, 0.9),
    (4, 40.0, 0.8),
    (4, 50.0, 1.5),
    (4, 60.0, 0.7),
    (5, 20.0, 0.9),
    (5, 30.0, 0.7),
    (5, 40.0, 1.5),
    (5, 50.0, 0.64),
    (5, 60.0, 1.06),
    (6, -10.0, 0.55),
    (6, 0.0, 0.8),
    (6, 10.0, 1.55),
    (6, 20.0, 0.64),
    (6, 30.0, 0.7),
    (6, 40.0, 0.55),
    (6, 50.0, 0.96),
    (6, 60.0, 0.6),
    (7, -90.0, 0.55),
    (7, -80.0, 0.64),
    (7, -70.0, 0.55),
    (7, -60.0, 1.14),
    (7, -50.0, 0.55),
    (7, -40.0, 1.92),
    (7, -30.0, 0.55),
    (7, -20.0, 0.82),
    (7, -10.0, 0.55),
    (7, 0.0, 1.44),
    (7, 10.0, 0.64),
    (7, 20.0, 0.64),
    (7, 30.0, 0.55),
    (7, 40.0, 1.62),
    (7, 50.0, 0.72),
    (7, 60.0, 0.64),
    (7, 70.0, 0.55),
    (7, 80.0, 0.5),
];

/// Table 2 as we read it: the canal spines below varices 1, 2 and 3, from the body down.
const TABLE_2: [&[f64]; 3] = [
    &[0.96, 0.92, 0.84, 0.68, 0.45, 0.25],
    &[0.95, 0.99, 0.76, 0.51, 0.35, 0.28],
    &[1.00, 0.90, 0.92, 0.70, 0.60],
];

fn spec_of(id: &str) -> ShellSpec {
    presets::preset(id).expect(id).spec.clone()
}

fn built(spec: &mut ShellSpec) -> Whorl {
    let (pattern, seed, rows) = (spec.pattern.clone(), spec.seed, spec.growth.rows as usize);
    whorl(implicit(spec), &pattern, seed, rows).expect("builds")
}

fn grown(spec: &ShellSpec) -> Generator {
    let mut g = Generator::new(spec).expect("builds");
    g.finish();
    g
}

#[test]
fn the_preset_carries_both_tables() {
    let mut spec = spec_of("murex-cabritii");
    let i = implicit(&mut spec);
    let table: Vec<(u32, f64, f64)> = i
        .varices
        .spines
        .iter()
        .map(|r| (r[0] as u32, r[1], r[2]))
        .collect();
    assert_eq!(table, TABLE_1);
    for (v, row) in TABLE_2.iter().enumerate() {
        let sizes: Vec<f64> = i
            .canal_spines
            .spines
            .iter()
            .filter(|s| s[0] == (v + 1) as f64)
            .map(|s| s[1])
            .collect();
        assert_eq!(&sizes, row, "varix {}", v + 1);
    }
    assert_eq!((i.whorls, i.sections, i.surfaces), (7, 3, 6));
    assert_eq!(i.whorl_angle, 348.0);
    assert_eq!(i.varices.bend, 30.0);
}

#[test]
fn every_varix_has_its_whorls_spines_and_the_last_three_their_canal_rows() {
    let mut spec = spec_of("murex-cabritii");
    let shell = built(&mut spec);
    assert_eq!(shell.varices.len(), 21, "three varices per whorl");
    let mut expected: BTreeMap<u32, Vec<f64>> = BTreeMap::new();
    for &(w, angle, _) in TABLE_1 {
        expected.entry(w).or_default().push(angle);
    }
    for (n, varix) in shell.varices.iter().enumerate() {
        let whorl = n as u32 / 3 + 1;
        let angles: Vec<f64> = varix.spines.iter().map(|s| s.spine.angle).collect();
        assert_eq!(
            angles,
            expected.get(&whorl).cloned().unwrap_or_default(),
            "varix {n} of whorl {whorl}"
        );
        let canal = if n >= 18 { TABLE_2[n - 18].len() } else { 0 };
        assert_eq!(varix.canal_spines, canal, "canal row below varix {n}");
    }
    // Varices close the sections: 116° apart, at the end of every sixth instance.
    let instances: Vec<u32> = shell.varices.iter().map(|v| v.instance).collect();
    assert_eq!(instances[..3], [5, 11, 17]);
}

/// The largest distance from the shell's axis (z) of the vertices within `degrees` of the
/// azimuth `azimuth`.
fn reach_from_axis(mesh: &Mesh, azimuth: f64, degrees: f64) -> f64 {
    mesh.vertices
        .iter()
        .map(|v| DVec3::from(v.position.map(f64::from)))
        .filter(|p| {
            let a = p.y.atan2(p.x);
            let d = (a - azimuth + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                - std::f64::consts::PI;
            d.abs() <= degrees.to_radians()
        })
        .map(|p| p.truncate().length())
        .fold(0.0, f64::max)
}

#[test]
fn spines_stand_out_of_the_body_by_their_relative_size() {
    // At each of the last two varices, the mesh reaches farther from the axis than the body
    // alone does by at least σ·D, with σ the table's horizontal spine (0°) of the last whorl.
    let mut spec = spec_of("murex-cabritii");
    implicit(&mut spec).resolution = 96;
    let mut body = spec.clone();
    implicit(&mut body).varices.spines.clear();
    implicit(&mut body).canal_spines.spines.clear();
    let (with, without) = (grown(&spec).snapshot(), grown(&body).snapshot());
    let rows = spec.growth.rows as usize;
    let instances = Instances::new(implicit(&mut spec), rows);
    let shell = built(&mut spec);
    let sigma = TABLE_1
        .iter()
        .find(|&&(w, a, _)| w == 7 && a == 0.0)
        .unwrap()
        .2;
    for varix in &shell.varices[19..] {
        let k = f64::from(varix.instance);
        let centre = instances.placement(k).translation;
        let azimuth = centre.y.atan2(centre.x);
        let gain = reach_from_axis(&with, azimuth, 4.0) - reach_from_axis(&without, azimuth, 4.0);
        let d = instances.size(k);
        assert!(
            gain >= sigma * d,
            "varix at {k}: spines reach {gain}, less than σ·D = {}",
            sigma * d
        );
    }
}

/// Hollow: the shell's volume is well below what its outer surface alone encloses, which is
/// the same shell without the opening. (That it is one closed piece at its resolution and at
/// 256³ is checked in `murex_resolutions.rs`.)
#[test]
fn the_opening_hollows_the_shell() {
    let mut spec = spec_of("murex-cabritii");
    implicit(&mut spec).resolution = 128;
    let mut solid = spec.clone();
    implicit(&mut solid).opening.inside.points.clear();
    implicit(&mut solid).opening.inside.cones.clear();
    let ratio = signed_volume(&grown(&spec).snapshot()) / signed_volume(&grown(&solid).snapshot());
    assert!(ratio < 0.75 && ratio > 0.2, "hollow / solid volume {ratio}");
}

#[test]
fn the_seed_decides_the_bumps_and_bends_and_a_link_reproduces_them() {
    let mut spec = spec_of("murex-cabritii");
    implicit(&mut spec).resolution = 48;
    let a = grown(&spec).mesh_hash();
    assert_eq!(a, grown(&spec).mesh_hash());
    let mut other = spec.clone();
    other.seed += 1;
    assert_ne!(a, grown(&other).mesh_hash(), "another seed, other bumps");
    let preset = presets::preset("murex-cabritii").unwrap();
    let decoded = decode(&encode(preset, &other));
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    assert_eq!(grown(&decoded.spec).mesh_hash(), grown(&other).mesh_hash());
}

/// What the reaction-diffusion process placed, varix by varix: (whorl from 1, its spines'
/// angles and σ, its section's bumps' angles).
type Arrangement = Vec<(u32, Vec<(f64, f64)>, Vec<f64>)>;

fn arrangement(spec: &mut ShellSpec) -> Arrangement {
    let per_whorl = {
        let i = implicit(spec);
        i.sections * i.surfaces
    };
    built(spec)
        .varices
        .iter()
        .map(|v| {
            (
                v.instance / per_whorl + 1,
                v.spines
                    .iter()
                    .map(|s| (s.spine.angle, s.spine.sigma))
                    .collect(),
                v.bumps.iter().map(|b| b.spine.angle).collect(),
            )
        })
        .collect()
}

#[test]
fn reaction_diffusion_places_spines_and_bumps_on_every_whorl_from_the_second() {
    let mut spec = spec_of("murex-rd-spines");
    assert_eq!(implicit(&mut spec).varices.placement, Placement::Pattern);
    let whorls = implicit(&mut spec).whorls;
    let arranged = arrangement(&mut spec);
    for whorl in 2..=whorls {
        let (spines, bumps): (usize, usize) = arranged
            .iter()
            .filter(|a| a.0 == whorl)
            .fold((0, 0), |(s, b), a| (s + a.1.len(), b + a.2.len()));
        assert!(spines > 0, "whorl {whorl} is bare: {arranged:?}");
        assert!(bumps > 0, "whorl {whorl} has no bumps: {arranged:?}");
    }
    // Over the whole outer lip, not table 1's windows: the spire's whorls carry spines off
    // their table angle of 50°, and the last whorl below the horizontal.
    let angles = |whorl: u32| -> Vec<f64> {
        arranged
            .iter()
            .filter(|a| a.0 == whorl)
            .flat_map(|a| a.1.iter().map(|s| s.0))
            .collect()
    };
    assert!(
        angles(2)
            .iter()
            .chain(&angles(3))
            .any(|a| (a - 50.0).abs() > 15.0)
    );
    assert!(angles(whorls).iter().any(|&a| a < -30.0));
    let v = &implicit(&mut spec).varices;
    let (lowest, highest) = (
        v.peak_sigma * (v.spine_level - v.bump_level) / (1.0 - v.bump_level),
        v.peak_sigma,
    );
    for (_, spines, _) in &arranged {
        for &(angle, sigma) in spines {
            assert!(angle.abs() <= 90.0, "a spine off the outer lip at {angle}°");
            assert!(
                (lowest - 1e-9..=highest + 1e-9).contains(&sigma),
                "σ {sigma}"
            );
        }
    }
}

#[test]
fn spine_lengths_follow_the_shells_growth_from_whorl_to_whorl() {
    // The longest spine of each whorl, in the shell's units (σ times the length times D),
    // grows with the shell: never shorter than the whorl before's, never more than twice it
    // (the table's last whorl jumps from σ 0.9 at the shoulder to 1.92).
    let mut spec = spec_of("murex-rd-spines");
    let arranged = arrangement(&mut spec);
    let i = implicit(&mut spec).clone();
    let instances = Instances::new(&i, spec.growth.rows as usize);
    let per_whorl = i.sections * i.surfaces;
    let longest: Vec<f64> = (2..=i.whorls)
        .map(|whorl| {
            arranged
                .iter()
                .zip(built(&mut spec).varices)
                .filter(|(a, _)| a.0 == whorl)
                .flat_map(|(a, v)| {
                    let d = instances.size(f64::from(v.instance));
                    a.1.iter().map(move |s| s.1 * i.varices.length * d)
                })
                .fold(0.0, f64::max)
        })
        .collect();
    assert_eq!(per_whorl, 18);
    for pair in longest.windows(2) {
        let ratio = pair[1] / pair[0];
        assert!((1.0..=2.0).contains(&ratio), "{longest:?}");
    }
}

#[test]
fn other_pattern_parameters_give_another_arrangement_and_the_same_spec_the_same() {
    let mut spec = spec_of("murex-rd-spines");
    let first = arrangement(&mut spec);
    assert_eq!(
        first,
        arrangement(&mut spec.clone()),
        "same spec, same arrangement"
    );
    let preset = presets::preset("murex-rd-spines").unwrap();
    let decoded = decode(&encode(preset, &spec));
    assert_eq!(
        first,
        arrangement(&mut decoded.spec.clone()),
        "through a link"
    );
    // Another pattern: the substrate diffuses half as far, so the peaks stand closer.
    let mut changed = spec.clone();
    if let seashells_core::spec::pattern::Model::ActivatorSubstrate(p) = &mut changed.pattern.model
    {
        p.d_s *= 0.5;
    } else {
        panic!("the preset's pattern is eq 8");
    }
    let decoded = decode(&encode(preset, &changed));
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    let second = arrangement(&mut decoded.spec.clone());
    let last = |a: &Arrangement| -> Vec<i64> {
        a.last()
            .unwrap()
            .1
            .iter()
            .map(|s| s.0.round() as i64)
            .collect()
    };
    let (a, b) = (last(&first), last(&second));
    let moved =
        a.iter().filter(|x| !b.contains(x)).count() + b.iter().filter(|x| !a.contains(x)).count();
    assert!(
        moved >= 2,
        "the last varix's spines hardly moved: {a:?} against {b:?}"
    );
    let count = |a: &Arrangement| a.iter().map(|v| v.1.len()).sum::<usize>();
    assert_ne!(first, second);
    // The levels decide what grows: a lower spine level turns bumps into spines.
    let mut lower = spec.clone();
    implicit(&mut lower).varices.spine_level = 0.6;
    assert!(count(&arrangement(&mut lower)) > count(&first));
    // And the table is not read.
    let mut no_table = spec.clone();
    implicit(&mut no_table).varices.spines.clear();
    assert_eq!(first, arrangement(&mut no_table));
}

#[test]
fn murex_pecten_has_many_more_spines_than_cabritii() {
    let count = |id: &str| -> usize {
        built(&mut spec_of(id))
            .varices
            .iter()
            .map(|v| v.spines.len())
            .sum()
    };
    let (pecten, cabritii) = (count("murex-pecten"), count("murex-cabritii"));
    assert!(pecten >= 2 * cabritii, "{pecten} against {cabritii}");
}

#[test]
fn bad_values_get_messages_that_name_the_key() {
    let base = spec_of("murex-cabritii");
    type Spoil = Box<dyn Fn(&mut ShellSpec)>;
    let cases: Vec<(&str, Spoil)> = vec![
        (
            "form.varices.spines",
            Box::new(|s| implicit(s).varices.spines[0][0] = 9.0),
        ),
        (
            "form.varices.spines",
            Box::new(|s| implicit(s).varices.spines[3][2] = f64::NAN),
        ),
        (
            "form.varices.length",
            Box::new(|s| implicit(s).varices.length = -1.0),
        ),
        (
            "form.varices.bend",
            Box::new(|s| implicit(s).varices.bend = 200.0),
        ),
        (
            "form.varices.bump_sets",
            Box::new(|s| implicit(s).varices.bump_sets = 1000),
        ),
        (
            "form.varices.spine_level",
            Box::new(|s| implicit(s).varices.spine_level = 1.5),
        ),
        (
            "form.varices.bump_level",
            Box::new(|s| implicit(s).varices.bump_level = 0.9),
        ),
        (
            "form.varices.peak_sigma",
            Box::new(|s| implicit(s).varices.peak_sigma = f64::NAN),
        ),
        (
            "form.canal_spines.spines",
            Box::new(|s| implicit(s).canal_spines.spines[0][0] = 4.0),
        ),
        (
            "form.opening.inside.cones",
            Box::new(|s| implicit(s).opening.inside.cones[0][6] = 0.0),
        ),
        (
            "form.opening.ahead",
            Box::new(|s| implicit(s).opening.ahead = 100),
        ),
        (
            "form.opening.extension",
            Box::new(|s| implicit(s).opening.extension[0][7] = f64::NAN),
        ),
        (
            "form.opening.extension",
            Box::new(|s| implicit(s).opening.extension[1][3] = 1e300),
        ),
        (
            "form.opening.wall",
            Box::new(|s| implicit(s).opening.wall = 65),
        ),
        // Sizes that once made the shell grow to nothing, without a word.
        (
            "form.spiral.r0",
            Box::new(|s| implicit(s).spiral.r0 = 1e-300),
        ),
        (
            "form.generator.points",
            Box::new(|s| implicit(s).generator.points[0][3] = 1e300),
        ),
        (
            "form.generator.cones",
            Box::new(|s| implicit(s).generator.cones[0][0] = -1e300),
        ),
    ];
    for (key, spoil) in cases {
        let mut spec = base.clone();
        spoil(&mut spec);
        assert_refused_and_repaired(spec, &base, key);
    }
    // Spines placed by a pattern that is not there.
    let mut spec = spec_of("murex-rd-spines");
    spec.pattern.model = seashells_core::spec::pattern::Model::None;
    let problems = repair(&mut spec, &spec_of("murex-rd-spines"));
    assert!(
        problems.iter().any(|p| p.key == "form.varices.placement"),
        "{problems:?}"
    );
    assert!(Generator::new(&spec).is_ok());
    // The new keys through a link: out of range, or levels the wrong way round.
    for (link, key) in [
        ("form.varices.spine_level=7", "form.varices.spine_level"),
        (
            "form.varices.spine_level=0.5&form.varices.bump_level=0.7",
            "form.varices.bump_level",
        ),
        ("form.varices.peak_sigma=x", "form.varices.peak_sigma"),
    ] {
        let decoded = decode(&format!("v=1&preset=murex-rd-spines&{link}"));
        assert!(
            decoded.problems.iter().any(|p| p.key == key),
            "{link}: {:?}",
            decoded.problems
        );
        assert!(Generator::new(&decoded.spec).is_ok(), "{link}");
    }
    // … and with no table to fall back on: no varices, so no canal spines either.
    let mut spec = spec_of("murex-rd-spines");
    spec.pattern.model = seashells_core::spec::pattern::Model::None;
    implicit(&mut spec).varices.spines.clear();
    let problems = repair(&mut spec, &spec_of("murex-rd-spines"));
    assert!(
        problems.iter().any(|p| p.key == "form.varices.placement"),
        "{problems:?}"
    );
    assert!(Generator::new(&spec).is_ok());
}

#[test]
fn the_aperture_is_open_at_every_stage_the_model_carves() {
    // From the centre of the newest generating surface forward along the growth direction,
    // the field stays below the iso-value: the hollow reaches through the growing edge. A
    // whorl is hollow once its wall is thick enough (`opening::THINNEST_WALL` of the shell),
    // from the same stage at every resolution: about where its generating surface spans 8
    // 112ths of the shell.
    let preset = implicit(&mut spec_of("murex-cabritii")).resolution;
    for resolution in [preset, 256] {
        let mut spec = spec_of("murex-cabritii");
        implicit(&mut spec).resolution = resolution;
        let rows = spec.growth.rows as usize;
        let instances = Instances::new(implicit(&mut spec), rows);
        let shell = built(&mut spec);
        let cell = (shell.tree.bounds.max - shell.tree.bounds.min).max_element() / 112.0;
        let last = shell.instances - 1;
        let first = (0..=last)
            .find(|&k| instances.size(f64::from(k)) >= 8.0 * cell)
            .unwrap();
        assert!(last - first >= 9, "{resolution}: stages {first}…{last}");
        for step in first..=last {
            let tree = shell.tree.cull(&shell.tree.bounds, step).expect("grown");
            let at = instances.placement(f64::from(step));
            for i in 0..=40 {
                let p = at.transform_point3(DVec3::new(0.0, 0.0, f64::from(i) * 0.05));
                let f = tree.field(p);
                assert!(
                    f < 0.5,
                    "{resolution}: step {step} closed {i}·D/20 ahead ({f})"
                );
            }
        }
    }
}
