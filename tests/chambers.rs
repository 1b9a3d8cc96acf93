//! Properties of Kawaguchi's accumulated chambers (1982) that must hold for any parameters:
//! one similarity carries each chamber onto the next, vertex distances from the centre of
//! similitude form a geometric progression, each chamber's top base lies at the position
//! T = (Tx, Ty, H) and is the next chamber's bottom base bit for bit, a position off the
//! vertical opens the whorls into a horn, the mesh is a closed outward-facing solid at every
//! stage of growth, handedness mirrors, growth is deterministic, links of the old reading of T
//! still open, and bad parameters get messages that name them.

use crate::common;

use glam::{DQuat, DVec3};
use proptest::prelude::*;
use seashells_core::forms::kawaguchi::chambers::chamber_stack::{
    ChamberStack, RingKind, SIPHUNCLE, turn_per_chamber,
};
use seashells_core::generator::{BuildError, Generator};
use seashells_core::mesh::Surface;
use seashells_core::presets::preset;
use seashells_core::share::link::{Decoded, decode};
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::Form;
use seashells_core::spec::form::chambers::{ChambersSpec, Look, Pair, Triple};
use seashells_core::spec::handedness::Handedness;

fn spec_of(id: &str) -> ShellSpec {
    preset(id).expect("preset").spec.clone()
}

fn chambers_of(spec: &mut ShellSpec) -> &mut ChambersSpec {
    match &mut spec.form {
        Form::Chambers(c) => c,
        _ => unreachable!("a chamber preset"),
    }
}

fn stack(spec: &ChambersSpec) -> ChamberStack {
    ChamberStack::new(spec).expect("a valid stack")
}

/// A chamber spec from proptest's numbers, with the width raised until the top base clears the
/// bottom base and the bottom base stays below the top base's plane.
fn arbitrary(ratio: f64, q: [f64; 3], t: [f64; 2], apexes: u32) -> ChambersSpec {
    let mut c = match spec_of("kawaguchi-shell").form {
        Form::Chambers(c) => c,
        _ => unreachable!(),
    };
    c.mouth.apexes = apexes;
    c.chamber.ratio = ratio;
    c.chamber.inclination = Triple {
        x: q[0],
        y: q[1],
        z: q[2],
    };
    c.chamber.shift = Pair { x: t[0], y: t[1] };
    c.chamber.width = 0.05;
    c.chambers = 12;
    while ChamberStack::new(&c).is_err() {
        c.chamber.width *= 1.25;
    }
    c
}

/// R(Q): rotations about x, then y, then z, by Q in degrees, as the paper's inclination.
fn inclination(q: [f64; 3]) -> DQuat {
    let [x, y, z] = q.map(f64::to_radians);
    DQuat::from_rotation_z(z) * DQuat::from_rotation_y(y) * DQuat::from_rotation_x(x)
}

/// Decodes `link` and checks that its first problem starts with `expected`.
fn first_problem_starts_with(link: &str, expected: &str) -> Decoded {
    let decoded = decode(link);
    let first = decoded.problems.first().map(ToString::to_string);
    assert!(
        first.as_deref().is_some_and(|p| p.starts_with(expected)),
        "{link}: {:?}",
        decoded.problems
    );
    decoded
}

