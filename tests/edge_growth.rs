//! The pattern on a growing edge (`pattern.edge_growth`, beyond Fowler et al. 1992, who fix
//! the number of cells): the cells divide as the rim lengthens, so their number follows the
//! rim, the stripes of fig 11's model keep their wavelength in absolute length from the apex to
//! the lip (on a fixed edge it grows with the rim), new stripes appear between old ones, the
//! same seed gives the same bits however the growth is cut, and a form without one growing
//! edge refuses the option by name; fig 14's waves keep their density on a growing edge.

use crate::common;

use seashells_core::forms::{has_one_growing_edge, shape_for};
use seashells_core::generator::{BuildError, Generator, RimLengths, pattern_alone};
use seashells_core::pattern::run::PatternRun;
use seashells_core::presets::{preset, presets};
use seashells_core::share::link::decode;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::Form;
use seashells_core::spec::pattern::EdgeGrowth;

fn spec_of(id: &str) -> ShellSpec {
    preset(id).expect("preset").spec.clone()
}

/// The pattern of `spec` alone, its rim's lengths computed afresh.
fn pattern_of(spec: &ShellSpec) -> PatternRun {
    pattern_alone(spec, &mut RimLengths::default())
        .unwrap()
        .unwrap()
}

/// The hash of the first 300 rows of each patterned preset of a fixed edge, computed before
/// edge growth existed (at fd19452): the paper's patterns
/// are bit for bit as they were.
const BEFORE_EDGE_GROWTH: &[(&str, u64)] = &[
    ("stripes", 0xc27666d814edc694),
    ("amoria-undulata", 0xf56e0f3d306988e5),
    ("volutoconus-bednalli", 0x273eb60f0ccbae5e),
    ("oliva-porphyria", 0x369cf9c8717502db),
    ("conus-marmoreus", 0xc31071a1ced64add),
    ("ca-waves", 0x27f88a71c7feaaa5),
    ("ca-solitons", 0x27d60dd090563cc5),
    ("ca-fractal-core", 0x8f2d44d47677f9d8),
    ("ca-trochidae", 0x6bdbf592727fe805),
    ("ca-cymbiolacca", 0xfe92bb1ffb2941f5),
    ("ca-conus-princeps", 0xde41000f0b427c15),
    ("kawaguchi-painted", 0x3c902cfa272af148),
];

#[test]
fn the_paper_presets_patterns_are_bit_for_bit_as_before_edge_growth() {
    for &(id, before) in BEFORE_EDGE_GROWTH {
        let spec = spec_of(id);
        assert_eq!(spec.pattern.edge_growth, EdgeGrowth::Off, "{id}");
        let mut run = pattern_of(&spec);
        for _ in 1..300 {
            run.advance().unwrap();
        }
        assert_eq!(run.hash(), before, "{id}");
        assert!(
            run.widths().iter().all(|&w| w as usize == run.cells()),
            "{id}"
        );
    }
}

/// fig 11's stripes on a growing edge, and the rim's length on each row.
fn growing_stripes() -> (ShellSpec, Vec<f64>) {
    let mut spec = spec_of("stripes");
    spec.pattern.edge_growth = EdgeGrowth::Uniform;
    let rows = spec.growth.rows as usize;
    let shape = shape_for(&spec, rows).unwrap();
    let rims = (0..rows).map(|r| shape.rim_length(r).unwrap()).collect();
    (spec, rims)
}

