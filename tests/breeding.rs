//! Breeding shells: a parent among eight offspring, each a few of its numbers moved, the same
//! from the same parent natively and in wasm; a lineage replayed from its link, Back, and bad
//! lineages read as far as they can be; every offspring of every preset a link that reopens it
//! with nothing to say, and whose shell grows.

use seashells_core::generator::Generator;
use seashells_core::presets::{preset, presets};
use seashells_core::share::lineage::{Lineage, MAX_CHOICES, OFFSPRING, RATES};
use seashells_core::share::link::{decode, flatten};
use seashells_core::spec::ShellSpec;
use seashells_core::spec::fields::Kind;
use seashells_core::variation::breeding::{Breeding, PARENT};
use seashells_core::view::picture::{TILE_PIXELS, picture_spec};
use std::collections::BTreeMap;

fn leaves(spec: &ShellSpec) -> BTreeMap<String, serde_json::Value> {
    flatten(&serde_json::to_value(spec).unwrap())
}

/// The keys whose values differ between two specs.
fn differing(a: &ShellSpec, b: &ShellSpec) -> Vec<String> {
    let (a, b) = (leaves(a), leaves(b));
    a.keys()
        .filter(|k| a.get(*k) != b.get(*k))
        .cloned()
        .collect()
}

#[test]
fn offspring_change_a_few_numbers_of_the_parent_and_are_the_same_every_time() {
    let oliva = preset("oliva-porphyria").unwrap();
    let (first, problems) = Breeding::new(oliva, &oliva.spec, &Lineage::default());
    assert!(problems.is_empty(), "{problems:?}");
    let (again, _) = Breeding::new(oliva, &oliva.spec, &Lineage::default());
    assert_eq!(first.tiles().len(), OFFSPRING + 1);
    assert_eq!(first.generation(), 1);
    assert_eq!(
        first.parent().spec,
        oliva.spec,
        "the parent stands in the middle"
    );
    assert!(first.changes(PARENT).is_empty());
    let mut links = std::collections::BTreeSet::new();
    for (index, tile) in first.tiles().iter().enumerate() {
        assert_eq!(
            tile.link,
            again.tiles()[index].link,
            "tile {index} is the same again"
        );
        links.insert(tile.link.clone());
        if index == PARENT {
            continue;
        }
        assert_eq!(tile.failure, None, "tile {index}");
        // One to three genes, and what hid one of them (ribs of no height, say).
        let changes = first.changes(index);
        assert!((1..=6).contains(&changes.len()), "{changes:?}");
        let mut changed = differing(&oliva.spec, &tile.spec);
        changed.sort();
        let mut said: Vec<String> = changes.iter().map(|c| c.field.key.to_string()).collect();
        said.sort();
        // A change may repair another value (fewer whorls at a faster rate): that is its note.
        assert!(
            said.iter().all(|k| changed.contains(k)),
            "tile {index}: {said:?} within {changed:?}"
        );
        assert_eq!(
            said.len() == changed.len(),
            tile.note.is_none(),
            "tile {index}"
        );
        for change in changes {
            assert_eq!(
                leaves(&tile.spec)[change.field.key].as_f64(),
                Some(change.to)
            );
            assert_ne!(change.from, change.to);
        }
        let opened = decode(&tile.link);
        assert!(opened.problems.is_empty(), "{:?}", opened.problems);
        assert_eq!(opened.spec, tile.spec, "its link reopens it");
    }
    assert_eq!(links.len(), OFFSPRING + 1, "nine different shells");
    let other = preset("volutoconus-bednalli").unwrap();
    let (theirs, _) = Breeding::new(other, &other.spec, &Lineage::default());
    let moved = |b: &Breeding, i: usize| -> Vec<&str> {
        b.changes(i).iter().map(|c| c.field.key).collect()
    };
    assert!(
        (0..OFFSPRING + 1).any(|i| moved(&first, i) != moved(&theirs, i)),
        "another parent's offspring are drawn from another stream"
    );
}

