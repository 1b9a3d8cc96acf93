//! Properties of the swept shell (Fowler et al. 1992, §2) that must hold for any parameters:
//! self-similarity, the Frenet frame, reparametrization, sculpture growing with the shell,
//! mirror symmetry of dextral and sinistral shells, and watertight solids.

use crate::common;
use glam::DQuat;
use proptest::prelude::*;

use seashells_core::export::{obj, stl};
use seashells_core::forms::sweep::frame::Frame;
use seashells_core::forms::sweep::helico_spiral::HelicoSpiral;
use seashells_core::forms::sweep::surface::Sweep;
use seashells_core::generator::Generator;
use seashells_core::presets::preset;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::Form;
use seashells_core::spec::form::sweep::FrameMode;
use seashells_core::spec::form::sweep::{RibSpec, SweepSpec};
use seashells_core::spec::handedness::Handedness;
use std::collections::HashMap;

fn turbinate() -> ShellSpec {
    preset("turbinate").expect("preset").spec.clone()
}

fn sweep_of(spec: &mut ShellSpec) -> &mut SweepSpec {
    match &mut spec.form {
        Form::Sweep(s) => s,
        _ => unreachable!("a sweep preset"),
    }
}

/// A self-similar shell: one λ for r, z and the curve, no sculpture, no lip.
fn self_similar(lambda: f64, z0: f64, frame: FrameMode, rotations: [f64; 3]) -> SweepSpec {
    let mut spec = turbinate();
    let s = sweep_of(&mut spec);
    s.spiral.lambda_r = lambda;
    s.spiral.lambda_z = lambda;
    s.curve.lambda_c = lambda;
    s.spiral.z0 = z0;
    s.spiral.whorls = 3.0;
    s.orientation.frame = frame;
    [
        s.orientation.rotate_e1,
        s.orientation.rotate_e2,
        s.orientation.rotate_e3,
    ] = rotations;
    s.wall.lip_length = 0.0;
    s.clone()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Rim i + k is rim i turned by kΔθ about the axis and scaled by λᵏ about the origin.
    #[test]
    fn the_surface_maps_into_itself(
        lambda in 1.001f64..1.08,
        z0 in -3.0f64..3.0,
        frenet in any::<bool>(),
        rotations in prop::array::uniform3(-60.0f64..60.0),
        i in 0usize..20,
        k in 1usize..30,
    ) {
        let frame = if frenet { FrameMode::Frenet } else { FrameMode::AxisAligned };
        let spec = self_similar(lambda, z0, frame, rotations);
        let sweep = Sweep::new(&spec).unwrap();
        let step = sweep.step();
        let per_rim = sweep.lambda()[0];
        let a = sweep.rim_at(i as f64 * step);
        let b = sweep.rim_at((i + k) as f64 * step);
        let turn = DQuat::from_rotation_z(k as f64 * step);
        let scale = per_rim.powi(k as i32);
        for (p, q) in a.points.iter().zip(&b.points) {
            let mapped = turn * p.position * scale;
            prop_assert!((mapped - q.position).length() < 1e-9 * q.position.length().max(1.0),
                "{mapped} vs {}", q.position);
            prop_assert!((turn * p.normal - q.normal).length() < 1e-6);
        }
    }

    /// In Frenet mode, a planar curve lies in the plane normal to the spiral's tangent.
    #[test]
    fn frenet_rims_lie_in_the_normal_plane(lambda in 1.001f64..1.05, z0 in -2.0f64..2.0, t in 0.0f64..15.0) {
        let spec = self_similar(lambda, z0, FrameMode::Frenet, [0.0; 3]);
        let sweep = Sweep::new(&spec).unwrap();
        let spiral = HelicoSpiral::from_step(spec.spiral.r0, z0, lambda, lambda, spec.spiral.delta_theta.to_radians());
        let e1 = Frame::frenet(&spiral, t).e1;
        let centre = spiral.point(t);
        for p in &sweep.rim_at(t).points {
            prop_assert!((p.position - centre).dot(e1).abs() < 1e-9 * centre.length().max(1.0));
        }
    }
}

