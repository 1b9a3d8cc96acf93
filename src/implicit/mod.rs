//! Implicit surfaces (Galbraith, Prusinkiewicz & Wyvill, *Modeling a Murex cabritii sea shell
//! with a structured implicit surface modeler*): the BlobTree of skeletal primitives and
//! operators, a chunked polygonizer, and shell whorls built of generating surfaces placed on
//! the helico-spiral.

pub mod bend;
pub mod blob_tree;
pub mod bumps;
pub mod canal_spines;
pub mod falloff;
pub mod implicit_mesh;
pub mod implicit_whorl;
pub mod polygonizer;
pub mod primitive;
pub mod texture_blend;
pub mod varix;
