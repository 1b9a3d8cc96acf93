//! The pigmentation part of a [`ShellSpec`](super::ShellSpec).

use serde::{Deserialize, Serialize};

/// The pattern computed on the growing edge.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PatternSpec {
    pub model: Model,
}

/// The pattern model.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Model {
    /// No pigmentation: the shell is painted in its ground colour.
    None,
}