#[test]
fn reparametrized_rim_points_are_equally_spaced() {
    let mut spec = turbinate();
    let s = sweep_of(&mut spec);
    // A lopsided closed curve whose parameter speed varies a lot.
    s.curve.points = vec![
        [0.4, 0.0, 0.0],
        [0.4, 0.05, 0.0],
        [0.05, 0.6, 0.0],
        [0.0, 0.6, 0.0],
        [-0.3, 0.6, 0.0],
        [-0.3, -0.2, 0.0],
        [0.0, -0.25, 0.0],
        [0.3, -0.3, 0.0],
        [0.4, -0.05, 0.0],
    ];
    s.curve.segments = 200;
    for (reparametrize, bound) in [(true, 0.01), (false, f64::INFINITY)] {
        s.curve.reparametrize = reparametrize;
        let rim = Sweep::new(s).unwrap().rim_at(2.0);
        let gaps: Vec<f64> = rim
            .points
            .windows(2)
            .map(|w| w[0].position.distance(w[1].position))
            .collect();
        let mean = gaps.iter().sum::<f64>() / gaps.len() as f64;
        let worst = gaps
            .iter()
            .map(|g| (g / mean - 1.0).abs())
            .fold(0.0, f64::max);
        if reparametrize {
            assert!(worst < bound, "spacing varies by {worst}");
        } else {
            assert!(
                worst > 0.3,
                "the test curve should be uneven without reparametrization ({worst})"
            );
        }
    }
}

#[test]
fn rib_amplitude_grows_in_proportion_to_the_curve() {
    let plain = self_similar(1.02, 1.5, FrameMode::Frenet, [0.0; 3]);
    let mut ribbed = plain.clone();
    ribbed.sculpture.growth_ribs = RibSpec {
        amplitude: 0.08,
        count: 10.0,
        sharpness: 2.0,
        ..RibSpec::NONE
    };
    let (a, b) = (Sweep::new(&plain).unwrap(), Sweep::new(&ribbed).unwrap());
    let relief = |t: f64| {
        let (p, q) = (a.rim_at(t), b.rim_at(t));
        let size = 1.02f64.powf(t / plain.spiral.delta_theta.to_radians());
        p.points
            .iter()
            .zip(&q.points)
            .map(|(p, q)| p.position.distance(q.position))
            .fold(0.0, f64::max)
            / size
    };
    let (early, late) = (relief(1.0), relief(15.0));
    assert!(early > 0.07 && early < 0.081, "relief {early}");
    assert!(
        (late / early - 1.0).abs() < 1e-6,
        "relative relief {early} then {late}"
    );
}

#[test]
fn sinistral_shells_mirror_dextral_ones() {
    let mut spec = turbinate();
    let (mut left, mut right) = (Generator::new(&spec).unwrap(), None);
    left.finish();
    sweep_of(&mut spec).spiral.handedness = Handedness::Sinistral;
    let mut g = Generator::new(&spec).unwrap();
    g.finish();
    right.replace(g);
    common::assert_mirrored(left.mesh(), right.unwrap().mesh());
}

fn assert_closed_and_outward(spec: &ShellSpec, what: &str) {
    let mut g = Generator::new(spec).unwrap();
    g.finish();
    common::assert_closed_and_outward(&g.snapshot(), what);
}

