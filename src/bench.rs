//! The benchmark (figures, not a test): cell updates per second of each pattern model (and
//! two whole patterns on a fixed and on a growing edge), the
//! time of one animation frame's growth for each species at its default speed, and the
//! implicit-surface modeller (field evaluations, whole polygonizations, frames of growth), and
//! the exports of the Murex written step by step (the whole file, and the longest step). The
//! same code runs natively and in wasm; only the clock is given from outside. Every rate and
//! every time of a whole piece of work is the median of five timings of at least a quarter of
//! a second each, printed with its spread, so that a browser's coarse clock cannot quantise
//! it; frame times are the distribution of single frames, as a user sees them.

use crate::blobtree::falloff::ISO;
use crate::blobtree::polygonize::{Grid, Refinement, polygonize};
use crate::export::MeshFormat;
use crate::export::job::Export;
use crate::export::print_size::PrintSize;
use crate::export::shell::Shell;
use crate::forms::murex::whorl::whorl;
use crate::generator::{GROWTH_BUDGET_MS, Generator, RimLengths, within};
use crate::pattern::build;
use crate::pattern::edge_growth::{Divisions, cell_counts};
use crate::pattern::run::PatternRun;
use crate::presets::{Preset, presets};
use crate::spec::ShellSpec;
use crate::spec::form::Form;
use crate::spec::form::implicit::ImplicitSpec;
use crate::spec::pattern::{EdgeGrowth, Model};
use std::fmt::Write;

/// Frames timed per species, in each of the [`REPEATS`] growths.
const FRAMES: usize = 120;
/// The preset whose whole pattern is timed, as the live preview redraws it.
const WHOLE_PATTERN: &str = "oliva-porphyria";
/// The presets whose whole patterns are timed on a growing edge and on the paper's fixed one.
const EDGE_GROWTH: [&str; 2] = ["stripes-growing-edge", "oliva-porphyria-growing-edge"];

/// One measured figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    pub what: String,
    pub value: f64,
    pub unit: &'static str,
    /// The spread of repeated timings (largest less smallest) over their median, when repeated.
    pub spread: Option<f64>,
}

/// Least time one timing covers, far above the coarse clocks of browsers.
const LEAST_MS: f64 = 250.0;
/// Timings taken of each measured piece of work.
const REPEATS: usize = 5;

/// The median time of one call of `work`, in milliseconds, and the spread of the timings:
/// each timing runs `work` as many times as fill `LEAST_MS` (250 ms), a count found by timing
/// ever longer runs (a single call may be shorter than the clock's resolution). `now` must
/// advance.
pub fn timed(now: &dyn Fn() -> f64, mut work: impl FnMut()) -> (f64, f64) {
    let mut run = |calls: usize| {
        let start = now();
        for _ in 0..calls {
            work();
        }
        now() - start
    };
    let mut calls = 1;
    let calls = loop {
        let spent = run(calls);
        if spent >= LEAST_MS / 4.0 {
            break ((calls as f64 * LEAST_MS / spent).ceil() as usize).max(1);
        }
        calls *= 4;
    };
    let mut times: Vec<f64> = (0..REPEATS).map(|_| run(calls) / calls as f64).collect();
    times.sort_by(f64::total_cmp);
    let median = times[REPEATS / 2];
    (median, (times[REPEATS - 1] - times[0]) / median)
}

/// Runs every measurement; `now` returns milliseconds from any fixed origin.
pub fn run(now: &dyn Fn() -> f64) -> Vec<Figure> {
    let mut figures = Vec::new();
    let patterned = || {
        presets()
            .iter()
            .filter(|p| p.spec.pattern.model != Model::None)
    };
    for preset in patterned() {
        if let Some(figure) = pattern_rows(now, preset) {
            figures.push(figure);
        }
    }
    figures.extend(whole_pattern(now));
    figures.extend(edge_growth(now));
    for preset in patterned() {
        figures.extend(growth_frames(now, preset));
    }
    figures.extend(implicit(now, "implicit-whorl"));
    figures.extend(implicit(now, "murex-cabritii"));
    figures.extend(exports(now, "murex-cabritii"));
    figures
}

