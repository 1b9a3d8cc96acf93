//! Bumps, the beaded riblets between varices (Galbraith, Prusinkiewicz & Wyvill §3.2, fig 8):
//! single point primitives of default size s, placed like the spines of eq 11 at every second
//! spine's angle, each scaled by (σx, σy, σz + 0.8) with σ drawn from a normal distribution.
//! We read the paper's σ_d = n(s, σ) as s times a factor of mean 1 and deviation `spread`, so
//! that σ_d keeps the unit of s while the +0.8 stretches every bump along the growth
//! direction into a bead of a riblet. They join the whorl by superelliptic blending with
//! n = 400 ([`BUMP_EXPONENT`]), which makes them stand out abruptly instead of melting into
//! the whorl's much stronger field. When the pattern places them (`rd_placement.rs`) they
//! stand at the lower peaks of the activator instead, each scaled by its peak's level.

use super::fine_parts::FineParts;
use super::varix::{Standing, outward};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::support_of;
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::Texture;
use crate::pattern::noise::Noise;
use glam::{DAffine3, DMat3, DVec3};

/// n of eq 4 for blending bumps into the whorl.
pub const BUMP_EXPONENT: f64 = 400.0;

/// The random stream of the bumps' sizes, among those of the spec's seed.
pub const BUMP_STREAM: u64 = 11;

/// One set of bumps, in the generating surface's coordinates and units of D: one at each of
/// `sites` (the table's every second spine, or the pattern's lower peaks), where its angle
/// meets the surface, its size scaled by the site's σ. Each is noted in `fine` with the level
/// of refinement that shows it; one thinner than the model's floor is enlarged to it
/// ([`FineParts::thickened`]), so that every bump stands, the same at every resolution.
pub fn bump_set(
    sites: &[Standing],
    size: f64,
    spread: f64,
    fine: &mut FineParts,
    time: f64,
    noise: &mut Noise,
) -> Vec<Node> {
    let mut bumps = Vec::new();
    for s in sites {
        let size = size * s.spine.sigma;
        let factors = [0.0, 0.0, 0.8].map(|extra| noise.normal(1.0, spread).max(0.1) + extra);
        let thickness = size * factors[0].min(factors[1]);
        // One thinner than the floor is drawn at that thickness, not left out.
        let size = size * fine.thickened(thickness) / thickness;
        let level = fine.level(fine.thickened(thickness));
        let direction = outward(s.spine.angle);
        let frame = DAffine3 {
            matrix3: DMat3::from_cols(
                direction * factors[0],
                outward(s.spine.angle + 90.0) * factors[1],
                DVec3::Z * factors[2],
            ),
            translation: direction * s.edge,
        };
        let bump = Node::leaf(
            Primitive::Point {
                centre: DVec3::ZERO,
                radius: support_of(size),
            },
            Texture::around(time).moved(frame),
        );
        let widest = factors.iter().copied().fold(0.0, f64::max);
        fine.add_tube(&[(frame.translation, size * widest)], level);
        // Its top, straight out of the surface.
        fine.tip(frame.translation + direction * size * factors[0], 0.0);
        bumps.push(Node::transform(frame, bump));
    }
    bumps
}
