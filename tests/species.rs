//! Every preset file parses, needs no repair, and grows into a finite mesh; the presets the
//! issues name exist.

use seashells_core::generator::Generator;
use seashells_core::presets::{preset, presets};
use seashells_core::share::repair::repair;

#[test]
fn every_preset_is_valid_and_grows_into_a_finite_mesh() {
    for p in presets() {
        let mut spec = p.spec.clone();
        let problems = repair(&mut spec, &p.spec);
        assert!(problems.is_empty(), "{}: {problems:?}", p.id);
        assert!(!p.name.is_empty() && !p.source.is_empty() && !p.description.is_empty());
        let mut g = Generator::new(&p.spec).unwrap_or_else(|e| panic!("{}: {e}", p.id));
        g.finish();
        let mesh = g.snapshot();
        // The fewest: the knotted nail, 18 faceted trunks of 8 sides.
        assert!(
            mesh.triangle_count() > 500,
            "{}: {}",
            p.id,
            mesh.triangle_count()
        );
        for v in &mesh.vertices {
            assert!(
                v.position.iter().chain(&v.normal).all(|x| x.is_finite()),
                "{}: non-finite vertex",
                p.id
            );
        }
    }
}

#[test]
fn the_shapes_of_the_paper_are_all_there() {
    for id in [
        "turbinate",
        "patelliform",
        "tubular",
        "spherical",
        "diskoid",
        "turreted",
        "fusiform",
        "fusiform-stout",
        "conical",
        "thatcheria-mirabilis",
        "epitonium-scalare",
        "epitonium-scalare-axis-aligned",
        "rapa-rapa",
        "cardium-costatum",
        "turritella-nivea",
        "lattice",
        "spiral-ribs",
    ] {
        assert!(preset(id).is_some(), "missing preset {id}");
    }
}

#[test]
fn figure_2_uses_the_papers_numbers() {
    use seashells_core::spec::form::Form;
    for (id, z0, lambda) in [
        ("turbinate", 1.9, 1.007),
        ("patelliform", 0.0, 1.34),
        ("tubular", 0.0, 1.011),
        ("spherical", 1.5, 1.03),
        ("diskoid", 1.4, 1.014),
    ] {
        let Form::Sweep(s) = &preset(id).unwrap().spec.form else {
            panic!("{id} is not a sweep")
        };
        assert_eq!(
            (s.spiral.z0, s.spiral.lambda_r, s.spiral.lambda_z),
            (z0, lambda, lambda),
            "{id}"
        );
        assert_eq!(s.spiral.delta_theta, 10.0, "{id}");
    }
}

/// The page and the file writer ask `forms::meshed_in_pieces` whether a shell's growth ends in
/// pieces meshed apart; `forms::piece_maker` makes those pieces. The two agree on every form.
#[test]
fn a_form_meshed_in_pieces_is_one_with_a_piece_maker() {
    use seashells_core::forms::{meshed_in_pieces, piece_maker};
    for p in presets() {
        let maker = piece_maker(&p.spec, 2).unwrap_or_else(|e| panic!("{}: {e}", p.id));
        assert_eq!(meshed_in_pieces(&p.spec.form), maker.is_some(), "{}", p.id);
    }
}
