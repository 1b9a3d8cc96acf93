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

use super::textures::look;
use crate::blobtree::bend::Bend;
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::{ISO, support_of};
use crate::blobtree::primitive::Primitive;
use crate::blobtree::texture_blend::Texture;
use crate::mesh::Bounds;
use crate::pattern::build;
use crate::shape::ShapeError;
use crate::spec::form::implicit::VaricesSpec;
use crate::spec::form::textures::{PartTexture, TexturesSpec};
use crate::spec::pattern::PatternSpec;
use glam::{DAffine3, DMat3, DVec3};

/// One spine of a varix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spine {
    /// α in degrees: from the horizontal pointing away from the axis, towards the apex
    /// (positive) or the canal (negative), in the plane of the generating curve.
    pub angle: f64,
    /// Relative size σ (table 1).
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

/// The angle of pattern cell `cell` of `cells` on the generating curve: the pattern runs
/// about w from +u (towards the axis) through +v, and α from −u through +v.
pub fn cell_angle(cell: usize, cells: usize) -> f64 {
    let a = 180.0 - 360.0 * (cell as f64 + 0.5) / cells as f64;
    if a <= -180.0 { a + 360.0 } else { a }
}

/// Spines where the pigment `pigment` (one value in [0, 1] per cell along the growing edge,
/// when the varix forms) has a peak of at least one half, within the range of angles the
/// table gives whorl `whorl`; a peak of full pigment grows the table's largest spine of that
/// whorl, weaker ones proportionally smaller. The paper's closing proposal: a
/// reaction-diffusion process on the edge decides where spines stand and how long they grow.
pub fn pattern_spines(table: &[[f64; 3]], whorl: u32, pigment: &[f64]) -> Vec<Spine> {
    let row = table_spines(table, whorl);
    let (Some(first), Some(last)) = (row.first(), row.last()) else {
        return Vec::new();
    };
    let largest = row.iter().map(|s| s.sigma).fold(0.0, f64::max);
    let n = pigment.len();
    let mut spines: Vec<Spine> = (0..n)
        .filter(|&c| {
            let left = pigment[(c + n - 1) % n];
            let right = pigment[(c + 1) % n];
            pigment[c] >= 0.5 && pigment[c] >= left && pigment[c] > right
        })
        .map(|c| Spine {
            angle: cell_angle(c, n),
            sigma: largest * pigment[c].min(1.0),
        })
        .filter(|s| (first.angle..=last.angle).contains(&s.angle))
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

/// The pigment in [0, 1] along the growing edge on each of `rows` (ascending), as the
/// pattern of `pattern` seeded by `seed` computes it; empty rows without a pattern model.
pub fn pigment_at(
    pattern: &PatternSpec,
    seed: u64,
    rows: &[usize],
) -> Result<Vec<Vec<f64>>, ShapeError> {
    let fail = |e: String| ShapeError::new("form.varices.placement", e);
    let mut model = build(pattern, seed)
        .map_err(|e| fail(format!("the pattern cannot place spines: {e}")))?
        .ok_or_else(|| {
            fail("spines placed by the pattern need a pattern model; choose one, or place them by the table".into())
        })?;
    let mut row = 0;
    let mut out = Vec::with_capacity(rows.len());
    let mut shade = vec![0.0f32; model.recorded().len()];
    for &wanted in rows {
        while row < wanted {
            model
                .advance_row()
                .map_err(|e| fail(format!("the pattern failed at row {row}: {e}")))?;
            row += 1;
        }
        model.pigment(pattern.low, pattern.high, &mut shade);
        out.push(shade.iter().map(|&p| f64::from(p)).collect());
    }
    Ok(out)
}

/// A spine of a varix and the distance of its angle's surface from the centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Standing {
    pub spine: Spine,
    pub edge: f64,
}

