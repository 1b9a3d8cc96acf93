//! The generator grows mesh and pattern in step, and a pattern that cannot go on stops growth
//! with a message instead of garbage.

use seashells_core::generator::Generator;
use seashells_core::presets::{preset, presets};
use seashells_core::spec::form::Form;
use seashells_core::spec::pattern::Model;

#[test]
fn every_row_the_clock_counts_is_a_row_of_the_pattern() {
    for p in presets()
        .iter()
        .filter(|p| p.spec.pattern.model != Model::None)
    {
        // The clock counts the same rows whatever the grid: an implicit shell meshes on a
        // coarse one here, and its own is tested in murex_resolutions.rs.
        let mut spec = p.spec.clone();
        if let Form::Implicit(i) = &mut spec.form {
            i.resolution = 32;
        }
        let mut g = Generator::new(&spec).unwrap();
        let mut step = 3;
        while !g.is_done() {
            let a = g.advance(step);
            let pattern = g.pattern().unwrap();
            assert_eq!(pattern.rows(), g.rows_done(), "{}", p.id);
            assert_eq!(pattern.rgba().len(), pattern.rows() * pattern.cells() * 4);
            assert_eq!(a.rows.end, g.rows_done());
            step = step % 11 + 1;
        }
        assert_eq!(g.rows_done(), p.spec.growth.rows as usize, "{}", p.id);
        assert!(g.failure().is_none(), "{}: {:?}", p.id, g.failure());
    }
}

#[test]
fn advance_while_stops_when_told_but_grows_at_least_a_row() {
    let mut g = Generator::new(&preset("oliva-porphyria").unwrap().spec).unwrap();
    let a = g.advance_while(50, || false);
    assert_eq!(a.rows, 1..2);
    let mut budget = 5;
    let b = g.advance_while(50, || {
        budget -= 1;
        budget > 0
    });
    assert_eq!(b.rows, 2..7);
}

#[test]
fn a_diverging_pattern_stops_growth_with_a_message() {
    // Unsaturated autocatalysis (κ = 0) against an inhibitor it outruns.
    let mut spec = preset("oliva-porphyria").unwrap().spec.clone();
    if let Model::ActivatorInhibitor(m) = &mut spec.pattern.model {
        m.kappa = 0.0;
        m.rho = 5.0;
    }
    let mut g = Generator::new(&spec).unwrap();
    g.finish();
    let message = g.failure().expect("the pattern must diverge");
    assert!(
        message.contains("row") && (message.contains("κ") || message.contains("ρ")),
        "{message}"
    );
    assert!(g.is_done());
    assert!(g.rows_done() < spec.growth.rows as usize);
    // The shape stops where the pattern stopped, however growth was cut into calls: finished
    // at once, a row a call, seven rows a call (the stop in the middle of one), or a few
    // milliseconds' budget a call. Finished at once, it once grew the whole shape; cut into
    // calls, the shape stopped at the row of the stop, so the page's shell was not the link's.
    let alone = g.mesh_hash();
    for rows in [1, 7] {
        let mut cut = Generator::new(&spec).unwrap();
        while !cut.is_done() {
            cut.advance(rows);
        }
        assert_eq!(cut.mesh_hash(), alone, "{rows} rows a call");
        cut.finish();
        assert_eq!(cut.mesh_hash(), alone, "{rows} rows a call, then finished");
    }
    let mut budgeted = Generator::new(&spec).unwrap();
    let mut reads = 0;
    while !budgeted.is_done() {
        budgeted.advance_while(50, || {
            reads += 1;
            reads % 3 != 0
        });
    }
    assert_eq!(budgeted.mesh_hash(), alone, "budgeted");
}

/// Growing a swept, chambered or branching shell to its end at once takes the room its mesh
/// needs once (`GrowingShape::finish_capacity`), not by doubling as it fills.
#[test]
fn a_shell_grown_to_its_end_at_once_holds_little_more_than_its_mesh() {
    use crate::common::heap::peak_of;
    for id in [
        "turbinate",
        "conus-marmoreus",
        "kawaguchi-horn",
        "kawaguchi-coral",
    ] {
        let spec = preset(id).expect(id).spec.clone();
        let mut generator = Generator::new(&spec).expect(id);
        let ((), peak) = peak_of(|| generator.finish());
        let mesh = generator.mesh();
        let bytes = size_of_val(mesh.vertices.as_slice()) + size_of_val(mesh.indices.as_slice());
        assert!(
            peak as f64 <= 1.25 * bytes as f64 && bytes > 100_000,
            "{id}: finishing held {peak} bytes at most for a mesh of {bytes}"
        );
    }
}
