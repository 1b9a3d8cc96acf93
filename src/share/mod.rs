//! Sharing a shell: the link codec that reproduces a spec exactly (and carries the page's
//! presentation of it), the repair of whatever a link or an edit asks that cannot be built, and
//! the parameter map of pattern previews.

pub mod link;
pub mod parameter_map;
pub mod presentation;
pub mod repair;
mod retired;
