//! The spec a picture is grown from (a gallery card's or a parameter map's tile): the shell's own, with a mesh no finer than the picture can show. Drawing a picture costs the browser in proportion to its
//! triangles (SwiftShader on a busy 2-core machine: about a second per 200 000), while the
//! pattern is sampled per pixel from its texture whatever the mesh: so the picture keeps every
//! pattern row and cell, every rib, the shape and the seed, and only the mesh is coarser. The
//! worker that grows a picture thins a swept shell's mesh further, to the size each whorl is
//! drawn at ([`crate::forms::sweep::drawn_size`]).

use crate::spec::ShellSpec;
use crate::spec::form::Form;
use crate::spec::form::sweep::{RibSpec, SweepSpec};

/// Pixels across a gallery card's picture as drawn (shown at 256, a little sharper).
pub const CARD_PIXELS: u32 = 320;

/// Pixels across a parameter map's tile as drawn (shown at about 100).
pub const TILE_PIXELS: u32 = 128;

/// Voxels along the longest side of an implicit shell in a picture `pixels` wide: enough for
/// its size (64 in a card), and quick to grow and to draw.
fn resolution(pixels: u32) -> u32 {
    pixels / 5
}

/// Points per rim of a swept shell in a picture `pixels` wide, at least: in a card, a rim of
/// 100 pixels' radius departs from its curve by under half a pixel between two of 64 points;
/// in a smaller picture the rim is smaller, and fewer points keep it as close.
fn segments(pixels: u32) -> u32 {
    pixels / 5
}

/// Rims or points of the mesh per period of a family of ribs, at least, so that each rib
/// keeps its crest and its shading.
const SAMPLES_PER_RIB: f64 = 8.0;

/// The spec of a picture of `spec`, `pixels` wide.
pub fn picture_spec(spec: &ShellSpec, pixels: u32) -> ShellSpec {
    let mut spec = spec.clone();
    match &mut spec.form {
        Form::Implicit(implicit) => {
            implicit.resolution = implicit.resolution.min(resolution(pixels));
        }
        Form::Sweep(sweep) => coarsen(sweep, pixels),
        Form::Chambers(_) | Form::Branching(_) => {}
    }
    spec
}

/// The most periods of `ribs` per whorl (curve ribs) or along the curve (growth ribs) over
/// `whorls`, or 0 when the family is off.
fn most_ribs(ribs: &RibSpec, whorls: f64) -> f64 {
    if ribs.amplitude == 0.0 || ribs.count <= 0.0 {
        return 0.0;
    }
    ribs.count * ribs.frequency_change.max(1.0).powf(whorls)
}

/// One rim per angular step Δθ (eq 2) and [`segments`] points per rim, unless the ribs need
/// more (never more than the shell's own).
fn coarsen(sweep: &mut SweepSpec, pixels: u32) {
    let whorls = sweep.spiral.whorls;
    let curve_ribs = most_ribs(&sweep.sculpture.curve_ribs, whorls);
    let steps_per_whorl = 360.0 / sweep.spiral.delta_theta;
    let subdivisions = (SAMPLES_PER_RIB * curve_ribs / steps_per_whorl).ceil() as u32;
    sweep.spiral.subdivisions = sweep.spiral.subdivisions.min(subdivisions.max(1));
    let growth_ribs = most_ribs(&sweep.sculpture.growth_ribs, whorls);
    let segments = (SAMPLES_PER_RIB * growth_ribs).ceil() as u32;
    sweep.curve.segments = sweep
        .curve
        .segments
        .min(segments.max(self::segments(pixels)));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::presets;

    fn sweep(spec: &ShellSpec) -> &SweepSpec {
        match &spec.form {
            Form::Sweep(s) => s,
            _ => unreachable!(),
        }
    }

    #[test]
    fn only_the_mesh_is_coarser() {
        for preset in presets() {
            let picture = picture_spec(&preset.spec, CARD_PIXELS);
            let mut same_form = picture.clone();
            same_form.form = preset.spec.form.clone();
            assert_eq!(
                same_form, preset.spec,
                "{}: the pattern, colours and seed stay",
                preset.id
            );
            match (&preset.spec.form, &picture.form) {
                (Form::Sweep(s), Form::Sweep(p)) => {
                    let mut coarse = s.clone();
                    coarse.spiral.subdivisions = p.spiral.subdivisions;
                    coarse.curve.segments = p.curve.segments;
                    assert_eq!(&coarse, p, "{}: only the mesh's resolution", preset.id);
                    assert!(p.spiral.subdivisions <= s.spiral.subdivisions);
                    assert!(p.curve.segments <= s.curve.segments);
                }
                (Form::Implicit(s), Form::Implicit(p)) => {
                    assert_eq!(p.resolution, s.resolution.min(resolution(CARD_PIXELS)));
                }
                (s, p) => assert_eq!(s, p, "{}", preset.id),
            }
        }
    }

    #[test]
    fn ribs_keep_their_samples() {
        for preset in presets() {
            let Form::Sweep(s) = &preset.spec.form else {
                continue;
            };
            let p = sweep(&picture_spec(&preset.spec, CARD_PIXELS)).clone();
            let whorls = s.spiral.whorls;
            let rims_per_whorl = 360.0 / s.spiral.delta_theta * f64::from(p.spiral.subdivisions);
            let curve = most_ribs(&s.sculpture.curve_ribs, whorls);
            let kept = p.spiral.subdivisions == s.spiral.subdivisions;
            assert!(
                kept || rims_per_whorl >= SAMPLES_PER_RIB * curve,
                "{}: {rims_per_whorl} rims a whorl for {curve} ribs",
                preset.id
            );
            let growth = most_ribs(&s.sculpture.growth_ribs, whorls);
            assert!(
                p.curve.segments == s.curve.segments
                    || f64::from(p.curve.segments) >= SAMPLES_PER_RIB * growth,
                "{}: {} points a rim for {growth} ribs",
                preset.id,
                p.curve.segments
            );
        }
    }

    #[test]
    fn the_finest_sweeps_lose_most_of_their_triangles() {
        let triangles = |s: &SweepSpec| {
            s.spiral.whorls * 360.0 / s.spiral.delta_theta
                * f64::from(s.spiral.subdivisions)
                * f64::from(s.curve.segments)
        };
        for id in ["conus-marmoreus", "oliva-porphyria", "turritella-nivea"] {
            let preset = presets().iter().find(|p| p.id == id).expect(id);
            let before = triangles(sweep(&preset.spec));
            let after = triangles(sweep(&picture_spec(&preset.spec, CARD_PIXELS)));
            assert!(after * 3.0 <= before, "{id}: {before} → {after}");
        }
    }
}