#[test]
fn the_cells_follow_the_rim_so_each_keeps_its_length() {
    let (spec, rims) = growing_stripes();
    let mut run = pattern_of(&spec);
    while run.rows() < rims.len() {
        run.advance().unwrap();
    }
    let (cells, widths) = (run.cells(), run.widths());
    let last = *rims.last().unwrap();
    assert_eq!(widths.len(), rims.len());
    assert_eq!(*widths.last().unwrap() as usize, cells);
    assert!(widths.windows(2).all(|w| w[0] <= w[1]), "no cell dies");
    assert!(
        (widths[0] as usize) * 10 < cells,
        "the rim grows {:.0}-fold: {} cells at the apex",
        last / rims[0],
        widths[0]
    );
    for (r, (&n, &rim)) in widths.iter().zip(&rims).enumerate() {
        let asked = cells as f64 * rim / last;
        assert!(
            (f64::from(n) - asked).abs() <= 0.5 + 1e-9,
            "row {r}: {n} cells for {asked}"
        );
    }
    // The texture's rows are all as wide, each cell stretched over its share; the planar
    // view's are as long as their cells, centred.
    let planar = run.planar();
    let row = 4 * cells;
    for (r, &n) in widths.iter().enumerate().step_by(97) {
        let shown = planar[r * row..(r + 1) * row]
            .chunks_exact(4)
            .filter(|p| p[3] == 255);
        assert_eq!(shown.count(), n as usize, "row {r}");
        assert!(
            run.rgba()[r * row..(r + 1) * row]
                .chunks_exact(4)
                .all(|p| p[3] == 255)
        );
    }
}

/// The link `make test`'s property test drew that ran for 13 minutes: a generating curve that
/// shrinks (λ_c = 0.8) has a rim 4,800 times longer at the apex than at the lip, and each of
/// its rows asked for up to 4,800 times the last row's cells, kept to the end since cells do
/// not die. Each row now has at most the last row's cells.
#[test]
fn a_shrinking_rim_keeps_the_last_rows_cells_from_the_apex() {
    let decoded = decode(
        "v=1&preset=stripes-growing-edge&form.curve.lambda_c=0.8&form.spiral.r0=9.931112054812846&pattern.iterations=40",
    );
    let spec = decoded.spec;
    let rows = spec.growth.rows as usize;
    let shape = shape_for(&spec, rows).unwrap();
    let (first, last) = (
        shape.rim_length(0).unwrap(),
        shape.rim_length(rows - 1).unwrap(),
    );
    assert!(
        first > 100.0 * last,
        "the rim shrinks from {first} to {last}"
    );
    let mut run = pattern_of(&spec);
    while run.rows() < rows {
        run.advance().unwrap();
    }
    let cells = spec.pattern.cells;
    assert_eq!(run.cells(), cells as usize);
    assert!(
        run.widths().iter().all(|&n| n == cells),
        "{:?}",
        &run.widths()[..8]
    );
}

/// Local maxima above `threshold`: the stripes a row crosses.
fn stripes(row: &[f32], threshold: f32) -> usize {
    (1..row.len() - 1)
        .filter(|&i| row[i] > threshold && row[i] >= row[i - 1] && row[i] > row[i + 1])
        .count()
}

/// The mean wavelength (shell units) over each half of the rows from `from` on, and the
/// stripes on every tenth row.
fn wavelengths(spec: &ShellSpec, rims: &[f64], from: usize) -> ([f64; 2], Vec<usize>) {
    let mut run: PatternRun = pattern_of(spec);
    let mut counts = Vec::new();
    let mut sums = [(0.0, 0); 2];
    let middle = (from + rims.len()) / 2;
    while run.rows() < rims.len() {
        run.advance().unwrap();
        let r = run.rows() - 1;
        if r >= from && r.is_multiple_of(10) {
            let n = stripes(run.recorded(), 1.5).max(1);
            counts.push(n);
            let half = &mut sums[usize::from(r >= middle)];
            half.0 += rims[r] / n as f64;
            half.1 += 1;
        }
    }
    (sums.map(|(sum, n)| sum / f64::from(n)), counts)
}

/// On a fixed edge each of fig 11's stripes widens with the rim; on a growing edge new
/// stripes appear between the old ones as the rim lengthens, so the wavelength in absolute
/// length keeps to a saw-tooth about one value (a new stripe fits once a gap has about
/// doubled): its mean over the first half of the rows where stripes have room and over the
/// second half agree within 10 %.
#[test]
fn fig_11_stripes_keep_their_wavelength_as_the_rim_grows() {
    let (mut spec, rims) = growing_stripes();
    let from = rims
        .iter()
        .position(|&l| l > rims.last().unwrap() / 4.0)
        .unwrap();
    let ([early, late], counts) = wavelengths(&spec, &rims, from);
    assert!(
        (late / early - 1.0).abs() < 0.1,
        "growing edge: wavelength {early:.3} then {late:.3}"
    );
    let (first, last) = (counts[0], *counts.last().unwrap());
    assert!(last >= 3 * first, "the stripes multiply: {first} to {last}");
    let branchings = counts.windows(2).filter(|w| w[1] > w[0]).count();
    assert!(branchings >= 2, "new stripes appear {branchings} times");
    spec.pattern.edge_growth = EdgeGrowth::Off;
    let ([early, late], _) = wavelengths(&spec, &rims, from);
    assert!(
        late > 1.8 * early,
        "fixed edge: wavelength {early:.3} then {late:.3}"
    );
}

