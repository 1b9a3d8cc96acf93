//! Seashells grown rim by rim: the pure core (the spec, the forms of four papers, the BlobTree
//! engine, the pattern models, the link codec and the presets) and, on wasm32, the thin
//! renderer and web adapters. Layers point down only; the README draws them.

pub mod bench;
pub mod blobtree;
pub mod export;
mod fnv;
pub mod forms;
pub mod generator;
pub mod markup;
pub mod mesh;
pub mod papers;
pub mod pattern;
mod pod_bytes;
pub mod presets;
pub mod shape;
pub mod share;
pub mod spec;
pub mod stories;
pub mod variation;
pub mod view;
pub mod work;

#[cfg(target_arch = "wasm32")]
pub mod render;
#[cfg(target_arch = "wasm32")]
pub mod web;
