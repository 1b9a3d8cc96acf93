//! Spines and bumps placed by reaction-diffusion: the extension Galbraith, Prusinkiewicz &
//! Wyvill propose in the last sentence of *Modeling a Murex cabritii sea shell with a
//! structured implicit surface modeler*. Their table 1 fixes the number, angle and size of the
//! spines of every whorl from a single view of one shell, so that they "suddenly change from
//! one whorl to another"; here the pattern on the growing edge (the reaction-diffusion models
//! of Fowler, Meinhardt & Prusinkiewicz, *Modeling seashells*, §3) decides instead.
//!
//! The edge is the whole generating curve: cell c of n stands at α = 180° − 360°(c + ½)/n
//! ([`cell_angle`]). When a varix forms, the activator along the edge at that row has peaks;
//! each peak's level is its height above the edge's lowest concentration relative to the
//! highest peak's ([`peaks`]). A peak of at least `spine_level` grows a spine of relative
//! size σ = `peak_sigma` (level − `bump_level`) / (1 − `bump_level`), so the strongest peak
//! grows the longest spine and a peak just at the level a short one ([`spines_of`]); at the
//! rows between varices, the lower peaks (from `bump_level` up to `spine_level`) bear bumps
//! sized by their level ([`bumps_of`]). Lengths are in units of the generating surface's size
//! D(θ), so they grow with the shell smoothly from whorl to whorl, and because the pattern
//! changes slowly from row to row, a spine of one varix stands where the one before had its
//! spine: spines continue along the spiral cords, as on the real shell.
//!
//! Only the part of the edge that is free in the grown shell carries them ([`free`]): a spine
//! or bump must stand on its own whorl's surface (not on the previous whorl, which the march
//! outward from the centre may reach where the whorls touch) and must not be buried by the
//! whorls that grow after it. That is why the earlier whorls carry spines on the shoulder
//! only, as the paper's table does, without any table.

use super::varix::{Spine, Standing, outward};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::pattern::build;
use crate::shape::ShapeError;
use crate::spec::form::implicit::VaricesSpec;
use crate::spec::pattern::PatternSpec;
use glam::DAffine3;

/// An edge whose activator varies by less than this fraction of its highest concentration has
/// not formed a pattern yet (the homogeneous start, with its small random fluctuations): it
/// has no peaks.
pub const CONTRAST: f64 = 0.5;

/// The outer lip: the part of the generating curve, α within ±90° of the horizontal pointing
/// away from the axis, that faces the open water. The rest (the inner lip) lies on the
/// columella and the previous whorl and grows no spines.
pub const OUTER_LIP: f64 = 90.0;

/// How far (units of D) beyond the surface the line of a spine or bump must meet no part of
/// the shell: it stands in the open, not in the hollow about the axis between the whorls or
/// against a later whorl.
pub const SIGHT: u32 = 3;

/// A local maximum of the activator on the edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    /// α in degrees, as a spine's angle.
    pub angle: f64,
    /// Height above the edge's lowest concentration, relative to the highest peak's (0 to 1).
    pub level: f64,
}

/// The angle of pattern cell `cell` of `cells` on the generating curve: the pattern runs
/// about w from +u (towards the axis) through +v, and α from −u through +v.
pub fn cell_angle(cell: usize, cells: usize) -> f64 {
    let a = 180.0 - 360.0 * (cell as f64 + 0.5) / cells as f64;
    if a <= -180.0 { a + 360.0 } else { a }
}

/// The peaks of `activator` (one value per cell around the closed edge) on the outer lip, by
/// angle; none when the edge has no pattern yet ([`CONTRAST`]). Their levels are measured
/// over the whole edge.
pub fn peaks(activator: &[f64]) -> Vec<Peak> {
    let n = activator.len();
    let high = activator.iter().copied().fold(f64::MIN, f64::max);
    let low = activator.iter().copied().fold(f64::MAX, f64::min);
    if n < 3 || high.is_nan() || high <= 0.0 || high - low < CONTRAST * high {
        return Vec::new();
    }
    let mut peaks: Vec<Peak> = (0..n)
        .filter(|&c| {
            let a = activator[c];
            a >= activator[(c + n - 1) % n] && a > activator[(c + 1) % n]
        })
        .map(|c| Peak {
            angle: cell_angle(c, n),
            level: (activator[c] - low) / (high - low),
        })
        .filter(|p| p.angle.abs() <= OUTER_LIP)
        .collect();
    peaks.sort_by(|a, b| a.angle.total_cmp(&b.angle));
    peaks
}

