//! `seashells mesh`: the grown shell's mesh as a file.

use crate::Failure;
use crate::finish::{grown, threads};
use crate::options::{Options, WRITES};
use crate::out::Out;
use seashells_core::export::MeshFormat;
use seashells_core::export::job::Export;
use seashells_core::export::print_size::{Along, PrintSize};
use seashells_core::export::shell::Shell;
use seashells_core::spec::form::Form;

/// The format `--format` names, else the one of the file's extension.
pub fn format(options: &Options, out: &Out) -> Result<MeshFormat, Failure> {
    match (options.get("format"), out.name()) {
        (Some(ext), _) => Ok(MeshFormat::from_path(&format!(".{ext}"))
            .map_err(|_| format!("--format takes glb, ply, 3mf, obj or stl, not '{ext}'"))?),
        (None, "-") => Err(Failure::usage(
            "--out - needs --format glb, ply, 3mf, obj or stl",
        )),
        (None, path) => Ok(MeshFormat::from_path(path)?),
    }
}

/// The size `--size` and `--size-axis` ask for.
fn size(options: &Options, format: MeshFormat) -> Result<PrintSize, Failure> {
    if !format.sized() && (options.get("size").is_some() || options.get("size-axis").is_some()) {
        return Err("--size and --size-axis apply to .glb and .3mf files only".into());
    }
    let size = match options.get("size") {
        None => PrintSize::default(),
        Some(text) => {
            let mm = text
                .parse()
                .map_err(|_| format!("--size takes a length in millimetres, not '{text}'"))?;
            PrintSize::new(mm, "--size").map_err(|e| e.to_string())?
        }
    };
    match options.get("size-axis") {
        None => Ok(size),
        Some(name) => Along::axis(name)
            .map(|along| size.along(along))
            .ok_or_else(|| format!("--size-axis takes x, y or z, not '{name}'").into()),
    }
}

pub fn mesh(args: &[String]) -> Result<(), Failure> {
    let options = Options::parse(
        args,
        &[WRITES, &["resolution", "size", "size-axis", "threads"]].concat(),
        false,
    )?;
    let out = Out::new(options.required("out")?);
    let format = format(&options, &out)?;
    let (preset, mut spec) = options.preset_and_spec()?;
    let key = match spec.form {
        Form::Branching(_) => "form.pixels",
        _ => "form.resolution",
    };
    if let Some(n) = options.count("resolution", &spec, key)? {
        match &mut spec.form {
            Form::Implicit(implicit) => implicit.resolution = n,
            Form::Branching(branching) => branching.pixels = n,
            _ => {
                return Err(
                    "--resolution applies to implicit shells and branching forms only".into(),
                );
            }
        }
    }
    let size = size(&options, format)?;
    let generator = grown(&spec, threads(&options)?)?;
    let shell = Shell::new(&generator, &spec, preset, size).map_err(|e| e.to_string())?;
    let (vertices, triangles, hash) = (
        shell.mesh.vertices.len(),
        shell.mesh.triangle_count(),
        shell.mesh.content_hash(),
    );
    // The counts and hash are the grown mesh's (as the page shows them); the file leaves out
    // the triangles of no area, and says how many.
    let left_out = match (0..triangles).filter(|&t| shell.mesh.collapsed(t)).count() {
        0 => String::new(),
        n => format!(" ({n} of no area left out of the file)"),
    };
    let bytes = Export::new(format, shell)
        .and_then(Export::run)
        .map_err(|e| e.to_string())?;
    out.write(&bytes)?;
    out.report(&format!(
        "wrote {}: {vertices} vertices, {triangles} triangles{left_out}, hash {hash:016x}, {} bytes",
        out.name(),
        bytes.len()
    ));
    Ok(())
}
