//! The preview of a pattern slider being dragged: the whole pattern of the values passed,
//! computed from its first row a frame's budget at a time, while the shell's growth waits. It
//! fills, is whole, or has stopped where the values drive the model out of range, and a
//! stopped preview never resumes.

use crate::pattern::PatternError;
use crate::pattern::run::PatternRun;
use serde::{Deserialize, Serialize};

/// Where a preview stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PreviewState {
    Filling,
    Whole,
    Stopped,
}

impl PreviewState {
    /// The word the page signals for it.
    pub fn signal(self) -> &'static str {
        match self {
            PreviewState::Filling => "filling",
            PreviewState::Whole => "whole",
            PreviewState::Stopped => "stopped",
        }
    }
}

/// The whole pattern of a spec being edited.
pub struct Preview {
    run: PatternRun,
    rows: usize,
    failed: bool,
}

impl Preview {
    /// The preview of `run` up to `rows` rows.
    pub fn new(run: PatternRun, rows: usize) -> Self {
        Self {
            run,
            rows,
            failed: false,
        }
    }

    /// Computes rows while `keep_going` says so, until all are done or the pattern fails.
    /// Returns the first row this call computed, and why the pattern stopped if it stopped now.
    pub fn fill(&mut self, mut keep_going: impl FnMut() -> bool) -> (usize, Option<PatternError>) {
        let first = self.run.rows();
        while !self.failed && self.run.rows() < self.rows && keep_going() {
            if let Err(e) = self.run.advance() {
                self.failed = true;
                return (first, Some(e));
            }
        }
        (first, None)
    }

    /// The pattern so far.
    pub fn run(&self) -> &PatternRun {
        &self.run
    }

    pub fn state(&self) -> PreviewState {
        if self.failed {
            PreviewState::Stopped
        } else if self.run.rows() < self.rows {
            PreviewState::Filling
        } else {
            PreviewState::Whole
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generator::{RimLengths, pattern_alone};
    use crate::presets::preset;
    use crate::spec::pattern::Model;

    /// A `keep_going` that allows `n` rows.
    fn rows(n: usize) -> impl FnMut() -> bool {
        let mut left = n;
        move || {
            let go = left > 0;
            left = left.saturating_sub(1);
            go
        }
    }

    #[test]
    fn a_preview_fills_frame_by_frame_to_the_whole_pattern() {
        let spec = &preset("oliva-porphyria").expect("the Oliva").spec;
        let run = pattern_alone(spec, &mut RimLengths::default())
            .expect("a pattern")
            .expect("a model");
        let total = spec.growth.rows as usize;
        let mut preview = Preview::new(run, total);
        assert_eq!(preview.state(), PreviewState::Filling);
        let (first, failure) = preview.fill(rows(100));
        assert_eq!((first, failure), (1, None), "row 0 is the start");
        assert_eq!(preview.run().rows(), 101);
        assert_eq!(preview.state(), PreviewState::Filling);
        while preview.state() == PreviewState::Filling {
            preview.fill(rows(500));
        }
        assert_eq!(preview.state(), PreviewState::Whole);
        assert_eq!(preview.run().rows(), total);
        assert_eq!(
            preview.fill(|| true).0,
            total,
            "a whole preview computes nothing"
        );
    }

    #[test]
    fn a_stopped_preview_says_why_and_never_resumes() {
        let mut spec = preset("oliva-porphyria").expect("the Oliva").spec.clone();
        let Model::ActivatorInhibitor(m) = &mut spec.pattern.model else {
            panic!("eq 9")
        };
        // Unsaturated autocatalysis (κ = 0) against an inhibitor it outruns.
        m.kappa = 0.0;
        m.rho = 5.0;
        let run = pattern_alone(&spec, &mut RimLengths::default())
            .expect("stable diffusion")
            .expect("a model");
        let mut preview = Preview::new(run, spec.growth.rows as usize);
        let (_, failure) = preview.fill(|| true);
        let failure = failure.expect("the pattern stops");
        assert!(failure.to_string().contains("row"), "{failure}");
        assert_eq!(preview.state(), PreviewState::Stopped);
        let stopped_at = preview.run().rows();
        assert_eq!(preview.fill(|| true), (stopped_at, None));
        assert_eq!(preview.run().rows(), stopped_at);
    }
}
