//! Sharing a shell: the link codec that reproduces a spec exactly, the repair of whatever a
//! link or an edit asks that cannot be built, and the parameter map of pattern previews.

pub mod link;
pub mod parameter_map;
pub mod repair;
mod retired;
