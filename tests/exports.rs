//! Exports written in resumable steps: for a preset of each form and every format, the file
//! written a step at a time (as the page writes it, a frame's budget at a time) is the file
//! written at once, with progress rising from 0 to 1; a large shell takes many steps; an
//! empty, collapsed, failed or open shell, and a size out of bounds, get messages naming what
//! to change instead of a file. What the files hold is read back by third-party tools in
//! tests/files/.

use glam::DVec3;
use seashells_core::export::error::ExportError;
use seashells_core::export::estimate::{Counts, Size};
use seashells_core::export::job::Export;
use seashells_core::export::paint::Paint;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::{Grown, Shell};
use seashells_core::export::{Download, MeshFormat};
use seashells_core::generator::Generator;
use seashells_core::mesh::{Mesh, Surface, Vertex};
use seashells_core::presets::preset;
use seashells_core::share::link;

/// The shell of a link grown to its end, and what an export makes of it.
fn grown(fragment: &str) -> (Generator, Result<Shell, ExportError>) {
    let decoded = link::decode(fragment);
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    let mut generator = Generator::new(&decoded.spec).unwrap();
    generator.finish();
    let shell = Shell::new(
        &generator,
        &decoded.spec,
        decoded.preset,
        PrintSize::default(),
    );
    (generator, shell)
}

fn shell(fragment: &str) -> Shell {
    grown(fragment).1.unwrap()
}

/// Writes `shell` one step per call, checking that progress rises; returns the file and the
/// number of steps.
fn stepped(format: MeshFormat, shell: Shell) -> (Vec<u8>, usize) {
    let mut export = Export::new(format, shell).unwrap();
    let (mut steps, mut last) = (0, 0.0);
    loop {
        steps += 1;
        if let Some(bytes) = export.work(|| false).unwrap() {
            return (bytes, steps);
        }
        let progress = export.progress();
        assert!(
            (last..=1.0).contains(&progress),
            "{format:?}: progress {last} then {progress}"
        );
        last = progress;
    }
}

#[test]
fn every_format_written_step_by_step_is_the_file_written_at_once() {
    for id in [
        "oliva-porphyria",
        "kawaguchi-painted",
        "kawaguchi-coral",
        "implicit-whorl",
    ] {
        let fragment = format!("v=1&preset={id}");
        for format in MeshFormat::ALL {
            let whole = Export::new(format, shell(&fragment))
                .and_then(Export::run)
                .unwrap();
            let (bytes, steps) = stepped(format, shell(&fragment));
            assert!(
                bytes == whole,
                "{id} {format:?}: the steps wrote another file"
            );
            assert!(steps >= 4, "{id} {format:?}: {steps} steps");
        }
    }
}

#[test]
fn the_murex_at_its_own_resolution_is_written_over_many_steps() {
    for format in [MeshFormat::Glb, MeshFormat::ThreeMf] {
        let (bytes, steps) = stepped(format, shell("v=1&preset=murex-cabritii"));
        assert!(steps > 100, "{format:?}: {steps} steps");
        assert!(bytes.len() > 1_000_000);
    }
}

#[test]
fn a_failed_shell_is_refused_with_why_it_stopped() {
    let fragment = "v=1&preset=oliva-porphyria&pattern.model.kappa=0&pattern.model.rho=5";
    let (_, refused) = grown(fragment);
    let Err(e @ ExportError::Failed(_)) = refused else {
        panic!("a failed shell was exported");
    };
    let message = e.to_string();
    assert!(
        message.contains("stopped growing") && message.contains("κ"),
        "{message}"
    );
}

#[test]
fn an_empty_or_collapsed_shell_is_refused_in_every_format() {
    let spec = &preset("turbinate").unwrap().spec;
    let with = |mesh: Mesh| Shell {
        mesh,
        paint: Paint::new(&spec.colours, None),
        roughness: 0.5,
        facing: 0.0,
        title: "nothing".into(),
        size: PrintSize::default(),
    };
    let mut collapsed = Mesh::default();
    for x in [0.0, 1.0, 1.0] {
        collapsed.vertices.push(Vertex::new(
            DVec3::new(x, 0.0, 0.0),
            DVec3::Z,
            [0.0, 0.0],
            Surface::Outer,
        ));
    }
    collapsed.triangle([0, 1, 2], false);
    for format in MeshFormat::ALL {
        assert_eq!(
            Export::new(format, with(Mesh::default())).err(),
            Some(ExportError::Empty),
            "{format:?}"
        );
        let e = Export::new(format, with(collapsed.clone()))
            .and_then(Export::run)
            .unwrap_err();
        assert_eq!(e, ExportError::Empty, "{format:?}");
        assert!(e.to_string().contains("nothing to export"));
    }
}