/// The varix of eq 12: the spines `standing` on the surface, joined by the ridge, with
/// pattern time `time`; the spines wear the spines' texture from base to tip, the ridge the
/// body's. `sigma_max` is the table's largest σ; `thinnest` is the thinnest
/// radius (units of D) the polygonizer resolves: thinner spines and ridges are thickened to
/// it so that they stay joined to the shell.
pub fn varix(
    spec: &VaricesSpec,
    standing: &[Standing],
    sigma_max: f64,
    thinnest: f64,
    time: f64,
    textures: &TexturesSpec,
) -> Option<Node> {
    let mut parts: Vec<Node> = standing
        .iter()
        .map(|s| spine(spec, s, sigma_max, thinnest, time, &textures.spines))
        .collect();
    if spec.ridge > 0.0 {
        let radius = spec.ridge.max(thinnest);
        for pair in standing.windows(2) {
            for lift in [0.5 * radius, 2.5 * radius] {
                let at = |s: &Standing| outward(s.spine.angle) * (s.edge + lift);
                parts.push(Node::leaf(
                    Primitive::Cone {
                        from: at(&pair[0]),
                        to: at(&pair[1]),
                        radii: [support_of(radius); 2],
                    },
                    Texture::around(time).looking(look(&textures.body, 0.0)),
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
    thinnest: f64,
    time: f64,
    texture: &PartTexture,
) -> Node {
    let sigma = s.spine.sigma;
    let length = spec.length;
    let base = spec.radius.max(thinnest / sigma);
    let tip = (spec.tip * sigma_max / sigma).max(thinnest / sigma);
    let direction = outward(s.spine.angle);
    // Turning α further: the way the spine curls (towards the apex for a level spine).
    let across = outward(s.spine.angle + 90.0);
    let frame = DAffine3 {
        matrix3: DMat3::from_cols(direction * sigma, across * sigma, DVec3::Z * sigma_max),
        translation: direction * (s.edge - base * sigma),
    };
    let bend = curl(spec.bend, length, base.max(tip));
    let cone = Node::leaf(
        Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * length,
            radii: [support_of(base), support_of(tip)],
        },
        Texture::around(time)
            .moved(frame)
            .looking(look(texture, base / length)),
    );
    Node::transform(frame, Node::warp(Bend::new(bend, length), cone))
}

/// The bend in radians of a cone of `length` and largest surface radius `radius` bent by
/// `degrees`, reduced where its field would fold over the centre of curvature.
pub fn curl(degrees: f64, length: f64, radius: f64) -> f64 {
    let most = 0.9 * length / support_of(radius);
    degrees.to_radians().clamp(-most, most)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_map_to_angles_from_the_outside_round_the_curve() {
        assert!((cell_angle(0, 4) - 135.0).abs() < 1e-12);
        assert!((cell_angle(2, 4) + 45.0).abs() < 1e-12);
        assert!((cell_angle(3, 4) + 135.0).abs() < 1e-12);
        let up = outward(90.0);
        assert!(up.distance(DVec3::Y) < 1e-12);
        assert!(outward(0.0).distance(DVec3::NEG_X) < 1e-12);
    }

    #[test]
    fn spines_stand_at_pigment_peaks_within_the_tables_angles() {
        let table = [[2.0, -40.0, 0.5], [2.0, 40.0, 1.5], [3.0, 0.0, 1.0]];
        // 36 cells: cell c lies at 175 − 10c degrees.
        let mut pigment = vec![0.0; 36];
        pigment[14] = 0.9; // 35°
        pigment[17] = 0.4; // 5°: too weak
        pigment[20] = 1.4; // −25°
        pigment[2] = 1.0; // 155°: outside the range
        let spines = pattern_spines(&table, 2, &pigment);
        assert_eq!(spines.len(), 2, "{spines:?}");
        assert!((spines[0].angle + 25.0).abs() < 1e-9 && (spines[0].sigma - 1.5).abs() < 1e-12);
        assert!((spines[1].angle - 35.0).abs() < 1e-9 && (spines[1].sigma - 1.35).abs() < 1e-9);
        assert!(pattern_spines(&table, 5, &pigment).is_empty());
    }
}
