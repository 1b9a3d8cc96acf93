//! A whole shell as a BlobTree (Galbraith, Prusinkiewicz & Wyvill §2.1 and §3.1): the generating
//! surface is placed along the helico-spiral by P(B, θ) (eq 8), its instances blend into
//! sections (eq 9), and the sections combine by blending or by controlled blending with their
//! neighbours only (eq 10). Each instance is one growth step.
//!
//! The helix is in `helix.rs`, the generating surface in `generating_surface.rs`, sections in
//! `sections.rs`, the opening in `opening.rs`; this module places the varices, their spines,
//! the bumps and the canal spines, and joins it all.

use super::bumps::{BUMP_EXPONENT, BUMP_STREAM, bump_set};
use super::canal_spines::{CANAL_STREAM, CANAL_VARICES, canal_row};
use super::check::check;
use super::fine_parts::{FineParts, Placed, SHOWS_THE_MODEL, THINNEST, THINNEST_VOXELS};
use super::helix::Instances;
use super::opening::{Opening, THINNEST_WALL, WALL_VOXELS, opening};
use super::rd_placement::{activator_at, bumps_of, free, peaks, spines_of};
use super::sections::{Gathered, joined, sections};
use super::textures::look;
use super::varix::{Spine, Standing, standing, table_spines, varix};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::polygonize::MAX_LEVEL;
use crate::blobtree::texture_blend::{Look, MapOn};
use crate::mesh::Bounds;
use crate::pattern::noise::Noise;
use crate::shape::ShapeError;
use crate::spec::form::implicit::{ImplicitSpec, Placement, Shows};
use crate::spec::pattern::PatternSpec;
use glam::{DAffine3, DVec3};
use std::collections::BTreeMap;

/// The BlobTree of a whole shell, with what growing it needs.
pub struct Whorl {
    pub tree: Node,
    /// Generating surfaces placed: one growth step each.
    pub instances: u32,
    /// The boxes of what each growth step adds or takes away, by step: where it changes the
    /// shell. Kept apart, not as one box about them all: a step adds a generating surface at
    /// the growing edge and takes away what lived there a whorl before, and the box about
    /// both would hold most of the shell.
    pub reach: Vec<Vec<Bounds>>,
    /// The direction the opening faces.
    pub front: DVec3,
    /// What stands on each varix, from the apex to the opening.
    pub varices: Vec<Varix>,
    /// The thin parts: their boxes with the level of refinement that shows them, and where
    /// each stands out ([`FineParts`]).
    pub fine: Placed,
}

/// One varix as built: where it stands and its spines.
#[derive(Clone, Debug, PartialEq)]
pub struct Varix {
    /// The instance (growth step) it closes.
    pub instance: u32,
    /// Its spines, each where its angle meets the surface.
    pub spines: Vec<Standing>,
    /// Spines in the canal row below it.
    pub canal_spines: usize,
    /// Where the bumps of the section it closes stand, set after set.
    pub bumps: Vec<Standing>,
}

