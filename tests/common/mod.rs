//! Checks of meshes shared by the tests of every form, and of implicit specs.
#![allow(dead_code)]

pub mod heap;

use glam::DVec3;
use seashells_core::forms::murex::check::check;
use seashells_core::generator::Generator;
use seashells_core::mesh::Mesh;
use seashells_core::share::repair::repair;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::Form;
use seashells_core::spec::form::implicit::ImplicitSpec;
use std::collections::HashMap;

/// Directed edges by welded position; a closed, consistently oriented surface has each edge
/// exactly once in each direction.
pub fn directed_edges(mesh: &Mesh) -> HashMap<([u32; 3], [u32; 3]), usize> {
    let key = |i: u32| mesh.vertices[i as usize].position.map(f32::to_bits);
    let mut edges = HashMap::new();
    for t in mesh.indices.chunks_exact(3) {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *edges.entry((key(a), key(b))).or_insert(0) += 1;
        }
    }
    edges
}

/// Volume enclosed by the triangles (divergence theorem): positive when they face outwards.
pub fn signed_volume(mesh: &Mesh) -> f64 {
    let p = |i: u32| DVec3::from(mesh.vertices[i as usize].position.map(f64::from));
    mesh.indices
        .chunks_exact(3)
        .map(|t| p(t[0]).dot(p(t[1]).cross(p(t[2]))) / 6.0)
        .sum()
}

/// Every edge is used once in each direction (closed, manifold, consistently wound) and the
/// enclosed volume is positive (outward-facing).
pub fn assert_closed_and_outward(mesh: &Mesh, what: &str) {
    let edges = directed_edges(mesh);
    for (&(a, b), &count) in &edges {
        assert_eq!(count, 1, "{what}: edge used {count} times in one direction");
        assert_eq!(
            edges.get(&(b, a)),
            Some(&1),
            "{what}: an edge has no opposite (a hole)"
        );
    }
    assert!(signed_volume(mesh) > 0.0, "{what}: triangles face inwards");
}

/// The share of triangles whose first vertex's normal lies on the side their winding faces;
/// every normal must be of unit length.
pub fn share_of_normals_agreeing(mesh: &Mesh) -> f64 {
    let mut agree = 0;
    for t in mesh.indices.chunks_exact(3) {
        let v = |k: usize| mesh.vertices[t[k] as usize];
        let p = |k: usize| DVec3::from(v(k).position.map(f64::from));
        let face = (p(1) - p(0)).cross(p(2) - p(0));
        let n = DVec3::from(v(0).normal.map(f64::from));
        assert!(
            (n.length() - 1.0).abs() < 1e-5,
            "a normal of length {}",
            n.length()
        );
        if face.dot(n) > 0.0 {
            agree += 1;
        }
    }
    agree as f64 / mesh.triangle_count() as f64
}

/// `b` is `a` mirrored in y (positions and normals), its triangles wound the other way so that
/// they still face outwards.
pub fn assert_mirrored(a: &Mesh, b: &Mesh) {
    assert_eq!(a.vertices.len(), b.vertices.len());
    for (p, q) in a.vertices.iter().zip(&b.vertices) {
        assert_eq!([p.position[0], -p.position[1], p.position[2]], q.position);
        assert_eq!([p.normal[0], -p.normal[1], p.normal[2]], q.normal);
    }
    for (s, t) in a.indices.chunks(3).zip(b.indices.chunks(3)) {
        assert_eq!([s[0], s[2], s[1]], [t[0], t[1], t[2]]);
    }
}

/// Triangles in each connected piece of a mesh (welded by position), largest first.
pub fn pieces(mesh: &Mesh) -> Vec<usize> {
    let key = |i: u32| mesh.vertices[i as usize].position.map(f32::to_bits);
    let mut id: HashMap<[u32; 3], usize> = HashMap::new();
    for &i in &mesh.indices {
        let n = id.len();
        id.entry(key(i)).or_insert(n);
    }
    let mut parent: Vec<usize> = (0..id.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for t in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| id[&key(i)]);
        for (x, y) in [(a, b), (b, c)] {
            let (rx, ry) = (root(&mut parent, x), root(&mut parent, y));
            parent[rx] = ry;
        }
    }
    let mut count: HashMap<usize, usize> = HashMap::new();
    for t in mesh.indices.chunks_exact(3) {
        let r = root(&mut parent, id[&key(t[0])]);
        *count.entry(r).or_insert(0) += 1;
    }
    let mut sizes: Vec<usize> = count.into_values().collect();
    sizes.sort_unstable_by(|a, b| b.cmp(a));
    sizes
}

/// The triangle count of a binary STL whose every edge (by exact corner coordinates) is shared
/// by exactly two triangles: a watertight file.
pub fn watertight_stl_triangles(bytes: &[u8]) -> usize {
    let count = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(bytes.len(), 84 + 50 * count);
    let mut edges: HashMap<(&[u8], &[u8]), usize> = HashMap::new();
    for tri in bytes[84..].chunks_exact(50) {
        let corner = |k: usize| &tri[12 + 12 * k..24 + 12 * k];
        for (p, q) in [(0, 1), (1, 2), (2, 0)].map(|(a, b)| (corner(a), corner(b))) {
            *edges
                .entry(if p < q { (p, q) } else { (q, p) })
                .or_insert(0) += 1;
        }
    }
    assert!(
        edges.values().all(|&n| n == 2),
        "every edge of the STL is shared by exactly two triangles"
    );
    count
}

/// The implicit form of a spec.
pub fn implicit(spec: &mut ShellSpec) -> &mut ImplicitSpec {
    match &mut spec.form {
        Form::Implicit(i) => i,
        _ => panic!("an implicit preset"),
    }
}

/// A spec spoiled at `key` is refused with a message naming the key, and repairing it from
/// `base` says what was used instead and gives a spec that builds.
pub fn assert_refused_and_repaired(mut spoiled: ShellSpec, base: &ShellSpec, key: &str) {
    let error = check(implicit(&mut spoiled.clone())).expect_err(key);
    assert!(error.key.starts_with(key), "{key}: {error}");
    let problems = repair(&mut spoiled, base);
    assert!(
        problems
            .iter()
            .any(|p| p.key == key && p.message.contains("used")),
        "{key}: {problems:?}"
    );
    assert!(check(implicit(&mut spoiled)).is_ok(), "{key}: repaired");
}

/// `spec` grown at once, and grown again in chunks of one to seven rows in turn: the two must
/// agree bit for bit.
pub fn grown_whole_and_in_chunks(spec: &ShellSpec) -> (Generator, Generator) {
    let mut whole = Generator::new(spec).unwrap();
    whole.finish();
    let mut pieces = Generator::new(spec).unwrap();
    let mut step = 1;
    while !pieces.is_done() {
        pieces.advance(step);
        step = step % 7 + 1;
    }
    (whole, pieces)
}
