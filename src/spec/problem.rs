//! What could not be used as given in a spec (a link's value, a preset's field, a value that
//! breaks a cap or another field's limit): the key concerned, what was wrong and what was used
//! instead. Links, the panel and the command line all report these.

use std::fmt;

/// Something a link asked for that could not be used as given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// The key concerned, or "link" for the link as a whole.
    pub key: String,
    /// What was wrong, and what was used instead.
    pub message: String,
    /// Whether the value was only read another way, meaning the same shell (a key of an
    /// earlier version, converted): a note, where every other problem changed what was asked.
    pub same_shell: bool,
}

impl Problem {
    pub fn new(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            key: key.into(),
            message: message.into(),
            same_shell: false,
        }
    }

    /// A value read another way that means the same shell.
    pub fn read_as(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            same_shell: true,
            ..Self::new(key, message)
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for Problem {}