#[test]
fn a_shell_grown_out_of_the_range_of_numbers_is_refused_not_written() {
    // No link within the panel's ranges grows out of the range of numbers any more (the
    // forms' growth checks refuse it: tests/any_link.rs); the gate every export passes still
    // refuses a mesh that did.
    let preset = preset("turbinate").unwrap();
    let mut mesh = Mesh::default();
    for p in [DVec3::ZERO, DVec3::X, DVec3::new(f64::NAN, 0.0, 1.0)] {
        mesh.vertices
            .push(Vertex::new(p, DVec3::Z, [0.0, 0.0], Surface::Outer));
    }
    mesh.triangle([0, 1, 2], false);
    let grown = Grown {
        mesh,
        failure: None,
        front: DVec3::X,
        pattern: None,
    };
    let Err(e) = Shell::of(grown, &preset.spec, preset, PrintSize::default()) else {
        panic!("a mesh with coordinates that are not finite was accepted for export");
    };
    assert_eq!(e, ExportError::NotFinite);
    assert!(e.to_string().contains("not finite"), "{e}");
}

#[test]
fn the_stl_holds_every_triangle_but_those_of_no_area() {
    let mut mesh = Mesh::default();
    for (x, y) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 0.0)] {
        mesh.vertices.push(Vertex::new(
            DVec3::new(x, y, 0.0),
            DVec3::Z,
            [0.0, 0.0],
            Surface::Outer,
        ));
    }
    mesh.triangle([0, 1, 2], false);
    mesh.triangle([0, 1, 3], false);
    let collapsed: Vec<bool> = (0..2).map(|t| mesh.collapsed(t)).collect();
    assert_eq!(collapsed, [false, true], "corners 1 and 3 share a position");
    let stl = seashells_core::export::stl::write(&mesh).unwrap();
    let written = u32::from_le_bytes(stl[80..84].try_into().unwrap());
    assert_eq!(written, 1);
    assert_eq!(stl.len(), 84 + 50);
}

#[test]
fn a_surface_without_a_wall_is_refused_as_3mf_and_exported_as_glb() {
    let fragment = "v=1&preset=turbinate&form.wall.thickness=0";
    let e = Export::new(MeshFormat::ThreeMf, shell(fragment))
        .and_then(Export::run)
        .unwrap_err();
    assert!(
        matches!(
            e,
            ExportError::Open {
                key: "form.wall.thickness"
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("form.wall.thickness"), "{e}");
    assert!(
        Export::new(MeshFormat::Glb, shell(fragment))
            .and_then(Export::run)
            .is_ok()
    );
}

#[test]
fn the_sizes_shown_before_export_are_within_half_again_of_the_files() {
    for id in [
        "oliva-porphyria",
        "turbinate",
        "kawaguchi-painted",
        "kawaguchi-coral",
        "implicit-whorl",
        "murex-cabritii",
    ] {
        let (generator, _) = grown(&format!("v=1&preset={id}"));
        let counts = Counts {
            vertices: generator.mesh().vertices.len() + generator.edge().vertices.len(),
            triangles: generator.mesh().triangle_count() + generator.edge().triangle_count(),
            pattern: generator.pattern().map(|p| (p.cells(), p.rows())),
            picture: (800, 600),
        };
        for format in MeshFormat::ALL {
            let file = Export::new(format, shell(&format!("v=1&preset={id}")))
                .and_then(Export::run)
                .unwrap()
                .len() as f64;
            let Some(Size::Bytes(estimate)) = Download::Mesh(format).estimate(&counts) else {
                panic!("no estimate of {format:?}");
            };
            let ratio = estimate as f64 / file;
            println!("{id} {format:?}: {estimate} for {file} ({ratio:.2})");
            assert!(
                (1.0 / 1.5..1.5).contains(&ratio),
                "{id} {format:?}: {estimate} for {file}"
            );
        }
        assert_eq!(
            Download::Pattern.estimate(&counts),
            counts.pattern.map(|(w, h)| Size::Pixels(w, h))
        );
        assert_eq!(
            Download::Picture.estimate(&counts),
            Some(Size::Pixels(800, 600))
        );
    }
}
