//! The BlobTree engine (Wyvill, Guy & Galin; as Galbraith, Prusinkiewicz & Wyvill use it, §2):
//! skeletal primitives with their field falloff, the operators that blend, bend and transform
//! them, pattern coordinates blended by field value, and a chunked polygonizer. It knows
//! nothing of shells: it needs only the mesh and glam.

pub mod bend;
pub mod blob_tree;
pub mod falloff;
pub mod image_map;
pub mod polygonize;
pub mod primitive;
pub mod texture_blend;
