//! `seashells`: the native exporter on the same core as the page.
//!
//!     seashells mesh (--preset ID | --link FRAGMENT) --out FILE.{glb,ply,3mf,obj,stl}
//!                    [--resolution N] [--size MM]
//!     seashells pattern (--preset ID | --link FRAGMENT) --out FILE.{png,csv}
//!                       [--cells N] [--rows N] [--iterations N]
//!     seashells presets
//!     seashells bench
//!     seashells help [COMMAND]
//!
//! A wrong preset, link, option or extension gets one line on stderr and exit status 2.

use seashells_core::export::job::Export;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::Shell;
use seashells_core::export::{self, MeshFormat};
use seashells_core::generator::Generator;
use seashells_core::pattern::run::PatternRun;
use seashells_core::presets::{self, Preset, presets};
use seashells_core::share::link;
use seashells_core::share::repair::repair;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::fields::{self, Kind};
use seashells_core::spec::form::Form;
use std::collections::BTreeMap;
use std::process::ExitCode;

const USAGE: &str = "usage: seashells mesh (--preset ID | --link FRAGMENT) --out FILE.{glb,ply,3mf,obj,stl} [--resolution N] [--size MM] | \
seashells pattern (--preset ID | --link FRAGMENT) --out FILE.{png,csv} [--cells N] [--rows N] [--iterations N] | \
seashells presets | seashells bench | seashells help [COMMAND]";

/// Options given as `--name value`.
struct Options(BTreeMap<String, String>);

impl Options {
    fn parse(args: &[String], allowed: &[&str]) -> Result<Self, String> {
        let mut map = BTreeMap::new();
        let mut it = args.iter();
        while let Some(arg) = it.next() {
            let name = arg
                .strip_prefix("--")
                .filter(|n| allowed.contains(n))
                .ok_or_else(|| format!("unexpected '{arg}' ({USAGE})"))?;
            let value = it.next().ok_or_else(|| format!("--{name} needs a value"))?;
            if map.insert(name.to_string(), value.clone()).is_some() {
                return Err(format!("--{name} is given twice"));
            }
        }
        Ok(Self(map))
    }

    fn get(&self, name: &str) -> Option<&str> {
        self.0.get(name).map(String::as_str)
    }

    fn required(&self, name: &str) -> Result<&str, String> {
        self.get(name)
            .ok_or_else(|| format!("--{name} is missing ({USAGE})"))
    }

    /// The spec named by --preset or --link (exactly one of them).
    fn spec(&self) -> Result<ShellSpec, String> {
        self.preset_and_spec().map(|(_, spec)| spec)
    }

    /// The preset and the spec named by --preset or --link (exactly one of them).
    fn preset_and_spec(&self) -> Result<(&'static Preset, ShellSpec), String> {
        match (self.get("preset"), self.get("link")) {
            (Some(id), None) => presets::preset(id)
                .map(|p| (p, p.spec.clone()))
                .ok_or_else(|| {
                    let ids: Vec<&str> = presets().iter().map(|p| p.id).collect();
                    format!("there is no preset '{id}' (presets: {})", ids.join(", "))
                }),
            (None, Some(fragment)) => {
                let decoded = link::decode(fragment);
                if decoded.problems.is_empty() {
                    Ok((decoded.preset, decoded.spec))
                } else {
                    let problems: Vec<String> =
                        decoded.problems.iter().map(ToString::to_string).collect();
                    Err(format!(
                        "the link cannot be used as given: {}",
                        problems.join("; ")
                    ))
                }
            }
            _ => Err(format!("give exactly one of --preset and --link ({USAGE})")),
        }
    }
}

fn grown(spec: &ShellSpec) -> Result<Generator, String> {
    let mut generator = Generator::new(spec).map_err(|e| e.to_string())?;
    generator.finish();
    Ok(generator)
}

fn write(path: &str, bytes: &[u8]) -> Result<(), String> {
    std::fs::write(path, bytes).map_err(|e| format!("cannot write '{path}': {e}"))
}

fn mesh(args: &[String]) -> Result<String, String> {
    let options = Options::parse(args, &["preset", "link", "out", "resolution", "size"])?;
    let out = options.required("out")?;
    let format = MeshFormat::from_path(out)?;
    let (preset, mut spec) = options.preset_and_spec()?;
    if let Some(n) = count(&options, "resolution", &spec, "form.resolution")? {
        let Form::Implicit(implicit) = &mut spec.form else {
            return Err("--resolution applies to implicit shells only".into());
        };
        implicit.resolution = n;
    }
    let size = match options.get("size") {
        None => PrintSize::default(),
        Some(_) if !format.sized() => {
            return Err("--size applies to .glb and .3mf files only".into());
        }
        Some(text) => {
            let mm = text
                .parse()
                .map_err(|_| format!("--size takes a height in millimetres, not '{text}'"))?;
            PrintSize::new(mm, "--size").map_err(|e| e.to_string())?
        }
    };
    let generator = grown(&spec)?;
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
    write(out, &bytes)?;
    Ok(format!(
        "wrote {out}: {vertices} vertices, {triangles} triangles{left_out}, hash {hash:016x}, {} bytes",
        bytes.len()
    ))
}