/// Cell updates per second of `preset`'s pattern model, advancing row after row (a failing
/// model gives no figure).
fn pattern_rows(now: &dyn Fn() -> f64, preset: &Preset) -> Option<Figure> {
    let spec = &preset.spec.pattern;
    let mut model = build(spec, preset.spec.seed).ok()??;
    model.advance_row().ok()?;
    let k = u64::from(spec.refinement.max(1));
    let per_row = model.recorded().len() as u64 * u64::from(spec.iterations) * k * k;
    let mut failed = false;
    let (ms, spread) = timed(now, || failed |= model.advance_row().is_err());
    (!failed).then(|| Figure {
        what: format!("{} ({})", preset.id, model_name(&spec.model)),
        value: per_row as f64 / ms / 1e3,
        unit: "M cell updates/s",
        spread: Some(spread),
    })
}

/// The whole pattern of [`WHOLE_PATTERN`], every row from the start, as the planar view redraws
/// it while a pattern parameter is dragged.
fn whole_pattern(now: &dyn Fn() -> f64) -> Option<Figure> {
    let preset = presets().iter().find(|p| p.id == WHOLE_PATTERN)?;
    let (spec, rows) = (&preset.spec.pattern, preset.spec.growth.rows);
    let mut complete = true;
    let (ms, spread) = timed(now, || {
        complete &= build(spec, preset.spec.seed)
            .ok()
            .flatten()
            .is_some_and(|mut model| (0..rows).all(|_| model.advance_row().is_ok()));
    });
    complete.then(|| Figure {
        what: format!(
            "{WHOLE_PATTERN} whole pattern ({} cells × {} iterations × {rows} rows)",
            spec.cells, spec.iterations
        ),
        value: ms,
        unit: "ms",
        spread: Some(spread),
    })
}

/// The whole pattern of each of [`EDGE_GROWTH`] on the paper's fixed edge and on its growing
/// one, in milliseconds for all its rows, as a user waits for it (the growing edge computes
/// fewer cells on its early rows); its model built on the first row's cells and divided to
/// the last row's without a step, what the divisions cost at most; and the time the form
/// takes to be built and give the rim's length on every row ([`RimLengths`]), which a growing
/// edge needs once.
fn edge_growth(now: &dyn Fn() -> f64) -> Vec<Figure> {
    let mut figures = Vec::new();
    for id in EDGE_GROWTH {
        let Some(preset) = presets().iter().find(|p| p.id == id) else {
            continue;
        };
        let spec = &preset.spec;
        let rows = spec.growth.rows as usize;
        let mut rims = Vec::new();
        let (rim_ms, rim_spread) = timed(now, || {
            if let Ok(lengths) = RimLengths::default().of(spec, rows) {
                rims = lengths.to_vec();
            }
        });
        for (growth, what) in [
            (EdgeGrowth::Off, "fixed edge (the paper's)"),
            (EdgeGrowth::Uniform, "growing edge"),
        ] {
            let mut spec = spec.clone();
            spec.pattern.edge_growth = growth;
            let mut complete = true;
            let (ms, spread) = timed(now, || {
                let Ok(Some(mut run)) = PatternRun::new(&spec, |r| rims.get(r).copied().flatten())
                else {
                    complete = false;
                    return;
                };
                while run.rows() < rows && complete {
                    complete &= run.advance().is_ok();
                }
            });
            figures.extend(complete.then(|| Figure {
                what: format!("{id} whole pattern ({rows} rows), {what}"),
                value: ms,
                unit: "ms",
                spread: Some(spread),
            }));
        }
        let Some(Ok(counts)) = rims
            .iter()
            .copied()
            .collect::<Option<Vec<f64>>>()
            .map(|rims| cell_counts(spec.pattern.cells, spec.pattern.apex_cells, &rims))
        else {
            continue;
        };
        let mut first = spec.pattern.clone();
        first.cells = counts[0];
        let last = counts[rows - 1] as usize * spec.pattern.refinement as usize;
        let (ms, spread) = timed(now, || {
            if let Ok(Some(mut model)) = build(&first, spec.seed) {
                Divisions::new(spec.seed).divide_to(model.as_mut(), last);
            }
        });
        figures.push(Figure {
            what: format!(
                "{id} model built on {} cells and divided to {last}, no step",
                counts[0]
            ),
            value: ms,
            unit: "ms",
            spread: Some(spread),
        });
        figures.push(Figure {
            what: format!("{id} form built and its rim lengths of {rows} rows"),
            value: rim_ms,
            unit: "ms",
            spread: Some(rim_spread),
        });
    }
    figures
}

