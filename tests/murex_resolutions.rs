//! The Murex whatever the grid (Galbraith, Prusinkiewicz & Wyvill §3): the model, not the
//! voxel, decides what exists. The BlobTree built for any grid is the same tree, and the
//! meshes of it enclose the same volume within 2 %; every spine, canal spine and bump that the
//! model shows stands out of the mesh at the preset's own resolution as at a finer one,
//! because the polygonizer refines the grid where they stand; and every Murex preset is one
//! closed, consistently wound piece at each. Meshing holds little more than the mesh it
//! makes: each piece is appended to it as it is made. `make test` compares the preset's own
//! resolution and 128³ with 256³; `make bench` runs the same check against 384³ (the ignored
//! test below), which takes three times as long.

use crate::common;

use common::heap::peak_of;
use common::{assert_closed_and_outward, implicit, pieces, signed_volume};
use glam::DVec3;
use seashells_core::blobtree::falloff::ISO;
use seashells_core::forms::murex::whorl::{Whorl, whorl};
use seashells_core::generator::Generator;
use seashells_core::mesh::Mesh;
use seashells_core::presets;
use seashells_core::spec::ShellSpec;
use std::collections::HashMap;

/// The shell of `spec` grown at `resolution` voxels, with the tips (and radii there) of the
/// spines, canal spines and bumps that the model itself shows: the tip is on or inside the
/// surface, painted mostly by the part's own texture (the pattern's share under a half; a
/// bump the opening carved away, or one sunk into the body, is not shown), and its voxel.
fn shell_at(spec: &ShellSpec, resolution: u32) -> (Mesh, Vec<(DVec3, f64)>, f64) {
    let mut spec = spec.clone();
    implicit(&mut spec).resolution = resolution;
    let built = tree_at(&spec, resolution);
    let extent = (built.tree.bounds.max - built.tree.bounds.min).max_element();
    let whole = (built.tree)
        .cull(&built.tree.bounds, built.instances - 1)
        .expect("a shell");
    let shown = (built.fine.tips.into_iter())
        .filter(|&(tip, _)| {
            let probe = whole.probe(tip);
            probe.field >= ISO - 0.02 && probe.paint.tint()[3] < 0.5
        })
        .collect();
    let ((grown, meshing), peak) = peak_of(|| {
        let mut grown = Generator::new(&spec).expect("builds");
        let ((), meshing) = peak_of(|| grown.finish());
        (grown, meshing)
    });
    let mesh = grown.snapshot();
    let bytes = size_of_val(mesh.vertices.as_slice()) + size_of_val(mesh.indices.as_slice());
    let megabytes = |b: usize| b as f64 / 1e6;
    let held = format!(
        "{resolution}³: meshing held {:.1} MB at most, building and meshing {:.1} MB, for a \
         mesh of {:.1} MB",
        megabytes(meshing),
        megabytes(peak),
        megabytes(bytes)
    );
    assert!(meshing as f64 <= 1.3 * bytes as f64, "{held}");
    assert!(resolution > 256 || peak <= 300_000_000, "{held}");
    (mesh, shown, extent / f64::from(resolution))
}

/// The BlobTree of `spec` built for a grid of `resolution` voxels.
fn tree_at(spec: &ShellSpec, resolution: u32) -> Whorl {
    let mut spec = spec.clone();
    implicit(&mut spec).resolution = resolution;
    let (pattern, seed, rows) = (spec.pattern.clone(), spec.seed, spec.growth.rows as usize);
    whorl(implicit(&mut spec), &pattern, seed, rows).expect("builds")
}

/// How many of `tips` stand out of `mesh`: a part stands out where the mesh has a vertex
/// within its radius and a voxel of its tip painted mostly by the part's own texture (the
/// pattern's share under a half), not by the body's.
fn standing_out(mesh: &Mesh, tips: &[(DVec3, f64)], voxel: f64) -> usize {
    let cell = |p: DVec3| (p / voxel).floor().as_i64vec3().to_array();
    let mut own: HashMap<[i64; 3], Vec<DVec3>> = HashMap::new();
    for v in mesh.vertices.iter().filter(|v| v.tint[3] < 0.5) {
        let p = DVec3::from(v.position.map(f64::from));
        own.entry(cell(p)).or_default().push(p);
    }
    (tips.iter())
        .filter(|&&(tip, radius)| {
            let reach = radius + voxel;
            let n = (reach / voxel).ceil() as i64;
            let c = cell(tip);
            (-n..=n).any(|dz| {
                (-n..=n).any(|dy| {
                    (-n..=n).any(|dx| {
                        own.get(&[c[0] + dx, c[1] + dy, c[2] + dz])
                            .is_some_and(|ps| ps.iter().any(|p| (*p - tip).length() <= reach))
                    })
                })
            })
        })
        .count()
}

/// Checks the preset `id` at its own resolution and at 128³ against `finest` voxels.
fn check_preset(id: &str, finest: u32) {
    let spec = presets::preset(id).expect(id).spec.clone();
    let default = implicit(&mut spec.clone()).resolution;
    let model = tree_at(&spec, finest);
    for resolution in [default, 128] {
        let built = tree_at(&spec, resolution);
        assert!(
            built.tree == model.tree && built.fine.tips == model.fine.tips,
            "{id}: the model built for {resolution}³ is the one built for {finest}³"
        );
    }
    // The parts the model shows, judged where the grid is finest.
    let (fine, tips, fine_voxel) = shell_at(&spec, finest);
    let parts = tips.len();
    assert!(
        parts > 50,
        "{id}: {parts} spines and bumps shown by the model"
    );
    let (mesh, _, voxel) = shell_at(&spec, default);
    assert_eq!(
        standing_out(&mesh, &tips, voxel),
        parts,
        "{id} at {default}³: of the parts the model shows, those standing out"
    );
    assert_eq!(
        standing_out(&fine, &tips, fine_voxel),
        parts,
        "{id} at {finest}³: of the parts the model shows, those standing out"
    );
    let volume = signed_volume(&fine);
    let (at_128, _, _) = shell_at(&spec, 128);
    for (resolution, mesh) in [(default, mesh), (128, at_128), (finest, fine)] {
        let what = format!("{id} at {resolution}³");
        assert_closed_and_outward(&mesh, &what);
        let pieces = pieces(&mesh);
        assert_eq!(pieces.len(), 1, "{what}: pieces {pieces:?}");
        let change = signed_volume(&mesh) / volume - 1.0;
        assert!(
            change.abs() <= 0.02,
            "{what}: volume {:+.2} % of {finest}³'s",
            100.0 * change
        );
    }
}

#[test]
fn murex_cabritii_shows_every_part_at_its_resolution_as_at_256_and_is_one_closed_piece() {
    check_preset("murex-cabritii", 256);
}

#[test]
fn murex_pecten_shows_every_part_at_its_resolution_as_at_256_and_is_one_closed_piece() {
    check_preset("murex-pecten", 256);
}

#[test]
fn murex_rd_spines_shows_every_part_at_its_resolution_as_at_256_and_is_one_closed_piece() {
    check_preset("murex-rd-spines", 256);
}

/// The same check against 384³, run by `make bench` (`cargo test … -- --ignored`).
#[test]
#[ignore = "about three minutes: run by make bench"]
fn every_murex_preset_shows_every_part_at_its_resolution_as_at_384_and_is_one_closed_piece() {
    for id in ["murex-cabritii", "murex-pecten", "murex-rd-spines"] {
        check_preset(id, 384);
    }
}
