//! The shape part of a [`ShellSpec`](super::ShellSpec): which model builds the surface, and its
//! parameters, one file per form: the swept surface of Fowler et al. 1992 §2 (`sweep`),
//! Kawaguchi's accumulated chambers and branching forms, 1982 (`chambers`, `branching`), and the
//! implicit surfaces of Galbraith, Prusinkiewicz & Wyvill (`implicit`). A new form is a new
//! file here and a variant of [`Form`].

pub mod branching;
pub mod chambers;
pub mod implicit;
pub mod sweep;
pub mod textures;

use branching::BranchingSpec;
use chambers::ChambersSpec;
use implicit::ImplicitSpec;
use serde::{Deserialize, Serialize};
use sweep::SweepSpec;

/// The model that builds the shell's surface.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Form {
    /// A generating curve swept along a helico-spiral (Fowler et al. 1992, §2).
    Sweep(SweepSpec),
    /// A stack of similar chambers (Kawaguchi 1982, "Shells' growth model").
    Chambers(ChambersSpec),
    /// Trunks, knots and branches (Kawaguchi 1982, "Growth model by branching").
    Branching(BranchingSpec),
    /// Generating surfaces of skeletal primitives blended along a helico-spiral (Galbraith,
    /// Prusinkiewicz & Wyvill, §3.1).
    Implicit(ImplicitSpec),
}

impl Form {
    /// The name of the form's kind, as `form.kind` writes it.
    pub fn kind(&self) -> &'static str {
        match self {
            Form::Sweep(_) => "sweep",
            Form::Chambers(_) => "chambers",
            Form::Branching(_) => "branching",
            Form::Implicit(_) => "implicit",
        }
    }
}
