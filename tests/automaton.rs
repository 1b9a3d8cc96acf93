//! The vector cellular automaton: waves that annihilate (1/6-8/4) or cross (1/6-6/5), the ring
//! closing on itself, an oscillator (1/6-8/5), determinism from the seed, and clear messages
//! for bad rules.

use seashells_core::pattern::automaton::Automaton;
use seashells_core::pattern::{EdgeModel, build};
use seashells_core::presets::preset;
use seashells_core::share::link::{decode, encode};
use seashells_core::spec::pattern::{Boundary, Model, PatternSpec};

/// A ring of `cells` cells under `rule`, starting from `starts` with one prepigment each.
fn ring(rule: &str, cells: u32, starts: &[u32]) -> PatternSpec {
    let mut spec = preset("ca-waves").unwrap().spec.pattern.clone();
    spec.cells = cells;
    spec.boundary = Boundary::Periodic;
    let Model::Automaton(a) = &mut spec.model else {
        panic!("an automaton preset")
    };
    a.rule = rule.to_string();
    a.start_cells = starts.to_vec();
    a.random_starts = 0;
    spec
}

/// Activity of every cell for `rows` rows.
fn activity(spec: &PatternSpec, rows: usize) -> Vec<Vec<u8>> {
    let Model::Automaton(a) = &spec.model else {
        panic!("an automaton")
    };
    let mut m = Automaton::new(a, spec, 1).unwrap();
    let mut out = vec![m.activity().to_vec()];
    for _ in 1..rows {
        m.advance_row().unwrap();
        out.push(m.activity().to_vec());
    }
    out
}

/// Separate stretches of active cells on a ring.
fn runs(row: &[u8]) -> usize {
    let n = row.len();
    (0..n)
        .filter(|&i| row[i] > 0 && row[(i + n - 1) % n] == 0)
        .count()
}

#[test]
fn under_1_6_8_4_each_start_sends_two_waves_that_annihilate_with_the_others() {
    let rows = activity(&ring("1/6-8/4", 300, &[75, 225]), 200);
    let counts: Vec<usize> = rows.iter().map(|r| runs(r)).collect();
    assert!(
        counts[10..70].iter().all(|&n| n == 4),
        "two waves from each start: {:?}",
        &counts[..80]
    );
    assert!(
        counts[90..].iter().all(|&n| n == 0),
        "after meeting, none is left: {:?}",
        &counts[70..]
    );
}

#[test]
fn the_ring_closes_a_wave_leaving_one_end_enters_the_other() {
    let spec = ring("1/6-8/4", 300, &[5]);
    let periodic = activity(&spec, 40);
    assert!(
        periodic[30][280..].iter().any(|&p| p > 0),
        "the left-going wave reappears at the far end"
    );
    let mut ends = spec.clone();
    ends.boundary = Boundary::ZeroFlux;
    let bounded = activity(&ends, 40);
    assert!(
        bounded[30][280..].iter().all(|&p| p == 0),
        "with closed ends it does not"
    );
}

/// Whether the first right-going front from the start at `from` is still active after it has
/// met the fronts from `other` (it trails its prepigment ramp by about five cells).
fn front_survives(rule: &str) -> f64 {
    let rows = activity(&ring(rule, 400, &[100, 300]), 200);
    let at = |t: usize| (0..5).any(|k| rows[t][(100 + t + k - 7) % 400] > 0);
    (110..190).filter(|&t| at(t)).count() as f64 / 80.0
}

#[test]
fn waves_annihilate_under_1_6_8_4_and_cross_like_solitons_under_1_6_6_5() {
    assert_eq!(front_survives("1/6-8/4"), 0.0);
    let crossing = front_survives("1/6-6/5");
    assert!(
        crossing > 0.7,
        "the 1/6-6/5 front goes on after the collision only {crossing} of the time"
    );
}

#[test]
fn one_start_under_1_6_8_5_becomes_an_oscillator() {
    let rows = activity(&ring("1/6-8/5", 400, &[200]), 180);
    let counts: Vec<usize> = rows.iter().map(|r| runs(r)).collect();
    assert!(
        counts[170] > 10,
        "a sequence of wave fronts: {} stretches",
        counts[170]
    );
    let near_start = |t: usize| rows[t][195..=205].iter().any(|&p| p > 0);
    let pulses = (1..180)
        .filter(|&t| near_start(t) && !near_start(t - 1))
        .count();
    assert!(pulses >= 5, "the start keeps firing ({pulses} times)");
}

#[test]
fn random_starts_come_from_the_seed() {
    let spec = preset("ca-cymbiolacca").unwrap().spec.pattern.clone();
    let first = |seed: u64| build(&spec, seed).unwrap().unwrap().recorded().to_vec();
    assert_eq!(first(4), first(4));
    assert_ne!(first(4), first(5));
}

#[test]
fn bad_rules_and_starts_in_links_get_clear_messages() {
    for (link, key, words) in [
        (
            "v=1&preset=ca-waves&pattern.model.rule=1/6-8",
            "pattern.model.rule",
            "not of the form a/b-c/d",
        ),
        (
            "v=1&preset=ca-waves&pattern.model.rule=custom&pattern.model.f=0,1;0",
            "pattern.model.rule",
            "same",
        ),
        (
            "v=1&preset=ca-waves&pattern.model.rule=custom&pattern.model.f=0,1;0,0&pattern.model.g=0,2;0,1",
            "pattern.model.rule",
            "0 or 1",
        ),
        (
            "v=1&preset=ca-waves&pattern.model.f=0,1;0,0",
            "pattern.model.rule",
            "must be empty",
        ),
        (
            "v=1&preset=ca-waves&pattern.model.start_cells=10,9999",
            "pattern.model.start_cells",
            "beyond",
        ),
        (
            "v=1&preset=ca-waves&pattern.refinement=2",
            "pattern.refinement",
            "discrete",
        ),
    ] {
        let d = decode(link);
        let p = d
            .problems
            .iter()
            .find(|p| p.key == key)
            .unwrap_or_else(|| panic!("{link}: {:?}", d.problems));
        assert!(p.message.contains(words), "{link}: {}", p.message);
        assert!(
            decode(&encode(d.preset, &d.spec)).problems.is_empty(),
            "{link} was repaired into a valid spec"
        );
    }
}

#[test]
fn custom_tables_travel_in_links() {
    let link = "v=1&preset=ca-waves&pattern.model.rule=custom&pattern.model.f=0,1,1,2;0,0,0,1&pattern.model.g=0,0,1;0,1,1";
    let d = decode(link);
    assert!(d.problems.is_empty(), "{:?}", d.problems);
    let Model::Automaton(a) = &d.spec.pattern.model else {
        panic!("automaton")
    };
    assert_eq!(a.f, vec![vec![0, 1, 1, 2], vec![0, 0, 0, 1]]);
    let canonical = "v=1&preset=ca-waves&pattern.model.f=0,1,1,2;0,0,0,1&pattern.model.g=0,0,1;0,1,1&pattern.model.rule=custom";
    assert_eq!(encode(d.preset, &d.spec), canonical);
    assert!(build(&d.spec.pattern, 1).is_ok());
}
