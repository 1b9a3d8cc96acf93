//! The generating surface B (Galbraith, Prusinkiewicz & Wyvill §2.1, §3.1): points, bent cones
//! and tori of the spec, blended by eq 4 or by controlled blending of chosen pairs (eq 6), each
//! part carrying its pattern coordinates.

use crate::blobtree::bend::Bend;
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::support_of;
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::Texture;
use crate::spec::form::implicit::GeneratorSpec;
use glam::{DAffine3, DMat3, DVec3};

/// The generating surface's BlobTree, its parts carrying growth time `time`; `whorl` is the
/// whorl (from 0 at the apex) it is placed in, for parts present only from a later whorl.
pub(crate) fn generating_surface(g: &GeneratorSpec, time: f64, whorl: f64) -> Option<Node> {
    let around = Texture::around(time);
    let mut parts: Vec<Option<Node>> = Vec::new();
    for p in &g.points {
        parts.push(Some(Node::leaf(
            Primitive::Point {
                centre: DVec3::new(p[0], p[1], p[2]),
                radius: support_of(p[3]),
            },
            around,
        )));
    }
    for c in &g.cones {
        let (from, to) = (DVec3::new(c[0], c[1], c[2]), DVec3::new(c[3], c[4], c[5]));
        parts.push((whorl >= c[9]).then(|| bent_cone(from, to, [c[6], c[7]], c[8], time)));
    }
    for t in &g.tori {
        parts.push(Some(Node::leaf(
            Primitive::Torus {
                centre: DVec3::new(t[0], t[1], t[2]),
                axis: DVec3::Z,
                major: t[3],
                radius: support_of(t[4]),
            },
            around,
        )));
    }
    combine(parts, g.exponent, &g.pairs)
}

/// Parts combined by eq 4 with exponent `n`, or by controlled blending of `pairs` (eq 6);
/// parts that are `None` (not yet grown) drop out with their pairs.
fn combine(parts: Vec<Option<Node>>, n: f64, pairs: &[[u32; 2]]) -> Option<Node> {
    let mut index = vec![usize::MAX; parts.len()];
    let mut kept = Vec::new();
    for (i, part) in parts.into_iter().enumerate() {
        if let Some(part) = part {
            index[i] = kept.len();
            kept.push(part);
        }
    }
    if kept.len() <= 1 {
        return kept.pop();
    }
    Some(if pairs.is_empty() {
        if n == 1.0 {
            Node::blend(kept)
        } else {
            Node::superelliptic(n, kept)
        }
    } else {
        let pairs = pairs
            .iter()
            .map(|&[i, k]| [index[i as usize], index[k as usize]])
            .filter(|p| p.iter().all(|&i| i != usize::MAX))
            .collect();
        Node::controlled(kept, pairs)
    })
}

/// The frame of a generator cone from `from` to `to`, with its length: x along the cone, z
/// as close to the generating surface's w as x allows (the bend turns x towards y, about z).
pub fn cone_frame(from: DVec3, to: DVec3) -> (DAffine3, f64) {
    let length = from.distance(to);
    let x = (to - from) / length;
    let z = (DVec3::Z - x * x.z).try_normalize().unwrap_or(DVec3::X);
    let y = z.cross(x);
    let frame = DAffine3 {
        matrix3: DMat3::from_cols(x, y, z),
        translation: from,
    };
    (frame, length)
}

/// A tapered segment from `from` to `to`, bent by `bend` degrees about the generating
/// surface's w axis; its pattern position is the angle, about w, of each point as it lies
/// before the bend.
fn bent_cone(from: DVec3, to: DVec3, radii: [f64; 2], bend: f64, time: f64) -> Node {
    let (frame, length) = cone_frame(from, to);
    let cone = Node::leaf(
        Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * length,
            radii: radii.map(support_of),
        },
        Texture::around(time).moved(frame),
    );
    let bend = Bend::new(bend.to_radians(), length);
    Node::transform(frame, Node::warp(bend, cone))
}