fn close(a: DVec3, b: DVec3, scale: f64) -> bool {
    (a - b).length() <= 1e-9 * scale.max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn one_similarity_of_ratio_r_carries_each_chamber_onto_the_next(
        ratio in 0.8f64..1.25,
        q in prop::array::uniform3(-25.0f64..25.0),
        t in prop::array::uniform2(-0.5f64..0.5),
        shifted in any::<bool>(),
        sinistral in any::<bool>(),
        wall in 0.01f64..0.4,
    ) {
        let mut c = arbitrary(ratio, q, if shifted { t } else { [0.0; 2] }, 9);
        if sinistral {
            c.handedness = Handedness::Sinistral;
        }
        c.wall = wall;
        let s = stack(&c);
        let similarity = s.similarity();
        let mirrored = |ring: Vec<DVec3>| -> Vec<DVec3> {
            ring.into_iter().map(|p| s.handedness().mirror(p)).collect()
        };
        let septum = s.septum();
        // The outside's bases, and the cavity's floor, ceiling and siphuncle: a hollow
        // chamber's cavity is the similarity's image of the one before, as its chamber is.
        let rings: [&dyn Fn(usize) -> Vec<DVec3>; 5] = [
            &|k| mirrored(s.ring(&s.frame(k), RingKind::Bottom)),
            &|k| mirrored(s.ring(&s.frame(k), RingKind::Top)),
            &|k| mirrored(s.cavity_ring(&s.frame(k), septum, 1.0)),
            &|k| mirrored(s.cavity_ring(&s.frame(k), 1.0 - septum, 1.0)),
            &|k| mirrored(s.cavity_ring(&s.frame(k), septum, SIPHUNCLE)),
        ];
        for k in 0..c.chambers as usize - 1 {
            for ring in rings {
                let now = ring(k);
                let next = ring(k + 1);
                let scale = now.iter().map(|p| p.length()).fold(1.0, f64::max);
                for (p, q) in now.iter().zip(&next) {
                    prop_assert!(close(similarity.transform_point3(*p), *q, scale * 2.0));
                }
                // Its ratio is r: every distance scales by it.
                let (a, b) = (now[0] - now[3], next[0] - next[3]);
                prop_assert!((b.length() - ratio * a.length()).abs() <= 1e-9 * scale);
            }
        }
    }

    #[test]
    fn distances_from_the_centre_of_similitude_form_a_geometric_progression(
        ratio in prop_oneof![0.8f64..0.98, 1.02f64..1.25],
        q in prop::array::uniform3(-25.0f64..25.0),
        t in prop::array::uniform2(-0.5f64..0.5),
    ) {
        // The centre of similitude is shell space's origin by construction.
        let c = arbitrary(ratio, q, t, 7);
        let s = stack(&c);
        let first = s.ring(&s.frame(0), RingKind::Top);
        for k in 1..c.chambers as usize {
            let ring = s.ring(&s.frame(k), RingKind::Top);
            for (p0, pk) in first.iter().zip(&ring) {
                let expected = p0.length() * ratio.powi(k as i32);
                prop_assert!((pk.length() - expected).abs() <= 1e-9 * expected.max(1e-3));
            }
        }
    }

    /// The principle of accumulation for any position T: a chamber's top base is the next
    /// one's bottom base exactly, and it lies at T = (Tx, Ty, H) from the bottom base, scaled
    /// by r and inclined by R(Q): C(x) = T + r R(Q) x.
    #[test]
    fn every_top_base_is_the_next_bottom_base_at_the_position_t(
        ratio in 0.7f64..1.4,
        q in prop::array::uniform3(-40.0f64..40.0),
        t in prop::array::uniform2(-3.0f64..3.0),
        apexes in 3u32..40,
        septa in any::<bool>(),
    ) {
        let mut c = arbitrary(ratio, q, t, apexes);
        c.septa = septa;
        let s = stack(&c);
        let rotation = inclination(q);
        let position = DVec3::new(t[0], t[1], c.chamber.width);
        for k in 0..c.chambers as usize - 1 {
            let frame = s.frame(k);
            let bottom = s.ring(&frame, RingKind::Bottom);
            let top = s.ring(&frame, RingKind::Top);
            prop_assert_eq!(&top, &s.ring(&s.frame(k + 1), RingKind::Bottom));
            let to_local = frame.inverse();
            let scale = frame.matrix3.x_axis.length();
            for (b, p) in bottom.iter().zip(&top) {
                let (b, p) = (to_local.transform_point3(*b), to_local.transform_point3(*p));
                prop_assert!(b.z.abs() <= 1e-9 * scale.max(1.0) / scale);
                let expected = position + ratio * (rotation * b);
                prop_assert!(
                    (p - expected).length() <= 1e-9 * (1.0 + expected.length()),
                    "chamber {}: top apex at {} in the bottom base's frame, not {}", k, p, expected
                );
            }
        }
    }
}

/// The highest point of a chamber on the coiling axis (z) and the lowest, over its two bases.
fn axial_extent(s: &ChamberStack, k: usize) -> (f64, f64) {
    let frame = s.frame(k);
    let z: Vec<f64> = [RingKind::Bottom, RingKind::Top]
        .into_iter()
        .flat_map(|kind| s.ring(&frame, kind))
        .map(|p| p.z)
        .collect();
    let low = z.iter().copied().fold(f64::INFINITY, f64::min);
    let high = z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (low, high)
}

