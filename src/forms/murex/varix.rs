//! A varix (Galbraith, Prusinkiewicz & Wyvill §3.2, eqs 11–12): a row of curving spines in the
//! plane of the generating curve, each a cone bent by a warp, rotated by its angle α and moved
//! out to the shell's surface (eq 11), scaled by its relative size σ across the spine and by
//! the table's largest σ along the growth direction so that the spines widen into a ridge, the
//! shorter ones with wider tips (eq 12); a ridge near the surface joins them. Everything here
//! is in the generating surface's own coordinates (u towards the axis, v towards the apex, w
//! along the growth), in units of its size D(θ); eq 13 places the varix like any generating
//! surface.
//!
//! The paper joins the spines with two concentric tori. Our body is not round where the canal
//! leaves it, so the ridge is two rows of segments from each spine's base to the next one's,
//! one on the surface and one a little above it: the same concentric ridge, following the
//! surface wherever the spines stand.

use super::fine_parts::FineParts;
use super::textures::look;
use crate::blobtree::bend::Bend;
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::{ISO, support_of};
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::{Look, MapOn, Texture};
use crate::mesh::Bounds;
use crate::spec::form::implicit::VaricesSpec;
use crate::spec::form::textures::PartTexture;
use glam::{DAffine3, DMat3, DVec3};

/// One spine of a varix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spine {
    /// α in degrees: from the horizontal pointing away from the axis, towards the apex
    /// (positive) or the canal (negative), in the plane of the generating curve.
    pub angle: f64,
    /// Relative size σ (table 1, or the pattern's peak; a bump's scale for bumps).
    pub sigma: f64,
}

/// The unit direction at `angle` degrees in the generating surface's uv plane.
pub fn outward(angle: f64) -> DVec3 {
    let a = angle.to_radians();
    DVec3::new(-libm::cos(a), libm::sin(a), 0.0)
}

/// The spines the table gives every varix of whorl `whorl` (from 1 at the apex), by angle.
pub fn table_spines(table: &[[f64; 3]], whorl: u32) -> Vec<Spine> {
    let mut spines: Vec<Spine> = table
        .iter()
        .filter(|row| row[0].round() == f64::from(whorl))
        .map(|row| Spine {
            angle: row[1],
            sigma: row[2],
        })
        .collect();
    spines.sort_by(|a, b| a.angle.total_cmp(&b.angle));
    spines
}

