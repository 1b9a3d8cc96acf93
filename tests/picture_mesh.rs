//! A picture's mesh (a gallery card's, a parameter map's tile) is no finer than the picture
//! shows: some of the rims of the full mesh (with as many points a rim), the same closed solid,
//! the same pattern as the shell's own, and whole wherever its growth stops.

use crate::common;
use seashells_core::generator::Generator;
use seashells_core::mesh::Mesh;
use seashells_core::presets::{preset, presets};
use seashells_core::spec::form::Form;
use seashells_core::view::picture::{CARD_PIXELS, TILE_PIXELS, picture_spec};
use std::collections::HashSet;

fn grown(mut generator: Generator) -> Generator {
    generator.finish();
    generator
}

/// The positions of `mesh`'s vertices, bit for bit.
fn positions(mesh: &Mesh) -> HashSet<[u32; 3]> {
    (mesh.vertices.iter())
        .map(|v| v.position.map(f32::to_bits))
        .collect()
}

/// Points per rim of a swept shell's mesh: its first rim's outer points.
fn points_per_rim(mesh: &Mesh) -> u32 {
    mesh.vertices.iter().take_while(|v| v.is_outer()).count() as u32 - 1
}

#[test]
fn a_picture_keeps_the_full_mesh_s_points_its_solid_and_its_pattern() {
    for p in presets() {
        if !matches!(p.spec.form, Form::Sweep(_)) {
            continue;
        }
        for pixels in [TILE_PIXELS, CARD_PIXELS] {
            let what = format!("{} at {pixels} pixels", p.id);
            let spec = picture_spec(&p.spec, pixels);
            let picture = grown(Generator::picture(&spec, pixels).unwrap());
            let mut same_points = spec.clone();
            if let Form::Sweep(s) = &mut same_points.form {
                s.curve.segments = points_per_rim(picture.mesh());
            }
            let full = grown(Generator::new(&same_points).unwrap());
            let (picture_mesh, full_mesh) = (picture.snapshot(), full.snapshot());
            let kept = positions(&full_mesh);
            assert!(
                positions(&picture_mesh).is_subset(&kept),
                "{what}: every point of the picture is one of the full mesh's"
            );
            assert!(picture_mesh.triangle_count() <= full_mesh.triangle_count());
            if matches!(&spec.form, Form::Sweep(s) if s.wall.thickness > 0.0) {
                common::assert_closed_and_outward(&picture_mesh, &what);
            }
            let own = grown(Generator::new(&spec).unwrap());
            assert_eq!(
                picture.pattern().map(|p| p.rgba()),
                own.pattern().map(|p| p.rgba()),
                "{what}: the shell's own pattern"
            );
        }
    }
}

#[test]
fn a_picture_stopped_part_way_is_closed_up_to_where_it_stopped() {
    let spec = picture_spec(&preset("turbinate").unwrap().spec, TILE_PIXELS);
    let rows = spec.growth.rows as usize;
    for stop in [rows / 7, rows / 2, rows - 3] {
        let mut picture = Generator::picture(&spec, TILE_PIXELS).unwrap();
        picture.advance(stop);
        let mut full = Generator::new(&spec).unwrap();
        full.advance(stop);
        let what = format!("turbinate's tile at row {}", picture.rows_done());
        let reach = |g: &Generator| {
            (g.snapshot().vertices.iter())
                .map(|v| v.pattern[1])
                .fold(f32::MIN, f32::max)
        };
        assert_eq!(
            reach(&picture),
            reach(&full),
            "{what}: as far as the full mesh"
        );
        let (_, room) = picture.capacity();
        assert!(
            picture.edge().vertices.len() <= room.vertices
                && picture.edge().indices.len() <= room.indices,
            "{what}: the edge within the room it asks for"
        );
        common::assert_closed_and_outward(&picture.snapshot(), &what);
    }
}

#[test]
fn the_turbinate_s_tile_has_under_a_quarter_of_the_triangles() {
    let spec = picture_spec(&preset("turbinate").unwrap().spec, TILE_PIXELS);
    let full = grown(Generator::new(&spec).unwrap()).snapshot();
    let picture = grown(Generator::picture(&spec, TILE_PIXELS).unwrap()).snapshot();
    let (full, picture) = (full.triangle_count(), picture.triangle_count());
    assert!(picture * 4 <= full, "{full} → {picture} triangles");
}
