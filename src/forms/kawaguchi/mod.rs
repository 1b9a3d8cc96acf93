//! Kawaguchi's GROWTH (*A morphological study of the form of nature*, SIGGRAPH 1982): shells,
//! horns, tusks and claws as stacks of similar chambers; plants, tendrils, corals and
//! tentacles grown by branching.

pub mod branching;
pub mod chambers;
pub(crate) mod facet;