#[test]
fn thick_walls_are_closed_solids_facing_outwards() {
    for sinistral in [false, true] {
        for closed in [true, false] {
            let mut spec = turbinate();
            let s = sweep_of(&mut spec);
            s.spiral.whorls = 2.0;
            s.wall.thickness = 0.06;
            s.wall.lip_length = 90.0;
            s.wall.lip_flare = 0.3;
            s.wall.lip_thickening = 2.0;
            s.sculpture.curve_ribs = RibSpec {
                amplitude: 0.03,
                count: 12.0,
                ..RibSpec::NONE
            };
            // A count that does not divide the curve: the closed curve's seam must still close.
            s.sculpture.growth_ribs = RibSpec {
                amplitude: 0.02,
                count: 7.5,
                ..RibSpec::NONE
            };
            if sinistral {
                s.spiral.handedness = Handedness::Sinistral;
            }
            if !closed {
                s.curve.closed = false;
                s.curve.points = vec![
                    [0.0, -0.3, 0.0],
                    [0.3, -0.3, 0.0],
                    [0.3, 0.3, 0.0],
                    [0.0, 0.3, 0.0],
                ];
            }
            assert_closed_and_outward(&spec, &format!("closed {closed}, sinistral {sinistral}"));
        }
    }
}

#[test]
fn the_exported_stl_of_a_closed_wall_is_watertight() {
    let mut g = Generator::new(&turbinate()).unwrap();
    g.finish();
    let count = common::watertight_stl_triangles(&stl::write(&g.snapshot()).unwrap());
    assert_eq!(count, g.snapshot().triangle_count());
}

#[test]
fn the_generator_hands_out_each_rim_once_whatever_the_chunks() {
    let spec = turbinate();
    let mut whole = Generator::new(&spec).unwrap();
    whole.finish();
    let mut pieces = Generator::new(&spec).unwrap();
    let mut vertices = pieces.mesh().vertices.len();
    let mut indices = pieces.mesh().indices.len();
    let mut step = 1;
    while !pieces.is_done() {
        let advance = pieces.advance(step);
        assert_eq!(
            advance.vertices.start, vertices,
            "new vertices start where the last ended"
        );
        assert_eq!(advance.indices.start, indices);
        vertices = advance.vertices.end;
        indices = advance.indices.end;
        step = step % 7 + 1;
    }
    assert_eq!(pieces.mesh(), whole.mesh());
    assert_eq!(pieces.edge(), whole.edge());
    let (capacity, edge_capacity) = whole.capacity();
    assert_eq!(whole.mesh().vertices.len(), capacity.vertices);
    assert_eq!(whole.mesh().indices.len(), capacity.indices);
    assert_eq!(whole.edge().vertices.len(), edge_capacity.vertices);
    assert_eq!(whole.edge().indices.len(), edge_capacity.indices);
    let Form::Sweep(s) = &spec.form else {
        unreachable!("turbinate is a sweep")
    };
    let rims = (s.spiral.whorls * 360.0 / s.spiral.delta_theta * f64::from(s.spiral.subdivisions))
        .round() as usize
        + 1;
    let points = s.curve.segments as usize + 1;
    assert_eq!(
        capacity.vertices,
        2 * rims * points + 2,
        "outer and inner rims plus two apex centres"
    );
}

#[test]
fn normals_are_unit_and_agree_with_the_triangles() {
    let mut g = Generator::new(&turbinate()).unwrap();
    g.finish();
    let share = common::share_of_normals_agreeing(&g.snapshot());
    assert!(
        share > 0.99,
        "only {share} of triangles agree with their vertex normals"
    );
}

#[test]
fn the_exported_obj_is_watertight_by_position_index() {
    let mut g = Generator::new(&turbinate()).unwrap();
    g.finish();
    let text = String::from_utf8(obj::write(&g.snapshot()).unwrap()).unwrap();
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    let mut faces = 0;
    for line in text.lines().filter(|l| l.starts_with("f ")) {
        faces += 1;
        let v: Vec<u32> = line[2..]
            .split(' ')
            .map(|corner| corner.split("//").next().unwrap().parse().unwrap())
            .collect();
        for (a, b) in [(v[0], v[1]), (v[1], v[2]), (v[2], v[0])] {
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    assert_eq!(faces, g.snapshot().triangle_count());
    assert!(edges.values().all(|&n| n == 2));
}