/// The growth of `preset` at its default speed, [`FRAMES`] frames from the start, grown
/// [`REPEATS`] times: the median of the mean frame, and the worst frame of all.
fn growth_frames(now: &dyn Fn() -> f64, preset: &Preset) -> Vec<Figure> {
    let speed = preset.spec.growth.speed;
    let (mut means, mut worst) = (Vec::with_capacity(REPEATS), 0.0f64);
    for _ in 0..REPEATS {
        let Ok(mut generator) = Generator::new(&preset.spec) else {
            return Vec::new();
        };
        let (mut carry, mut total) = (0.0, 0.0);
        for _ in 0..FRAMES {
            carry += speed;
            let rows = carry.floor();
            carry -= rows;
            let start = now();
            generator.advance(rows as usize);
            let spent = now() - start;
            total += spent;
            worst = worst.max(spent);
        }
        means.push(total / FRAMES as f64);
    }
    means.sort_by(f64::total_cmp);
    let median = means[REPEATS / 2];
    let what = |which: &str| format!("{} frame at {speed} rows/frame, {which}", preset.id);
    vec![
        Figure {
            what: what("mean"),
            value: median,
            unit: "ms",
            spread: Some((means[REPEATS - 1] - means[0]) / median.max(1e-9)),
        },
        Figure {
            what: what("worst"),
            value: worst,
            unit: "ms",
            spread: None,
        },
    ]
}

/// The implicit modeller on preset `id`: field evaluations per second of its whole BlobTree,
/// the time to polygonize all of it at 128³ and 256³, and its growth in frames of the page's
/// budget.
fn implicit(now: &dyn Fn() -> f64, id: &str) -> Vec<Figure> {
    let Some(preset) = presets().iter().find(|p| p.id == id) else {
        return Vec::new();
    };
    let Form::Implicit(spec) = &preset.spec.form else {
        return Vec::new();
    };
    let Ok(shell) = whorl(
        spec,
        &preset.spec.pattern,
        preset.spec.seed,
        preset.spec.growth.rows as usize,
    ) else {
        return Vec::new();
    };
    let tree = &shell.tree;
    let mut figures = Vec::new();
    const LATTICE: u32 = 24;
    let (min, size) = (tree.bounds.min, tree.bounds.max - tree.bounds.min);
    let (ms, spread) = timed(now, || {
        let mut inside = 0;
        for i in 0..LATTICE * LATTICE * LATTICE {
            let t = glam::UVec3::new(i % LATTICE, i / LATTICE % LATTICE, i / (LATTICE * LATTICE));
            let p = min + size * (t.as_dvec3() + 0.5) / f64::from(LATTICE);
            inside += usize::from(tree.field(p) >= ISO);
        }
        std::hint::black_box(inside);
    });
    figures.push(Figure {
        what: format!("{id} field evaluations, whole tree"),
        value: f64::from(LATTICE.pow(3)) / ms / 1e3,
        unit: "M/s",
        spread: Some(spread),
    });
    for resolution in [128, 256] {
        figures.extend(polygonized(now, id, spec, &preset.spec, resolution));
    }
    if let Ok(mut generator) = Generator::new(&preset.spec) {
        let rows = preset.spec.growth.speed.ceil() as usize;
        let (mut frames, mut longest) = (Vec::new(), 0.0);
        while !generator.is_done() {
            let start = now();
            generator.advance_while(rows, within(now, GROWTH_BUDGET_MS, &mut longest));
            frames.push(now() - start);
        }
        frames.sort_by(f64::total_cmp);
        let n = frames.len();
        // The worst frame alone also counts the times the system took the processor away.
        let ranks = [
            ("99th percentile", n * 99 / 100),
            ("worst", n.saturating_sub(1)),
        ];
        for (what, rank) in ranks {
            let Some(&value) = frames.get(rank) else {
                continue;
            };
            figures.push(Figure {
                what: format!("{id} growth in {GROWTH_BUDGET_MS} ms frames: {n} frames, {what}"),
                value,
                unit: "ms",
                spread: None,
            });
        }
    }
    figures
}

/// The time to polygonize the whole shell of preset `id` (`spec` its form, `shell` the rest)
/// built for `resolution`³ on one thread, refined where its thin parts stand as the page
/// refines it.
fn polygonized(
    now: &dyn Fn() -> f64,
    id: &str,
    spec: &ImplicitSpec,
    shell: &ShellSpec,
    resolution: u32,
) -> Option<Figure> {
    let spec = ImplicitSpec {
        resolution,
        ..spec.clone()
    };
    let built = whorl(
        &spec,
        &shell.pattern,
        shell.seed,
        shell.growth.rows as usize,
    )
    .ok()?;
    let refinement = Refinement::new(Grid::new(&built.tree.bounds, resolution), &built.fine.boxes);
    let last = built.instances - 1;
    let (ms, spread) = timed(now, || {
        std::hint::black_box(polygonize(&built.tree, &refinement, last));
    });
    Some(Figure {
        what: format!("{id} polygonized at {resolution}³"),
        value: ms,
        unit: "ms",
        spread: Some(spread),
    })
}

