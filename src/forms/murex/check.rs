//! What the numbers of an implicit shell must satisfy for its BlobTree to be built, and the
//! caps that keep any shell within memory and time; each refusal names its key.

use super::grid_sight;
use super::textures::check_textures;
use crate::blobtree::bend::MAX_BEND_DEGREES;
use crate::blobtree::falloff::support_of;
use crate::mesh::MAX_GROWTH_DECADES;
use crate::shape::ShapeError;
use crate::spec::fields;
use crate::spec::form::implicit::{GeneratorSpec, ImplicitSpec, Placement};
use glam::DVec3;

/// Most generating surfaces (growth steps) in one shell.
pub const MAX_INSTANCES: u64 = 5_000;

/// The most whorls a spiral whose radii grow by `lambda` a turn may have (at least 1): as
/// many as keep its growth within 10^[`MAX_GROWTH_DECADES`].
pub(crate) fn most_whorls(lambda: f64) -> u32 {
    (MAX_GROWTH_DECADES / lambda.log10())
        .floor()
        .clamp(1.0, f64::from(u32::MAX)) as u32
}

/// Checks what the numbers must satisfy for the tree to be built.
pub fn check(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let h = &spec.spiral;
    within("form.spiral.lambda", h.lambda, "λ (whorls grow)")?;
    within("form.spiral.beta", h.beta, "β")?;
    within("form.spiral.r0", h.r0, "R₀")?;
    within("form.whorls", f64::from(spec.whorls), "the whorls")?;
    within(
        "form.sections",
        f64::from(spec.sections),
        "the sections per whorl",
    )?;
    within(
        "form.surfaces",
        f64::from(spec.surfaces),
        "the generating surfaces per section",
    )?;
    let most = most_whorls(h.lambda);
    if spec.whorls > most {
        return Err(ShapeError::new(
            "form.whorls",
            format!(
                "{} whorls at λ = {} grow the shell 10^{:.0} times from its apex: at most {most} at this λ (a float32 file keeps no finer detail than 10^-{MAX_GROWTH_DECADES} of a shell)",
                spec.whorls,
                h.lambda,
                f64::from(spec.whorls) * h.lambda.log10()
            ),
        ));
    }
    let instances = u64::from(spec.whorls) * u64::from(spec.sections) * u64::from(spec.surfaces);
    if instances > MAX_INSTANCES {
        return Err(ShapeError::new(
            "form.surfaces",
            format!(
                "{} whorls × {} sections × {} surfaces make {instances} generating surfaces, more than the cap of {MAX_INSTANCES}",
                spec.whorls, spec.sections, spec.surfaces
            ),
        ));
    }
    within(
        "form.whorl_angle",
        spec.whorl_angle,
        "the rotation per whorl (degrees)",
    )?;
    within(
        "form.resolution",
        f64::from(spec.resolution),
        "the resolution (voxels along the longest side)",
    )?;
    check_generator(&spec.generator, "form.generator")?;
    check_varices(spec)?;
    check_canal_spines(spec)?;
    let o = &spec.opening;
    within(
        "form.opening.ahead",
        f64::from(o.ahead),
        "the generating surfaces the hollow reaches ahead",
    )?;
    if parts(&o.inside) > 0 {
        check_generator(&o.inside, "form.opening.inside")?;
    }
    check_cones(&o.extension, "form.opening.extension")?;
    within(
        "form.opening.wall",
        f64::from(o.wall),
        "the generating surfaces the inside wall stands over",
    )?;
    check_textures(&spec.textures)?;
    grid_sight::check(spec)
}

/// The largest radius or distance from its centre a part of a generating surface may have,
/// and the smallest radius, in units of the generating surface's size D: beyond them a part
/// is either lost in the arithmetic or swallows the whole shell, which grows to nothing.
pub const MAX_PART: f64 = 100.0;
pub const MIN_PART: f64 = 1e-4;

/// Most spines in the table of a varix's spines, and in the canal spines' table.
pub const MAX_SPINES: usize = 1024;

/// A value within the panel's range of its field `key` (the one source of its limits).
fn within(key: &str, x: f64, what: &str) -> Result<(), ShapeError> {
    let (least, most) = fields::range("implicit", key);
    if (least..=most).contains(&x) {
        Ok(())
    } else {
        Err(ShapeError::new(
            key,
            format!("{what} must lie from {least} to {most}, not {x}"),
        ))
    }
}

