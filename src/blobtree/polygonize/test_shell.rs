//! A shell-like tree built from the engine alone, for the polygonizer's tests: a tube of
//! spheres blended along a logarithmic helix (eqs 1–3 of Galbraith et al., β = 22.5°,
//! λ = 1.3), hollowed by a thinner tube, with bent spines standing out of it: thick and thin
//! parts, a difference, warps and transforms, one growth step per sphere.

use crate::blobtree::bend::Bend;
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::support_of;
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::Texture;
use glam::{DAffine3, DMat3, DVec3};
use std::f64::consts::TAU;

/// Spheres (growth steps) along the helix.
const STEPS: u32 = 120;

/// The tree and its last growth step.
pub(super) fn test_shell() -> (Node, u32) {
    let (beta, lambda) = (22.5f64.to_radians(), 1.3f64);
    let (mut body, mut hollow) = (Vec::new(), Vec::new());
    for k in 0..STEPS {
        let theta = f64::from(k) * 0.12;
        let r = 0.2 * lambda.powf(theta / TAU);
        let d = r * (lambda - 1.0) / ((lambda + 1.0) * beta.sin());
        let centre = DVec3::new(r * theta.cos(), r * theta.sin(), r / beta.tan());
        let texture = Texture::around(f64::from(k));
        let sphere = |radius: f64| {
            Node::leaf(
                Primitive::Point {
                    centre,
                    radius: support_of(radius),
                },
                texture,
            )
            .born_at(k)
        };
        body.push(sphere(0.5 * d));
        hollow.push(sphere(0.3 * d));
        if k % 12 == 11 {
            // A spine from the tube's surface outward, bent towards the growth.
            let outward = DVec3::new(theta.cos(), theta.sin(), 0.0);
            let growth = DVec3::new(-theta.sin(), theta.cos(), 0.0);
            let length = 0.9 * d;
            let frame = DAffine3 {
                matrix3: DMat3::from_cols(outward, growth, DVec3::Z),
                translation: centre + outward * 0.4 * d,
            };
            let spine = Node::leaf(
                Primitive::Cone {
                    from: DVec3::ZERO,
                    to: DVec3::X * length,
                    radii: [0.07 * d, 0.02 * d].map(support_of),
                },
                texture,
            );
            let bent = Node::warp(Bend::new(30f64.to_radians(), length), spine);
            body.push(Node::transform(frame, bent).born_at(k));
        }
    }
    let tree = Node::difference(Node::blend(body), Node::blend(hollow));
    (tree, STEPS - 1)
}
