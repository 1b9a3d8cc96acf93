//! Shells, horns, tusks and claws as stacks of similar chambers (Kawaguchi 1982, "Algorithm of
//! three-dimensional small chambers" and "Relationship between two flat surfaces"): the mouth
//! polygon, the similarity from chamber to chamber, and the polyhedral mesh.

pub(crate) mod chamber_mesh;
pub mod chamber_stack;
pub(crate) mod mouth;
pub(crate) mod overlap;
pub(crate) mod repair;