fn parts(g: &GeneratorSpec) -> usize {
    g.points.len() + g.cones.len() + g.tori.len()
}

/// A radius of a part of a generating surface: within [`MIN_PART`, `MAX_PART`].
fn part_radius(key: &str, x: f64, what: &str) -> Result<(), ShapeError> {
    if (MIN_PART..=MAX_PART).contains(&x) {
        Ok(())
    } else {
        Err(ShapeError::new(
            key,
            format!(
                "{what} must lie from {MIN_PART} to {MAX_PART} (units of the generating surface's size D), not {x:e}: the shell would grow to nothing"
            ),
        ))
    }
}

/// A position of a part of a generating surface: within [`MAX_PART`] of its centre.
fn part_position(key: &str, coordinates: &[f64]) -> Result<(), ShapeError> {
    match coordinates
        .iter()
        .find(|c| c.is_nan() || c.abs() > MAX_PART)
    {
        None => Ok(()),
        Some(c) => Err(ShapeError::new(
            key,
            format!(
                "a part must lie within {MAX_PART} (units of D) of the generating surface's centre, not at {c:e}"
            ),
        )),
    }
}

fn positive(key: &str, x: f64, what: &str) -> Result<(), ShapeError> {
    if x > 0.0 && x.is_finite() {
        Ok(())
    } else {
        Err(ShapeError::new(
            key,
            format!("{what} must be positive, not {x}"),
        ))
    }
}

fn check_varices(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let v = &spec.varices;
    if v.spines.len() > MAX_SPINES {
        return Err(ShapeError::new(
            "form.varices.spines",
            format!(
                "{} spines are more than the cap of {MAX_SPINES}",
                v.spines.len()
            ),
        ));
    }
    for &[whorl, angle, sigma] in &v.spines {
        if !(whorl >= 1.0 && whorl <= f64::from(spec.whorls) && whorl.fract() == 0.0) {
            return Err(ShapeError::new(
                "form.varices.spines",
                format!(
                    "a spine's whorl must be a whole number from 1 to {}, not {whorl}",
                    spec.whorls
                ),
            ));
        }
        if !(-180.0..=180.0).contains(&angle) {
            return Err(ShapeError::new(
                "form.varices.spines",
                format!("a spine's angle must lie from −180° to 180°, not {angle}°"),
            ));
        }
        if !(sigma > 0.0 && sigma <= 10.0) {
            return Err(ShapeError::new(
                "form.varices.spines",
                format!("a spine's relative size σ must lie in (0, 10], not {sigma}"),
            ));
        }
    }
    positive("form.varices.length", v.length, "the spines' length")?;
    positive("form.varices.radius", v.radius, "the spines' radius")?;
    positive("form.varices.tip", v.tip, "the spines' tip radius")?;
    positive("form.varices.bump_size", v.bump_size, "the bumps' size")?;
    if v.bend.is_nan() || v.bend.abs() > MAX_BEND_DEGREES {
        return Err(ShapeError::new(
            "form.varices.bend",
            format!(
                "a spine may curve by at most {MAX_BEND_DEGREES}°, not {}°",
                v.bend
            ),
        ));
    }
    if !(v.ridge >= 0.0 && v.ridge.is_finite()) {
        return Err(ShapeError::new(
            "form.varices.ridge",
            format!(
                "the ridge's radius must be 0 (none) or positive, not {}",
                v.ridge
            ),
        ));
    }
    within(
        "form.varices.bump_sets",
        f64::from(v.bump_sets),
        "the sets of bumps between two varices",
    )?;
    within(
        "form.varices.bump_spread",
        v.bump_spread,
        "the bumps' spread",
    )?;
    within(
        "form.varices.spine_level",
        v.spine_level,
        "the activator level that grows a spine (of the edge's highest peak)",
    )?;
    if !(0.0..=v.spine_level).contains(&v.bump_level) {
        return Err(ShapeError::new(
            "form.varices.bump_level",
            format!(
                "the activator level that bears bumps must lie from 0 to the spines' level {}, not {}",
                v.spine_level, v.bump_level
            ),
        ));
    }
    within(
        "form.varices.peak_sigma",
        v.peak_sigma,
        "the relative size σ of a spine on the highest peak",
    )?;
    Ok(())
}

