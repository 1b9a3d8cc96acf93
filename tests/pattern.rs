//! The pigmentation models of Fowler, Meinhardt & Prusinkiewicz 1992 §3 behave as the paper
//! describes: determinism from the seed, the analytic steady state of eq 8, stable stripes whose
//! spacing the parameters set, oscillations, travelling waves that annihilate and are kept in
//! number by the hormone, triangles, and refusal of what explicit Euler cannot integrate.

use seashells_core::generator::{Generator, RimLengths, pattern_alone};
use seashells_core::pattern::build;
use seashells_core::presets::{preset, presets};
use seashells_core::spec::ShellSpec;
use seashells_core::spec::pattern::{Boundary, Model, PatternSpec};

fn pattern_of(id: &str) -> PatternSpec {
    preset(id).unwrap().spec.pattern.clone()
}

/// The recorded rows of `n` rows of a pattern.
fn rows(spec: &PatternSpec, seed: u64, n: usize) -> Vec<Vec<f64>> {
    let mut model = build(spec, seed).unwrap().unwrap();
    let row = |v: &[f32]| v.iter().map(|&x| f64::from(x)).collect::<Vec<_>>();
    let mut out = vec![row(model.recorded())];
    for _ in 1..n {
        model.advance_row().unwrap();
        out.push(row(model.recorded()));
    }
    out
}

/// Positions of the local maxima above `threshold`.
fn maxima(row: &[f64], threshold: f64) -> Vec<usize> {
    (1..row.len() - 1)
        .filter(|&i| row[i] > threshold && row[i] >= row[i - 1] && row[i] > row[i + 1])
        .collect()
}

/// Number of separate stretches above `threshold`.
fn runs(row: &[f64], threshold: f64) -> usize {
    (0..row.len())
        .filter(|&i| row[i] > threshold && (i == 0 || row[i - 1] <= threshold))
        .count()
}

fn hash(spec: &ShellSpec) -> u64 {
    let mut run = pattern_alone(spec, &mut RimLengths::default())
        .unwrap()
        .unwrap();
    for _ in 1..400 {
        run.advance().unwrap();
    }
    run.hash()
}

#[test]
fn the_same_spec_and_seed_give_the_same_bits() {
    for p in presets()
        .iter()
        .filter(|p| p.spec.pattern.model != Model::None)
    {
        let spec = &p.spec;
        assert_eq!(hash(spec), hash(spec), "{}", p.id);
        let random = match &spec.pattern.model {
            Model::ActivatorSubstrate(m) => m.rho_noise > 0.0,
            Model::ActivatorInhibitor(m) => m.rho_noise > 0.0 || m.starts > 0,
            Model::Coupled(m) => m.rho_noise > 0.0 || m.starts > 0,
            Model::Automaton(m) => m.random_starts > 0,
            Model::None => false,
        };
        let mut other = spec.clone();
        other.seed += 1;
        assert_eq!(
            hash(spec) != hash(&other),
            random,
            "{}: the seed matters exactly when the model draws",
            p.id
        );
    }
}

#[test]
fn eq_8_keeps_its_analytic_uniform_steady_state() {
    // With ν = 0 the uniform steady state is a* = σ/μ and s* = μa* / (ρ(a*²/(1 + κa*²) + ρ₀)).
    let mut spec = pattern_of("stripes");
    let Model::ActivatorSubstrate(m) = &mut spec.model else {
        panic!("stripes use eq 8")
    };
    m.rho_noise = 0.0;
    let a = m.sigma / m.mu;
    let s = m.mu * a / (m.rho * (a * a / (1.0 + m.kappa * a * a) + m.rho0));
    m.a_init = a;
    m.s_init = s;
    let model_rows = rows(&spec, 1, 300);
    for row in &model_rows {
        for &x in row {
            assert!((x - a).abs() < 1e-6 * a, "a = {x}, steady state {a}");
        }
    }
}

fn spacing(cells: u32, refinement: u32) -> (f64, Vec<usize>, Vec<usize>) {
    let mut spec = pattern_of("stripes");
    spec.cells = cells;
    spec.refinement = refinement;
    let r = rows(&spec, 1, 2100);
    let late = maxima(&r[2099], 1.5);
    (
        f64::from(cells) / late.len() as f64,
        maxima(&r[1700], 1.5),
        late,
    )
}

#[test]
fn fig_11_stripes_stop_moving_and_their_spacing_is_set_by_the_parameters() {
    let (narrow, before, after) = spacing(180, 1);
    let (wide, _, _) = spacing(360, 1);
    assert!(after.len() >= 15, "only {} stripes", after.len());
    assert!(
        (narrow / wide - 1.0).abs() < 0.1,
        "spacing {narrow} with 180 cells, {wide} with 360"
    );
    let kept = after
        .iter()
        .filter(|&&i| before.iter().any(|&j| i.abs_diff(j) <= 1))
        .count();
    assert!(
        kept * 10 >= after.len() * 9,
        "only {kept} of {} stripes stayed in place",
        after.len()
    );
}

#[test]
fn refining_the_run_changes_the_stripes_little() {
    let (coarse, _, _) = spacing(180, 1);
    let (fine, _, _) = spacing(180, 2);
    assert!(
        (fine / coarse - 1.0).abs() < 0.15,
        "spacing {coarse} refined to {fine}"
    );
}

