//! Sharing a shell: the link codec that reproduces a spec exactly, the repair of whatever a
//! link or an edit asks that cannot be built, the parameter map of pattern previews, the
//! interface an embedded link asks for and its `<iframe>`, and the link's QR code.

pub mod embed;
pub mod link;
pub mod parameter_map;
pub mod qr;
pub mod repair;