/// The shell of `spec` as one BlobTree (eqs 9–15), instance k carrying growth time
/// k·(rows − 1)/(K − 1). Spines and bumps placed by the pattern read the activator of
/// `pattern` (seeded by `seed`) on the row each varix or set of bumps forms on
/// (`rd_placement.rs`); bumps and canal spines take their random sizes and bends from `seed`.
pub fn whorl(
    spec: &ImplicitSpec,
    pattern: &PatternSpec,
    seed: u64,
    rows: usize,
) -> Result<Whorl, ShapeError> {
    check(spec)?;
    let body_look = look(&spec.textures.body, MapOn::Growth { rows: rows as f64 });
    let instances = Instances::new(spec, rows);
    let count = instances.count;
    let mut gathered = Gathered {
        reach: vec![Vec::new(); count as usize],
    };
    let mut sections = sections(
        &spec.generator,
        &instances,
        (0..count).map(|k| (k, 1.0)),
        spec.surfaces,
        0,
        &mut gathered,
    );
    let body = joined(
        spec.blending,
        sections.iter().map(|s| s.1.clone()).collect(),
        Vec::new(),
    );
    let v = &spec.varices;
    let by_pattern = v.placement == Placement::Pattern;
    // The largest σ of eq 12: the table's, or that of a spine on the pattern's highest peak.
    let sigma_max = if by_pattern {
        v.peak_sigma
    } else {
        v.spines.iter().map(|s| s[2]).fold(0.0, f64::max)
    };
    // The shell's extent, with the longest spine: what the model's least sizes are fractions
    // of, and what the grid's voxel divides.
    let last = f64::from(count - 1);
    let reach = (v.length * sigma_max).max(spec.canal_spines.length) * instances.size(last);
    let extent = (body.bounds.max - body.bounds.min + 2.0 * reach).max_element();
    let voxel = extent / f64::from(spec.resolution);
    // The model's least sizes, unless the grid is too coarse to show them (a gallery card's,
    // say): then what its finest voxel shows.
    let (floor, thinnest_wall) = if spec.resolution >= SHOWS_THE_MODEL {
        (extent * THINNEST, extent * THINNEST_WALL)
    } else {
        let finest = voxel / f64::from(1u32 << MAX_LEVEL);
        (THINNEST_VOXELS * finest, WALL_VOXELS * voxel)
    };
    // The thin parts of instance k, in its own units: the grid's voxel, the floor.
    let fine_at = |k: f64| {
        let size = instances.size(k);
        FineParts::new(voxel / size, floor / size)
    };
    let mut fine = Placed::default();
    // A varix closes every section (at its last instance), when the spec has spines.
    let varix_rows: Vec<u32> = if v.spines.is_empty() && !by_pattern {
        Vec::new()
    } else {
        (1..=spec.whorls * spec.sections)
            .map(|i| i * spec.surfaces - 1)
            .collect()
    };
    // The sets of bumps between a varix (at instance k) and the one before.
    let bump_instances = |k: f64| -> Vec<f64> {
        (1..=v.bump_sets)
            .map(|j| {
                k - f64::from(spec.surfaces) * (1.0 - f64::from(j) / f64::from(v.bump_sets + 1))
            })
            .filter(|&kb| kb >= 0.0)
            .collect()
    };
    let row_of = |k: f64| instances.time(k).round() as usize;
    // The activator on every row a varix or a set of bumps forms on, for the pattern to read.
    let activator: BTreeMap<usize, Vec<f64>> = if by_pattern {
        let mut rows: Vec<usize> = varix_rows
            .iter()
            .flat_map(|&k| {
                let kf = f64::from(k);
                std::iter::once(kf).chain(bump_instances(kf))
            })
            .map(row_of)
            .collect();
        rows.sort_unstable();
        rows.dedup();
        rows.iter()
            .copied()
            .zip(activator_at(pattern, seed, &rows)?)
            .collect()
    } else {
        BTreeMap::new()
    };
    let peaks_at = |k: f64| peaks(activator.get(&row_of(k)).map_or(&[], Vec::as_slice));
    // Spines and bumps placed by the pattern where they stand free (`rd_placement.rs`).
    let length = v.length;
    let bump_reach = 2.0 * v.bump_size;
    // Their own part of the whorl: the section of instance k and its neighbours along the
    // spiral (not the whorls before and after, a turn away).
    let free_on =
        |k: f64, at: &DAffine3, standing: Vec<Standing>, reach: &dyn Fn(&Spine) -> f64| {
            let section = k.round() as u32 / spec.surfaces;
            let own: Vec<Node> = sections
                .iter()
                .filter(|s| s.0 + 1 >= section && s.0 <= section + 1)
                .map(|s| s.1.clone())
                .collect();
            free(&body, &Node::blend(own), at, standing, reach)
        };
    let mut parts = Vec::new();
    // Each varix's spines and ridge with the instance it closes, for the opening to leave
    // intact.
    let mut kept: Vec<(u32, Node)> = Vec::new();
    let mut varices = Vec::new();
    let mut bump_noise = Noise::new(seed, BUMP_STREAM);
    let mut canal_noise = Noise::new(seed, CANAL_STREAM);
    let section_of = |k: u32| sections.iter().position(|s| s.0 == k / spec.surfaces);
    let mut extra: Vec<Vec<Node>> = vec![Vec::new(); sections.len()];
    for (i, &k) in varix_rows.iter().enumerate() {
        let kf = f64::from(k);
        let whorl_number = k / (spec.sections * spec.surfaces) + 1;
        let at = instances.placement(kf);
        let on_surface = if by_pattern {
            let spines = spines_of(&peaks_at(kf), v);
            free_on(kf, &at, standing(&body, &at, &spines), &|s| {
                length * s.sigma
            })
        } else {
            standing(&body, &at, &table_spines(&v.spines, whorl_number))
        };
        let time = instances.time(kf);
        let mut thin = fine_at(kf);
        let mut members: Vec<Node> = varix(
            v,
            &on_surface,
            sigma_max,
            &mut thin,
            time,
            &spec.textures.spines,
            body_look,
        )
        .into_iter()
        .collect();
        if let Some(spines) = members.first() {
            kept.push((k, spines.clone()));
        }
        let from_opening = varix_rows.len() - i;
        let mut canal = Vec::new();
        if from_opening <= CANAL_VARICES {
            let varix_number = (CANAL_VARICES + 1 - from_opening) as f64;
            let sizes: Vec<f64> = spec
                .canal_spines
                .spines
                .iter()
                .filter(|s| s[0].round() == varix_number)
                .map(|s| s[1])
                .collect();
            if let Some(cone) = spec
                .generator
                .cones
                .iter()
                .find(|c| instances.whorl(kf) >= c[9])
            {
                canal = canal_row(
                    cone,
                    &sizes,
                    [spec.canal_spines.length, spec.canal_spines.radius],
                    &mut thin,
                    time,
                    &spec.textures.canal_spines,
                    &mut canal_noise,
                );
            }
        }
        let canal_spines = canal.len();
        members.extend(canal);
        thin.place(&at, instances.size(kf), &mut fine);
        varices.push(Varix {
            instance: k,
            canal_spines,
            spines: on_surface,
            bumps: Vec::new(),
        });
        if !members.is_empty() {
            let part = gathered.placed(at, Node::blend(members), k);
            let with = [section_of(k), section_of(k + 1)]
                .into_iter()
                .flatten()
                .collect();
            parts.push((part, with));
        }
        // The bumps of the section this varix closes, in sets between it and the one before.
        let Some(section) = section_of(k) else {
            continue;
        };
        for kb in bump_instances(kf) {
            let at = instances.placement(kb);
            let sites = if by_pattern {
                let bumps = bumps_of(&peaks_at(kb), v);
                free_on(kb, &at, standing(&body, &at, &bumps), &|s| {
                    bump_reach * s.sigma
                })
            } else {
                // The table's bumps: one at every second spine, of the default size.
                let every_second: Vec<Spine> = table_spines(&v.spines, whorl_number)
                    .into_iter()
                    .step_by(2)
                    .map(|s| Spine { sigma: 1.0, ..s })
                    .collect();
                standing(&body, &at, &every_second)
            };
            let mut thin = fine_at(kb);
            let bumps = bump_set(
                &sites,
                v.bump_size,
                v.bump_spread,
                &mut thin,
                instances.time(kb),
                &mut bump_noise,
            );
            thin.place(&at, instances.size(kf), &mut fine);
            let bump_look = look(&spec.textures.bumps, MapOn::Part { start: 0.0 });
            for bump in bumps {
                let bump = bump.looking(bump_look);
                extra[section].push(gathered.placed(at, bump, kb.round() as u32));
            }
            if let Some(built) = varices.last_mut() {
                built.bumps.extend(sites);
            }
        }
    }
    for ((_, node), bumps) in sections.iter_mut().zip(extra) {
        if body_look != Look::Pattern {
            *node = std::mem::replace(node, Node::blend(Vec::new())).looking(body_look);
        }
        if !bumps.is_empty() {
            let whorl = std::mem::replace(node, Node::blend(Vec::new()));
            *node =
                Node::superelliptic(BUMP_EXPONENT, std::iter::once(whorl).chain(bumps).collect());
        }
    }
    let shell = joined(
        spec.blending,
        sections.into_iter().map(|s| s.1).collect(),
        parts,
    );
    // Eqs 14 and 15: B_murex = (B_shell − B_opening) ∪ B_inside_wall.
    let tree = match opening(
        spec,
        &instances,
        &kept,
        (thinnest_wall, WALL_VOXELS * voxel),
        &shell,
        body_look,
        &mut gathered,
    ) {
        Some(Opening {
            inside,
            hollow,
            wall,
            thin_walls,
        }) => {
            fine.boxes
                .extend(thin_walls.into_iter().map(|b| (b, MAX_LEVEL)));
            match spec.opening.shows {
                Shows::Shell => {
                    let carved = Node::difference(shell, hollow);
                    match wall {
                        Some(wall) => Node::union(vec![carved, wall]),
                        None => carved,
                    }
                }
                Shows::Inside => inside,
                Shows::Opening => hollow,
            }
        }
        None if spec.opening.shows == Shows::Shell => shell,
        None => {
            return Err(ShapeError::new(
                "form.opening.shows",
                if spec.opening.inside.is_empty() {
                    "this shell is solid: it has no inside generating surface to carve with"
                        .to_string()
                } else {
                    format!(
                        "on a grid of {} voxels the wall the hollow would leave is too thin to show in every whorl, so nothing is carved: a resolution of {SHOWS_THE_MODEL} or more shows the model",
                        spec.resolution
                    )
                },
            ));
        }
    };
    Ok(Whorl {
        tree,
        instances: count,
        reach: gathered.reach,
        front: instances.growth_direction(last),
        varices,
        fine,
    })
}