/// A whole number option, within the range `spec` allows for its key.
fn count(
    options: &Options,
    name: &str,
    spec: &ShellSpec,
    key: &str,
) -> Result<Option<u32>, String> {
    let Some(text) = options.get(name) else {
        return Ok(None);
    };
    let n: u32 = text
        .parse()
        .map_err(|_| format!("--{name} takes a whole number, not '{text}'"))?;
    match fields::field(spec.form.kind(), key).map(|f| f.kind) {
        Some(Kind::Integer { min, max }) if !(min..=max).contains(&u64::from(n)) => {
            Err(format!("--{name} must be between {min} and {max}, not {n}"))
        }
        _ => Ok(Some(n)),
    }
}

fn pattern(args: &[String]) -> Result<String, String> {
    let options = Options::parse(
        args,
        &["preset", "link", "out", "cells", "rows", "iterations"],
    )?;
    let out = options.required("out")?;
    let csv = match out
        .rsplit_once('.')
        .map(|(_, e)| e.to_ascii_lowercase())
        .as_deref()
    {
        Some("png") => false,
        Some("csv") => true,
        _ => return Err(format!("'{out}' should end in .png or .csv")),
    };
    let mut spec = options.spec()?;
    let base = spec.clone();
    if let Some(n) = count(&options, "cells", &spec, "pattern.cells")? {
        spec.pattern.cells = n;
    }
    if let Some(n) = count(&options, "rows", &spec, "growth.rows")? {
        spec.growth.rows = n;
    }
    if let Some(n) = count(&options, "iterations", &spec, "pattern.iterations")? {
        spec.pattern.iterations = n;
    }
    let problems = repair(&mut spec, &base);
    if let Some(p) = problems.first() {
        return Err(p.to_string());
    }
    let mut run = PatternRun::new(&spec)
        .map_err(|e| format!("the pattern cannot be computed: {e}"))?
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
        export::png::encode(run.cells(), run.rows(), run.rgba())
    };
    write(out, &bytes)?;
    Ok(format!(
        "wrote {out}: {} cells × {} rows, hash {:016x}",
        run.cells(),
        run.rows(),
        run.hash()
    ))
}

/// Prints the benchmark's figures, timed with the native clock.
fn bench() -> String {
    let origin = std::time::Instant::now();
    let now = || origin.elapsed().as_secs_f64() * 1000.0;
    format!(
        "native\n{}",
        seashells_core::bench::report(&seashells_core::bench::run(&now))
    )
}

fn list() -> String {
    let lines: Vec<String> = presets()
        .iter()
        .map(|p| format!("{:<24} {} ({})", p.id, p.name, p.source))
        .collect();
    lines.join("\n")
}

/// What `seashells help` prints.
const HELP: &str = "seashells: the shells of the page's gallery and links, written as files by the same core

usage:
  seashells mesh (--preset ID | --link FRAGMENT) --out FILE.{glb,ply,3mf,obj,stl} [--resolution N] [--size MM]
  seashells pattern (--preset ID | --link FRAGMENT) --out FILE.{png,csv} [--cells N] [--rows N] [--iterations N]
  seashells presets       lists every preset's ID and name
  seashells bench         times growth, patterns and meshing natively
  seashells help [COMMAND]

A FRAGMENT is the part of a page's link after '#', as in 'v=1&preset=turbinate&form.spiral.whorls=5'.
Exit status: 0 when done; 2 when refused or failed, with one line on standard error saying why.";

/// What `seashells help mesh` prints.
const HELP_MESH: &str =
    "seashells mesh (--preset ID | --link FRAGMENT) --out FILE [--resolution N] [--size MM]

Grows the shell to its end and writes its mesh in the format of FILE's extension: .glb (glTF
binary, with its pattern as a texture), .ply and .3mf (colour per vertex), .obj, .stl. Prints the
mesh's vertex and triangle counts and hash (as the page shows them) and the file's bytes.
  --resolution N   the polygonization grid of an implicit shell (the Murex), N³ voxels
  --size MM        the height of a .glb or .3mf shell in millimetres, 5 to 500 (80 unless given)
A shell whose growth stopped, one whose values take it out of the range of numbers, or a wall-less
surface as .3mf is refused, and no file is written.";

/// What `seashells help pattern` prints.
const HELP_PATTERN: &str = "seashells pattern (--preset ID | --link FRAGMENT) --out FILE [--cells N] [--rows N] [--iterations N]

Computes the shell's pigmentation pattern on its growing edge and writes its planar
representation: .png (the colours, a row per time step) or .csv (the recorded value, the
activator's concentration, a line per row and a value per cell).
  --cells N, --rows N, --iterations N   override the spec's cells, rows and iterations per row";

/// The help on `topic` (a command, or everything).
fn help(topic: Option<&str>) -> Result<String, String> {
    match topic {
        None => Ok(HELP.into()),
        Some("mesh") => Ok(HELP_MESH.into()),
        Some("pattern") => Ok(HELP_PATTERN.into()),
        Some("presets" | "bench" | "help") => Ok(HELP.into()),
        Some(other) => Err(format!("there is no command '{other}' ({USAGE})")),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let asks_help = |a: &String| matches!(a.as_str(), "--help" | "-h");
    let result = match args.first().map(String::as_str) {
        Some("help" | "--help" | "-h") => help(args.get(1).map(String::as_str)),
        Some(command) if args[1..].iter().any(asks_help) => help(Some(command)),
        Some("mesh") => mesh(&args[1..]),
        Some("pattern") => pattern(&args[1..]),
        Some("presets") => Ok(list()),
        Some("bench") => Ok(bench()),
        Some(other) => Err(format!("unknown command '{other}' ({USAGE})")),
        None => Err(USAGE.to_string()),
    };
    match result {
        Ok(report) => {
            println!("{report}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("seashells: {message}");
            ExitCode::from(2)
        }
    }
}