/// How far from the generating surface's centre, along `direction` (in its coordinates,
/// units of D), the surface of `body` lies, where `at` places the generating surface: the
/// first crossing outward, marched in steps of D/20 and refined by bisection. `None` when
/// the centre is not inside or no crossing lies within 5 D.
pub fn edge_distance(body: &Node, at: &DAffine3, direction: DVec3) -> Option<f64> {
    let f = |t: f64| body.field(at.transform_point3(direction * t)) - ISO;
    if f(0.0) <= 0.0 {
        return None;
    }
    let step = 0.05;
    let mut inside = 0.0;
    while f(inside + step) > 0.0 {
        inside += step;
        if inside > 5.0 {
            return None;
        }
    }
    let mut outside = inside + step;
    for _ in 0..24 {
        let mid = 0.5 * (inside + outside);
        if f(mid) > 0.0 {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    Some(0.5 * (inside + outside))
}

/// The spines standing where their angles meet the surface of `body`, at the generating
/// surface placed by `at`; spines whose angle leaves no surface to stand on are left out.
pub fn standing(body: &Node, at: &DAffine3, spines: &[Spine]) -> Vec<Standing> {
    let near = {
        let mut b = Bounds::EMPTY;
        for corner in (Bounds {
            min: DVec3::splat(-6.0),
            max: DVec3::splat(6.0),
        })
        .corners()
        {
            b.include(at.transform_point3(corner));
        }
        b
    };
    let Some(body) = body.cull(&near, u32::MAX) else {
        return Vec::new();
    };
    spines
        .iter()
        .filter_map(|&spine| {
            edge_distance(&body, at, outward(spine.angle)).map(|edge| Standing { spine, edge })
        })
        .collect()
}

/// A spine of a varix and the distance of its angle's surface from the centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Standing {
    pub spine: Spine,
    pub edge: f64,
}

/// The varix of eq 12: the spines `standing` on the surface, joined by the ridge, with
/// pattern time `time`; the spines wear the spines' texture from base to tip, the ridge the
/// body's look `body`. `sigma_max` is the table's largest σ. Each spine and ridge is noted in `fine` with
/// the level of refinement that shows its thinnest end; a spine or ridge thinner than the
/// model's floor is thickened to it ([`FineParts::thickened`]), so that it stays joined to the
/// shell at every resolution.
pub fn varix(
    spec: &VaricesSpec,
    standing: &[Standing],
    sigma_max: f64,
    fine: &mut FineParts,
    time: f64,
    spines: &PartTexture,
    body: Look,
) -> Option<Node> {
    let mut parts: Vec<Node> = standing
        .iter()
        .map(|s| spine(spec, s, sigma_max, fine, time, spines))
        .collect();
    if spec.ridge > 0.0 {
        let radius = fine.thickened(spec.ridge);
        let level = fine.level(radius);
        for pair in standing.windows(2) {
            for lift in [0.5 * radius, 2.5 * radius] {
                let at = |s: &Standing| outward(s.spine.angle) * (s.edge + lift);
                let (from, to) = (at(&pair[0]), at(&pair[1]));
                fine.add_tube(&[(from, radius), (to, radius)], level);
                parts.push(Node::leaf(
                    Primitive::Cone {
                        from,
                        to,
                        radii: [support_of(radius); 2],
                    },
                    Texture::around(time).looking(body),
                ));
            }
        }
    }
    match parts.len() {
        0 => None,
        1 => parts.pop(),
        _ => Some(Node::blend(parts)),
    }
}

/// One curving spine (eqs 11–12): a cone along x from its base, bent towards y by the spec's
/// bend, scaled by (σ, σ, σ_max), turned by α and moved out to the surface, its base sunk by
/// its own radius so that it grows out of the shell; its texture's ramp starts there.
fn spine(
    spec: &VaricesSpec,
    s: &Standing,
    sigma_max: f64,
    fine: &mut FineParts,
    time: f64,
    texture: &PartTexture,
) -> Node {
    let sigma = s.spine.sigma;
    let length = spec.length;
    let base = fine.thickened(spec.radius * sigma) / sigma;
    let tip = fine.thickened(spec.tip * sigma_max) / sigma;
    let level = fine.level(base.min(tip) * sigma);
    let direction = outward(s.spine.angle);
    // Turning α further: the way the spine curls (towards the apex for a level spine).
    let across = outward(s.spine.angle + 90.0);
    let frame = DAffine3 {
        matrix3: DMat3::from_cols(direction * sigma, across * sigma, DVec3::Z * sigma_max),
        translation: direction * (s.edge - base * sigma),
    };
    let bend = curl(spec.bend, length, base.max(tip));
    // Its axis as placed, with the surface's radius along it (σ_max across the varix).
    let widest = sigma.max(sigma_max);
    let axis: Vec<(DVec3, f64)> = (0..=AXIS_POINTS)
        .map(|i| {
            let t = f64::from(i) / f64::from(AXIS_POINTS);
            let on = Bend::new(bend, length).forward(DVec3::X * t * length);
            (
                frame.transform_point3(on),
                (base + (tip - base) * t) * widest,
            )
        })
        .collect();
    fine.add_tube(&axis, level);
    if let Some(&(end, radius)) = axis.last() {
        fine.tip(end, radius);
    }
    let cone = Node::leaf(
        Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * length,
            radii: [support_of(base), support_of(tip)],
        },
        Texture::around(time).moved(frame).looking(look(
            texture,
            MapOn::Part {
                start: base / length,
            },
        )),
    );
    Node::transform(frame, Node::warp(Bend::new(bend, length), cone))
}

/// Points along a spine's axis at which the refinement about it is measured.
const AXIS_POINTS: u32 = 8;

/// The bend in radians of a cone of `length` and largest surface radius `radius` bent by
/// `degrees`, reduced where its field would fold over the centre of curvature.
pub fn curl(degrees: f64, length: f64, radius: f64) -> f64 {
    let most = 0.9 * length / support_of(radius);
    degrees.to_radians().clamp(-most, most)
}
