//! The link of a story's step, `story=NAME&step=K` (K counted from 1; `ui=` and `view=` as any
//! link takes them, for embeds): which step it opens, and the link of the shell that step
//! shows. A step beyond the end opens the last, one before the first the first, each with a
//! note; an unknown story is refused by name.

use super::catalogue::{stories, story};
use super::story::{Step, Story};
use crate::share::link;
use crate::share::presentation::{UI_KEY, VIEW_KEY};
use crate::spec::problem::Problem;

/// The link key naming a story.
pub const STORY_KEY: &str = "story";
/// The link key of the step, counted from 1.
pub const STEP_KEY: &str = "step";

/// A step of a story, as a link opened it.
#[derive(Clone, Debug)]
pub struct StoryAt {
    pub story: &'static Story,
    /// The step, counted from 0.
    pub index: usize,
    /// The link's own presentation (`&ui=controls`), kept on every step's link.
    presentation: String,
}

/// What a story's link opens.
#[derive(Clone, Debug)]
pub struct Opened {
    pub at: StoryAt,
    /// The link of the shell the step shows, with the story link's presentation.
    pub link: String,
    /// What the story's link asked that could not be used as given.
    pub problems: Vec<Problem>,
}

impl StoryAt {
    pub fn step(&self) -> &'static Step {
        &self.story.steps[self.index]
    }

    /// The link (a fragment) of step `index` of the same story, in the same presentation.
    fn link_to(&self, index: usize) -> String {
        format!("{}{}", self.bare_link(index), self.presentation)
    }

    /// The link of step `index` of the same story, without a presentation.
    fn bare_link(&self, index: usize) -> String {
        format!("{STORY_KEY}={}&{STEP_KEY}={}", self.story.id, index + 1)
    }

    /// The link of this step without its presentation, which the page writes after it as after
    /// any link (one view or four as shown now, the interface).
    pub fn step_link(&self) -> String {
        self.bare_link(self.index)
    }

    /// Where the step is in its story, as the page says it.
    pub fn count(&self) -> String {
        format!("Step {} of {}", self.index + 1, self.story.steps.len())
    }

    /// The link of this step.
    pub fn link(&self) -> String {
        self.link_to(self.index)
    }

    /// The link of the step before, if any.
    pub fn previous(&self) -> Option<String> {
        self.index.checked_sub(1).map(|i| self.link_to(i))
    }

    /// The link of the step after, if any.
    pub fn next(&self) -> Option<String> {
        (self.index + 1 < self.story.steps.len()).then(|| self.link_to(self.index + 1))
    }
}

/// Reads a link fragment (with or without its '#') that names a story: none when it names no
/// story (a shell's link), the step it opens, or why it opens none (no such story).
pub fn open(fragment: &str) -> Option<Result<Opened, Problem>> {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    let (pairs, _) = link::pairs(fragment);
    let name = pairs.iter().rev().find(|(k, _)| k == STORY_KEY)?.1.clone();
    Some(opened(&name, &pairs))
}

fn opened(name: &str, pairs: &[(String, String)]) -> Result<Opened, Problem> {
    let story = story(name).ok_or_else(|| {
        let names: Vec<&str> = stories().iter().map(|s| s.id).collect();
        Problem::new(
            STORY_KEY,
            format!(
                "there is no story '{name}' (there are {}); showing the gallery",
                names.join(", ")
            ),
        )
    })?;
    let Some(last) = story.steps.len().checked_sub(1) else {
        return Err(Problem::new(
            STORY_KEY,
            format!("the story '{name}' has no steps; showing the gallery"),
        ));
    };
    let mut problems = Vec::new();
    let mut presentation = String::new();
    let mut asked = None;
    for (key, value) in pairs {
        match key.as_str() {
            STORY_KEY | "v" => {}
            STEP_KEY => asked = Some(value.as_str()),
            UI_KEY | VIEW_KEY => presentation.push_str(&format!("&{key}={value}")),
            _ => problems.push(Problem::new(
                key.clone(),
                "is not read in a story's link (story, step, ui, view); ignored",
            )),
        }
    }
    let index = match asked.map(str::parse::<usize>) {
        None => 0,
        Some(Ok(k)) if (1..=last + 1).contains(&k) => k - 1,
        Some(Ok(k)) if k > last => {
            problems.push(Problem::new(
                STEP_KEY,
                format!("the story has {} steps, not {k}; opened the last", last + 1),
            ));
            last
        }
        Some(_) => {
            problems.push(Problem::new(
                STEP_KEY,
                format!(
                    "'{}' is not a step from 1 to {}; opened the first",
                    asked.unwrap_or_default(),
                    last + 1
                ),
            ));
            0
        }
    };
    let at = StoryAt {
        story,
        index,
        presentation,
    };
    let link = format!("{}{}", at.step().link, at.presentation);
    Ok(Opened { at, link, problems })
}
