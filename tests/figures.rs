//! The papers' figures beside ours (species/papers/figures.json joined with the presets and
//! stories): every figure is either reproduced by a preset or says why not, never both; every
//! figure a preset or a story names is one its paper has; every figure is numbered once.

use seashells_core::papers::papers;
use seashells_core::presets::presets;
use seashells_core::stories::stories;

#[test]
fn every_figure_is_reproduced_or_says_why_not() {
    assert_eq!(papers().len(), 4, "the four papers");
    for paper in papers() {
        let mut numbers: Vec<u32> = paper.figures.iter().map(|f| f.number).collect();
        numbers.dedup();
        assert_eq!(
            numbers.len(),
            paper.figures.len(),
            "{}: a figure twice",
            paper.source
        );
        assert!(
            numbers.windows(2).all(|w| w[0] < w[1]),
            "{}: in order",
            paper.source
        );
        for shown in paper.shown() {
            let f = shown.figure;
            assert!(
                !f.caption.trim().is_empty(),
                "{} fig. {}",
                paper.source,
                f.number
            );
            match (&f.why_not, shown.presets.is_empty()) {
                (None, true) => panic!("{} fig. {}: no preset, and no why", paper.source, f.number),
                (Some(why), false) => panic!(
                    "{} fig. {}: reproduced by {:?}, yet says why not: {why}",
                    paper.source,
                    f.number,
                    shown.presets.iter().map(|p| p.id).collect::<Vec<_>>()
                ),
                _ => {}
            }
        }
    }
}

#[test]
fn every_figure_a_preset_or_a_story_names_is_one_its_paper_has() {
    let named = |source: &str| -> Vec<(String, u32)> {
        papers()
            .iter()
            .flat_map(|p| p.names(source).into_iter().map(|n| (p.source.clone(), n)))
            .collect()
    };
    let has = |paper: &str, n: u32| {
        papers()
            .iter()
            .any(|p| p.source == paper && p.figures.iter().any(|f| f.number == n))
    };
    let mut sources: Vec<(String, String)> = presets()
        .iter()
        .map(|p| (p.id.to_string(), p.source.clone()))
        .collect();
    for s in stories() {
        for (i, step) in s.steps.iter().enumerate() {
            if let Some(figure) = &step.figure {
                sources.push((format!("story {} step {}", s.id, i + 1), figure.clone()));
            }
        }
    }
    for (who, source) in sources {
        let names_a_figure = source.contains("fig. ") || source.contains("figs. ");
        let found = named(&source);
        assert_eq!(
            !found.is_empty(),
            names_a_figure,
            "{who}: '{source}' names a figure of no paper listed"
        );
        for (paper, n) in found {
            assert!(has(&paper, n), "{who}: {paper} has no fig. {n}");
        }
    }
}

#[test]
fn a_source_names_one_figure_or_a_range() {
    let paper = &papers()[0];
    let at = |tail: &str| paper.names(&format!("{}{tail}", paper.source));
    assert_eq!(at(", fig. 2 (leftmost)"), [2]);
    assert_eq!(at(", figs. 7–9"), [7, 8, 9]);
    assert_eq!(at(", fig. 4-5"), [4, 5]);
    assert_eq!(at(", §3"), Vec::<u32>::new());
    assert_eq!(paper.names("Kawaguchi 1982, fig. 3"), Vec::<u32>::new());
}
