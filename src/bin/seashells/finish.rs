//! Growing a shell to its end on the command line, on several threads: the pieces an implicit
//! shell's growth leaves to be meshed apart (as the page's workers mesh them) are shared out
//! among threads, each with its own copy of the model built from the same spec, and joined in
//! their fixed order, so that the file is the same bit for bit however many threads made it.

use crate::Failure;
use crate::options::Options;
use seashells_core::bench::{Figure, timed};
use seashells_core::forms::piece_maker;
use seashells_core::generator::Generator;
use seashells_core::mesh::Mesh;
use seashells_core::presets::preset;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::Form;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// Most threads `--threads` may ask for.
const MOST_THREADS: usize = 64;

/// Most threads used unless `--threads` asks for more: each holds its own copy of the model,
/// and the page's pool stops at as many workers.
const MOST_BY_DEFAULT: usize = 8;

/// The threads `--threads` asks for, else as many as the machine runs at once, at most
/// [`MOST_BY_DEFAULT`].
pub fn threads(options: &Options) -> Result<usize, Failure> {
    match options.get("threads") {
        None => Ok(std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(MOST_BY_DEFAULT)),
        Some(text) => match text.parse::<usize>() {
            Ok(n @ 1..=MOST_THREADS) => Ok(n),
            _ => Err(format!(
                "--threads takes a whole number from 1 to {MOST_THREADS}, not '{text}'"
            )
            .into()),
        },
    }
}

/// The shell of `spec` grown to its end, its last pieces meshed on `threads` threads.
pub fn grown(spec: &ShellSpec, threads: usize) -> Result<Generator, Failure> {
    let mut generator = Generator::new(spec).map_err(|e| e.to_string())?;
    if threads <= 1 {
        generator.finish();
        return Ok(generator);
    }
    let Some(pieces) = generator.finish_apart() else {
        return Ok(generator);
    };
    let groups = &pieces.groups;
    let made: Vec<Mutex<Mesh>> = groups.iter().map(|_| Mutex::default()).collect();
    let next = AtomicUsize::new(0);
    let rows = generator.rows();
    // Each thread builds its own model (its tree is not shared between threads) and takes the
    // next group not yet taken until none is left, as the page's workers take them.
    let work = || -> Result<(), String> {
        let maker = piece_maker(spec, rows)
            .map_err(|e| e.to_string())?
            .ok_or("this shell's growth leaves no pieces to mesh apart")?;
        loop {
            let index = next.fetch_add(1, Ordering::Relaxed);
            let Some(ids) = groups.get(index) else {
                return Ok(());
            };
            let mut work = maker.start(pieces.step, ids);
            maker.work(&mut work, &mut || true);
            *made[index].lock().unwrap_or_else(PoisonError::into_inner) = maker.finished(work);
        }
    };
    // A thread that panicked is a bug: its panic goes on as it would on one thread.
    let results: Vec<Result<(), String>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads.min(groups.len()))
            .map(|_| scope.spawn(work))
            .collect();
        (handles.into_iter())
            .map(|handle| {
                handle
                    .join()
                    .unwrap_or_else(|e| std::panic::resume_unwind(e))
            })
            .collect()
    });
    if let Some(why) = results.into_iter().find_map(Result::err) {
        return Err(Failure::Failed(format!(
            "the shell could not be meshed on {threads} threads: {why}"
        )));
    }
    let made = (made.into_iter())
        .map(|m| m.into_inner().unwrap_or_else(PoisonError::into_inner))
        .collect();
    generator.join_apart(made);
    Ok(generator)
}

/// The preset and the resolution [`bench`] finishes.
const BENCHED: (&str, u32) = ("murex-cabritii", 256);

/// The time to grow the Murex at 256³ to its end (building it, growing its first step and
/// meshing the rest) on one thread and on two, and how many times quicker two are.
pub fn bench(now: &dyn Fn() -> f64) -> Vec<Figure> {
    let (id, resolution) = BENCHED;
    let Some(preset) = preset(id) else {
        return Vec::new();
    };
    let mut spec = preset.spec.clone();
    if let Form::Implicit(implicit) = &mut spec.form {
        implicit.resolution = resolution;
    }
    let on = |threads: usize| {
        timed(now, || {
            std::hint::black_box(grown(&spec, threads).is_ok());
        })
    };
    let (one, two) = (on(1), on(2));
    let figure = |threads: usize, (ms, spread): (f64, f64)| Figure {
        what: format!(
            "{id} grown whole at {resolution}³ by the command line on {threads} thread{}",
            if threads == 1 { "" } else { "s" }
        ),
        value: ms,
        unit: "ms",
        spread: Some(spread),
    };
    vec![
        figure(1, one),
        figure(2, two),
        Figure {
            what: format!("{id} grown whole at {resolution}³: 2 threads against 1"),
            value: one.0 / two.0,
            unit: "×",
            spread: None,
        },
    ]
}
