//! The page's session: what the page shows and every decision it makes about it, without a
//! page. Events come in as calls (a link followed, a value edited or dragged, play, step,
//! finish, restart, the speed, one view or four, a frame with what the viewer said of itself,
//! the graphics device as the viewer found it); what the page is to do comes out as
//! [`Effect`]s, in order, which `web/app/` applies to the DOM, the viewer, the panel, the
//! gallery, the map, breeding and the recorder, deciding nothing itself. The simulator
//! (`tests/simulator.rs`) drives this same session with the viewer's core state behind it.

use super::pool::Replaced;
use super::shell_change::{ShellChange, Shown};
use super::status_readout::{Readout, Say};
use super::viewer_command::{PresetSpec, ViewCommand};
use super::viewer_inbox::Taken;
use super::viewer_message::PoolNews;
use super::viewer_status::{Device, FrameReport, ViewStatus};
use crate::presets::Preset;
use crate::share::link::{self, Decoded};
use crate::share::presentation::Presentation;
use crate::spec::ShellSpec;
use crate::spec::fields::{SHELL, Section};
use crate::spec::problem::Problem;
use crate::stories::{self, Growth, MapAxes, Opened, StoryAt};
use crate::variation::breeding::Breeding;

/// The element whose words say where the shells grow, and what became of the workers.
const WORKERS_STATUS: &str = "workers-status";

/// Quiet time after an edit before the address bar is updated, milliseconds.
pub const URL_DELAY_MS: f64 = 300.0;

/// How a value reached the session from the panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    /// A slider being dragged: previewed, not yet set.
    Moving,
    /// Set (a slider let go, a value typed, a choice made).
    Set,
}

