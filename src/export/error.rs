//! Why a file cannot be exported, in words that name what to change.

use crate::spec::problem::Problem;
use std::fmt;

/// Why an export was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum ExportError {
    /// Nothing has grown that has a surface: no triangles, or only collapsed ones.
    Empty,
    /// Growth stopped early; the message says why.
    Failed(String),
    /// Some coordinate or normal of the grown mesh is not a finite number: values whose
    /// product runs out of range (no file may carry it).
    NotFinite,
    /// The form passes through itself (whorls that overlap): the problem names the key and
    /// the fix.
    Overlap(Problem),
    /// A closed solid was needed (3MF, for printing) and the surface is open: a swept shell
    /// with no wall is a single surface.
    Open { key: &'static str },
    /// The print size (mm) is outside what makes sense.
    Size {
        key: &'static str,
        mm: f64,
        min: f64,
        max: f64,
    },
}

impl fmt::Display for ExportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExportError::Empty => write!(
                f,
                "there is nothing to export yet: the shell has no surface (let it grow first)"
            ),
            ExportError::Failed(why) => write!(
                f,
                "this shell stopped growing before its end, so there is no whole shell to \
                 export ({})",
                why.trim_end_matches('.')
            ),
            ExportError::NotFinite => write!(
                f,
                "this shell's values make it grow out of the range of numbers (some of its \
                 coordinates are not finite), so no file is written: bring the values you \
                 changed back towards the preset's"
            ),
            ExportError::Overlap(problem) => write!(f, "{problem}"),
            ExportError::Open { key } => write!(
                f,
                "3MF holds closed solids for printing, and this shell is an open surface: give \
                 it a wall ({key} above 0)"
            ),
            ExportError::Size { key, mm, min, max } if mm.is_finite() => write!(
                f,
                "{key}: {mm} mm is outside the sizes an exported shell may have, {min} to \
                 {max} mm"
            ),
            ExportError::Size { key, min, max, .. } => write!(
                f,
                "{key}: give the exported shell's size in millimetres, from {min} to {max}"
            ),
        }
    }
}

impl std::error::Error for ExportError {}
