//! The page's fixed sections as data: the gallery's cards ([`gallery`]) and the papers'
//! figures beside ours ([`figures`]), built here from the presets, the stories and the papers
//! so that a native test reads every card and link; the web adapter (`web/dom.rs`) only turns
//! an [`Element`] into the page's. Text only, never HTML.

mod element;
mod figures;
mod gallery;

pub use element::Element;
pub use figures::figures;
pub use gallery::gallery;