#[test]
fn oliva_keeps_the_number_of_its_travelling_waves_in_a_band() {
    let r = rows(&pattern_of("oliva-porphyria"), 1, 2900);
    let counts: Vec<usize> = r.iter().skip(200).map(|row| runs(row, 0.5)).collect();
    let (low, high) = (counts.iter().min().unwrap(), counts.iter().max().unwrap());
    assert!(*low >= 3, "the waves nearly died out ({low})");
    assert!(*high <= 60, "the waves proliferated ({high})");
}

#[test]
fn oliva_waves_annihilate_when_they_meet() {
    // One start on a ring sends two waves round it; with the hormone held constant nothing
    // branches, so after they meet on the far side nothing is left (crossing waves would go on).
    let mut spec = pattern_of("oliva-porphyria");
    spec.boundary = Boundary::Periodic;
    spec.cells = 200;
    let Model::ActivatorInhibitor(m) = &mut spec.model else {
        panic!("Oliva uses eq 9")
    };
    m.starts = 1;
    m.eta = 0.0;
    m.rho_c = 0.0;
    m.c_init = 0.5;
    let counts: Vec<usize> = rows(&spec, 3, 500)
        .iter()
        .map(|row| runs(row, 0.5))
        .collect();
    let travelling = counts.iter().take_while(|&&n| n != 0).count();
    assert!(
        counts[20..300].iter().all(|&n| n == 2),
        "two waves travel: {:?}",
        &counts[..300]
    );
    assert!(
        travelling > 300 && travelling < 450,
        "they meet after {travelling} rows"
    );
    assert!(
        counts[travelling..].iter().all(|&n| n == 0),
        "after meeting nothing is left"
    );
}

#[test]
fn amoria_oscillates_in_time() {
    let r = rows(&pattern_of("amoria-undulata"), 1, 600);
    let cell: Vec<f64> = r.iter().map(|row| row[150]).collect();
    let peaks: Vec<usize> = (1..cell.len() - 1)
        .filter(|&i| cell[i] > 0.5 && cell[i] >= cell[i - 1] && cell[i] > cell[i + 1])
        .collect();
    assert!(peaks.len() >= 10, "peaks at {peaks:?}");
    let periods: Vec<f64> = peaks.windows(2).map(|w| (w[1] - w[0]) as f64).collect();
    let mean = periods.iter().sum::<f64>() / periods.len() as f64;
    assert!(
        periods.iter().all(|p| (p / mean - 1.0).abs() < 0.4),
        "periods {periods:?}"
    );
}

#[test]
fn volutoconus_has_permanent_stripes_with_waves_between() {
    // σ(x) = σ_max (1 − depth (1 − cos 2πx/period)/2) exceeds μ only near x = 0, period, ...
    let spec = pattern_of("volutoconus-bednalli");
    let Model::ActivatorSubstrate(m) = &spec.model else {
        panic!("eq 8")
    };
    let period = m.sigma_period as usize;
    let r = rows(&spec, 1, 800);
    let high_share =
        |cell: usize| r[300..].iter().filter(|row| row[cell] > 1.0).count() as f64 / 500.0;
    assert!(
        high_share(period) > 0.95,
        "the cell where σ > μ stays active"
    );
    let between = period + period / 2;
    let share = high_share(between);
    assert!(
        share > 0.01 && share < 0.5,
        "between stripes the activator comes and goes ({share})"
    );
}

fn conus_width(rho_e0: f64) -> (f64, f64) {
    let mut spec = pattern_of("conus-marmoreus");
    let Model::Coupled(m) = &mut spec.model else {
        panic!("Conus uses the coupled model")
    };
    m.rho_e0 = rho_e0;
    let r = rows(&spec, 1, 2000);
    let mut widths = Vec::new();
    let mut active = 0;
    for row in &r[500..] {
        let mut run = 0;
        for &v in row.iter().chain(std::iter::once(&0.0)) {
            if v > 1.0 {
                run += 1;
                active += 1;
            } else if run > 0 {
                widths.push(run);
                run = 0;
            }
        }
    }
    let share = f64::from(active) / (1500.0 * r[0].len() as f64);
    (
        share,
        widths.iter().sum::<usize>() as f64 / widths.len() as f64,
    )
}

#[test]
fn conus_keeps_drawing_triangles_and_a_stronger_extinction_makes_them_smaller() {
    let (share, width) = conus_width(0.012);
    assert!(
        share > 0.05 && share < 0.6,
        "white covers {share} of the shell"
    );
    let (_, smaller) = conus_width(0.014);
    assert!(smaller < width * 0.95, "widths {width} then {smaller}");
}

#[test]
fn parameters_explicit_euler_cannot_integrate_are_refused_with_a_message() {
    let mut spec = preset("stripes").unwrap().spec.clone();
    let Model::ActivatorSubstrate(m) = &mut spec.pattern.model else {
        panic!("eq 8")
    };
    m.d_a = 0.6;
    let e = Generator::new(&spec).err().expect("refused").to_string();
    assert!(e.contains("D_a = 0.6") && e.contains("0.5"), "{e}");
    let Model::ActivatorSubstrate(m) = &mut spec.pattern.model else {
        panic!("eq 8")
    };
    m.d_a = 0.45;
    m.mu = 0.3;
    let e = Generator::new(&spec).err().expect("refused").to_string();
    assert!(e.contains("4·D_a + μ"), "{e}");
}