#[test]
fn a_growing_edge_gives_the_same_bits_however_the_growth_is_cut() {
    for id in [
        "stripes",
        "oliva-porphyria",
        "ca-trochidae",
        "kawaguchi-painted",
        "conus-marmoreus",
    ] {
        let mut spec = spec_of(id);
        spec.pattern.edge_growth = EdgeGrowth::Uniform;
        spec.growth.rows = spec.growth.rows.min(600);
        let (whole, pieces) = common::grown_whole_and_in_chunks(&spec);
        let (a, b) = (whole.pattern().unwrap(), pieces.pattern().unwrap());
        assert_eq!(a.hash(), b.hash(), "{id}");
        assert_eq!(a.widths(), b.widths(), "{id}");
        assert!(
            a.widths()[0] < a.widths()[a.widths().len() - 1],
            "{id}: the edge grows"
        );
        let mut alone = pattern_of(&spec);
        while alone.rows() < a.rows() {
            alone.advance().unwrap();
        }
        assert_eq!(
            alone.hash(),
            a.hash(),
            "{id}: the preview's pattern is the shell's"
        );
    }
}

#[test]
fn a_form_without_one_growing_edge_refuses_edge_growth_by_name() {
    for id in ["murex-rd-spines", "kawaguchi-tendril"] {
        let mut spec = spec_of(id);
        if spec.pattern.model == seashells_core::spec::pattern::Model::None {
            spec.pattern = spec_of("stripes").pattern;
        }
        spec.pattern.edge_growth = EdgeGrowth::Uniform;
        match Generator::new(&spec) {
            Err(BuildError::Pattern(e)) => {
                assert!(e.0.contains("pattern.edge_growth"), "{id}: {e}")
            }
            Err(e) => panic!("{id}: {e}"),
            Ok(_) => panic!("{id}: grown with edge growth"),
        }
        // A link asking for it opens with edge growth off, and says why.
        let decoded = decode(&format!("v=1&preset={id}&pattern.edge_growth=uniform"));
        assert_eq!(decoded.spec.pattern.edge_growth, EdgeGrowth::Off, "{id}");
        assert!(
            decoded
                .problems
                .iter()
                .any(|p| p.key == "pattern.edge_growth"),
            "{id}: {:?}",
            decoded.problems
        );
    }
    // Each form says whether it has one growing edge, and its shape agrees.
    for p in presets()
        .iter()
        .filter(|p| p.spec.form.kind() != "implicit")
    {
        let shape = shape_for(&p.spec, 8).unwrap();
        assert_eq!(
            has_one_growing_edge(&p.spec.form),
            shape.rim_length(0).is_some(),
            "{}",
            p.id
        );
    }
}

/// The RGBA's rows are as wide as the cells the model computes on the last row: the spec's
/// cells times the refinement k of a reaction-diffusion model, and the automaton's own (which
/// is not refined), on a fixed edge and on a growing one.
#[test]
fn the_rows_are_as_wide_as_the_last_rows_computed_cells_whatever_the_refinement() {
    for (id, refined) in [("stripes", 2), ("ca-trochidae", 1)] {
        for growth in [EdgeGrowth::Off, EdgeGrowth::Uniform] {
            let mut spec = spec_of(id);
            spec.pattern.refinement = 2;
            spec.pattern.edge_growth = growth;
            spec.growth.rows = 300;
            let mut run = pattern_of(&spec);
            while run.rows() < 300 {
                run.advance().unwrap();
            }
            let cells = spec.pattern.cells as usize * refined;
            assert_eq!(run.cells(), cells, "{id}, {growth:?}");
            assert_eq!(run.recorded().len(), cells, "{id}, {growth:?}");
            assert_eq!(run.rgba().len(), 300 * cells * 4, "{id}, {growth:?}");
            assert_eq!(
                *run.widths().last().unwrap() as usize,
                cells,
                "{id}, {growth:?}"
            );
        }
    }
}