/// The presets whose pattern rates [`one_core`] measures: one per model.
const ONE_CORE_PATTERNS: [&str; 4] = [
    "stripes",
    "oliva-porphyria",
    "conus-marmoreus",
    "ca-conus-princeps",
];

/// What one core does, to compare a worker's thread with the page's (`make bench` runs it on
/// both in the same browser): the pattern rates of one preset per model, and the Murex
/// polygonized whole at 128³.
pub fn one_core(now: &dyn Fn() -> f64) -> Vec<Figure> {
    let mut figures: Vec<Figure> = ONE_CORE_PATTERNS
        .iter()
        .filter_map(|id| presets().iter().find(|p| p.id == *id))
        .filter_map(|preset| pattern_rows(now, preset))
        .collect();
    let murex = presets().iter().find(|p| p.id == "murex-cabritii");
    if let Some(preset) = murex
        && let Form::Implicit(spec) = &preset.spec.form
    {
        figures.extend(polygonized(now, preset.id, spec, &preset.spec, 128));
    }
    figures
}

/// Every mesh format of preset `id` grown whole, written a step at a time as the page writes
/// it: the time of the whole file, and of the longest step (what one frame may have to wait).
fn exports(now: &dyn Fn() -> f64, id: &str) -> Vec<Figure> {
    let Some(preset) = presets().iter().find(|p| p.id == id) else {
        return Vec::new();
    };
    let Ok(mut generator) = Generator::new(&preset.spec) else {
        return Vec::new();
    };
    generator.finish();
    let mut figures = Vec::new();
    for format in MeshFormat::ALL {
        let shell = Shell::new(&generator, &preset.spec, preset, PrintSize::default());
        let Ok(mut export) = shell.and_then(|s| Export::new(format, s)) else {
            continue;
        };
        let (start, mut longest, mut steps) = (now(), 0.0f64, 0);
        let bytes = loop {
            let before = now();
            let done = export.work(|| false);
            longest = longest.max(now() - before);
            steps += 1;
            match done {
                Ok(Some(bytes)) => break Some(bytes),
                Ok(None) => {}
                Err(_) => break None,
            }
        };
        let Some(bytes) = bytes else {
            continue;
        };
        let what = format!("{id} as {}", format.extension().to_uppercase());
        figures.push(Figure {
            what: format!("{what}: {} bytes in {steps} steps", bytes.len()),
            value: now() - start,
            unit: "ms",
            spread: None,
        });
        figures.push(Figure {
            what: format!("{what}: longest step"),
            value: longest,
            unit: "ms",
            spread: None,
        });
    }
    figures
}

fn model_name(model: &Model) -> &'static str {
    match model {
        Model::None => "none",
        Model::ActivatorSubstrate(_) => "eq 8",
        Model::ActivatorInhibitor(_) => "eq 9",
        Model::Coupled(_) => "coupled",
        Model::Automaton(_) => "automaton",
    }
}

/// The figures as aligned text, one per line.
pub fn report(figures: &[Figure]) -> String {
    let width = figures
        .iter()
        .map(|f| f.what.chars().count())
        .max()
        .unwrap_or(0);
    let mut out = String::new();
    for f in figures {
        let pad = width - f.what.chars().count();
        let spread = f
            .spread
            .map(|s| format!("  (spread {:.1} %)", s * 100.0))
            .unwrap_or_default();
        writeln!(
            out,
            "{}{}  {:>9.3} {}{spread}",
            f.what,
            " ".repeat(pad),
            f.value,
            f.unit
        )
        .expect("write to string");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    #[test]
    fn a_call_far_below_the_clocks_resolution_is_timed_to_within_a_percent() {
        // A clock that ticks every 0.1 ms, as browsers' do, and work of 0.013 ms a call.
        let time = Cell::new(0.0);
        let now = || (time.get() / 0.1f64).floor() * 0.1;
        let (ms, spread) = timed(&now, || time.set(time.get() + 0.013));
        assert!((ms / 0.013 - 1.0).abs() < 0.01, "{ms} ms a call");
        assert!(spread < 0.01, "spread {spread}");
        assert!(
            time.get() >= REPEATS as f64 * LEAST_MS,
            "timed {} ms in all",
            time.get()
        );
    }
}
