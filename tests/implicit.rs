//! The BlobTree modeller and its polygonizer (Galbraith, Prusinkiewicz & Wyvill §2.2): field
//! signs, the CSG laws, superelliptic and controlled blending, and meshes that are closed,
//! outward and accurate, across chunk seams.

use crate::common;

use common::{assert_closed_and_outward, share_of_normals_agreeing, signed_volume};
use glam::DVec3;
use proptest::prelude::*;
use seashells_core::blobtree::blob_tree::{Node, superelliptic};
use seashells_core::blobtree::falloff::{ISO, support_of};
use seashells_core::blobtree::polygonize::{Grid, MAX_LEVEL, Refinement, polygonize};
use seashells_core::blobtree::primitive::Primitive;
use seashells_core::blobtree::texture_blend::Texture;
use seashells_core::mesh::{Bounds, Mesh};
use std::f64::consts::PI;

fn plain() -> Texture {
    Texture::around(0.0)
}

fn ball(centre: DVec3, radius: f64) -> Node {
    Node::leaf(
        Primitive::Point {
            centre,
            radius: support_of(radius),
        },
        plain(),
    )
}

fn area(mesh: &Mesh) -> f64 {
    let p = |i: u32| DVec3::from(mesh.vertices[i as usize].position.map(f64::from));
    mesh.indices
        .chunks_exact(3)
        .map(|t| (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).length() / 2.0)
        .sum()
}

