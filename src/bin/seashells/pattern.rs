//! `seashells pattern`: the pigmentation pattern's planar representation as a file.

use crate::Failure;
use crate::options::{Options, WRITES};
use crate::out::Out;
use seashells_core::export;
use seashells_core::generator::{RimLengths, pattern_alone};
use seashells_core::share::repair::repair;

pub fn pattern(args: &[String]) -> Result<(), Failure> {
    let options = Options::parse(
        args,
        &[WRITES, &["cells", "rows", "iterations"]].concat(),
        false,
    )?;
    let out = Out::new(options.required("out")?);
    let name = match options.get("format") {
        Some(ext) => format!(".{ext}"),
        None if out.name() == "-" => {
            return Err(Failure::usage("--out - needs --format png or csv"));
        }
        None => out.name().to_string(),
    };
    let csv = match name
        .rsplit_once('.')
        .map(|(_, e)| e.to_ascii_lowercase())
        .as_deref()
    {
        Some("png") => false,
        Some("csv") => true,
        _ => return Err(format!("'{name}' should end in .png or .csv").into()),
    };
    let (_, mut spec) = options.preset_and_spec()?;
    let base = spec.clone();
    if let Some(n) = options.count("cells", &spec, "pattern.cells")? {
        spec.pattern.cells = n;
    }
    if let Some(n) = options.count("rows", &spec, "growth.rows")? {
        spec.growth.rows = n;
    }
    if let Some(n) = options.count("iterations", &spec, "pattern.iterations")? {
        spec.pattern.iterations = n;
    }
    let problems = repair(&mut spec, &base);
    if let Some(p) = problems.first() {
        return Err(p.to_string().into());
    }
    let mut run = pattern_alone(&spec, &mut RimLengths::default())
        .map_err(|e| e.to_string())?
        .ok_or("this shell has no pattern model")?;
    let mut text = String::new();
    if csv {
        export::csv::write_row(&mut text, run.recorded());
    }
    while run.rows() < spec.growth.rows as usize {
        run.advance()
            .map_err(|e| format!("the pattern stopped {e}"))?;
        if csv {
            export::csv::write_row(&mut text, run.recorded());
        }
    }
    let bytes = if csv {
        text.into_bytes()
    } else {
        export::png::encode(run.cells(), run.rows(), &run.planar())
    };
    out.write(&bytes)?;
    out.report(&format!(
        "wrote {}: {} cells × {} rows, hash {:016x}",
        out.name(),
        run.cells(),
        run.rows(),
        run.hash()
    ));
    Ok(())
}
