//! Kawaguchi's ways of looking at a shell, in the core: the line grid each form gives its line
//! drawing falls on the form's own edges (the chambers' and trunks' facets, the sweep's rims),
//! and the link carries the four-view layout without touching the shell.

use seashells_core::generator::Generator;
use seashells_core::mesh::Surface;
use seashells_core::presets::preset;
use seashells_core::share::link::{decode, encode};
use seashells_core::share::presentation::{Layout, Presentation};
use seashells_core::spec::material::Drawing;

/// The grown shape of preset `id`.
fn grown(id: &str) -> Generator {
    let mut generator = Generator::new(&preset(id).expect("preset").spec).expect("builds");
    generator.finish();
    generator
}

fn whole(x: f64) -> bool {
    (x - x.round()).abs() < 1e-4
}

#[test]
fn a_faceted_forms_lines_are_its_facets_edges() {
    // Every vertex of the outer surface of a chamber stack or a branching tube is an apex of a
    // base: its pattern coordinates lie on a line across and on a rim of the grid.
    for id in ["kawaguchi-shell", "kawaguchi-horn", "kawaguchi-coral"] {
        let generator = grown(id);
        let grid = generator.line_grid();
        let outer: Vec<_> = generator
            .snapshot()
            .vertices
            .into_iter()
            .filter(|v| v.surface == Surface::Outer as u8 as f32)
            .collect();
        assert!(!outer.is_empty(), "{id}");
        for v in outer {
            let [x, y] = v.pattern.map(f64::from);
            assert!(whole(x * grid.across), "{id}: x = {x} is between lines");
            assert!(whole(y / grid.rows), "{id}: row {y} is between rims");
        }
    }
}

#[test]
fn a_sweeps_rims_are_some_of_its_own_rims() {
    let generator = grown("turbinate");
    let grid = generator.line_grid();
    let rows: std::collections::BTreeSet<u64> = generator
        .snapshot()
        .vertices
        .iter()
        .map(|v| (f64::from(v.pattern[1]) * 1e3).round() as u64)
        .collect();
    let last = generator.rows() as f64 - 1.0;
    let mut k = 0.0;
    while k * grid.rows <= last {
        let row = ((k * grid.rows) * 1e3).round() as u64;
        assert!(
            rows.range(row.saturating_sub(2)..=row + 2).next().is_some(),
            "no rim of the mesh at row {}",
            k * grid.rows
        );
        k += 1.0;
    }
    assert!(k > 24.0, "a few rims a whorl, not {k} in all");
    assert_eq!(grid.across, 16.0);
}

#[test]
fn the_link_carries_the_four_views_apart_from_the_shell() {
    let plain = decode("v=1&preset=kawaguchi-horn");
    let four = decode("v=1&preset=kawaguchi-horn&view=four");
    assert_eq!(four.presentation.layout, Layout::Four);
    assert_eq!(plain.presentation, Presentation::default());
    assert!(four.problems.is_empty(), "{:?}", four.problems);
    assert_eq!(four.spec, plain.spec, "the layout is not part of the shell");
    let mut link = encode(four.preset, &four.spec);
    assert_eq!(link, "v=1&preset=kawaguchi-horn");
    four.presentation.write(&mut link);
    assert_eq!(link, "v=1&preset=kawaguchi-horn&view=four");
    assert_eq!(decode(&link).presentation, four.presentation);
    let single = decode("v=1&preset=kawaguchi-horn&view=single");
    assert_eq!(single.presentation.layout, Layout::Single);
}

#[test]
fn an_unknown_view_is_named_and_one_view_shown() {
    let decoded = decode("v=1&preset=kawaguchi-horn&view=<b>nine</b>");
    assert_eq!(decoded.presentation.layout, Layout::Single);
    assert_eq!(decoded.problems.len(), 1);
    assert_eq!(decoded.problems[0].key, "view");
    assert!(decoded.problems[0].message.contains("single, four"));
}

#[test]
fn the_line_drawing_is_a_material_field_of_every_shell() {
    let decoded = decode("v=1&preset=murex-cabritii&material.drawing=lines");
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    assert_eq!(decoded.spec.material.drawing, Drawing::Lines);
    assert_eq!(
        encode(decoded.preset, &decoded.spec),
        "v=1&preset=murex-cabritii&material.drawing=lines"
    );
    let wrong = decode("v=1&preset=turbinate&material.drawing=crayon");
    assert_eq!(wrong.spec.material.drawing, Drawing::Shaded);
    assert_eq!(wrong.problems[0].key, "material.drawing");
}
