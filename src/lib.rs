//! Seashells grown rim by rim: the pure core (geometry, pattern models, the spec and its link
//! codec, presets) and, on wasm32, the thin renderer and web adapters.

pub mod bench;
pub mod camera;
pub mod export;
pub mod generator;
pub mod geometry;
pub mod gestures;
pub mod growing_shape;
pub mod growth;
pub mod implicit;
pub mod mesh;
pub mod pattern;
pub mod spec;
pub mod species;
pub mod texture_layout;

#[cfg(target_arch = "wasm32")]
pub mod render;
#[cfg(target_arch = "wasm32")]
pub mod web;
