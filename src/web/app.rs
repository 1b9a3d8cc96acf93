//! The page as a whole: the gallery or the viewer, chosen by the URL fragment (empty: the
//! gallery; a link: that shell), the controls and the panel around the viewer, and the signals
//! on <body> that tests read: `data-view`, `data-state` (gallery, loading, growing, grown —
//! the whole shell grown and the view come to rest on it —, stopped, error), `data-rows`,
//! `data-playing`, `data-pattern-hash`, `data-mesh` (the grown mesh's vertex and triangle
//! counts, as the command line prints them), `data-pictures`, `data-preview` (filling, whole,
//! stopped: the planar view's preview of a pattern slider being dragged, or empty), `data-map`
//! (filling, whole, refused, none: the parameter map, or empty when it is closed), `data-ui`
//! (the interface the link asks for), `data-layout` (single, four: one view or Kawaguchi's
//! four), `data-encoder` (what the page records video with: a codec's name, MediaRecorder, none,
//! or checking), `data-record` (recording, saved, cancelled, failed) and `data-record-frames`
//! (video frames captured), `data-growth` (growing, done: whether the shell is grown whole, before
//! the view comes to rest), `data-workers` (workers in the pool, 0 on the page's own thread),
//! `data-worker-deaths` (workers replaced so far), `data-settled` (true when the page's copy
//! of the shell has every answer it asked its worker for, said in the frame that shows its
//! rows: paused, it stands still) and
//! `data-recoveries` (how many times the graphics device was lost and opened again; the state
//! is `recovering` meanwhile), `data-backend` (WebGPU, WebGL2, none) and `data-drawn-in`
//! (worker, page, nowhere: where the main view is drawn).

use super::activity;
use super::breed::BreedView;
use super::canvases::replace;
use super::clock::now;
use super::debug::Loss;
use super::dom;
use super::download::Downloads;
use super::gallery::Pictures;
use super::map::MapView;
use super::page::{self, element, set_text, show_message, signal};
use super::panel::{Change, OnChange, Panel};
use super::planar::PlanarView;
use super::record::{self, Recording, Step, Support};
use super::share_panel;
use super::shown_size::ShownSize;
use super::viewer::Viewer;
use super::viewer_handle::{Taken, ViewerHandle};
use super::webcodecs::VideoFrame;
use super::workers::Workers;
use crate::export::Download;
use crate::presets::Preset;
use crate::render::Canvas;
use crate::share::lineage::{self, Lineage};
use crate::share::link::{self, Decoded};
use crate::share::presentation::{Layout, Presentation};
use crate::spec::ShellSpec;
use crate::spec::fields::{SHELL, Section};
use crate::spec::problem::Problem;
use crate::view::panes::arrangement;
use crate::view::recording::RecordingPlan;
use crate::work::message::{Reply, Request};
use crate::work::shell_change::{ShellChange, Shown};
use crate::work::status_readout::{Readout, Say};
use crate::work::viewer_command::{PresetSpec, ViewCommand};
use crate::work::viewer_message::PoolNews;
use crate::work::viewer_status::{Device, ViewStatus};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use web_sys::{HtmlCanvasElement, HtmlInputElement, HtmlProgressElement};

/// Quiet time after an edit before the address bar is updated.
const URL_DELAY_MS: f64 = 300.0;

