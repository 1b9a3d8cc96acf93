//! The swept shell of Fowler, Meinhardt & Prusinkiewicz 1992, §2: a generating curve (Bézier,
//! reparametrized by arc length) laid on a frame of the helico-spiral, sculptured, swept rim by
//! rim into a mesh.

pub(crate) mod arc_length;
pub(crate) mod bezier_curve;
pub(crate) mod drawn_size;
pub mod frame;
pub mod helico_spiral;
pub mod raup;
pub(crate) mod repair;
pub(crate) mod sculpture;
pub mod surface;
pub(crate) mod sweep_mesh;
