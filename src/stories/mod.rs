//! Stories a teacher steps through: each a short sequence of steps (species/stories/*.json,
//! compiled in by build.rs), each step a link the page opens with a paragraph about it, opened
//! by the link `story=NAME&step=K`. The page moves between steps as between links, without
//! reloading.

mod catalogue;
mod opening;
mod story;

pub use catalogue::{stories, story};
pub use opening::{Opened, StoryAt, open};
pub use story::{Growth, MapAxes, Step, Story, StoryError};
