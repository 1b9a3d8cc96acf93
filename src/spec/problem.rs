//! What could not be used as given in a spec (a link's value, a preset's field, a value that
//! breaks a cap or another field's limit): the key concerned, what was wrong and what was used
//! instead; or what was used as asked but read another way, or shown but not to be written to a
//! file. Links, the panel and the command line all report these.

use std::fmt;

/// Something a link asked for that could not be used as given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// The key concerned, or "link" for the link as a whole.
    pub key: String,
    /// What was wrong, and what was used instead.
    pub message: String,
    /// What became of what was asked.
    pub said: Said,
}

/// What became of the value a problem concerns, from the least to the most it changed: the
/// page says each kind apart, and the command line writes only what no problem changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Said {
    /// Only read another way, meaning the same shell (a key of an earlier version, converted):
    /// a note.
    ReadAs,
    /// Used as asked, and shown so, but no file is written of it (whorls that overlap).
    Shown,
    /// Not used: something else was, which the message names.
    Changed,
}

impl Problem {
    pub fn new(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            key: key.into(),
            message: message.into(),
            said: Said::Changed,
        }
    }

    /// A value read another way that means the same shell.
    pub fn read_as(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            said: Said::ReadAs,
            ..Self::new(key, message)
        }
    }

    /// A value used as asked and shown, of which no file is written.
    pub fn shown(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            said: Said::Shown,
            ..Self::new(key, message)
        }
    }

    /// What the page says of a link's problems, each kind apart: what was not used and what
    /// was used instead, what is shown but written to no file, and what was only read another
    /// way; none when there is nothing to say.
    pub fn report(problems: &[Problem]) -> Option<String> {
        let parts: Vec<String> = [
            (
                Said::Changed,
                "Parts of this link could not be used as given",
            ),
            (Said::Shown, "Shown as asked, but"),
            (Said::ReadAs, "Read as today's keys"),
        ]
        .into_iter()
        .filter_map(|(said, heading)| {
            let list: Vec<String> = problems
                .iter()
                .filter(|p| p.said == said)
                .map(ToString::to_string)
                .collect();
            (!list.is_empty()).then(|| format!("{heading}: {}.", list.join("; ")))
        })
        .collect();
        (!parts.is_empty()).then(|| parts.join(" "))
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for Problem {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_report_says_each_kind_apart_and_nothing_of_none() {
        assert_eq!(Problem::report(&[]), None);
        let report = Problem::report(&[
            Problem::read_as("form.chamber.translation", "read as width H = 1"),
            Problem::shown("form.chamber.ratio", "whorls overlap"),
            Problem::new("form.chambers", "at most 13; used 13"),
            Problem::new("seed", "not a number; used 1"),
        ]);
        assert_eq!(
            report.as_deref(),
            Some(
                "Parts of this link could not be used as given: form.chambers: at most 13; used 13; seed: not a number; used 1. \
                 Shown as asked, but: form.chamber.ratio: whorls overlap. \
                 Read as today's keys: form.chamber.translation: read as width H = 1."
            )
        );
        let overlap = Problem::report(&[Problem::shown("form.chamber.ratio", "whorls overlap")]);
        assert_eq!(
            overlap.as_deref(),
            Some("Shown as asked, but: form.chamber.ratio: whorls overlap.")
        );
    }
}
