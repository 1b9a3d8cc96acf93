//! Sharing a shell: the link codec that reproduces a spec exactly (and carries the page's
//! presentation of it: one view or four, the interface an embed shows), the repair of whatever
//! a link or an edit asks that cannot be built, the keys of earlier links now read another way,
//! the lineage of shells bred from one that a link carries (breeding itself is
//! `crate::variation`'s), the `<iframe>` of an embedded link, and the link's QR code.

pub mod embed;
pub mod lineage;
pub mod link;
pub mod presentation;
pub mod qr;
pub mod repair;
mod retired;