fn points() -> impl Strategy<Value = DVec3> {
    (-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

proptest! {
    #[test]
    fn csg_laws_hold_at_every_point(p in points(), shift in -1.5..1.5f64) {
        let a = ball(DVec3::ZERO, 1.0);
        let b = ball(DVec3::new(shift, 0.3, 0.0), 0.8);
        let inside = |n: &Node| n.field(p) > ISO;
        let union = Node::union(vec![a.clone(), b.clone()]);
        let meet = Node::intersection(vec![a.clone(), b.clone()]);
        let minus = Node::difference(a.clone(), b.clone());
        if inside(&a) || inside(&b) {
            prop_assert!(inside(&union), "A ∪ B contains A and B");
        }
        prop_assert_eq!(inside(&meet), inside(&a) && inside(&b));
        if inside(&b) {
            prop_assert!(!inside(&minus), "A − B misses B");
        }
        prop_assert_eq!(inside(&minus), inside(&a) && !inside(&b));
    }

    #[test]
    fn superelliptic_blending_lies_between_blend_and_union(
        f in proptest::collection::vec(0.0..1.0f64, 2..6),
        n in 1.0..400.0f64,
    ) {
        let s = superelliptic(n, &f);
        let max = f.iter().copied().fold(0.0, f64::max);
        let sum: f64 = f.iter().sum();
        prop_assert!(s.is_finite());
        prop_assert!(s >= max * (1.0 - 1e-12) && s <= sum * (1.0 + 1e-12));
    }
}

#[test]
fn superelliptic_blending_tends_to_the_union_and_stays_finite_at_n_400() {
    let fields = [0.5, 0.45, 1e-200];
    let gap = |n: f64| superelliptic(n, &fields) - 0.5;
    assert!((superelliptic(1.0, &fields) - 0.95).abs() < 1e-12);
    assert!(gap(2.0) > gap(10.0) && gap(10.0) > gap(50.0) && gap(50.0) > gap(200.0));
    assert!(gap(400.0) >= 0.0 && gap(400.0) < 1e-9);
    assert!(superelliptic(400.0, &[1e-300, 2e-300]).is_finite());
    assert!(superelliptic(400.0, &[1e300, 1e300]).is_finite());
}

#[test]
fn controlled_blending_blends_neighbours_only() {
    // Three balls in a row; 0–1 and 1–2 blend, 0–2 do not.
    let parts: Vec<Node> = (0..3)
        .map(|i| ball(DVec3::new(f64::from(i) * 1.2, 0.0, 0.0), 0.8))
        .collect();
    let controlled = Node::controlled(parts.clone(), vec![[0, 1], [1, 2]]);
    let union = Node::union(parts.clone());
    let blend = Node::blend(parts.clone());
    let alone = |i: usize| Node::controlled(vec![parts[0].clone(), parts[i].clone()], vec![]);
    for k in 0..200 {
        let p = DVec3::new(-1.0 + 0.02 * f64::from(k), 0.5, 0.1);
        // Between neighbours the field is their sum, as in a blend.
        let pair = parts[0].field(p) + parts[1].field(p);
        let c = controlled.field(p);
        assert!(c >= pair - 1e-12 && c <= blend.field(p) + 1e-12);
        // Where only 0 and 2 reach, the field is their union's.
        if parts[1].field(p) == 0.0 {
            assert_eq!(c, union.field(p));
        }
        assert_eq!(alone(2).field(p), parts[0].field(p).max(parts[2].field(p)));
    }
    // A point where 0 and 2 overlap but 1 does not reach: far off the axis between them.
    let p = DVec3::new(1.2, 0.0, 1.9);
    let two = Node::controlled(
        vec![
            ball(DVec3::new(0.0, 0.0, 1.2), 0.8),
            ball(DVec3::new(1.2, 0.0, 0.0), 0.8),
            ball(DVec3::new(2.4, 0.0, 1.2), 0.8),
        ],
        vec![[0, 1], [1, 2]],
    );
    let (f0, f2) = (
        ball(DVec3::new(0.0, 0.0, 1.2), 0.8).field(p),
        ball(DVec3::new(2.4, 0.0, 1.2), 0.8).field(p),
    );
    assert!(f0 > 0.0 && f2 > 0.0);
    assert_eq!(two.field(p), f0.max(f2));
}

#[test]
fn a_sphere_at_128_cubed_is_closed_and_accurate_to_one_percent() {
    let r = 1.3;
    let sphere = ball(DVec3::new(0.1, -0.2, 0.3), r);
    let surface = sphere.bounds.padded(-support_of(r) + r);
    let grid = Grid::new(&surface, 128);
    assert!(grid.chunk_count() > 1, "several chunks");
    let mesh = polygonize(&sphere, &Refinement::uniform(grid), 0);
    assert_closed_and_outward(&mesh, "sphere");
    let (a, v) = (area(&mesh), signed_volume(&mesh));
    let (a0, v0) = (4.0 * PI * r * r, 4.0 / 3.0 * PI * r * r * r);
    assert!((a / a0 - 1.0).abs() < 0.01, "area {a} against {a0}");
    assert!((v / v0 - 1.0).abs() < 0.01, "volume {v} against {v0}");
    assert!(share_of_normals_agreeing(&mesh) > 0.999);
    // Refined where a thin part might stand (one side of it, across chunk faces), it is as
    // closed and as accurate, with more triangles there.
    let half = Bounds {
        min: surface.min,
        max: DVec3::new(0.1, surface.max.y, surface.max.z),
    };
    let refined = polygonize(&sphere, &Refinement::new(grid, &[(half, MAX_LEVEL)]), 0);
    assert_closed_and_outward(&refined, "sphere refined on one side");
    assert!(refined.triangle_count() > 2 * mesh.triangle_count());
    let (a, v) = (area(&refined), signed_volume(&refined));
    assert!((a / a0 - 1.0).abs() < 0.01, "refined area {a} against {a0}");
    assert!(
        (v / v0 - 1.0).abs() < 0.01,
        "refined volume {v} against {v0}"
    );
    assert!(share_of_normals_agreeing(&refined) > 0.999);
}

#[test]
fn a_blobby_shape_of_many_chunks_is_closed_across_the_seams() {
    let blobs: Vec<Node> = (0..12)
        .map(|i| {
            let a = f64::from(i) * 0.6;
            ball(
                DVec3::new(a.cos() * 2.0, a.sin() * 2.0, a * 0.3),
                0.5 + 0.05 * f64::from(i),
            )
        })
        .collect();
    let shape = Node::difference(Node::blend(blobs), ball(DVec3::new(2.0, 0.0, 0.0), 0.6));
    let grid = Grid::new(&shape.bounds, 96);
    assert!(grid.chunk_count() >= 27);
    let mesh = polygonize(&shape, &Refinement::uniform(grid), 0);
    assert!(mesh.triangle_count() > 10_000);
    assert_closed_and_outward(&mesh, "blobs");
    // The carved surface is marked as the inside of a wall.
    assert!(mesh.vertices.iter().any(|v| v.surface == 1.0));
}
