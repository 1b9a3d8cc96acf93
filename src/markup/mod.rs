//! The page's elements as data: the gallery's cards ([`gallery`]), the papers' figures beside
//! ours ([`figures`]), the parameter panel's rows ([`panel`]) and the tiles of the parameter
//! map and of breeding ([`tile`], [`map_tile`]), built here from the presets,
//! the stories, the papers and the field table so that a native test reads every card, link
//! and control; the web adapter (`web/dom.rs`) only turns an [`Element`] into the page's, and
//! wires the controls. Text only, never HTML.

mod element;
mod figures;
mod gallery;
mod panel;
mod tile;

pub use element::Element;
pub use figures::figures;
pub use gallery::gallery;
pub use panel::{field_id, field_options, panel};
pub use tile::{Shows, map_tile, tile};
