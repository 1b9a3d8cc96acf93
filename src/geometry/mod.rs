//! Shell geometry of Fowler, Meinhardt & Prusinkiewicz 1992, §2.

pub mod arc_length;
pub mod bezier_curve;
pub mod frame;
pub mod helico_spiral;
pub mod sculpture;
pub mod sweep;
pub mod sweep_mesh;
