//! The benchmark (figures, not a test): cell updates per second of each pattern model, and the
//! time of one animation frame's growth for each species at its default speed. The same code
//! runs natively and in wasm; only the clock is given from outside.

use crate::generator::Generator;
use crate::pattern::build;
use crate::spec::pattern::Model;
use crate::species::presets;
use std::fmt::Write;

/// Rows timed per model.
const ROWS: usize = 200;
/// Frames timed per species.
const FRAMES: usize = 120;

/// One measured figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    pub what: String,
    pub value: f64,
    pub unit: &'static str,
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
        let spec = &preset.spec.pattern;
        let Ok(Some(mut model)) = build(spec, preset.spec.seed) else {
            continue;
        };
        let k = u64::from(spec.refinement.max(1));
        let per_row = model.recorded().len() as u64 * u64::from(spec.iterations) * k * k;
        let start = now();
        for _ in 0..ROWS {
            if model.advance_row().is_err() {
                break;
            }
        }
        let seconds = (now() - start).max(1e-3) / 1000.0;
        figures.push(Figure {
            what: format!("{} ({})", preset.id, model_name(&spec.model)),
            value: (per_row * ROWS as u64) as f64 / seconds / 1e6,
            unit: "M cell updates/s",
        });
    }
    for preset in patterned() {
        let Ok(mut generator) = Generator::new(&preset.spec) else {
            continue;
        };
        let speed = preset.spec.growth.speed;
        let (mut carry, mut total, mut worst) = (0.0, 0.0, 0.0f64);
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
        figures.push(Figure {
            what: format!("{} frame at {speed} rows/frame, mean", preset.id),
            value: total / FRAMES as f64,
            unit: "ms",
        });
        figures.push(Figure {
            what: format!("{} frame at {speed} rows/frame, worst", preset.id),
            value: worst,
            unit: "ms",
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
        writeln!(
            out,
            "{}{}  {:>9.3} {}",
            f.what,
            " ".repeat(pad),
            f.value,
            f.unit
        )
        .expect("write to string");
    }
    out
}
