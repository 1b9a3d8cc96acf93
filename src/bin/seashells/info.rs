//! `seashells info`: what a link's shell is, and what files it makes.

use crate::Failure;
use crate::finish::{grown, threads};
use crate::options::Options;
use seashells_core::export::MeshFormat;
use seashells_core::export::job::Export;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::Shell;
use seashells_core::share::link;

pub fn info(args: &[String]) -> Result<(), Failure> {
    let options = Options::parse(args, &["preset", "link", "threads"], true)?;
    let (preset, spec) = options.preset_and_spec()?;
    let generator = grown(&spec, threads(&options)?)?;
    let mesh = generator.snapshot();
    let mut lines = vec![
        format!(
            "shell: {} ({}), {} form",
            preset.id,
            preset.name,
            spec.form.kind()
        ),
        format!("link: {}", link::encode(preset, &spec)),
        format!(
            "mesh: {} vertices, {} triangles, hash {:016x}",
            mesh.vertices.len(),
            mesh.triangle_count(),
            mesh.content_hash()
        ),
    ];
    if let Some(pattern) = generator.pattern() {
        lines.push(format!(
            "pattern: {} cells × {} rows, hash {:016x}",
            pattern.cells(),
            pattern.rows(),
            pattern.hash()
        ));
    }
    let shell = || Shell::new(&generator, &spec, preset, PrintSize::default());
    match shell() {
        Err(refused) => lines.push(format!("files: none, {refused}")),
        Ok(first) => {
            let sides = first.printed_sides();
            lines.push(format!(
                "size: {:.1} × {:.1} × {:.1} mm (x across, y front to back, z up) at --size {}",
                sides.x,
                sides.y,
                sides.z,
                PrintSize::DEFAULT_MM
            ));
            lines.push("files:".into());
            for format in MeshFormat::ALL {
                let name = format!("{}.{}", preset.id, format.extension());
                let written = shell()
                    .and_then(|s| Export::new(format, s))
                    .and_then(Export::run);
                lines.push(match written {
                    Ok(bytes) => format!("  {name:<28} {} bytes", bytes.len()),
                    Err(refused) => format!("  {name:<28} refused: {refused}"),
                });
            }
        }
    }
    println!("{}", lines.join("\n"));
    Ok(())
}