/// The spines a varix grows on `peaks`: one on every peak of at least the spine level, of
/// relative size σ rising linearly from the bump level to `peak_sigma` at the highest peak.
pub fn spines_of(peaks: &[Peak], v: &VaricesSpec) -> Vec<Spine> {
    let span = (1.0 - v.bump_level).max(f64::EPSILON);
    peaks
        .iter()
        .filter(|p| p.level >= v.spine_level)
        .map(|p| Spine {
            angle: p.angle,
            sigma: v.peak_sigma * (p.level - v.bump_level) / span,
        })
        .collect()
}

/// The bumps a row between varices bears on `peaks`: one on every peak from the bump level up
/// to (not including) the spine level, its σ the peak's level relative to the spine level
/// (the bump's size is scaled by it).
pub fn bumps_of(peaks: &[Peak], v: &VaricesSpec) -> Vec<Spine> {
    peaks
        .iter()
        .filter(|p| p.level >= v.bump_level && p.level < v.spine_level && p.level > 0.0)
        .map(|p| Spine {
            angle: p.angle,
            sigma: p.level / v.spine_level,
        })
        .collect()
}

/// The parts of `standing` (spines or bumps of the generating surface placed by `at`) that
/// stand free in the grown shell: the surface they stand on belongs to `own` (their own
/// section of the whorl), and the points along their line out to `reach(spine)` (units of D)
/// and on to [`SIGHT`] beyond the surface lie outside `body` (the whole shell), so that no
/// later whorl buries them and none stands in the closed space about the axis.
pub fn free(
    body: &Node,
    own: &Node,
    at: &DAffine3,
    standing: Vec<Standing>,
    reach: impl Fn(&Spine) -> f64,
) -> Vec<Standing> {
    let field = |node: &Node, s: &Standing, t: f64| {
        node.field(at.transform_point3(outward(s.spine.angle) * (s.edge + t)))
    };
    standing
        .into_iter()
        .filter(|s| {
            let length = reach(&s.spine);
            field(own, s, -0.05) >= ISO
                && (1..=4)
                    .map(|i| 0.25 * f64::from(i) * length)
                    .chain((1..=4 * SIGHT).map(|i| 0.25 * f64::from(i)))
                    .all(|t| field(body, s, t) < ISO)
        })
        .collect()
}

/// The activator along the growing edge (the value each pattern model records) on each of
/// `rows` (ascending), as the pattern of `pattern` seeded by `seed` computes it.
pub fn activator_at(
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
    for &wanted in rows {
        while row < wanted {
            model
                .advance_row()
                .map_err(|e| fail(format!("the pattern failed at row {row}: {e}")))?;
            row += 1;
        }
        out.push(model.recorded().iter().map(|&a| f64::from(a)).collect());
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn cells_map_to_angles_from_the_outside_round_the_curve() {
        assert!((cell_angle(0, 4) - 135.0).abs() < 1e-12);
        assert!((cell_angle(2, 4) + 45.0).abs() < 1e-12);
        assert!((cell_angle(3, 4) + 135.0).abs() < 1e-12);
        assert!(outward(90.0).distance(DVec3::Y) < 1e-12);
        assert!(outward(0.0).distance(DVec3::NEG_X) < 1e-12);
    }

    #[test]
    fn high_peaks_grow_spines_and_lower_ones_bumps() {
        // 36 cells: cell c lies at 175 − 10c degrees; the lowest concentration is 1.
        let mut activator = vec![1.0; 36];
        activator[14] = 9.0; // 35°: the highest peak
        activator[17] = 8.0; // 5°: level 0.875
        activator[20] = 6.0; // −25°: level 0.625
        activator[11] = 3.0; // 65°: level 0.25, too low for anything
        activator[2] = 9.0; // 155°: on the inner lip
        let v = VaricesSpec::default();
        let p = peaks(&activator);
        assert_eq!(p.len(), 4, "{p:?}");
        assert!(p.iter().all(|p| p.angle.abs() <= OUTER_LIP));
        let spines = spines_of(&p, &v);
        let angles: Vec<f64> = spines.iter().map(|s| s.angle).collect();
        assert_eq!(angles, [5.0, 35.0]);
        assert!((spines[1].sigma - v.peak_sigma).abs() < 1e-12);
        let expected = v.peak_sigma * (0.875 - 0.55) / 0.45;
        assert!((spines[0].sigma - expected).abs() < 1e-12);
        let bumps = bumps_of(&p, &v);
        assert_eq!(bumps.len(), 1);
        assert!((bumps[0].angle + 25.0).abs() < 1e-12);
        assert!((bumps[0].sigma - 0.625 / 0.8).abs() < 1e-12);
    }

    #[test]
    fn an_edge_without_a_pattern_has_no_peaks() {
        let flat: Vec<f64> = (0..40).map(|c| 1.5 + 0.01 * f64::from(c % 3)).collect();
        assert!(peaks(&flat).is_empty());
        assert!(peaks(&[0.0; 10]).is_empty());
    }
}