/// The smallest gap along the coiling axis between a chamber of the last whorl and the chamber
/// one whorl before it: negative where the whorls rest on each other.
fn gap_between_whorls(c: &ChambersSpec) -> f64 {
    let s = stack(c);
    let per_whorl = (std::f64::consts::TAU / turn_per_chamber(&c.chamber)).round() as usize;
    let n = c.chambers as usize;
    assert!(n > per_whorl, "more than one whorl");
    (per_whorl.max(n - per_whorl)..n)
        .map(|k| axial_extent(&s, k).0 - axial_extent(&s, k - per_whorl).1)
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn a_position_off_the_vertical_opens_the_whorls_into_a_horn() {
    let mut horn = spec_of("kawaguchi-horn");
    let c = chambers_of(&mut horn);
    let open = gap_between_whorls(c);
    assert!(
        open > 0.0,
        "the horn's whorls rest on each other: gap {open}"
    );
    // The same chamber with its top base straight above the bottom base, as high as the
    // horn's chamber reaches: the whorls coil in one plane and rest on each other.
    c.chamber.shift = Pair { x: 0.0, y: 0.0 };
    let closed = gap_between_whorls(c);
    assert!(
        closed < 0.0,
        "without the position the whorls still part: gap {closed}"
    );
}

/// Every combination of look, handedness, shift, septa, wall and protuberances.
fn variants() -> Vec<(String, ShellSpec)> {
    let mut out = Vec::new();
    for look in [Look::Faceted, Look::Smooth] {
        for sinistral in [false, true] {
            for shifted in [false, true] {
                for (septa, wall) in [(false, 0.0), (true, 0.0), (false, 0.1), (true, 0.15)] {
                    let mut spec = spec_of("kawaguchi-shell");
                    let c = chambers_of(&mut spec);
                    c.look = look;
                    c.septa = septa;
                    c.wall = wall;
                    c.chambers = 30;
                    c.mouth.protuberances = vec![0.2, -0.1, 0.0, 0.3, -0.2];
                    if sinistral {
                        c.handedness = Handedness::Sinistral;
                    }
                    if shifted {
                        c.chamber.shift = Pair { x: 0.1, y: 0.2 };
                    }
                    spec.growth.rows = 31;
                    let what = format!(
                        "{look:?}, sinistral {sinistral}, shifted {shifted}, septa {septa}, wall {wall}"
                    );
                    out.push((what, spec));
                }
            }
        }
    }
    out
}

#[test]
fn the_stack_is_a_closed_outward_solid_at_every_stage_of_growth() {
    for (what, spec) in variants() {
        let mut g = Generator::new(&spec).unwrap();
        assert_eq!(
            g.snapshot().triangle_count(),
            0,
            "{what}: the apex base alone shows nothing"
        );
        while !g.is_done() {
            g.advance(3);
            let rows = g.rows_done();
            common::assert_closed_and_outward(&g.snapshot(), &format!("{what}, row {rows}"));
        }
        let mesh = g.snapshot();
        let share = common::share_of_normals_agreeing(&mesh);
        assert!(share > 0.97, "{what}: only {share} of normals agree");
        let (capacity, edge) = g.capacity();
        assert_eq!(g.mesh().vertices.len(), capacity.vertices, "{what}");
        assert_eq!(g.mesh().indices.len(), capacity.indices, "{what}");
        assert_eq!(g.edge().vertices.len(), edge.vertices, "{what}");
    }
}

#[test]
fn every_chamber_preset_exports_a_closed_solid() {
    for id in [
        "kawaguchi-shell",
        "kawaguchi-ammonite",
        "kawaguchi-horn",
        "kawaguchi-tusk",
        "kawaguchi-claw",
        "kawaguchi-painted",
    ] {
        let mut g = Generator::new(&spec_of(id)).unwrap();
        g.finish();
        common::assert_closed_and_outward(&g.snapshot(), id);
    }
}

/// A walled stack is hollow: the thicker its wall, the more of the solid stack it keeps, and
/// however thick, its cavities, septa and siphuncles make one body with the outside (no
/// void closed inside it), open at the mouth.
#[test]
fn walled_chambers_are_hollow_and_one_body_open_at_the_mouth() {
    for id in ["kawaguchi-shell", "kawaguchi-ammonite", "kawaguchi-horn"] {
        let volume = |wall: f64| {
            let mut spec = spec_of(id);
            chambers_of(&mut spec).wall = wall;
            let mut g = Generator::new(&spec).unwrap();
            g.finish();
            let mesh = g.snapshot();
            common::assert_closed_and_outward(&mesh, &format!("{id}, wall {wall}"));
            assert_eq!(
                common::pieces(&mesh).len(),
                1,
                "{id}, wall {wall}: one body"
            );
            let mouth = g.edge();
            if wall > 0.0 {
                let inner = mouth
                    .vertices
                    .iter()
                    .filter(|v| v.surface == Surface::Inner as u8 as f32)
                    .count();
                assert!(inner > 0, "{id}: the mouth opens into the last cavity");
            }
            common::signed_volume(&mesh)
        };
        let solid = volume(0.0);
        let walls = [0.4, 0.2, 0.1, 0.05].map(volume);
        for pair in walls.windows(2) {
            assert!(
                pair[1] < pair[0],
                "{id}: a thinner wall keeps less: {walls:?}"
            );
        }
        assert!(walls[0] < solid, "{id}: the thickest wall is still hollow");
        let kept = walls[2] / solid;
        assert!(
            (0.15..0.6).contains(&kept),
            "{id}: a wall a tenth of the radius keeps {kept} of the solid"
        );
    }
}

#[test]
fn sinistral_stacks_mirror_dextral_ones() {
    let mut spec = spec_of("kawaguchi-horn");
    let mut right = Generator::new(&spec).unwrap();
    right.finish();
    chambers_of(&mut spec).handedness = Handedness::Sinistral;
    let mut left = Generator::new(&spec).unwrap();
    left.finish();
    common::assert_mirrored(&right.snapshot(), &left.snapshot());
}

#[test]
fn growth_is_deterministic_whatever_the_chunks() {
    let spec = spec_of("kawaguchi-painted");
    let (whole, pieces) = common::grown_whole_and_in_chunks(&spec);
    assert_eq!(pieces.mesh(), whole.mesh());
    assert_eq!(pieces.edge(), whole.edge());
    assert_eq!(
        pieces.pattern().unwrap().hash(),
        whole.pattern().unwrap().hash()
    );
}

#[test]
fn each_chamber_is_a_row_and_each_apex_a_cell_of_the_pattern() {
    let spec = spec_of("kawaguchi-painted");
    let c = match &spec.form {
        Form::Chambers(c) => c.clone(),
        _ => unreachable!(),
    };
    assert_eq!(spec.pattern.cells, c.mouth.apexes, "one cell per apex");
    assert_eq!(spec.growth.rows, c.chambers + 1, "one row per chamber");
    let mut g = Generator::new(&spec).unwrap();
    g.finish();
    let rows: std::collections::BTreeSet<u32> = g
        .mesh()
        .vertices
        .iter()
        .map(|v| {
            assert!((0.0..=1.0).contains(&v.pattern[0]));
            v.pattern[1] as u32
        })
        .collect();
    assert_eq!(rows.len(), c.chambers as usize + 1, "a row per base");
    assert_eq!(*rows.last().unwrap(), c.chambers);
}

#[test]
fn bad_parameters_get_messages_that_name_them() {
    let cases: [(&str, &str); 7] = [
        ("form.mouth.apexes=2", "outside the range 3 to 256"),
        ("form.chamber.ratio=0", "outside the range 0.5 to 2"),
        ("form.chamber.ratio=-1", "outside the range 0.5 to 2"),
        (
            "form.mouth.protuberances=0,-1.5,0",
            "fold the mouth polygon over itself",
        ),
        ("form.chambers=5000", "outside the range 1 to 2000"),
        (
            "form.mouth.apexes=256&form.chambers=2000&form.septa=true&form.chamber.ratio=1.001",
            "more than the cap of 2000000",
        ),
        (
            "form.chambers=2000",
            "2000 chambers at ratio 1.035 grow the last to 10^30 times the first: at most 267 at this ratio",
        ),
    ];
    for (change, expected) in cases {
        let link = format!("v=1&preset=kawaguchi-shell&{change}");
        let decoded = decode(&link);
        let said: Vec<String> = decoded.problems.iter().map(ToString::to_string).collect();
        assert!(
            said.iter().any(|p| p.contains(expected)),
            "{change}: {said:?}"
        );
        Generator::new(&decoded.spec).unwrap_or_else(|e| panic!("{change}: {e}"));
    }
    first_problem_starts_with(
        "v=1&preset=kawaguchi-shell&form.chamber.width=0.01",
        "form.chamber.inclination: the top base crosses the bottom base",
    );
    let leaning = first_problem_starts_with(
        "v=1&preset=kawaguchi-shell&form.chamber.shift.x=-5",
        "form.chamber.shift: the chamber leans over so far that its bottom base crosses the top base's plane",
    );
    Generator::new(&leaning.spec).unwrap();
    // A spec that skips validation still gets a message, never a broken mesh.
    let mut spec = spec_of("kawaguchi-shell");
    chambers_of(&mut spec).chamber.ratio = 0.0;
    let e = Generator::new(&spec).err().expect("refused");
    let BuildError::Shape(e) = e else {
        panic!("a shape error, not {e}")
    };
    assert_eq!(e.key, "form.chamber.ratio");
    assert!(e.message.contains("growth ratio r must be above 0"), "{e}");
}

#[test]
fn a_link_switches_a_sweep_to_chambers_and_back() {
    let decoded = decode("v=1&preset=turbinate&form.kind=chambers");
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    assert!(matches!(decoded.spec.form, Form::Chambers(_)));
    let decoded = decode("v=1&preset=kawaguchi-horn&form.kind=sweep&form.curve.points=1,2,3");
    assert!(matches!(decoded.spec.form, Form::Sweep(_)));
    assert!(
        decoded.problems[0]
            .to_string()
            .contains("used the preset's curve"),
        "{:?}",
        decoded.problems
    );
    Generator::new(&decoded.spec).unwrap();
}

#[test]
fn a_link_of_the_old_reading_of_t_opens_as_the_same_spiral_and_says_so() {
    // Before T became the top base's position, a link shifted each chamber by T beyond its
    // top base (in that base's scaled frame): one period was x ↦ (0, 0, H) + r R(Q)(x + T).
    let decoded = decode(
        "v=1&preset=kawaguchi-shell&form.chamber.translation.x=0.1&form.chamber.translation.y=0.2&form.chamber.translation.z=0.15",
    );
    let said: Vec<String> = decoded.problems.iter().map(ToString::to_string).collect();
    assert_eq!(said.len(), 1, "{said:?}");
    assert!(
        said[0].starts_with(
            "form.chamber.translation: links made before T became the top base's position"
        ),
        "{said:?}"
    );
    let Form::Chambers(new) = &decoded.spec.form else {
        panic!("a chamber stack")
    };
    let Form::Chambers(old) = &spec_of("kawaguchi-shell").form else {
        unreachable!()
    };
    let c = &old.chamber;
    let rotation = inclination(c.inclination.to_array());
    let beyond = DVec3::new(0.1, 0.2, 0.15);
    let position = DVec3::new(0.0, 0.0, c.width) + c.ratio * (rotation * beyond);
    let n = &new.chamber;
    assert!((DVec3::new(n.shift.x, n.shift.y, n.width) - position).length() < 1e-12);
    assert_eq!((n.ratio, n.inclination), (c.ratio, c.inclination));
    // The encoded link carries today's keys, and opens without a word.
    let link = seashells_core::share::link::encode(decoded.preset, &decoded.spec);
    assert!(
        link.contains("form.chamber.shift.x=") && !link.contains("translation"),
        "{link}"
    );
    assert!(decode(&link).problems.is_empty());
    Generator::new(&decoded.spec).unwrap();
    // A bad old value is read as 0 and named; on another form the old key is ignored.
    first_problem_starts_with(
        "v=1&preset=kawaguchi-horn&form.chamber.translation.y=x",
        "form.chamber.translation.y: 'x' is not a finite number; read as 0",
    );
    let decoded = decode("v=1&preset=turbinate&form.chamber.translation.y=0.2");
    assert_eq!(
        decoded.problems[0].to_string(),
        "form.chamber.translation: is not a key of this shell; ignored"
    );
}
