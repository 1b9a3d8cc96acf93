//! `seashells`: the native exporter on the same core as the page.
//!
//!     seashells mesh (--preset ID | --link FRAGMENT) --out FILE.{glb,ply,3mf,obj,stl}
//!                    [--resolution N] [--size MM] [--size-axis x|y|z] [--threads N]
//!     seashells pattern (--preset ID | --link FRAGMENT) --out FILE.{png,csv}
//!                       [--cells N] [--rows N] [--iterations N]
//!     seashells info (LINK | --preset ID | --link FRAGMENT) [--threads N]
//!     seashells presets
//!     seashells bench
//!     seashells help [COMMAND]
//!
//! Exit status 0 when done, 2 when refused (one line on stderr saying why), 1 when the file
//! could not be written.

mod finish;
mod help;
mod info;
mod mesh;
mod options;
mod out;
mod pattern;

use seashells_core::presets::presets;
use std::process::ExitCode;

/// Why a command did not do what was asked.
pub enum Failure {
    /// The input cannot be used (a command, option, preset, link or value, or a shell no file
    /// may hold): exit status 2.
    Refused(String),
    /// The file could not be written: exit status 1.
    Failed(String),
}

impl Failure {
    /// A refusal of how the command was given, with the usage.
    pub fn usage(why: impl std::fmt::Display) -> Self {
        Failure::Refused(format!("{why} ({})", help::USAGE))
    }
}

impl From<String> for Failure {
    fn from(why: String) -> Self {
        Failure::Refused(why)
    }
}

impl From<&str> for Failure {
    fn from(why: &str) -> Self {
        Failure::Refused(why.to_string())
    }
}

/// Prints the benchmark's figures, timed with the native clock: the core's, then the command
/// line's own.
fn bench() -> String {
    let origin = std::time::Instant::now();
    let now = || origin.elapsed().as_secs_f64() * 1000.0;
    let mut figures = seashells_core::bench::run(&now);
    figures.extend(finish::bench(&now));
    format!("native\n{}", seashells_core::bench::report(&figures))
}

fn list() -> String {
    let lines: Vec<String> = presets()
        .iter()
        .map(|p| format!("{:<24} {} ({})", p.id, p.name, p.source))
        .collect();
    lines.join("\n")
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let asks_help = |a: &String| matches!(a.as_str(), "--help" | "-h");
    let printed = |text: String| {
        println!("{text}");
        Ok(())
    };
    let result = match args.first().map(String::as_str) {
        Some("help" | "--help" | "-h") => {
            help::help(args.get(1).map(String::as_str)).and_then(printed)
        }
        Some(command) if args[1..].iter().any(asks_help) => {
            help::help(Some(command)).and_then(printed)
        }
        Some("mesh") => mesh::mesh(&args[1..]),
        Some("pattern") => pattern::pattern(&args[1..]),
        Some("info") => info::info(&args[1..]),
        Some("presets") => printed(list()),
        Some("bench") => printed(bench()),
        Some(other) => Err(Failure::usage(format!("unknown command '{other}'"))),
        None => Err(Failure::Refused(help::USAGE.to_string())),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Refused(why)) => {
            eprintln!("seashells: {why}");
            ExitCode::from(2)
        }
        Err(Failure::Failed(why)) => {
            eprintln!("seashells: {why}");
            ExitCode::from(1)
        }
    }
}
