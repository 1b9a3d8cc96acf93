//! Every story of species/stories/, compiled in by build.rs, read once.

use super::story::Story;
use std::sync::OnceLock;

include!(concat!(env!("OUT_DIR"), "/stories.rs"));

/// Every story, by name. A story file that does not parse is a build defect, caught by the
/// native tests (as a preset's is); here it panics with the file's name.
pub fn stories() -> &'static [Story] {
    static STORIES: OnceLock<Vec<Story>> = OnceLock::new();
    STORIES.get_or_init(|| {
        STORY_FILES
            .iter()
            .map(|&(id, json)| Story::parse(id, json).unwrap_or_else(|e| panic!("{e}")))
            .collect()
    })
}

/// The story named `id`.
pub fn story(id: &str) -> Option<&'static Story> {
    stories().iter().find(|s| s.id == id)
}
