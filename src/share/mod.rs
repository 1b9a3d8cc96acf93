//! Sharing a shell: the link codec that reproduces a spec exactly (and carries the page's
//! presentation of it: one view or four, the interface an embed shows), the repair of whatever
//! a link or an edit asks that cannot be built, the keys of earlier links now read another way,
//! the parameter map of a shell's variants, breeding shells by choosing among offspring (and
//! the lineage a link carries), the `<iframe>` of an embedded link, and the link's QR
//! code.

pub mod breeding;
pub mod embed;
pub mod lineage;
pub mod link;
pub mod parameter_map;
pub mod presentation;
pub mod qr;
pub mod repair;
mod retired;
pub mod tile;
