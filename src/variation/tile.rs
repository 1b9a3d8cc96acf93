//! One small shell among many shown side by side, as the parameter map and breeding show
//! them: a variant of a shell, read exactly as a link's values would be, with its link, its
//! picture once computed, and what became of the values that made it.

use crate::forms::sweep::raup::whorls_apart;
use crate::pattern::run::PatternRun;
use crate::presets::Preset;
use crate::share::link;
use crate::spec::form::Form;
use crate::spec::{Problem, ShellSpec};
use serde::{Deserialize, Serialize};

/// One tile: its shell, its link, and its picture once computed (or why there is none).
pub struct Tile {
    pub preset: &'static Preset,
    pub spec: ShellSpec,
    pub link: String,
    /// The pattern's picture, on a map over the pattern model's parameters.
    pub picture: Option<Picture>,
    /// Whether its shell is drawn, where tiles are whole shells (drawn by the page, as a
    /// gallery picture is).
    pub shown: bool,
    /// Why it has no picture: its values cannot grow.
    pub failure: Option<String>,
    /// What else its link changed so that its values can grow (fewer whorls at a faster
    /// growth, say): it is drawn, and this is said beside it.
    pub note: Option<String>,
    /// Whether its whorls lie apart, where tiles are whole shells (a swept shell's open
    /// coiling, which Raup found rare among real shells: the empty side of his cube).
    pub apart: bool,
}

impl Tile {
    pub(crate) fn done(&self) -> bool {
        self.picture.is_some() || self.shown || self.failure.is_some()
    }

    /// Keeps what computing its pattern gave: its picture, or why it has none.
    pub(crate) fn place(&mut self, result: Result<Picture, String>) {
        match result {
            Ok(picture) => self.picture = Some(picture),
            Err(why) => self.failure = Some(why),
        }
    }

    /// Its shell was drawn, or could not be grown for the reason given.
    pub(crate) fn shown(&mut self, result: Result<(), String>) {
        match result {
            Ok(()) => self.shown = true,
            Err(why) => self.failure = Some(why),
        }
    }
}

/// A variant of a shell being made, a few values at a time, each set read as a link's values
/// would be; it remembers the keys it set, so that it can tell a value of its own that could
/// not be kept (the tile is refused) from another value repaired for it (the tile is drawn,
/// and says so).
pub(crate) struct Variant {
    preset: &'static Preset,
    pub(crate) spec: ShellSpec,
    set: Vec<String>,
    problems: Vec<Problem>,
}

impl Variant {
    pub(crate) fn of(preset: &'static Preset, spec: &ShellSpec) -> Self {
        Self {
            preset,
            spec: spec.clone(),
            set: Vec::new(),
            problems: Vec::new(),
        }
    }

    /// Sets the `key=value`s, repaired at once; or keeps why they could not be written.
    pub(crate) fn set(&mut self, pairs: Result<Vec<(String, String)>, Problem>) {
        match pairs {
            Ok(pairs) => {
                self.set.extend(pairs.iter().map(|(k, _)| k.clone()));
                let read = link::with_all(self.preset, &self.spec, pairs);
                self.problems.extend(read.problems);
                (self.preset, self.spec) = (read.preset, read.spec);
            }
            Err(refused) => {
                self.set.push(refused.key.clone());
                self.problems.push(refused);
            }
        }
    }

    /// Whether a value it set could not be kept.
    pub(crate) fn refused(&self) -> bool {
        self.problems.iter().any(|p| self.set.contains(&p.key))
    }

    /// The tile of this variant; `shells` when tiles are whole shells, not patterns.
    pub(crate) fn tile(self, shells: bool) -> Tile {
        let (refused, repaired): (Vec<&Problem>, Vec<&Problem>) = self
            .problems
            .iter()
            .partition(|p| self.set.contains(&p.key));
        let words = |problems: Vec<&Problem>| {
            let words: Vec<String> = problems.iter().map(ToString::to_string).collect();
            (!words.is_empty()).then(|| words.join("; "))
        };
        let apart =
            shells && matches!(&self.spec.form, Form::Sweep(s) if whorls_apart(s) == Some(true));
        Tile {
            preset: self.preset,
            link: link::encode(self.preset, &self.spec),
            failure: words(refused),
            note: words(repaired),
            spec: self.spec,
            picture: None,
            shown: false,
            apart,
        }
    }
}

/// A tile's picture: RGBA pixels, each the mean of a block of cells and rows.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Picture {
    pub width: usize,
    pub height: usize,
    #[serde(with = "crate::pod_bytes")]
    pub rgba: Vec<u8>,
}

impl Picture {
    /// The pattern of `run` as the planar view shows it, averaged over blocks of `block` ×
    /// `block` cells and rows.
    pub(crate) fn of(run: &PatternRun, block: usize) -> Self {
        let (cells, rows, rgba) = (run.cells(), run.rows(), run.planar());
        let (width, height) = (cells.div_ceil(block), rows.div_ceil(block));
        let mut out = vec![0u8; width * height * 4];
        for (py, line) in out.chunks_exact_mut(width * 4).enumerate() {
            for (px, pixel) in line.chunks_exact_mut(4).enumerate() {
                let mut sum = [0u32; 4];
                let mut count = 0;
                for r in py * block..((py + 1) * block).min(rows) {
                    for c in px * block..((px + 1) * block).min(cells) {
                        let at = (r * cells + c) * 4;
                        for (s, &v) in sum.iter_mut().zip(&rgba[at..at + 4]) {
                            *s += u32::from(v);
                        }
                        count += 1;
                    }
                }
                for (p, s) in pixel.iter_mut().zip(sum) {
                    *p = ((s + count / 2) / count) as u8;
                }
            }
        }
        Self {
            width,
            height,
            rgba: out,
        }
    }
}