#[test]
fn a_lineage_replays_from_its_link_and_back_returns_to_the_generation_before() {
    let turbinate = preset("turbinate").unwrap();
    let (first, _) = Breeding::new(turbinate, &turbinate.spec, &Lineage::default());
    let chosen = Lineage::default().choose(3);
    let (second, problems) = Breeding::new(turbinate, &turbinate.spec, &chosen);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(second.generation(), 2);
    assert_eq!(
        second.parent().spec,
        first.tiles()[2].spec,
        "offspring 3 is now the parent"
    );
    let third_lineage = chosen.at_rate(0.8).choose(6);
    let (third, _) = Breeding::new(turbinate, &turbinate.spec, &third_lineage);
    assert_eq!(third.parent().spec, {
        let (at_rate, _) = Breeding::new(turbinate, &turbinate.spec, &chosen.at_rate(0.8));
        at_rate.tiles()[6].spec.clone()
    });
    let link = third.link(&third.lineage);
    assert!(link.ends_with("&breed=0.4/3,0.8/6,0.8"), "{link}");
    let opened = decode(&link);
    assert!(opened.problems.is_empty(), "{:?}", opened.problems);
    assert_eq!(
        opened.spec, turbinate.spec,
        "the link holds the first shell"
    );
    assert_eq!(opened.lineage.as_ref(), Some(&third_lineage));
    let back = third_lineage.back().unwrap();
    assert_eq!(back, chosen.at_rate(0.8));
    let (behind, _) = Breeding::new(turbinate, &turbinate.spec, &back);
    assert_eq!(behind.parent().spec, second.parent().spec);
    assert_eq!(
        Lineage::default().back(),
        None,
        "nothing before the first shell"
    );
}

#[test]
fn a_bad_lineage_is_read_as_far_as_it_goes_and_says_why() {
    let (read, problems) = Lineage::parse("0.4/3,9/2,0.3/11,0.5");
    assert_eq!(read.chosen, [(0.4, 3), (RATES.1, 2)]);
    let words: Vec<String> = problems.iter().map(ToString::to_string).collect();
    assert!(words[0].contains("9 is outside"), "{words:?}");
    assert!(words[1].contains("'11' is not an offspring"), "{words:?}");
    let (read, problems) = Lineage::parse("fast");
    assert_eq!(read, Lineage::default());
    assert!(
        problems[0]
            .to_string()
            .contains("'fast' is not a mutation rate")
    );
    // A lineage too long to replay at once is followed as far as the cap.
    let long = vec!["0.4/1"; MAX_CHOICES + 50].join(",") + ",0.4";
    let (read, problems) = Lineage::parse(&long);
    assert_eq!(read.chosen.len(), MAX_CHOICES);
    assert!(
        problems[0].to_string().contains("more than 100 choices"),
        "{problems:?}"
    );
    let turbinate = preset("turbinate").unwrap();
    let (far, _) = Breeding::new(turbinate, &turbinate.spec, &read);
    assert_eq!(far.generation(), MAX_CHOICES + 1);
    let opened = decode("v=1&preset=turbinate&breed=0.4/x");
    assert_eq!(opened.lineage.unwrap().chosen, []);
    assert_eq!(opened.problems.len(), 1, "{:?}", opened.problems);
    assert_eq!(opened.problems[0].key, "breed");
}

#[test]
fn a_higher_rate_moves_the_same_numbers_further() {
    let conus = preset("conus-marmoreus").unwrap();
    let bred = |rate: f64| Breeding::new(conus, &conus.spec, &Lineage::default().at_rate(rate)).0;
    let (slow, fast) = (bred(0.1), bred(1.0));
    // The same draws at either rate: the same genes move, ten times as far on their scale (a
    // gene that hid another moves it a whole step at least; an integer moves by one at least).
    let mut ratios = Vec::new();
    for i in (0..OFFSPRING + 1).filter(|&i| i != PARENT) {
        for s in slow.changes(i) {
            let Some(f) = fast.changes(i).iter().find(|f| f.field.key == s.field.key) else {
                continue;
            };
            let far = |c: &seashells_core::variation::breeding::Change| match c.field.kind {
                Kind::Real { log: true, .. } if c.from > 0.0 => (c.to / c.from).ln().abs(),
                _ => (c.to - c.from).abs(),
            };
            assert!(far(f) >= far(s), "{s} at 0.1, {f} at 1");
            ratios.push(far(f) / far(s));
        }
    }
    ratios.sort_by(f64::total_cmp);
    assert!(ratios.len() >= 6, "{ratios:?}");
    let median = ratios[ratios.len() / 2];
    assert!(median > 4.0, "{ratios:?}");
}