fn check_canal_spines(spec: &ImplicitSpec) -> Result<(), ShapeError> {
    let c = &spec.canal_spines;
    if c.spines.len() > MAX_SPINES {
        return Err(ShapeError::new(
            "form.canal_spines.spines",
            format!(
                "{} canal spines are more than the cap of {MAX_SPINES}",
                c.spines.len()
            ),
        ));
    }
    for &[varix, sigma] in &c.spines {
        if ![1.0, 2.0, 3.0].contains(&varix) {
            return Err(ShapeError::new(
                "form.canal_spines.spines",
                format!(
                    "a canal spine stands below varix 1, 2 or 3 (the last three, 3 at the opening), not {varix}"
                ),
            ));
        }
        if !(sigma > 0.0 && sigma <= 10.0) {
            return Err(ShapeError::new(
                "form.canal_spines.spines",
                format!("a canal spine's relative size σ must lie in (0, 10], not {sigma}"),
            ));
        }
    }
    if !c.spines.is_empty() && spec.generator.cones.is_empty() {
        return Err(ShapeError::new(
            "form.canal_spines.spines",
            "canal spines stand on the canal: the generating surface needs a cone for it",
        ));
    }
    if !c.spines.is_empty()
        && spec.varices.spines.is_empty()
        && spec.varices.placement != Placement::Pattern
    {
        return Err(ShapeError::new(
            "form.canal_spines.spines",
            "canal spines stand below varices: give the varices spines, or place them by the pattern",
        ));
    }
    positive(
        "form.canal_spines.length",
        c.length,
        "the canal spines' length",
    )?;
    positive(
        "form.canal_spines.radius",
        c.radius,
        "the canal spines' radius",
    )
}

/// Checks cones given as a generating surface's are (positions, radii, bend, from whorl),
/// under the key `key`.
fn check_cones(cones: &[[f64; 10]], key: &str) -> Result<(), ShapeError> {
    for c in cones {
        part_position(key, &c[..6])?;
        part_radius(key, c[6], "a cone's radius")?;
        part_radius(key, c[7], "a cone's radius")?;
        let length = DVec3::new(c[3] - c[0], c[4] - c[1], c[5] - c[2]).length();
        positive(key, length, "a cone's length")?;
        if c[8].abs() > MAX_BEND_DEGREES {
            return Err(ShapeError::new(
                key.to_string(),
                format!(
                    "a cone may bend by at most {MAX_BEND_DEGREES}°, not {}°",
                    c[8]
                ),
            ));
        }
        if support_of(c[6].max(c[7])) * c[8].abs().to_radians() >= length {
            return Err(ShapeError::new(
                key.to_string(),
                format!(
                    "a cone of length {length} bent by {}° is too thick for its bend: its field would fold over the centre of curvature",
                    c[8]
                ),
            ));
        }
    }
    Ok(())
}

/// Checks the generating surface `g`, whose keys start with `prefix`.
fn check_generator(g: &GeneratorSpec, prefix: &str) -> Result<(), ShapeError> {
    let parts = parts(g);
    let key = |k: &str| format!("{prefix}.{k}");
    if parts == 0 {
        return Err(ShapeError::new(
            key("points"),
            "the generating surface needs at least one primitive",
        ));
    }
    for p in &g.points {
        part_position(&key("points"), &p[..3])?;
        part_radius(&key("points"), p[3], "a point's radius")?;
    }
    check_cones(&g.cones, &key("cones"))?;
    for t in &g.tori {
        part_position(&key("tori"), &t[..3])?;
        part_radius(&key("tori"), t[3], "a torus's major radius")?;
        part_radius(&key("tori"), t[4], "a torus's radius")?;
    }
    within(&key("exponent"), g.exponent, "the blending exponent n")?;
    if let Some([i, k]) = g
        .pairs
        .iter()
        .find(|[i, k]| i == k || *i as usize >= parts || *k as usize >= parts)
    {
        return Err(ShapeError::new(
            key("pairs"),
            format!(
                "the pair ({i}, {k}) must name two different parts of the {parts} the generating surface has (numbered from 0: points, then cones, then tori)"
            ),
        ));
    }
    Ok(())
}