/// The share of a row's cells that a wave of fig 14 has raised above 0.5, averaged over each
/// row of `rows`, for `spec`'s pattern grown to its last row.
fn wave_shares(spec: &ShellSpec, rows: &[std::ops::Range<usize>]) -> Vec<f64> {
    let mut run = pattern_of(spec);
    let mut sums = vec![0.0; rows.len()];
    while run.rows() < spec.growth.rows as usize {
        run.advance().unwrap();
        let r = run.rows() - 1;
        let row = run.recorded();
        let share = row.iter().filter(|&&a| a > 0.5).count() as f64 / row.len() as f64;
        for (sum, range) in sums.iter_mut().zip(rows) {
            if range.contains(&r) {
                *sum += share / range.len() as f64;
            }
        }
    }
    sums
}

/// Fig 14's Oliva on a growing edge: eq 9's hormone follows the mean activator, so as the
/// cells divide and the waves thin out it lets more of them branch, and the share of cells a
/// wave covers stays that of the fixed edge, for any seed. The apex holds 50 cells
/// (`pattern.apex_cells`): on the one or two a rim from the apex has room for, the eight
/// starting waves die out and never start again.
#[test]
fn fig_14_waves_keep_their_density_as_the_edge_grows() {
    let grown = spec_of("oliva-porphyria-growing-edge");
    assert_eq!(grown.pattern.edge_growth, EdgeGrowth::Uniform);
    let rows = grown.growth.rows as usize;
    // The rim has room for more than the apex's 50 cells from about row 1,950 of 2,900: the
    // edge has about 110 to 170 cells over the middle rows, 260 to 400 over the late ones.
    let (late, middle) = (rows - 300..rows, rows - 600..rows - 400);
    for seed in 1..=3 {
        let mut spec = grown.clone();
        spec.seed = seed;
        let mut fixed = spec_of("oliva-porphyria");
        fixed.seed = seed;
        let growing = wave_shares(&spec, &[late.clone(), middle.clone()]);
        let paper = wave_shares(&fixed, std::slice::from_ref(&late))[0];
        assert!(
            paper > 0.05,
            "seed {seed}: the paper's waves cover {paper:.3}"
        );
        for share in growing {
            assert!(
                (share / paper - 1.0).abs() < 0.25,
                "seed {seed}: waves cover {share:.3} of a growing edge, {paper:.3} of a fixed one"
            );
        }
    }
    let mut bare = grown;
    bare.pattern.apex_cells = 1;
    let dead = wave_shares(&bare, &[late])[0];
    assert_eq!(dead, 0.0, "on one cell at the apex the waves die out");
}

/// A preview keeps the rim's lengths of its last form: a pattern of the same form and rows
/// reuses them, and one of another form or of other rows computes its own, so the pattern is
/// the one a fresh computation gives whatever was previewed before.
#[test]
fn kept_rim_lengths_serve_only_the_form_and_rows_they_were_computed_for() {
    let mut rims = RimLengths::default();
    let stripes = spec_of("stripes-growing-edge");
    let mut faster = stripes.clone();
    let Form::Sweep(sweep) = &mut faster.form else {
        panic!("a sweep")
    };
    sweep.curve.lambda_c = 1.03;
    let mut shorter = stripes.clone();
    shorter.growth.rows = 900;
    let mut paler = stripes.clone();
    paler.pattern.low = 1.0;
    for spec in [&stripes, &faster, &shorter, &paler, &stripes] {
        let mut kept = pattern_alone(spec, &mut rims).unwrap().unwrap();
        let mut fresh = pattern_of(spec);
        while kept.rows() < spec.growth.rows as usize {
            kept.advance().unwrap();
            fresh.advance().unwrap();
        }
        assert_eq!(kept.widths(), fresh.widths());
        assert_eq!(kept.hash(), fresh.hash());
    }
}