/// Three generations from every preset, always the first offspring that can grow: every
/// offspring reopens from its link, saying nothing its tile does not; the third chosen of the first preset of
/// each form grows whole, as a tile draws it.
#[test]
fn every_presets_offspring_are_links_that_reopen_and_grow() {
    let mut kinds_grown = Vec::new();
    for p in presets() {
        let mut lineage = Lineage::default();
        for generation in 1..=3 {
            let (b, problems) = Breeding::new(p, &p.spec, &lineage);
            assert!(problems.is_empty(), "{}: {problems:?}", p.id);
            let mut chosen = None;
            for (index, tile) in b.tiles().iter().enumerate() {
                if tile.failure.is_some() {
                    continue;
                }
                // What the link says on opening (whorls that overlap, say) the tile says too.
                let opened = decode(&tile.link);
                for problem in &opened.problems {
                    let note = tile.note.as_deref().unwrap_or_default();
                    assert!(
                        note.contains(&problem.message),
                        "{} generation {generation} tile {index}: {problem} not in '{note}'",
                        p.id,
                    );
                }
                assert_eq!(opened.spec, tile.spec);
                if chosen.is_none() && index != PARENT {
                    chosen = Some(index);
                }
            }
            let index = chosen.unwrap_or_else(|| panic!("{}: every offspring refused", p.id));
            lineage = lineage.choose(Breeding::child(index).unwrap());
            let kind = p.spec.form.kind();
            if generation == 3 && !kinds_grown.contains(&kind) {
                kinds_grown.push(kind);
                let spec = picture_spec(&b.tiles()[index].spec, TILE_PIXELS);
                let mut grown = Generator::new(&spec).expect("the chosen offspring builds");
                while !grown.is_done() && grown.failure().is_none() {
                    grown.advance(64);
                }
                assert_eq!(grown.failure(), None, "{}", p.id);
                let mesh = grown.mesh();
                assert!(!mesh.indices.is_empty(), "{}", p.id);
                assert!(
                    mesh.vertices
                        .iter()
                        .all(|v| v.position.iter().all(|x| x.is_finite())),
                    "{}",
                    p.id
                );
            }
        }
    }
    assert!(kinds_grown.len() >= 4, "{kinds_grown:?}");
}

#[test]
fn the_parent_keeps_itself_and_each_offspring_says_what_it_changed_and_breeds_on() {
    let oliva = preset("oliva-porphyria").unwrap();
    let (breeding, _) = Breeding::new(oliva, &oliva.spec, &Lineage::default());
    let (parent, keep) = breeding.label(PARENT);
    assert_eq!(parent, "The parent, generation 1: open it to keep it");
    assert_eq!(keep.as_deref(), Some(breeding.parent().link.as_str()));
    for index in (0..breeding.tiles().len()).filter(|&i| i != PARENT) {
        let (label, href) = breeding.label(index);
        let child = Breeding::child(index).unwrap();
        assert!(
            label.starts_with(&format!("Offspring {child}: ")),
            "{label}"
        );
        for change in breeding.changes(index) {
            assert!(label.contains(&change.to_string()), "{label}");
        }
        let opens = href.expect("an offspring that grows opens");
        let decoded = decode(&opens);
        assert_eq!(decoded.lineage.map(|l| l.chosen.len()), Some(1), "{opens}");
    }
    assert!(breeding.status().starts_with("Generation 1."));
}

#[test]
fn a_slow_machine_draws_fewer_offspring_and_says_why() {
    use seashells_core::variation::breeding::offspring_for;
    assert_eq!(offspring_for(None), OFFSPRING, "not timed yet: all of them");
    assert_eq!(
        offspring_for(Some(0.14)),
        OFFSPRING,
        "software rendering here"
    );
    assert_eq!(
        offspring_for(Some(5.0)),
        3,
        "parent and 3 offspring in 20 s"
    );
    assert_eq!(offspring_for(Some(60.0)), 2, "never fewer than two");
    let turbinate = preset("turbinate").unwrap();
    let lineage = Lineage {
        chosen: Vec::new(),
        rate: 0.4,
    };
    let (mut breeding, _) = Breeding::new(turbinate, &turbinate.spec, &lineage);
    breeding.pace(Some(0.14), |_| false);
    assert!(breeding.tiles().iter().all(|t| t.failure.is_none()));
    // The sixth offspring's picture is at hand (a generation gone back to): shown too.
    let sixth = breeding.tiles()[6].link.clone();
    breeding.pace(Some(5.0), |tile| tile.link == sixth);
    for (index, tile) in breeding.tiles().iter().enumerate() {
        let drawn = Breeding::child(index).is_none_or(|child| child <= 3 || child == 6);
        assert_eq!(
            tile.failure.is_none(),
            drawn,
            "tile {index}: {:?}",
            tile.failure
        );
        if !drawn {
            let why = tile.failure.as_deref().unwrap_or_default();
            assert!(why.starts_with("not drawn: "), "{why}");
            assert!(breeding.label(index).1.is_none(), "not chosen blind");
        }
    }
    assert!(
        breeding.status().contains("3 of 8 offspring drawn"),
        "{}",
        breeding.status()
    );
}
