//! A shell's variants to look through and choose among: the parameter map, a grid of the
//! shell's neighbours over any two fields (Raup's W, D and T among them), and breeding, a
//! generation of offspring mutated from a parent, one of which the user chooses as the next
//! parent (the lineage a link carries is the link codec's, `share::lineage`). Each variant is
//! a tile: its link, and its picture once computed.

pub mod breeding;
pub mod map_plan;
pub mod parameter_map;
pub mod tile;
pub mod tile_grid;