pub struct App {
    viewer: ViewerHandle,
    /// Whether the viewer was last told to hold its growth.
    held: bool,
    /// Workers replaced so far in the page's pool and in the drawing worker's.
    deaths: (usize, u32),
    /// The size the main viewer's canvas is shown at, and what the viewer was last told of it
    /// (CSS pixels and the device pixel ratio).
    shown: Option<ShownSize>,
    told_shown: (u32, u32, f64),
    /// A fresh canvas that took the main viewer's place, until the page moves its listeners.
    replaced_canvas: Option<HtmlCanvasElement>,
    /// The planar view beside the main viewer, drawn as the viewer says.
    planar: Option<PlanarView>,
    /// What the viewer said of itself after the last frame (and nothing of a shell just
    /// loaded until it has).
    status: ViewStatus,
    /// What the page last showed of that status.
    readout: Readout,
    /// Where shells, pictures and pieces grow.
    workers: Rc<RefCell<Workers>>,
    pictures: Pictures,
    map: MapView,
    breed: BreedView,
    downloads: Downloads,
    current: Option<(&'static Preset, ShellSpec)>,
    /// How the link asks the page to show the shell: one view or four, the interface.
    presentation: Presentation,
    panel: Option<Panel>,
    on_change: Option<OnChange>,
    in_gallery: bool,
    url_due: Option<f64>,
    /// Whether growth advances each frame (Play or Pause).
    playing: bool,
    /// What the browser can record video with (found out after the start).
    support: Rc<RefCell<Support>>,
    /// A video being recorded.
    recording: Option<Recording>,
    /// A viewer being opened on the page's thread, on a fresh canvas, after the drawing worker
    /// failed.
    moving: Option<Moving>,
}

/// A viewer being opened on the page's thread on the fresh canvas element it will draw on, and
/// the answer once the browser has given it.
struct Moving {
    element: HtmlCanvasElement,
    opened: Rc<RefCell<Option<Result<Viewer, String>>>>,
}

/// Shows which backend the main view is drawn with (none: no 3D).
fn show_backend(backend: Option<String>) {
    if let Some(backend) = backend {
        signal("backend", &backend);
        set_text("backend", &format!("Drawn with {backend}"));
    }
}

/// Signals where the main view is drawn (`data-drawn-in`): in the drawing worker, on the
/// page's thread, or nowhere.
fn show_drawn_in(viewer: &ViewerHandle) {
    let place = match (viewer.in_worker(), viewer.backend()) {
        (true, _) => "worker",
        (false, Some(_)) => "page",
        (false, None) => "nowhere",
    };
    signal("drawnIn", place);
}

fn say(problems: &[Problem]) {
    match Problem::report(problems) {
        Some(report) => show_message(&report),
        None => page::hide_message(),
    }
}

/// Sets the signals and says the words the core's [`Readout`] decided on.
fn tell(signals: &[(&'static str, String)], say: &Say) {
    for (name, value) in signals {
        signal(name, value);
    }
    match say {
        Say::Nothing => {}
        Say::Show(words) => show_message(words),
        Say::Hide => page::hide_message(),
    }
}

/// Whether dragging the field `key` previews the whole pattern: a field of the pattern model
/// (the colours and the seed have no sliders).
fn previews(key: &str) -> bool {
    SHELL
        .iter()
        .any(|f| f.key == key && f.section == Section::Pattern)
}

/// Marks the main canvas as drawn at a recording's size, which the page shows scaled to fit
/// (or, with `false`, at its own size again).
fn fix_canvas(fixed: bool) {
    if let Some(canvas) = element("shell") {
        let _ = canvas.class_list().toggle_with_force("fixed", fixed);
    }
}

fn location_hash() -> String {
    web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default()
}

impl App {
    pub fn new(viewer: ViewerHandle, pictures: Pictures, workers: Rc<RefCell<Workers>>) -> Self {
        show_backend(viewer.backend());
        show_drawn_in(&viewer);
        let shown = element("shell").and_then(|e| ShownSize::observe(&e).ok());
        let planar = element("planar")
            .and_then(|e| e.dyn_into().ok())
            .map(PlanarView::new);
        Self {
            viewer,
            held: false,
            deaths: (0, 0),
            shown,
            told_shown: (0, 0, 0.0),
            replaced_canvas: None,
            planar,
            status: ViewStatus::default(),
            readout: Readout::default(),
            workers,
            pictures,
            map: MapView::default(),
            breed: BreedView::default(),
            downloads: Downloads::default(),
            current: None,
            presentation: Presentation::default(),
            panel: None,
            on_change: None,
            in_gallery: false,
            url_due: None,
            playing: false,
            support: Rc::new(RefCell::new(Support::Unasked)),
            recording: None,
            moving: None,
        }
    }

    /// Where the browser's answer about video encoders is written.
    pub fn support(&self) -> Rc<RefCell<Support>> {
        Rc::clone(&self.support)
    }

    /// Whether the page is embedded in another (an interface other than the full one).
    pub fn embedded(&self) -> bool {
        self.presentation.ui.embedded()
    }

    /// The panel's callback, which needs the shared handle of the app itself.
    pub fn set_on_change(&mut self, on_change: OnChange) {
        self.on_change = Some(on_change);
    }

    pub fn viewer(&mut self) -> &mut ViewerHandle {
        &mut self.viewer
    }

    /// Whether a shell is shown (the gallery shows none).
    pub fn has_shell(&self) -> bool {
        self.current.is_some()
    }

    /// Follows the URL fragment (closing the parameter map, whose tiles are links): a shell,
    /// or a lineage of shells bred from one, shown with its last parent behind it.
    pub fn route(&mut self) {
        self.map
            .close(&mut self.workers.borrow_mut(), &mut self.pictures);
        let fragment = location_hash();
        activity::set(format!("opening the link {fragment}"));
        if fragment.trim_start_matches('#').is_empty() {
            self.close_breeding();
            self.stop_recording("you went back to the gallery");
            self.present(Presentation::default());
            self.show(true);
            page::hide_message();
            signal("state", "gallery");
            return;
        }
        let Decoded {
            preset,
            spec,
            presentation,
            lineage,
            mut problems,
        } = link::decode(&fragment);
        let (preset, spec) = match lineage {
            Some(lineage) => {
                self.stop_recording("you chose to breed shells");
                let (parent, spec, said) = self.breed.open(
                    preset,
                    &spec,
                    &lineage,
                    &mut self.workers.borrow_mut(),
                    &mut self.pictures,
                );
                problems.extend(said);
                (parent, spec)
            }
            None => {
                self.close_breeding();
                (preset, spec)
            }
        };
        say(&problems);
        self.present(presentation);
        self.show(false);
        // An embed for a reader who asked for less motion: the grown shell, still.
        let still = presentation.ui.embedded() && share_panel::reduced_motion();
        match self.change_to(preset, &spec, still) {
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
        self.viewer
            .command(ViewCommand::Restyle(PresetSpec::new(preset, spec.clone())));
        if let Some(panel) = &self.panel {
            panel.refresh(&spec);
        }
        self.current = Some((preset, spec));
        if let Some(link) = self.link() {
            share_panel::show_qr(&link);
        }
    }

    fn show(&mut self, gallery: bool) {
        self.in_gallery = gallery;
        let mut workers = self.workers.borrow_mut();
        if gallery {
            self.pictures.ask(&mut workers);
        } else {
            self.pictures.pause(&mut workers);
        }
        drop(workers);
        if let (Some(g), Some(v)) = (element("gallery"), element("viewer")) {
            g.set_hidden(!gallery);
            v.set_hidden(gallery);
        }
        page::place_no_3d(!gallery);
        signal("view", if gallery { "gallery" } else { "viewer" });
        let title = match (&self.current, gallery) {
            (Some((p, _)), false) => format!("{} — Seashells", p.name),
            _ => "Seashells".to_string(),
        };
        page::document().set_title(&title);
    }

    /// Shows `spec`, grown from its apex (with `finish`, to its end at once: see
    /// [`ShellChange`] for when).
    fn load(&mut self, preset: &'static Preset, spec: ShellSpec, finish: bool) {
        self.stop_recording("the shell was changed");
        signal("state", "loading");
        signal("patternHash", "");
        signal("mesh", "");
        self.viewer.command(ViewCommand::Load {
            shell: PresetSpec::new(preset, spec.clone()),
            finish,
        });
        self.status = ViewStatus::default();
        set_text("title", &preset.name);
        set_text("source", &preset.source);
        page::document().set_title(&format!("{} — Seashells", preset.name));
        if let Some(speed) = element("speed").and_then(|e| e.dyn_into::<HtmlInputElement>().ok()) {
            speed.set_value(&crate::spec::fields::display(spec.growth.speed));
        }
        match (&self.panel, &self.on_change, element("panel-fields")) {
            (Some(panel), _, _) if panel.fits(&spec) => panel.refresh(&spec),
            (_, Some(on_change), Some(container)) => {
                self.panel = Some(Panel::build(&container, &spec, on_change))
            }
            _ => {}
        }
        self.current = Some((preset, spec));
        if let Some(link) = self.link() {
            share_panel::show_qr(&link);
        }
        self.set_playing(true);
    }

    /// A value changed in the panel: read it as a link's value. Set, growth restarts with the
    /// result, or the grown shell is drawn again when only its material changed; passed by a
    /// dragged slider of the pattern, the planar view shows the whole pattern of the result
    /// while the shell waits, and by one of the material, the shell is drawn in it.
    pub fn edit(&mut self, key: &str, value: String, change: Change) {
        activity::set(format!("applying {key}={value}"));
        let Some((preset, spec)) = &self.current else {
            return;
        };
        let Decoded {
            preset,
            spec: next,
            problems,
            ..
        } = link::with(preset, spec, key, &value);
        if change == Change::Set {
            // The shell edited is no longer the parent of the offspring shown.
            self.close_breeding();
        }
        if change == Change::Moving {
            if previews(key) {
                say(&problems);
                self.viewer
                    .command(ViewCommand::Preview(link::encode(preset, &next)));
            } else if self.change_to(preset, &next, false) == ShellChange::Restyle {
                // A material slider dragged: the grown shell follows it.
                self.viewer
                    .command(ViewCommand::Restyle(PresetSpec::new(preset, next)));
            }
            return;
        }
        self.viewer.command(ViewCommand::EndPreview);
        say(&problems);
        match self.change_to(preset, &next, false) {
            ShellChange::Same => {
                if let (Some(panel), Some((_, s))) = (&self.panel, &self.current) {
                    panel.refresh(s);
                }
                return;
            }
            ShellChange::Restyle => self.restyle(preset, next),
            ShellChange::Grow { finish } => self.load(preset, next, finish),
        }
        self.url_due = Some(now() + URL_DELAY_MS);
    }

    /// The link of what is shown, as it is shown: the shell, or the lineage bred to it.
    fn fragment(&self) -> Option<String> {
        let shell = || self.current.as_ref().map(|(p, s)| link::encode(p, s));
        self.breed.link().or_else(shell).map(|link| {
            let mut fragment = format!("#{link}");
            self.presentation.write(&mut fragment);
            fragment
        })
    }

    /// The whole link of what is shown, in the full interface: what the QR code holds.
    fn link(&self) -> Option<String> {
        self.current
            .as_ref()
            .map(|(p, s)| format!("{}#{}", share_panel::page_url(), link::encode(p, s)))
    }

    /// Shows the shell as `presentation` asks: one view, or Kawaguchi's four with each pane
    /// named over the canvas.
    fn present(&mut self, presentation: Presentation) {
        self.presentation = presentation;
        share_panel::apply_ui(presentation.ui);
        let layout = presentation.layout;
        self.viewer.command(ViewCommand::Layout(layout));
        signal("layout", layout.name());
        if let Some(button) = element("views") {
            dom::attr(
                &button,
                "aria-pressed",
                if layout == Layout::Four {
                    "true"
                } else {
                    "false"
                },
            );
        }
        if let Some(viewer) = element("viewer") {
            let _ = viewer
                .class_list()
                .toggle_with_force("four", layout == Layout::Four);
        }
        if let Some(labels) = element("panes") {
            dom::clear(&labels);
            labels.set_hidden(layout == Layout::Single);
            for place in arrangement(layout) {
                let label = dom::create("span", "pane", Some(place.name));
                let style = label.style();
                for (property, fraction) in ["left", "top", "width", "height"]
                    .into_iter()
                    .zip(place.viewport)
                {
                    let _ = style.set_property(property, &format!("{}%", fraction * 100.0));
                }
                dom::append(&labels, &[&label]);
            }
        }
    }

    /// Between one view and Kawaguchi's four (the link follows).
    pub fn toggle_views(&mut self) {
        let mut presentation = self.presentation;
        presentation.layout = presentation.layout.toggled();
        self.present(presentation);
        self.update_url();
    }

    fn update_url(&mut self) {
        self.url_due = None;
        let Some(fragment) = self.fragment() else {
            return;
        };
        if let Some(history) = web_sys::window().and_then(|w| w.history().ok()) {
            // Replacing the current entry keeps Back for leaving the viewer.
            let _ =
                history.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&fragment));
        }
    }

    pub fn set_playing(&mut self, playing: bool) {
        self.playing = playing;
        self.viewer.command(ViewCommand::Play(playing));
        signal("playing", if playing { "true" } else { "false" });
        set_text("play", if playing { "Pause" } else { "Play" });
    }

    pub fn toggle_playing(&mut self) {
        self.set_playing(!self.playing);
    }

    pub fn restart(&mut self) {
        self.stop_recording("growth was restarted");
        if let Some((preset, spec)) = self.current.clone() {
            self.load(preset, spec, false);
        }
    }

    /// Grows one row, paused.
    pub fn step(&mut self) {
        self.stop_recording("growth was moved by hand");
        self.set_playing(false);
        self.viewer.command(ViewCommand::Grow(1));
    }

    /// Grows the shell to its end at once.
    pub fn finish(&mut self) {
        self.stop_recording("growth was moved by hand");
        self.viewer.command(ViewCommand::Finish);
    }

    /// Sets the growth speed in rows per frame (part of the link; growth goes on).
    pub fn set_speed(&mut self, speed: f64) {
        let Some((_, spec)) = &mut self.current else {
            return;
        };
        let field = SHELL
            .iter()
            .find(|f| f.key == "growth.speed")
            .map(|f| f.kind);
        let speed = match field {
            Some(crate::spec::fields::Kind::Real { min, max, .. }) => speed.clamp(min, max),
            _ => speed,
        };
        spec.growth.speed = speed;
        self.viewer.command(ViewCommand::Speed(speed));
        if let Some(input) = element("speed").and_then(|e| e.dyn_into::<HtmlInputElement>().ok()) {
            input.set_value(&crate::spec::fields::display(speed));
        }
        self.url_due = Some(now() + URL_DELAY_MS);
    }

    pub fn speed(&self) -> f64 {
        self.current
            .as_ref()
            .map_or(1.0, |(_, spec)| spec.growth.speed)
    }

    pub fn reset_camera(&mut self) {
        self.viewer.command(ViewCommand::ResetCamera);
    }

    /// Full screen for the viewer, or back.
    pub fn toggle_fullscreen(&self) {
        let document = page::document();
        if document.fullscreen_element().is_some() {
            document.exit_fullscreen();
        } else if let Some(v) = element("viewer") {
            // A refusal (no user gesture, or not allowed) leaves the page as it is.
            let _ = v.request_fullscreen();
        }
    }

    /// Copies the link to the clipboard, saying so.
    pub fn copy_link(&mut self) {
        self.update_url();
        let Some(window) = web_sys::window() else {
            return;
        };
        let url = window.location().href().unwrap_or_default();
        share_panel::copy(url.clone(), "Link copied", format!("Copy this link: {url}"));
    }

    /// Copies the `<iframe>` that embeds what is shown, in the interface chosen beside it.
    pub fn copy_embed(&mut self) {
        if let Some((preset, spec)) = &self.current {
            let presentation = Presentation {
                ui: share_panel::chosen_ui(),
                ..self.presentation
            };
            let snippet =
                share_panel::snippet(&link::encode(preset, spec), presentation, &preset.name);
            share_panel::copy_embed(snippet);
        }
    }

    /// Shows what the browser can record with, and refuses Record where it cannot.
    pub fn show_support(&self) {
        let support = self.support.borrow();
        signal("encoder", support.signal());
        set_text("record-status", &support.note());
        if let Some(button) = element("record") {
            dom::attr(
                &button,
                "aria-disabled",
                if matches!(*support, Support::Nothing(_)) {
                    "true"
                } else {
                    "false"
                },
            );
        }
    }

    /// Grows the shell from its apex again and records every frame of its growth as a video,
    /// with the options chosen in the panel.
    pub fn record(&mut self) {
        if self.recording.is_some() {
            return;
        }
        let support = self.support.borrow().clone();
        if matches!(
            support,
            Support::Unasked | Support::Checking | Support::Nothing(_)
        ) {
            set_text("record-status", &support.note());
            return;
        }
        let Some((preset, spec)) = self.current.clone() else {
            return;
        };
        self.close_map();
        self.close_breeding();
        let rows = spec.growth.rows.max(2) as usize;
        let speed = spec.growth.speed;
        self.load(preset, spec, false);
        let plan = RecordingPlan::new(rows, speed, record::options());
        let size = (plan.width, plan.height);
        match Recording::start(plan, preset.id, &support) {
            Ok(recording) => {
                self.viewer.command(ViewCommand::RecordAt(Some(size)));
                fix_canvas(true);
                signal("record", "recording");
                record::show_recording(Some(&recording));
                self.recording = Some(recording);
            }
            Err(e) => {
                signal("record", "failed");
                set_text(
                    "record-status",
                    &format!("The recording could not start: {e}."),
                );
            }
        }
    }

    /// Stops a recording under way, keeping nothing of it, and says why.
    pub fn stop_recording(&mut self, why: &str) {
        let Some(recording) = self.recording.take() else {
            return;
        };
        recording.cancel();
        self.viewer.command(ViewCommand::RecordAt(None));
        fix_canvas(false);
        record::show_recording(None);
        signal("record", "cancelled");
        set_text(
            "record-status",
            &format!("Recording cancelled: {why}. Nothing was saved."),
        );
    }

    /// One animation frame of a recording under way: the frame the viewer drew (`recorded`)
    /// goes to the encoder, the next is asked for (and worked on in the viewer's next frame).
    fn record_frame(&mut self, recorded: Option<Result<VideoFrame, String>>) {
        let Some(recording) = &mut self.recording else {
            return;
        };
        let mut step = recording.step();
        if let Some(frame) = recorded
            && let Err(e) = recording.took(frame)
        {
            step = Step::Failed(e);
        }
        if let Step::Working = step {
            if let Some(ask) = recording.ask() {
                self.viewer.command(ViewCommand::AskFrame(ask));
            }
            record::show_recording(Some(recording));
            return;
        }
        let Some(recording) = self.recording.take() else {
            return;
        };
        let (frames, seconds) = (
            recording.plan().frames(),
            recording.plan().duration_us() as f64 / 1e6,
        );
        self.viewer.command(ViewCommand::RecordAt(None));
        fix_canvas(false);
        record::show_recording(None);
        signal("recordFrames", &recording.frames_done().to_string());
        let outcome = match step {
            Step::Done => recording.save(),
            Step::Failed(e) => {
                recording.cancel();
                Err(e)
            }
            Step::Working => unreachable!("handled above"),
        };
        match outcome {
            Ok(name) => {
                signal("record", "saved");
                set_text(
                    "record-status",
                    &format!("Saved {name}: {frames} frames, {seconds:.2} s."),
                );
            }
            Err(e) => {
                signal("record", "failed");
                set_text(
                    "record-status",
                    &format!("The recording failed: {e}. Nothing was saved."),
                );
            }
        }
    }

    /// Starts a download of the shell shown (written over the next frames).
    pub fn download(&mut self, what: Download) {
        if let Some(command) = self.downloads.start(what) {
            self.viewer.command(command);
        }
    }

    /// Test-only (see `debug.rs`): takes both graphics devices away, the main viewer's and the
    /// gallery pictures', as a driver reset or the browser would.
    pub fn take_devices(&self, loss: Loss) -> Result<(), String> {
        self.viewer.take_device(loss)?;
        self.pictures.take_device(loss)
    }

    /// Test-only (see `debug.rs`): passes a hook that acts where the viewer grows on to a
    /// viewer drawing in a worker.
    pub fn forward_debug(&self, ask: &str) {
        self.viewer.forward_debug(ask);
    }

    /// Keeps the main viewer's graphics device, saying in words when it was lost and when it
    /// is back; returns whether the frame may draw.
    fn survive(&mut self) -> Result<bool, String> {
        let device = match self.viewer.survive() {
            Device::NeedsCanvas(reason) => {
                // The canvas cannot be drawn on again: a fresh copy takes its place.
                let fresh = replace("shell")?;
                self.viewer.give_canvas(fresh.clone())?;
                self.canvas_replaced(&fresh);
                self.replaced_canvas = Some(fresh);
                Device::Reopening(reason)
            }
            device => device,
        };
        let shown = self.readout.device(device, &self.status, self.in_gallery)?;
        tell(&shown.signals, &shown.say);
        if shown.backend.is_some() {
            show_backend(shown.backend);
        }
        Ok(shown.draws)
    }

    /// One animation frame.
    pub fn frame(&mut self) -> Result<(), String> {
        if self.viewer.crashed() {
            return Ok(());
        }
        if self.moving.is_some() {
            self.take_moved();
            self.workers.borrow_mut().send();
            return Ok(());
        }
        self.tell_shown();
        let outcome = self.work_and_draw();
        // What this frame asked goes out now, to be worked on before the next frame.
        self.workers.borrow_mut().send();
        if self.moving.is_none() {
            self.viewer.tick();
        }
        outcome
    }

    /// The main viewer cannot draw where it is (`why`): the drawing worker gives way to the
    /// page's thread, on a fresh canvas, and a viewer on the page's thread to none that draws
    /// (the shell grows, its pattern shows and its files are written all the same). Said in
    /// words; growth starts again from the apex.
    fn fall_back(&mut self, why: String) {
        if !self.viewer.in_worker() {
            self.without_3d(&why);
            return;
        }
        web_sys::console::info_1(&format!("The view moves to the page's thread: {why}").into());
        show_message(
            "The shell could not be drawn in a worker here, so the page draws it on its own \
             thread; it grows again from its apex.",
        );
        let element = match replace("shell") {
            Ok(element) => element,
            Err(e) => {
                self.without_3d(&format!("{why}; {e}"));
                return;
            }
        };
        let opened: Rc<RefCell<Option<Result<Viewer, String>>>> = Rc::default();
        let (slot, canvas, workers) = (
            Rc::clone(&opened),
            Canvas::Element(element.clone()),
            Rc::clone(&self.workers),
        );
        wasm_bindgen_futures::spawn_local(async move {
            let viewer = Viewer::new(canvas, true, page::background(), true, workers).await;
            *slot.borrow_mut() = Some(viewer);
        });
        self.moving = Some(Moving { element, opened });
    }

    /// No viewer can draw here (`why`): one that draws nothing takes the main viewer's place,
    /// and the page says so in the words of its `#no-3d` notice.
    fn without_3d(&mut self, why: &str) {
        page::show_no_3d(why);
        let viewer = Viewer::without_drawing(true, page::background(), Rc::clone(&self.workers));
        self.install(ViewerHandle::Here(Box::new(viewer)), None);
    }

    /// Takes the viewer opened on the page's thread once the browser has answered (or, when it
    /// could not be opened, one that draws nothing).
    fn take_moved(&mut self) {
        let Some(moving) = &self.moving else { return };
        let Some(opened) = moving.opened.borrow_mut().take() else {
            return;
        };
        let Some(Moving { element, .. }) = self.moving.take() else {
            return;
        };
        match opened {
            Ok(viewer) => self.install(ViewerHandle::Here(Box::new(viewer)), Some(element)),
            Err(why) => {
                self.without_3d(&why);
            }
        }
    }

    /// Puts `viewer` in the old one's place (drawing on `element`, a fresh canvas of the page,
    /// if it draws) and tells it what the page told the old one: the layout, the background,
    /// the shell shown, grown again from its apex. A recording or a file under way is dropped.
    fn install(&mut self, viewer: ViewerHandle, element: Option<HtmlCanvasElement>) {
        self.stop_recording("the view moved to another thread");
        self.downloads
            .abandon("the view moved to another thread; ask for the file again");
        self.viewer = viewer;
        show_backend(self.viewer.backend());
        show_drawn_in(&self.viewer);
        if let Some(element) = element {
            self.canvas_replaced(&element);
            self.replaced_canvas = Some(element);
        }
        self.held = false;
        self.viewer
            .command(ViewCommand::Layout(self.presentation.layout));
        self.viewer
            .command(ViewCommand::Background(page::background()));
        self.status = ViewStatus::default();
        if let Some((preset, spec)) = self.current.clone() {
            self.load(preset, spec, false);
        }
    }

    /// Tells the viewer the size its canvas is shown at, when the page's layout or the pixel
    /// ratio changed it.
    fn tell_shown(&mut self) {
        let Some(shown) = &self.shown else { return };
        let (width, height) = shown.css();
        let pixel_ratio = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        if (width, height, pixel_ratio) != self.told_shown {
            self.told_shown = (width, height, pixel_ratio);
            self.viewer.command(ViewCommand::Shown {
                width,
                height,
                pixel_ratio,
            });
        }
    }

    /// A fresh canvas that took the main viewer's old one's place since the last call: the
    /// page listens to it instead.
    pub fn take_replaced_canvas(&mut self) -> Option<HtmlCanvasElement> {
        self.replaced_canvas.take()
    }

    /// A fresh canvas took the main viewer's place (a lost device opened again): its size is
    /// observed instead.
    fn canvas_replaced(&mut self, canvas: &HtmlCanvasElement) {
        self.shown = ShownSize::observe(canvas).ok();
        self.told_shown = (0, 0, 0.0);
    }

    /// What a frame does: takes in the workers' replies, grows, draws.
    fn work_and_draw(&mut self) -> Result<(), String> {
        if !self.survive()? {
            return Ok(());
        }
        self.take_replies();
        // The map and breeding cover the shell, and the gallery hides it: growth waits
        // meanwhile.
        let held = self.recording.is_none() && (self.in_gallery || self.covered());
        if held != self.held {
            self.held = held;
            self.viewer.command(ViewCommand::Hold(held));
        }
        let Taken {
            frames,
            refused,
            pool,
        } = match self.viewer.frames() {
            Ok(taken) => taken,
            Err(why) => {
                self.fall_back(why);
                return Ok(());
            }
        };
        for message in refused {
            self.current = None;
            page::show_error(&message);
        }
        if let Some(pool) = pool {
            self.pool_said(pool);
        }
        let mut drawn = false;
        let mut recorded = None;
        let mut status = None;
        for frame in frames {
            let report = frame.report;
            self.downloads.show(report.file);
            if let Some(notice) = report.notice {
                show_message(&notice);
            }
            for update in report.planar {
                if let Some(planar) = &mut self.planar {
                    planar.apply(update);
                }
            }
            // A frame made before the last load reached the viewer shows the shell left.
            if frame.current {
                drawn |= report.drawn;
                status = Some(report.status);
            }
            if let Some(frame) = frame.recorded {
                recorded = Some(frame);
            }
        }
        if self.recording.is_some() {
            self.record_frame(recorded);
            return Ok(());
        }
        if self.in_gallery {
            self.pictures.work(&mut self.workers.borrow_mut());
            signal(
                "pictures",
                if !self.pictures.draws() {
                    "none"
                } else if self.pictures.finished() {
                    "done"
                } else {
                    "drawing"
                },
            );
            return Ok(());
        }
        if self.url_due.is_some_and(|due| now() >= due) {
            self.update_url();
        }
        if self.covered() {
            if let Some(tile) = self.pictures.work(&mut self.workers.borrow_mut()) {
                self.map.shown(tile, Ok(()));
                self.breed.shown(tile, Ok(()));
            }
            activity::set("drawing the parameter map or the offspring".to_string());
            return Ok(());
        }
        let Some(status) = status else {
            // A viewer in a worker sent no frame since the page's last.
            return Ok(());
        };
        self.status = status;
        let shown = self.readout.frame(&self.status, drawn, now());
        tell(&shown.signals, &shown.say);
        if let Some((done, total)) = shown.progress {
            if let Some(bar) =
                element("progress").and_then(|e| e.dyn_into::<HtmlProgressElement>().ok())
            {
                bar.set_max(total as f64);
                bar.set_value(done as f64);
            }
            set_text("progress-text", &format!("{done} of {total} rows"));
        }
        if let (true, Some(shell)) = (shown.sizes, &self.status.shell) {
            self.downloads.show_sizes(shell);
        }
        Ok(())
    }

    /// Takes in what the workers sent back: the shell's growth and pieces go to the viewer,
    /// gallery shells to the pictures; a worker replaced with the shell's session has it grown
    /// again where the page's copy stands.
    fn take_replies(&mut self) {
        let polled = self.workers.borrow_mut().poll();
        if let Some(replaced) = &polled.replaced {
            self.deaths.0 = replaced.deaths;
            signal(
                "workerDeaths",
                &(self.deaths.0 + self.deaths.1 as usize).to_string(),
            );
            if let Some(words) = replaced.words() {
                set_text("workers-status", &words);
            }
        }
        if let Some(lost) = polled.sessions_lost {
            self.viewer.resume(lost);
        }
        for (request, reply) in polled.replies {
            match (request, reply) {
                (Request::Whole { job, .. }, Reply::Grown { result, .. }) => {
                    if let Some((tile, why)) = self.pictures.take(job, result) {
                        self.map.shown(tile, Err(why.clone()));
                        self.breed.shown(tile, Err(why));
                    }
                }
                (_, Reply::Tiled { job, result }) => self.map.take(job, result),
                (request, reply) => {
                    if let Err(message) = self.viewer.take(&request, reply) {
                        self.current = None;
                        page::show_error(&message);
                    }
                }
            }
        }
    }

    /// What the drawing worker's pool says of itself: how many workers (its status line) and
    /// how many were replaced.
    fn pool_said(&mut self, pool: PoolNews) {
        if pool.deaths == 0 {
            set_text("workers-status", &pool.status);
            return;
        }
        self.deaths.1 = pool.deaths;
        signal(
            "workerDeaths",
            &(self.deaths.0 + self.deaths.1 as usize).to_string(),
        );
        if let Some(words) = pool.words {
            set_text("workers-status", &words);
        }
    }

    /// Shows the parameter map of the shell shown.
    pub fn open_map(&mut self) {
        self.stop_recording("the map covered the shell");
        self.close_breeding();
        if let Some((preset, spec)) = &self.current {
            self.map.open(
                preset,
                spec,
                &mut self.workers.borrow_mut(),
                &mut self.pictures,
            );
        }
    }

    /// Draws the map anew over the axes its controls now describe.
    pub fn draw_map(&mut self) {
        if let Some((preset, spec)) = &self.current {
            self.map.draw(
                preset,
                spec,
                &mut self.workers.borrow_mut(),
                &mut self.pictures,
            );
        }
    }

    /// A parameter was chosen for the map's axis `name` ("x" or "y").
    pub fn map_chose(&mut self, name: &str) {
        self.map.chose(name);
    }

    pub fn close_map(&mut self) {
        self.map
            .close(&mut self.workers.borrow_mut(), &mut self.pictures);
    }

    /// Whether the map or breeding covers the shell.
    pub fn covered(&self) -> bool {
        self.map.is_open() || self.breed.is_open()
    }

    /// Breeds from the shell shown: it stands among its first eight offspring.
    pub fn open_breeding(&mut self) {
        if let Some((preset, spec)) = &self.current {
            let lineage = Lineage::default();
            let link = format!(
                "{}&{}={}",
                link::encode(preset, spec),
                lineage::KEY,
                lineage.write()
            );
            let _ = web_sys::window().map(|w| w.location().set_hash(&link));
        }
    }

    /// Leaves breeding where the link stays: the shell shown is the last parent, and the link
    /// becomes its own.
    fn close_breeding(&mut self) {
        if self.breed.is_open() {
            self.breed
                .close(&mut self.workers.borrow_mut(), &mut self.pictures);
            self.url_due = Some(now());
        }
    }

    /// The view over the shell closes (Escape): breeding leaves with its parent.
    pub fn escape(&mut self) {
        if self.breed.is_open() {
            self.breed.keep();
        } else {
            self.close_map();
        }
    }

    /// Moves the focus across the map's tiles or the offspring (arrow keys).
    pub fn step_tiles(&self, dx: i32, dy: i32) {
        if self.breed.is_open() {
            self.breed.step(dx, dy);
        } else {
            self.map.step(dx, dy);
        }
    }

    /// Back to the generation before.
    pub fn breed_back(&mut self) {
        self.breed.back();
    }

    /// Leaves breeding with the parent.
    pub fn breed_keep(&mut self) {
        self.breed.keep();
    }

    /// Breeds the generation shown again at `rate`.
    pub fn breed_rate(&mut self, rate: f64) {
        self.breed.set_rate(rate);
    }

    /// Follows a change of the page's light or dark theme.
    pub fn theme_changed(&mut self) {
        self.viewer
            .command(ViewCommand::Background(page::background()));
        self.pictures.set_background(page::background());
    }
}
