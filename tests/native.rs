//! Every native integration test, in one binary: one link of the crate and its dependencies
//! instead of one per file, so `make test` builds and stores it once. Each file beside this
//! one is a module; `cargo test --test native murex::` runs one of them.
#![cfg(not(target_arch = "wasm32"))]

mod common;

/// Counts the heap each thread holds, for the tests that measure it (`common::heap`).
#[global_allocator]
static HEAP: common::heap::Counting = common::heap::Counting;

mod any_link;
mod automaton;
mod branching;
mod breeding;
mod chambers;
mod cli;
mod drawing;
mod edge_growth;
mod exports;
mod figures;
mod file_writer;
mod generator;
mod geometry;
mod implicit;
mod implicit_whorl;
mod layers;
mod link;
mod markup;
mod murex;
mod murex_opening;
mod murex_resolutions;
mod parameter_map;
mod pattern;
mod picture_mesh;
mod pictures;
mod simulated_workers;
mod simulator;
mod species;
mod stories;
mod textures;
mod viewer_message;
mod workers;
