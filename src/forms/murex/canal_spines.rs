//! The axial rows of spines on the canal (Galbraith, Prusinkiewicz & Wyvill §3.2, table 2,
//! fig 9): below each of the last three varices, a row of cones stands out of the canal at
//! even intervals along it, away from the shell's axis, sized by the table from the body
//! downwards; each is bent one to three times by a random 3–9° (with a random roll about the
//! spine), since spines in nature are not straight. Coordinates are the generating surface's,
//! in units of D.

use super::fine_parts::FineParts;
use super::generating_surface::cone_frame;
use super::textures::look;
use crate::blobtree::bend::Bend;
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::support_of;
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::{MapOn, Texture};
use crate::pattern::noise::Noise;
use crate::spec::form::textures::PartTexture;
use glam::{DAffine3, DMat3, DQuat, DVec3};

/// The random stream of the canal spines' bends, among those of the spec's seed.
pub const CANAL_STREAM: u64 = 12;
/// The varices, counted back from the opening, with a row of spines on the canal below them.
pub const CANAL_VARICES: usize = 3;

/// Where along the canal (as fractions of its length) the first and last spines stand.
const SPAN: [f64; 2] = [0.15, 0.95];
/// A canal spine's tip radius as a fraction of its base radius.
const TAPER: f64 = 0.35;

/// The canal spines of one row: `sizes` (σ, from the body down the canal) on the canal
/// `cone` (a generator cone row: from, to, radii, bend), each `length`·σ long beyond the
/// canal's surface with base radius `radius`·σ, each textured by `texture` from the canal's
/// surface to its tip and noted in `fine` with the level of refinement that shows its tapered
/// end; none is thinner than the model's floor ([`FineParts::thickened`]).
pub fn canal_row(
    cone: &[f64; 10],
    sizes: &[f64],
    [length, radius]: [f64; 2],
    fine: &mut FineParts,
    time: f64,
    texture: &PartTexture,
    noise: &mut Noise,
) -> Vec<Node> {
    let (from, to) = (
        DVec3::new(cone[0], cone[1], cone[2]),
        DVec3::new(cone[3], cone[4], cone[5]),
    );
    let (frame, canal_length) = cone_frame(from, to);
    let bend = Bend::new(cone[8].to_radians(), canal_length);
    let on_axis = |t: f64| frame.transform_point3(bend.forward(DVec3::X * t * canal_length));
    let n = sizes.len();
    let mut spines = Vec::with_capacity(n);
    for (j, &sigma) in sizes.iter().enumerate() {
        let t = if n == 1 {
            SPAN[0]
        } else {
            SPAN[0] + (SPAN[1] - SPAN[0]) * j as f64 / (n - 1) as f64
        };
        let base = on_axis(t);
        let along = (on_axis(t + 1e-4) - base).normalize();
        let mut away = DVec3::new(along.y, -along.x, 0.0).normalize();
        if away.x > 0.0 {
            away = -away;
        }
        let canal_radius = cone[6] + t * (cone[7] - cone[6]);
        let spine_length = canal_radius + length * sigma;
        let radii = [radius * sigma, radius * sigma * TAPER].map(|r| fine.thickened(r));
        let level = fine.level(radii[1]);
        let placed = DAffine3 {
            matrix3: DMat3::from_cols(away, DVec3::Z.cross(away), DVec3::Z),
            translation: base,
        };
        let mut spine = Node::leaf(
            Primitive::Cone {
                from: DVec3::ZERO,
                to: DVec3::X * spine_length,
                radii: radii.map(support_of),
            },
            Texture::around(time).moved(placed).looking(look(
                texture,
                MapOn::Part {
                    start: canal_radius / spine_length,
                },
            )),
        );
        let bends = 1 + noise.below(3);
        let piece = spine_length / (bends + 1) as f64;
        // Its tip, carried through the bends as the spine is.
        let mut tip = DVec3::X * spine_length;
        for b in 1..=bends {
            let degrees = 3.0 + 6.0 * noise.unit();
            let roll = std::f64::consts::TAU * noise.unit();
            let at = DAffine3::from_rotation_translation(
                DQuat::from_rotation_x(roll),
                DVec3::X * piece * b as f64,
            );
            let bend = Bend::new(degrees.to_radians(), piece);
            tip = at.transform_point3(bend.forward(at.inverse().transform_point3(tip)));
            spine = Node::transform(at, Node::warp(bend, Node::transform(at.inverse(), spine)));
        }
        let spine = Node::transform(placed, spine);
        fine.add(spine.bounds, level);
        fine.tip(placed.transform_point3(tip), radii[1]);
        spines.push(spine);
    }
    spines
}
