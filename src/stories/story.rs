//! One story: a title, a line for its card in the gallery, and its steps, each a link the page
//! can already open (a shell, a view, a lineage of bred shells) with a paragraph about it, the
//! paper's figure and equation it shows where it shows one, and what the viewer does on
//! arriving: grow the shell from its apex or show it grown, turn the camera, open the parameter
//! map over two of the shell's numbers.

use crate::generator::Generator;
use crate::presets::View;
use crate::share::link;
use crate::spec::problem::{Problem, Said};
use crate::variation::parameter_map::parameters;
use serde::Deserialize;
use std::fmt;

/// A story file of species/stories/.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Story {
    /// The file name without extension: the story's name in links (`story=NAME`).
    #[serde(skip)]
    pub id: &'static str,
    pub title: String,
    /// One sentence for the story's card in the gallery.
    pub summary: String,
    pub steps: Vec<Step>,
}

/// One step of a story.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    pub title: String,
    /// The link the step opens (a fragment, without its '#').
    pub link: String,
    /// What to look at, and why it looks so.
    pub text: String,
    /// The paper's figure the step reproduces, named as the presets' sources name it.
    #[serde(default)]
    pub figure: Option<String>,
    /// The paper's equations the step shows, by number.
    #[serde(default)]
    pub equation: Option<String>,
    #[serde(default)]
    pub growth: Growth,
    /// Where the camera looks from (as a preset's first view); the preset's own otherwise.
    #[serde(default)]
    pub turn: Option<View>,
    /// The parameter map the step opens over the shell.
    #[serde(default)]
    pub map: Option<MapAxes>,
}

impl Step {
    /// The paper's figure and equations the step shows, as one line ("…, fig. 2 · eq. 1").
    pub fn cites(&self) -> Option<String> {
        let cited: Vec<&str> = [&self.figure, &self.equation]
            .into_iter()
            .flatten()
            .map(String::as_str)
            .collect();
        (!cited.is_empty()).then(|| cited.join(" · "))
    }
}

/// How the shell of a step is shown on arriving.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Growth {
    /// Grown from its apex, rim by rim.
    #[default]
    Grow,
    /// Grown whole at once, and still: the finished form is the point.
    Whole,
}

/// The two numbers a step's parameter map spans, by their link keys (`raup.w`,
/// `pattern.model.d_a`).
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapAxes {
    pub across: String,
    pub down: String,
}

/// What is wrong with a story: which story, which step (counted from 1, as links count them),
/// which key, and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StoryError {
    pub story: String,
    pub step: Option<usize>,
    pub key: String,
    pub message: String,
}

impl fmt::Display for StoryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "story '{}'", self.story)?;
        if let Some(step) = self.step {
            write!(f, ", step {step}")?;
        }
        write!(f, ": {}: {}", self.key, self.message)
    }
}

impl std::error::Error for StoryError {}

impl Story {
    /// Reads the story file `id` (its JSON `json`); an unknown field or a missing one is
    /// refused with the file's name.
    pub fn parse(id: &'static str, json: &str) -> Result<Self, StoryError> {
        let mut story: Story = serde_json::from_str(json).map_err(|e| StoryError {
            story: id.to_string(),
            step: None,
            key: "file".into(),
            message: e.to_string(),
        })?;
        story.id = id;
        Ok(story)
    }

    /// Everything wrong with the story: no steps, a step without words, a step's link that the
    /// page would repair (a value not used as given; whorls that overlap are shown as asked, and
    /// may be the point of a step) or whose shell cannot be built, a map over numbers the shell
    /// does not have.
    pub fn check(&self) -> Vec<StoryError> {
        let error = |step: Option<usize>, key: &str, message: String| StoryError {
            story: self.id.to_string(),
            step,
            key: key.to_string(),
            message,
        };
        let mut errors = Vec::new();
        if self.steps.is_empty() {
            errors.push(error(None, "steps", "the story has no steps".into()));
        }
        if self.title.trim().is_empty() || self.summary.trim().is_empty() {
            errors.push(error(None, "title", "needs a title and a summary".into()));
        }
        for (i, step) in self.steps.iter().enumerate() {
            let at = Some(i + 1);
            if step.title.trim().is_empty() || step.text.trim().is_empty() {
                errors.push(error(at, "text", "needs a title and a paragraph".into()));
            }
            let decoded = link::decode(&step.link);
            let repaired = decoded.problems.iter().filter(|p| p.said == Said::Changed);
            errors.extend(repaired.map(|p: &Problem| error(at, &p.key, p.message.clone())));
            if let Err(e) = Generator::new(&decoded.spec) {
                errors.push(error(at, "link", format!("its shell cannot be built: {e}")));
            }
            if let Some(map) = &step.map {
                let mappable = parameters(&decoded.spec);
                for key in [&map.across, &map.down] {
                    if !mappable.iter().any(|(f, _)| f.key == key) {
                        let message = format!("this shell has no number '{key}' to map");
                        errors.push(error(at, "map", message));
                    }
                }
                if map.across == map.down {
                    errors.push(error(at, "map", "maps one number on both axes".into()));
                }
            }
        }
        errors
    }
}
