//! Plants, tendrils, corals and tentacles grown by branching (Kawaguchi 1982, "Growth model by
//! branching"): trunks and knots by rule, and the tubes that mesh them.

pub mod branching_mesh;
pub mod branching_tree;
pub(crate) mod repair;
pub mod tendril;
