//! The swept shell of Fowler, Meinhardt & Prusinkiewicz 1992, §2: a generating curve (Bézier,
//! reparametrized by arc length) laid on a frame of the helico-spiral, sculptured, swept rim by
//! rim into a mesh.

pub mod arc_length;
pub mod bezier_curve;
pub mod frame;
pub mod helico_spiral;
pub(crate) mod repair;
pub mod sculpture;
pub mod surface;
pub mod sweep_mesh;