/// One thing the page is to do.
pub enum Effect {
    /// Ask the viewer.
    View(ViewCommand),
    /// Set a `data-*` signal on `<body>`.
    Signal(&'static str, String),
    /// Write these words in the element of this id.
    Text(&'static str, String),
    /// Show or hide the message line.
    Say(Say),
    /// Show the gallery (its pictures asked for) or the viewer (the pictures paused).
    Gallery(bool),
    /// The document's title.
    Title(String),
    /// A shell is loaded, to grow from its apex: its name and source shown, the speed box and
    /// the panel set to it (the panel built anew when it does not fit it).
    Loaded(&'static Preset, Box<ShellSpec>),
    /// The panel shows these values.
    Panel(Box<ShellSpec>),
    /// The QR code and the share panel hold the link of this shell (its fragment).
    Share(String),
    /// The speed box shows this value.
    SpeedBox(f64),
    /// Show the shell as this presentation asks (one view or four, the interface).
    Present(Presentation),
    /// Stop a recording under way, for this reason.
    StopRecording(&'static str),
    /// Close the parameter map.
    CloseMap,
    /// Show the offspring of this breeding, its parent behind them.
    Breed(Box<Breeding>),
    /// Close breeding, its parent staying as the shell shown.
    CloseBreeding,
    /// Write the address bar's fragment anew (what is shown, as it is shown).
    UpdateAddress,
    /// Move the progress bar to these rows done and rows in all.
    Progress(usize, usize),
    /// Show the downloads' estimated sizes anew from the shell's counts.
    Sizes,
    /// Show this backend as the one the shell is drawn with.
    Backend(String),
    /// Show this step of a story beside the shell (its words, its figure, the links to the
    /// steps before and after), or no story.
    Story(Option<StoryAt>),
    /// Open the parameter map over the shell shown, spanning these two numbers.
    OpenMap(MapAxes),
}

/// What the viewer said since the page's last frame.
#[derive(Debug, Default)]
struct Heard {
    /// Each of its frames: the loads it had taken, what it said of itself, and whether it drew
    /// the shell.
    statuses: Vec<(u32, ViewStatus, bool)>,
    /// Shells it could not build or grow: the loads it had taken when it said so (none: said
    /// whatever was loaded), and why.
    refused: Vec<(Option<u32>, String)>,
}

/// The viewer's frames as the page's frame hears them ([`Session::hear`]): the task for the
/// rest of the frame, each frame's report for what the page shows of it beside the session (a
/// file's progress, a notice, the planar view's updates; its status, taken by the session, left
/// empty), and a recording's video frame: the
/// last one the frames carry, or the first failure among them (the recording then fails).
#[derive(Debug)]
pub struct Hearing<F> {
    pub task: FrameTask,
    pub reports: Vec<FrameReport>,
    pub recorded: Option<Result<F, String>>,
}

/// What the rest of the page's frame does, once it has heard its viewer ([`Session::hear`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameTask {
    /// A recording is under way: the frame hands it the viewer's video frame.
    Record,
    /// The gallery is shown: its pictures are drawn.
    Pictures,
    /// The map or breeding covers the shell: their tiles are drawn.
    Tiles,
    /// The shell is shown, as the viewer said.
    Shown,
}

/// The page as the session knows it.
#[derive(Default)]
pub struct Session {
    /// The shell shown (none in the gallery before one is opened, or after one was refused).
    current: Option<(&'static Preset, ShellSpec)>,
    presentation: Presentation,
    in_gallery: bool,
    /// Whether growth advances each frame (Play or Pause).
    playing: bool,
    /// Whether the viewer was last told to hold its growth.
    held: bool,
    /// When the address bar is due to be written, after the last edit.
    url_due: Option<f64>,
    /// What the viewer said of itself after its last frame of the shell shown.
    status: ViewStatus,
    readout: Readout,
    /// Whether breeding is open (its offspring cover the shell).
    breeding: bool,
    /// Loads sent to the viewer: a frame it made before the last reached it is of a shell left.
    loads: u32,
    /// The story's step the last link opened, if it opened one.
    story: Option<StoryAt>,
    /// Whether the shell of the story's step was changed since it opened (a value edited, the
    /// speed): the address is then the shell's own link, no longer the step's.
    story_edited: bool,
    /// Workers replaced so far in the page's pool and in the drawing worker's.
    deaths: (usize, u32),
    effects: Vec<Effect>,
}

impl Session {
    /// The page's own pool replaced a worker: the count is signalled (`data-worker-deaths`)
    /// and, from the second or when the workers are given up, the status line says so
    /// ([`Replaced::words`]).
    pub fn page_worker_replaced(&mut self, replaced: &Replaced) {
        self.deaths.0 = replaced.deaths;
        self.signal_deaths();
        if let Some(words) = replaced.words() {
            self.effects.push(Effect::Text(WORKERS_STATUS, words));
        }
    }

    /// What the drawing worker's pool says of itself: its status line while none of its
    /// workers was replaced, else the count and, from the second, the words.
    fn drawing_pool_said(&mut self, pool: PoolNews) {
        if pool.deaths == 0 {
            self.effects.push(Effect::Text(WORKERS_STATUS, pool.status));
            return;
        }
        self.deaths.1 = pool.deaths;
        self.signal_deaths();
        if let Some(words) = pool.words {
            self.effects.push(Effect::Text(WORKERS_STATUS, words));
        }
    }

    /// Signals the workers replaced so far, the page's pool's and the drawing worker's.
    fn signal_deaths(&mut self) {
        let (page, drawing) = self.deaths;
        let total = page + drawing as usize;
        self.effects
            .push(Effect::Signal("workerDeaths", total.to_string()));
    }

    /// What the page is to do, in order, since the last call.
    pub fn take_effects(&mut self) -> Vec<Effect> {
        std::mem::take(&mut self.effects)
    }

    /// The shell shown, if any.
    pub fn current(&self) -> Option<(&'static Preset, &ShellSpec)> {
        self.current.as_ref().map(|(p, s)| (*p, s))
    }

    pub fn presentation(&self) -> Presentation {
        self.presentation
    }

    pub fn in_gallery(&self) -> bool {
        self.in_gallery
    }

    pub fn playing(&self) -> bool {
        self.playing
    }

    /// What the viewer last said of the shell shown.
    pub fn status(&self) -> &ViewStatus {
        &self.status
    }

    /// Whether the last link opened a story's step.
    pub fn in_story(&self) -> bool {
        self.story.is_some()
    }

    /// The link (a fragment) of the story's next step (`forward`) or its previous one, if the
    /// page shows a story's step that has one.
    pub fn story_step(&self, forward: bool) -> Option<String> {
        let at = self.story.as_ref()?;
        if forward { at.next() } else { at.previous() }
    }

    fn push(&mut self, effect: Effect) {
        self.effects.push(effect);
    }

    fn signal(&mut self, name: &'static str, value: impl Into<String>) {
        self.push(Effect::Signal(name, value.into()));
    }

    fn view(&mut self, command: ViewCommand) {
        if matches!(command, ViewCommand::Load { .. }) {
            self.loads = self.loads.wrapping_add(1);
        }
        self.push(Effect::View(command));
    }

    /// Says what went wrong with a link or a value, or clears the message line.
    fn say(&mut self, problems: &[Problem]) {
        let say = Problem::report(problems).map_or(Say::Hide, Say::Show);
        self.push(Effect::Say(say));
    }

    /// Follows the URL fragment `fragment` at `now` (closing the parameter map, whose tiles
    /// are links): the gallery, a shell, a lineage of shells bred from one (shown with its
    /// last parent behind it), or a story's step (the shell of its link, shown as the step
    /// asks: grown at once, from another side, under a parameter map). An embed for a reader
    /// who asked for less motion (`reduced_motion`) shows the shell grown whole, still.
    pub fn route(&mut self, fragment: &str, reduced_motion: bool, now: f64) {
        self.push(Effect::CloseMap);
        let opened = stories::open(fragment);
        self.story = opened
            .as_ref()
            .and_then(|o| o.as_ref().ok())
            .map(|o| o.at.clone());
        self.story_edited = false;
        self.push(Effect::Story(self.story.clone()));
        match opened {
            None if fragment.trim_start_matches('#').is_empty() => self.gallery(now),
            None => self.open(fragment, Vec::new(), Growth::Grow, reduced_motion, now),
            Some(Err(problem)) => {
                self.gallery(now);
                self.say(&[problem]);
            }
            Some(Ok(Opened { at, link, problems })) => {
                let step = at.step();
                self.open(&link, problems, step.growth, reduced_motion, now);
                // An embed shows no map: its shell stays in view, growing.
                if let Some(axes) = step
                    .map
                    .as_ref()
                    .filter(|_| !self.presentation.ui.embedded())
                {
                    self.push(Effect::StopRecording("the map covered the shell"));
                    self.push(Effect::OpenMap(axes.clone()));
                }
            }
        }
    }

    /// Shows the gallery at `now`, breeding and a recording left.
    fn gallery(&mut self, now: f64) {
        self.close_breeding(now);
        self.push(Effect::StopRecording("you went back to the gallery"));
        self.present(Presentation::default());
        self.show(true);
        self.push(Effect::Say(Say::Hide));
        self.signal("state", "gallery");
    }

    /// Shows the shell of the link `fragment` (`growth`: grown from its apex, or at once and
    /// still), saying what could not be used as given, with the `problems` of the link that
    /// led to it.
    fn open(
        &mut self,
        fragment: &str,
        mut problems: Vec<Problem>,
        growth: Growth,
        reduced_motion: bool,
        now: f64,
    ) {
        let Decoded {
            preset,
            spec,
            presentation,
            lineage,
            problems: said,
        } = link::decode(fragment);
        problems.extend(said);
        let (preset, spec) = match lineage {
            Some(lineage) => {
                self.push(Effect::StopRecording("you chose to breed shells"));
                let (breeding, said) = Breeding::new(preset, &spec, &lineage);
                problems.extend(said);
                let parent = breeding.parent();
                let shell = (parent.preset, parent.spec.clone());
                self.breeding = true;
                self.push(Effect::Breed(Box::new(breeding)));
                shell
            }
            None => {
                self.close_breeding(now);
                (preset, spec)
            }
        };
        self.say(&problems);
        self.present(presentation);
        self.show(false);
        let still = (presentation.ui.embedded() && reduced_motion) || growth == Growth::Whole;
        match self.change_to(preset, &spec, still) {
            // A story's step shows its shell as it asks, grown again from its apex or whole,
            // even when the step before showed the same shell.
            ShellChange::Same | ShellChange::Restyle if self.story.is_some() => {
                self.load(preset, spec, still);
                if still {
                    self.set_playing(false);
                }
            }
            ShellChange::Same => {}
            ShellChange::Restyle => self.restyle(preset, spec),
            ShellChange::Grow { finish } => {
                self.load(preset, spec, finish);
                if still {
                    self.set_playing(false);
                }
            }
        }
    }

    /// A story's step shows its shell from the side it asks for (the preset's own first view
    /// otherwise) whenever the shell grows again: opened, restarted, edited, recorded, on a
    /// viewer that took the place of another.
    fn turn(&mut self) {
        if let (Some(at), Some((preset, _))) = (&self.story, &self.current) {
            let view = at.step().turn.unwrap_or(preset.view);
            self.view(ViewCommand::Turn(view));
        }
    }

    /// What asking for `spec` of `preset` does to the shell shown.
    fn change_to(&self, preset: &Preset, spec: &ShellSpec, finish: bool) -> ShellChange {
        let shown = self.current.as_ref().map(|(preset, spec)| Shown {
            preset,
            spec,
            grown_whole: self.status.shell.as_ref().is_some_and(|s| s.done),
        });
        ShellChange::of(shown, preset, spec, finish)
    }

    /// Shows the shell shown in the material of `spec` ([`ShellChange::Restyle`]): its growth,
    /// its recording and its status go on.
    fn restyle(&mut self, preset: &'static Preset, spec: ShellSpec) {
        self.view(ViewCommand::Restyle(PresetSpec::new(preset, spec.clone())));
        self.push(Effect::Panel(Box::new(spec.clone())));
        self.push(Effect::Share(link::encode(preset, &spec)));
        self.current = Some((preset, spec));
    }

    /// Shows the gallery or the viewer.
    fn show(&mut self, gallery: bool) {
        self.in_gallery = gallery;
        self.push(Effect::Gallery(gallery));
        let title = match (&self.current, gallery) {
            (Some((p, _)), false) => format!("{} — Seashells", p.name),
            _ => "Seashells".to_string(),
        };
        self.push(Effect::Title(title));
    }

    /// Shows `spec`, grown from its apex (with `finish`, to its end at once: see
    /// [`ShellChange`] for when).
    fn load(&mut self, preset: &'static Preset, spec: ShellSpec, finish: bool) {
        self.push(Effect::StopRecording("the shell was changed"));
        self.signal("state", "loading");
        self.signal("patternHash", "");
        self.signal("mesh", "");
        self.view(ViewCommand::Load {
            shell: PresetSpec::new(preset, spec.clone()),
            finish,
        });
        self.status = ViewStatus::default();
        self.push(Effect::Title(format!("{} — Seashells", preset.name)));
        self.push(Effect::Loaded(preset, Box::new(spec.clone())));
        self.push(Effect::Share(link::encode(preset, &spec)));
        self.current = Some((preset, spec));
        self.turn();
        self.set_playing(true);
    }

    /// A value changed in the panel at `now`, read as a link's value. Set, growth restarts
    /// with the result, or the grown shell is drawn again when only its material changed;
    /// dragged (`Edit::Moving`), a slider of the pattern has the planar view show the whole
    /// pattern of the result while the shell waits, and one of the material has the shell
    /// drawn in it.
    pub fn edit(&mut self, key: &str, value: &str, edit: Edit, now: f64) {
        let Some((preset, spec)) = &self.current else {
            return;
        };
        let Decoded {
            preset,
            spec: next,
            problems,
            ..
        } = link::with(preset, spec, key, value);
        if edit == Edit::Set {
            // The shell edited is no longer the parent of the offspring shown.
            self.close_breeding(now);
        }
        if edit == Edit::Moving {
            if previews(key) {
                self.say(&problems);
                self.view(ViewCommand::Preview(link::encode(preset, &next)));
            } else if self.change_to(preset, &next, false) == ShellChange::Restyle {
                // A material slider dragged: the grown shell follows it.
                self.view(ViewCommand::Restyle(PresetSpec::new(preset, next)));
            }
            return;
        }
        self.view(ViewCommand::EndPreview);
        self.say(&problems);
        match self.change_to(preset, &next, false) {
            ShellChange::Same => {
                if let Some((_, shown)) = &self.current {
                    self.push(Effect::Panel(Box::new(shown.clone())));
                }
                return;
            }
            ShellChange::Restyle => self.restyle(preset, next),
            ShellChange::Grow { finish } => self.load(preset, next, finish),
        }
        self.story_edited = true;
        self.url_due = Some(now + URL_DELAY_MS);
    }

    /// The link of what is shown, without its presentation: the story's step as it opened, or
    /// the shell.
    pub fn shown_link(&self) -> Option<String> {
        let step = self.story.as_ref().filter(|_| !self.story_edited);
        let shell = || self.current.as_ref().map(|(p, s)| link::encode(p, s));
        step.map(StoryAt::step_link).or_else(shell)
    }

    /// The fragment of what is shown, as it is shown: the story's step as it opened, the
    /// lineage bred to the shell (`lineage_link`, breeding's own link while it is open), or
    /// the shell.
    pub fn fragment(&self, lineage_link: Option<String>) -> Option<String> {
        let link = if self.story.is_some() && !self.story_edited {
            self.shown_link()
        } else {
            lineage_link.or_else(|| self.shown_link())
        };
        link.map(|link| {
            let mut fragment = format!("#{link}");
            self.presentation.write(&mut fragment);
            fragment
        })
    }

    /// Shows the shell as `presentation` asks.
    fn present(&mut self, presentation: Presentation) {
        self.presentation = presentation;
        self.view(ViewCommand::Layout(presentation.layout));
        self.signal("layout", presentation.layout.name());
        self.push(Effect::Present(presentation));
    }

    /// Between one view and Kawaguchi's four (the link follows at once).
    pub fn toggle_views(&mut self) {
        let mut presentation = self.presentation;
        presentation.layout = presentation.layout.toggled();
        self.present(presentation);
        self.url_due = None;
        self.push(Effect::UpdateAddress);
    }

    pub fn set_playing(&mut self, playing: bool) {
        self.playing = playing;
        self.view(ViewCommand::Play(playing));
        self.signal("playing", if playing { "true" } else { "false" });
        self.push(Effect::Text(
            "play",
            (if playing { "Pause" } else { "Play" }).into(),
        ));
    }

    pub fn toggle_playing(&mut self) {
        self.set_playing(!self.playing);
    }

    /// Grows the shell shown again from its apex.
    pub fn restart(&mut self) {
        self.push(Effect::StopRecording("growth was restarted"));
        if let Some((preset, spec)) = self.current.clone() {
            self.load(preset, spec, false);
        }
    }

    /// Grows the shell shown again from its apex for a recording: the map and breeding close
    /// first. Returns the shell, to plan the recording of.
    pub fn record(&mut self, now: f64) -> Option<(&'static Preset, ShellSpec)> {
        let (preset, spec) = self.current.clone()?;
        self.push(Effect::CloseMap);
        self.close_breeding(now);
        self.load(preset, spec.clone(), false);
        Some((preset, spec))
    }

    /// The parameter map opens over the shell shown: a recording stops and breeding closes.
    /// Returns the shell, to map the neighbourhood of.
    pub fn open_map(&mut self, now: f64) -> Option<(&'static Preset, ShellSpec)> {
        self.push(Effect::StopRecording("the map covered the shell"));
        self.close_breeding(now);
        self.current.clone()
    }

    /// Grows one row, paused.
    pub fn step(&mut self) {
        self.push(Effect::StopRecording("growth was moved by hand"));
        self.set_playing(false);
        self.view(ViewCommand::Grow(1));
    }

    /// Grows the shell to its end at once.
    pub fn finish(&mut self) {
        self.push(Effect::StopRecording("growth was moved by hand"));
        self.view(ViewCommand::Finish);
    }

    /// Sets the growth speed in rows per frame at `now` from the text `speed`, read as the link
    /// reads it (a speed out of range is clamped, and said; one that is no number is said, and
    /// the speed kept, which is then no edit); growth goes on, and the link follows.
    pub fn set_speed(&mut self, speed: &str, now: f64) {
        let Some((preset, spec)) = &self.current else {
            return;
        };
        let Decoded {
            spec: next,
            problems,
            ..
        } = link::with(preset, spec, "growth.speed", speed);
        let refused = !problems.is_empty() && next.growth.speed == spec.growth.speed;
        let speed = next.growth.speed;
        if let Some((_, spec)) = &mut self.current {
            spec.growth.speed = speed;
        }
        if !problems.is_empty() {
            self.say(&problems);
        }
        self.push(Effect::SpeedBox(speed));
        if refused {
            return;
        }
        self.view(ViewCommand::Speed(speed));
        self.story_edited = true;
        self.url_due = Some(now + URL_DELAY_MS);
    }

    /// The growth speed of the shell shown (rows per frame).
    pub fn speed(&self) -> f64 {
        self.current
            .as_ref()
            .map_or(1.0, |(_, spec)| spec.growth.speed)
    }

    /// Leaves breeding where the link stays: the shell shown is the last parent, and the link
    /// becomes its own.
    fn close_breeding(&mut self, now: f64) {
        if std::mem::take(&mut self.breeding) {
            self.push(Effect::CloseBreeding);
            self.url_due = Some(now);
        }
    }

    /// The viewer refused the shell shown (it cannot be built, `why`): none is shown, and the
    /// page says why as an error.
    pub fn refused(&mut self, why: String) {
        self.current = None;
        self.push(Effect::Say(Say::Show(why)));
        self.signal("state", "error");
    }

    /// What the page's frame takes from its viewer (`taken`, with the map or breeding
    /// `covered` the shell and a recording under way or not): what the drawing worker's pool
    /// said of itself, then the viewer's frames and refusals: a refusal of the shell shown is
    /// said, then the frame's task is chosen and the status shown (see `Session::heard`).
    pub fn hear<F>(
        &mut self,
        taken: Taken<F>,
        covered: bool,
        recording: bool,
        now: f64,
    ) -> Hearing<F> {
        if let Some(pool) = taken.pool {
            self.drawing_pool_said(pool);
        }
        let mut heard = Heard {
            refused: taken.refused,
            ..Heard::default()
        };
        let (mut reports, mut recorded) = (Vec::new(), None);
        for frame in taken.frames {
            // The status goes to the session; the page shows the rest of the report.
            let mut report = frame.report;
            let status = std::mem::take(&mut report.status);
            (heard.statuses).push((report.loads, status, report.drawn));
            reports.push(report);
            if !matches!(recorded, Some(Err(_))) && frame.recorded.is_some() {
                recorded = frame.recorded;
            }
        }
        let task = self.heard(heard, covered, recording, now);
        Hearing {
            task,
            reports,
            recorded,
        }
    }

    /// The page's frame after its viewer's frames came in (`heard`, with the shells the viewer
    /// refused since): a refusal of the shell shown is said (one of a shell left since is not);
    /// then the frame hands a video frame to a recording under way, or draws the gallery's
    /// pictures, or (the address written when due) the tiles of a map or breeding covering the
    /// shell; else the last of the viewer's frames of the shell shown is shown, drawn when any
    /// of them drew it.
    fn heard(&mut self, frames: Heard, covered: bool, recording: bool, now: f64) -> FrameTask {
        for (loads, why) in frames.refused {
            if loads.is_none_or(|l| self.is_current(l)) {
                self.refused(why);
            }
        }
        if recording {
            return FrameTask::Record;
        }
        if self.in_gallery {
            return FrameTask::Pictures;
        }
        self.address_due(now);
        if covered {
            return FrameTask::Tiles;
        }
        let mut drawn = false;
        let mut last = None;
        for (loads, status, frame_drew) in frames.statuses {
            if self.is_current(loads) {
                drawn |= frame_drew;
                last = Some(status);
            }
        }
        if let Some(status) = last {
            self.viewed(status, drawn, now);
        }
        FrameTask::Shown
    }

    /// Before the viewer's frame: growth waits while the gallery is shown or the map or
    /// breeding (`covered`) covers the shell, unless a recording is under way.
    pub fn hold(&mut self, covered: bool, recording: bool) {
        let held = !recording && (self.in_gallery || covered);
        if held != self.held {
            self.held = held;
            self.view(ViewCommand::Hold(held));
        }
    }

    /// Whether the viewer said something (a frame, a refusal) having taken `loads` loads:
    /// only what it said after the last load the page sent reached it is of the shell shown
    /// (a viewer in a worker may send a frame before; see
    /// [`super::viewer_status::FrameReport::loads`]).
    fn is_current(&self, loads: u32) -> bool {
        loads == self.loads
    }

    /// The address bar is due to follow the last edit at `now`.
    fn address_due(&mut self, now: f64) {
        if self.url_due.is_some_and(|due| now >= due) {
            self.url_due = None;
            self.push(Effect::UpdateAddress);
        }
    }

    /// The address bar was written (a link copied): nothing is due.
    pub fn address_written(&mut self) {
        self.url_due = None;
    }

    /// After a frame of the viewer that drew the shell shown (`drawn`) or not, at `now`: what
    /// it said of itself (`status`) is shown, as [`Readout::frame`] decides.
    fn viewed(&mut self, status: ViewStatus, drawn: bool, now: f64) {
        self.status = status;
        let shown = self.readout.frame(&self.status, drawn, now);
        for (name, value) in shown.signals {
            self.signal(name, value);
        }
        if shown.say != Say::Nothing {
            self.push(Effect::Say(shown.say));
        }
        if let Some((done, total)) = shown.progress {
            self.push(Effect::Progress(done, total));
        }
        if shown.sizes && self.status.shell.is_some() {
            self.push(Effect::Sizes);
        }
    }

    /// Before a frame: the graphics device as the viewer found it. Returns whether the frame
    /// may draw; an error with the words to show when no device can be opened again.
    pub fn device(&mut self, device: Device) -> Result<bool, String> {
        let shown = self.readout.device(device, &self.status, self.in_gallery)?;
        for (name, value) in shown.signals {
            self.signal(name, value);
        }
        if shown.say != Say::Nothing {
            self.push(Effect::Say(shown.say));
        }
        if let Some(backend) = shown.backend {
            self.push(Effect::Backend(backend));
        }
        Ok(shown.draws)
    }

    /// The viewer was replaced (it moved to another thread): it is told what the old one was
    /// told, and the shell shown grows again from its apex.
    pub fn viewer_replaced(&mut self, background: [u8; 3]) {
        self.held = false;
        self.loads = 0;
        self.readout.viewer_replaced();
        self.view(ViewCommand::Layout(self.presentation.layout));
        self.view(ViewCommand::Background(background));
        self.status = ViewStatus::default();
        if let Some((preset, spec)) = self.current.clone() {
            let whole = self
                .story
                .as_ref()
                .is_some_and(|at| at.step().growth == Growth::Whole);
            let still = whole && !self.story_edited;
            self.load(preset, spec, still);
            if still {
                self.set_playing(false);
            }
        }
    }
}

/// Whether dragging the field `key` previews the whole pattern: a field of the pattern model
/// (the colours and the seed have no sliders).
fn previews(key: &str) -> bool {
    SHELL
        .iter()
        .any(|f| f.key == key && f.section == Section::Pattern)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::work::viewer_status::ShellStatus;

    /// The viewer commands among `effects`, by name.
    fn commands(effects: &[Effect]) -> Vec<String> {
        effects
            .iter()
            .filter_map(|e| match e {
                Effect::View(command) => Some(format!("{command:?}")),
                _ => None,
            })
            .map(|c| c.split([' ', '(']).next().unwrap_or_default().to_string())
            .collect()
    }

    fn signals(effects: &[Effect]) -> Vec<(&'static str, String)> {
        effects
            .iter()
            .filter_map(|e| match e {
                Effect::Signal(name, value) => Some((*name, value.clone())),
                _ => None,
            })
            .collect()
    }

    fn opened(link: &str) -> Session {
        let mut session = Session::default();
        session.route(link, false, 0.0);
        session.take_effects();
        session
    }

    #[test]
    fn the_page_hears_every_frames_report_and_keeps_the_last_video_frame_or_a_failure() {
        use crate::work::viewer_inbox::ViewFrame;
        let mut session = Session::default();
        let frame = |loads: u32, recorded: Option<Result<&'static str, String>>| ViewFrame {
            report: FrameReport {
                loads,
                notice: Some(format!("frame of load {loads}")),
                ..FrameReport::default()
            },
            recorded,
        };
        let taken = Taken {
            frames: vec![
                frame(0, Some(Ok("first"))),
                frame(0, Some(Ok("second"))),
                frame(0, None),
            ],
            ..Taken::default()
        };
        let hearing = session.hear(taken, false, true, 0.0);
        assert_eq!(hearing.task, FrameTask::Record);
        let notices: Vec<_> = (hearing.reports.iter()).map(|r| r.notice.clone()).collect();
        assert_eq!(notices, vec![Some("frame of load 0".to_string()); 3]);
        assert_eq!(hearing.recorded, Some(Ok("second")), "the last drawn");
        let failing = Taken {
            frames: vec![
                frame(0, Some(Ok("first"))),
                frame(0, Some(Err("too big".into()))),
                frame(0, Some(Ok("third"))),
            ],
            ..Taken::default()
        };
        let hearing = session.hear(failing, false, true, 0.0);
        assert_eq!(
            hearing.recorded,
            Some(Err("too big".into())),
            "a failure wins"
        );
    }

    #[test]
    fn the_workers_replaced_in_both_pools_are_counted_and_said_from_the_second() {
        let mut session = Session::default();
        let texts = |effects: &[Effect]| -> Vec<String> {
            (effects.iter())
                .filter_map(|e| match e {
                    Effect::Text(WORKERS_STATUS, words) => Some(words.clone()),
                    _ => None,
                })
                .collect()
        };
        let news = |deaths: u32, words: Option<&str>| PoolNews {
            count: 3,
            status: "Growing on 3 workers.".into(),
            deaths,
            words: words.map(str::to_string),
        };
        // The drawing worker's pool speaks through the frame's news, as the page hears it.
        let said = |session: &mut Session, pool| {
            let taken: Taken<()> = Taken {
                pool: Some(pool),
                ..Taken::default()
            };
            session.hear(taken, false, false, 0.0);
        };
        said(&mut session, news(0, None));
        let effects = session.take_effects();
        assert_eq!(texts(&effects), ["Growing on 3 workers."]);
        assert!(
            signals(&effects).is_empty(),
            "nothing replaced, nothing counted"
        );
        let first = Replaced {
            deaths: 1,
            why: "it threw".into(),
            given_up: None,
        };
        session.page_worker_replaced(&first);
        let effects = session.take_effects();
        assert_eq!(signals(&effects), [("workerDeaths", "1".to_string())]);
        assert!(
            texts(&effects).is_empty(),
            "the first death is redone silently"
        );
        said(&mut session, news(2, Some("A worker stopped twice.")));
        let effects = session.take_effects();
        assert_eq!(signals(&effects), [("workerDeaths", "3".to_string())]);
        assert_eq!(texts(&effects), ["A worker stopped twice."]);
        let second = Replaced { deaths: 2, ..first };
        session.page_worker_replaced(&second);
        let effects = session.take_effects();
        assert_eq!(signals(&effects), [("workerDeaths", "4".to_string())]);
        assert_eq!(texts(&effects).len(), 1, "from the second, said");
    }

    #[test]
    fn a_link_grows_its_shell_and_an_empty_one_shows_the_gallery() {
        let mut session = Session::default();
        session.route("#v=1&preset=stripes", false, 0.0);
        let effects = session.take_effects();
        assert_eq!(
            commands(&effects),
            ["Layout", "Load", "Play"],
            "laid out, loaded, played"
        );
        assert!(signals(&effects).contains(&("state", "loading".into())));
        assert_eq!(session.current().map(|(p, _)| p.id), Some("stripes"));
        assert!(!session.in_gallery());
        session.route("", false, 1.0);
        let effects = session.take_effects();
        assert!(signals(&effects).contains(&("state", "gallery".into())));
        assert!(session.in_gallery());
        assert!(
            effects
                .iter()
                .any(|e| matches!(e, Effect::StopRecording("you went back to the gallery")))
        );
    }

    #[test]
    fn a_storys_link_shows_its_step_as_the_step_asks_and_moves_on_by_its_links() {
        use crate::stories::{Growth, stories};
        let story = stories()
            .iter()
            .find(|s| s.id == "coiling")
            .expect("coiling");
        let mut session = Session::default();
        for (i, step) in story.steps.iter().enumerate() {
            session.route(&format!("#story=coiling&step={}", i + 1), false, i as f64);
            let effects = session.take_effects();
            let shown = effects.iter().find_map(|e| match e {
                Effect::Story(at) => Some(at.clone()),
                _ => None,
            });
            let at = shown.flatten().expect("the step is shown");
            assert_eq!((at.story.id, at.index), ("coiling", i));
            assert!(session.in_story());
            let decoded = link::decode(&step.link);
            let (preset, spec) = session.current().expect("the step's shell");
            assert_eq!(
                link::encode(preset, spec),
                link::encode(decoded.preset, &decoded.spec)
            );
            let turned = effects.iter().find_map(|e| match e {
                Effect::View(ViewCommand::Turn(view)) => Some(*view),
                _ => None,
            });
            assert_eq!(
                turned,
                Some(step.turn.unwrap_or(preset.view)),
                "step {}",
                i + 1
            );
            let finish = effects.iter().find_map(|e| match e {
                Effect::View(ViewCommand::Load { finish, .. }) => Some(*finish),
                _ => None,
            });
            let whole = step.growth == Growth::Whole;
            assert_eq!(finish, Some(whole), "step {}: loaded as it asks", i + 1);
            assert_eq!(session.playing(), !whole, "step {}", i + 1);
            assert_eq!(
                session.fragment(None),
                Some(format!("#story=coiling&step={}", i + 1)),
                "the address stays the step's"
            );
            let map = effects.iter().find_map(|e| match e {
                Effect::OpenMap(axes) => Some(axes.clone()),
                _ => None,
            });
            assert_eq!(map, step.map, "step {}", i + 1);
            let last = i + 1 == story.steps.len();
            assert_eq!(session.story_step(true).is_none(), last);
            assert_eq!(session.story_step(false).is_none(), i == 0);
        }
        assert!(
            story.steps.iter().any(|s| s.map.is_some()),
            "the coiling story opens Raup's map"
        );

        // The same step again (the same shell) grows again as it asks, and from its side
        // after a restart; an edit makes the address the shell's.
        session.route("#story=coiling&step=3", false, 8.0);
        session.take_effects();
        session.route("#story=coiling&step=3", false, 8.5);
        assert!(commands(&session.take_effects()).contains(&"Load".to_string()));
        session.restart();
        let said = commands(&session.take_effects());
        assert_eq!(&said[..2], ["Load", "Turn"], "{said:?}");
        session.edit("form.spiral.whorls", "3", Edit::Set, 8.7);
        assert!(commands(&session.take_effects()).contains(&"Turn".to_string()));
        let edited = session.fragment(None).expect("a shell");
        assert!(
            edited.contains("preset=turbinate") && edited.contains("whorls=3"),
            "{edited}"
        );

        // Embedded, the step whose map the full page opens shows its shell instead.
        let mapped = story.steps.iter().position(|s| s.map.is_some()).unwrap() + 1;
        session.route(
            &format!("#story=coiling&step={mapped}&ui=controls"),
            false,
            8.8,
        );
        let effects = session.take_effects();
        assert!(!effects.iter().any(|e| matches!(e, Effect::OpenMap(_))));

        session.route("#story=nautilus", false, 9.0);
        let effects = session.take_effects();
        assert!(session.in_gallery() && !session.in_story());
        assert!(effects.iter().any(|e| matches!(e, Effect::Story(None))));
        assert!(
            effects.iter().any(
                |e| matches!(e, Effect::Say(Say::Show(words)) if words.contains("'nautilus'"))
            )
        );

        session.route("#v=1&preset=stripes", false, 10.0);
        let effects = session.take_effects();
        assert!(!session.in_story(), "a shell's link leaves the story");
        assert!(effects.iter().any(|e| matches!(e, Effect::Story(None))));
        assert!(!commands(&effects).contains(&"Turn".to_string()));
    }

    #[test]
    fn following_the_link_shown_changes_nothing_and_a_material_only_restyles() {
        let mut session = opened("#v=1&preset=stripes");
        session.route("#v=1&preset=stripes", false, 1.0);
        assert_eq!(commands(&session.take_effects()), ["Layout"]);
        session.route("#v=1&preset=stripes&material.gloss=0.9", false, 2.0);
        assert_eq!(commands(&session.take_effects()), ["Layout", "Restyle"]);
    }

    #[test]
    fn a_dragged_pattern_slider_previews_and_letting_go_regrows() {
        let mut session = opened("#v=1&preset=stripes");
        session.edit("pattern.iterations", "7", Edit::Moving, 1.0);
        assert_eq!(commands(&session.take_effects()), ["Preview"]);
        session.edit("pattern.iterations", "7", Edit::Set, 2.0);
        assert_eq!(
            commands(&session.take_effects()),
            ["EndPreview", "Load", "Play"]
        );
        session.address_due(2.0 + URL_DELAY_MS - 1.0);
        assert!(session.take_effects().is_empty(), "the address waits");
        session.address_due(2.0 + URL_DELAY_MS);
        assert!(matches!(
            session.take_effects()[..],
            [Effect::UpdateAddress]
        ));
        let fragment = session.fragment(None).unwrap();
        assert!(fragment.contains("pattern.iterations=7"), "{fragment}");
    }

    #[test]
    fn a_speed_out_of_range_is_clamped_as_the_link_clamps_it_and_said() {
        let mut session = opened("#v=1&preset=stripes");
        session.set_speed("1e9", 0.0);
        let effects = session.take_effects();
        assert_eq!(session.speed(), 200.0);
        assert!(
            effects.iter().any(
                |e| matches!(e, Effect::Say(Say::Show(words)) if words.contains("growth.speed"))
            )
        );
        session.set_speed("3", 1.0);
        let effects = session.take_effects();
        assert!(!effects.iter().any(|e| matches!(e, Effect::Say(_))));
        assert_eq!(session.speed(), 3.0);
        // What is not a number (a number box's cleared text) is said, and the box shows the
        // speed kept; it is no edit, and the address waits for none.
        session.address_due(2.0 + URL_DELAY_MS);
        session.take_effects();
        session.set_speed("", 2.0);
        let effects = session.take_effects();
        assert_eq!(session.speed(), 3.0);
        session.address_due(3.0 + URL_DELAY_MS);
        assert!(session.take_effects().is_empty(), "no address is written");
        assert!(
            effects.iter().any(
                |e| matches!(e, Effect::Say(Say::Show(words)) if words.contains("growth.speed"))
            ),
            "not said"
        );
        assert!(
            effects
                .iter()
                .any(|e| matches!(e, Effect::SpeedBox(s) if *s == 3.0))
        );
    }

    #[test]
    fn growth_is_held_under_the_gallery_and_the_map_but_not_while_recording() {
        let mut session = opened("#v=1&preset=stripes");
        session.hold(true, false);
        assert_eq!(commands(&session.take_effects()), ["Hold"]);
        session.hold(true, false);
        assert!(session.take_effects().is_empty(), "said once");
        session.hold(true, true);
        assert_eq!(commands(&session.take_effects()), ["Hold"]);
        session.route("", false, 0.0);
        session.take_effects();
        session.hold(false, false);
        assert_eq!(commands(&session.take_effects()), ["Hold"]);
    }

    /// A frame of the viewer, having taken `loads` loads, at `rows_done` of 100 rows.
    fn frame(loads: u32, rows_done: usize, drawn: bool) -> (u32, ViewStatus, bool) {
        let shell = ShellStatus {
            rows_done,
            rows: 100,
            ..Default::default()
        };
        let status = ViewStatus {
            shell: Some(shell),
            preview: None,
        };
        (loads, status, drawn)
    }

    #[test]
    fn the_page_shows_the_last_frame_of_the_shell_shown_and_says_its_refusal_only() {
        let mut session = opened("#v=1&preset=stripes");
        session.route("#v=1&preset=turbinate", false, 1.0);
        session.take_effects();
        // Two frames of the stripes still on their way, then two of the turbinate.
        let heard = Heard {
            statuses: vec![frame(1, 90, true), frame(2, 3, false), frame(2, 5, false)],
            refused: vec![(Some(1), "the stripes could not grow".into())],
        };
        assert_eq!(session.heard(heard, false, false, 2.0), FrameTask::Shown);
        let effects = session.take_effects();
        assert!(
            !effects.iter().any(|e| matches!(e, Effect::Say(_))),
            "a refusal of a shell left is not said"
        );
        assert!(
            effects
                .iter()
                .any(|e| matches!(e, Effect::Progress(5, 100)))
        );
        assert_eq!(
            session.status().shell.as_ref().map(|s| s.rows_done),
            Some(5)
        );
        // Frames of the stripes alone, the last of them drawn: the turbinate's status stays.
        let stale = Heard {
            statuses: vec![frame(1, 95, false), frame(1, 99, true)],
            refused: Vec::new(),
        };
        session.heard(stale, false, false, 2.5);
        assert!(
            !session
                .take_effects()
                .iter()
                .any(|e| matches!(e, Effect::Progress(..))),
            "nothing of a shell left is shown"
        );
        assert_eq!(
            session.status().shell.as_ref().map(|s| s.rows_done),
            Some(5)
        );
        let refused = Heard {
            refused: vec![(Some(2), "the turbinate could not grow".into())],
            ..Heard::default()
        };
        session.heard(refused, false, false, 3.0);
        let effects = session.take_effects();
        assert!(effects.iter().any(
            |e| matches!(e, Effect::Say(Say::Show(words)) if words == "the turbinate could not grow")
        ));
        assert!(signals(&effects).contains(&("state", "error".into())));
        assert!(session.current().is_none(), "no shell is shown");
        // A command the viewer could not read is refused whatever was loaded.
        let mut session = opened("#v=1&preset=stripes");
        let unread = Heard {
            refused: vec![(None, "a command could not be read".into())],
            ..Heard::default()
        };
        session.heard(unread, false, false, 1.0);
        assert!(session.current().is_none(), "said even so");
    }

    #[test]
    fn a_frame_records_draws_pictures_or_tiles_before_it_shows_the_shell() {
        let mut session = opened("#v=1&preset=stripes");
        session.edit("material.gloss", "0.5", Edit::Set, 1.0);
        session.take_effects();
        let task = |session: &mut Session, covered, recording, now| {
            let heard = Heard {
                statuses: vec![frame(1, 7, true)],
                ..Heard::default()
            };
            let task = session.heard(heard, covered, recording, now);
            (task, session.take_effects())
        };
        let (recorded, effects) = task(&mut session, true, true, 1e6);
        assert_eq!(recorded, FrameTask::Record);
        assert!(effects.is_empty(), "a recording's frame shows nothing else");
        let (tiles, effects) = task(&mut session, true, false, 1e6);
        assert_eq!(tiles, FrameTask::Tiles);
        assert!(
            matches!(effects[..], [Effect::UpdateAddress]),
            "under the map the address still follows the edit"
        );
        let (shown, effects) = task(&mut session, false, false, 1e6);
        assert_eq!(shown, FrameTask::Shown);
        assert!(
            effects
                .iter()
                .any(|e| matches!(e, Effect::Progress(7, 100)))
        );
        session.route("", false, 2e6);
        session.take_effects();
        assert_eq!(task(&mut session, false, false, 2e6).0, FrameTask::Pictures);
    }

    #[test]
    fn only_what_the_viewer_said_after_the_last_load_is_of_the_shell_shown() {
        let mut session = opened("#v=1&preset=stripes");
        assert!(session.is_current(1));
        session.route("#v=1&preset=turbinate", false, 1.0);
        assert!(!session.is_current(1), "a frame of the stripes");
        assert!(session.is_current(2));
    }

    #[test]
    fn a_stop_is_said_again_of_the_shell_a_new_viewer_grows_under_the_same_number() {
        let diverging = "#v=1&preset=oliva-porphyria&pattern.model.kappa=0&pattern.model.rho=5";
        let mut session = opened(diverging);
        let stopped = ViewStatus {
            shell: Some(crate::work::viewer_status::ShellStatus {
                session: 1,
                done: true,
                failure: Some("The pattern stopped.".into()),
                ..Default::default()
            }),
            preview: None,
        };
        let said = |session: &mut Session| {
            session
                .take_effects()
                .iter()
                .filter(|e| matches!(e, Effect::Say(Say::Show(w)) if w == "The pattern stopped."))
                .count()
        };
        session.viewed(stopped.clone(), true, 0.0);
        assert_eq!(said(&mut session), 1);
        session.viewed(stopped.clone(), true, 1.0);
        assert_eq!(said(&mut session), 0, "said once");
        // The view moved to the page's thread: its pool numbers the regrown shell 1 again.
        session.viewer_replaced([255; 3]);
        session.take_effects();
        session.viewed(stopped, true, 2.0);
        assert_eq!(said(&mut session), 1, "the regrown shell's stop is said");
    }

    #[test]
    fn a_lineage_shows_its_offspring_behind_its_parent_and_an_edit_closes_it() {
        let mut session = Session::default();
        session.route("#v=1&preset=stripes&breed=r0.3", false, 0.0);
        let effects = session.take_effects();
        assert!(effects.iter().any(|e| matches!(e, Effect::Breed(_))));
        session.edit("pattern.iterations", "7", Edit::Set, 5.0);
        let effects = session.take_effects();
        assert!(effects.iter().any(|e| matches!(e, Effect::CloseBreeding)));
    }
}
