//! The papers' figures beside ours: each paper's figures (species/papers/figures.json: its number and
//! its caption in our words, and for a figure no preset reproduces, why), joined with the
//! presets whose source names the figure and the stories' steps that show it. Built from the
//! presets' and stories' own `source` and `figure`, so that the list cannot drift from them.

use crate::presets::{Preset, presets};
use crate::stories::{Story, stories};
use serde::Deserialize;
use std::sync::OnceLock;

/// One paper, as species/papers/figures.json lists it.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Paper {
    /// How the presets' sources name the paper, before ", fig. N".
    pub source: String,
    pub title: String,
    pub figures: Vec<Figure>,
}

/// One figure of a paper.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Figure {
    pub number: u32,
    /// What the figure shows, in our words.
    pub caption: String,
    /// Why no preset reproduces it (none: some preset does).
    #[serde(default)]
    pub why_not: Option<String>,
}

/// A figure with what shows it here.
pub struct Shown<'a> {
    pub figure: &'a Figure,
    /// The presets whose source names the figure.
    pub presets: Vec<&'static Preset>,
    /// The stories' steps (counted from 0) whose figure is this one.
    pub steps: Vec<(&'static Story, usize)>,
}

/// Every paper of species/papers/figures.json. A file that does not parse is a build defect, caught by
/// the native tests; here it panics.
pub fn papers() -> &'static [Paper] {
    static PAPERS: OnceLock<Vec<Paper>> = OnceLock::new();
    PAPERS.get_or_init(|| {
        let json = include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/species/papers/figures.json"
        ));
        serde_json::from_str(json).unwrap_or_else(|e| panic!("species/papers/figures.json: {e}"))
    })
}

impl Paper {
    /// Each of the paper's figures with the presets and the stories' steps that show it.
    pub fn shown(&self) -> Vec<Shown<'_>> {
        self.figures
            .iter()
            .map(|figure| Shown {
                figure,
                presets: presets()
                    .iter()
                    .filter(|p| self.names(&p.source).contains(&figure.number))
                    .collect(),
                steps: stories()
                    .iter()
                    .flat_map(|s| {
                        s.steps
                            .iter()
                            .enumerate()
                            .map(move |(i, step)| (s, i, step))
                    })
                    .filter(|(_, _, step)| {
                        step.figure
                            .as_deref()
                            .is_some_and(|f| self.names(f).contains(&figure.number))
                    })
                    .map(|(s, i, _)| (s, i))
                    .collect(),
            })
            .collect()
    }

    /// The figures of this paper that `source` names ("<paper>, fig. 2 (leftmost)", "<paper>,
    /// figs. 7–14"): none when it names another paper or no figure.
    pub fn names(&self, source: &str) -> Vec<u32> {
        let Some(rest) = source.strip_prefix(self.source.as_str()) else {
            return Vec::new();
        };
        let Some(numbers) = rest
            .strip_prefix(", figs. ")
            .or_else(|| rest.strip_prefix(", fig. "))
        else {
            return Vec::new();
        };
        let number = |s: &str| {
            let digits: String = s.chars().take_while(char::is_ascii_digit).collect();
            digits.parse::<u32>().ok()
        };
        let Some(first) = number(numbers) else {
            return Vec::new();
        };
        let after = &numbers[first.to_string().len()..];
        let last = after
            .strip_prefix('–')
            .or_else(|| after.strip_prefix('-'))
            .and_then(number)
            .unwrap_or(first);
        (first..=last.max(first)).collect()
    }
}
