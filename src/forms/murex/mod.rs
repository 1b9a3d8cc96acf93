//! The implicit shell of Galbraith, Prusinkiewicz & Wyvill, *Modeling a Murex cabritii sea
//! shell with a structured implicit surface modeler* (§3, the spec's `implicit` form): whorls
//! of generating surfaces placed on the helico-spiral, varices with their spines and bumps, the
//! canal's spines and the carved opening, built as a BlobTree on the
//! [`blobtree`](crate::blobtree) engine and polygonized as the shell grows.

pub mod bumps;
pub mod canal_spines;
pub mod check;
pub mod fine_parts;
pub(crate) mod generating_surface;
mod grid_sight;
pub mod helix;
pub mod implicit_mesh;
pub(crate) mod opening;
pub mod rd_placement;
pub(crate) mod repair;
pub(crate) mod sections;
mod species_image;
pub mod textures;
pub mod varix;
pub mod whorl;
