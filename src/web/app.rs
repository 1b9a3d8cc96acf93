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
use super::panel::{OnChange, Panel};
use super::planar::PlanarView;
use super::record::{self, Recording, Step};
use super::share_panel;
use super::shown_size::ShownSize;
use super::viewer::Viewer;
use super::viewer_handle::{Taken, ViewerHandle};
use super::webcodecs::VideoFrame;
use super::workers::Workers;
use crate::export::Download;
use crate::render::Canvas;
use crate::share::lineage::Lineage;
use crate::share::link;
use crate::share::presentation::{Layout, Presentation};
use crate::variation::breeding;
use crate::view::panes::arrangement;
use crate::view::recording::RecordingPlan;
use crate::work::message::{Reply, Request};
use crate::work::recording::{Ended, Support};
use crate::work::session::{Edit, Effect, Session};
use crate::work::status_readout::Say;
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_message::PoolNews;
use crate::work::viewer_status::Device;
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use web_sys::{HtmlCanvasElement, HtmlInputElement, HtmlProgressElement};

pub struct App {
    viewer: ViewerHandle,
    /// What the page shows and every decision about it (see [`Session`]): this only applies
    /// its effects.
    session: Session,
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
    /// Where shells, pictures and pieces grow.
    workers: Rc<RefCell<Workers>>,
    pictures: Pictures,
    map: MapView,
    breed: BreedView,
    downloads: Downloads,
    panel: Option<Panel>,
    on_change: Option<OnChange>,
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

/// Shows or hides the message line as the session said.
fn say(say: Say) {
    match say {
        Say::Nothing => {}
        Say::Show(words) => show_message(&words),
        Say::Hide => page::hide_message(),
    }
}

/// The speed box shows `speed` rows per frame.
fn show_speed(speed: f64) {
    if let Some(input) = element("speed").and_then(|e| e.dyn_into::<HtmlInputElement>().ok()) {
        input.set_value(&crate::spec::fields::display(speed));
    }
}

/// Shows the shell as `presentation` asks: the interface, one view, or Kawaguchi's four with
/// each pane named over the canvas.
fn present(presentation: Presentation) {
    share_panel::apply_ui(presentation.ui);
    let layout = presentation.layout;
    if let Some(button) = element("views") {
        let pressed = if layout == Layout::Four {
            "true"
        } else {
            "false"
        };
        dom::attr(&button, "aria-pressed", pressed);
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
            session: Session::default(),
            deaths: (0, 0),
            shown,
            told_shown: (0, 0, 0.0),
            replaced_canvas: None,
            planar,
            workers,
            pictures,
            map: MapView::default(),
            breed: BreedView::default(),
            downloads: Downloads::default(),
            panel: None,
            on_change: None,
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
        self.session.presentation().ui.embedded()
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
        self.session.current().is_some()
    }

    /// Follows the URL fragment, as the session decides.
    pub fn route(&mut self) {
        let fragment = location_hash();
        activity::set(format!("opening the link {fragment}"));
        let still = share_panel::reduced_motion();
        self.session.route(&fragment, still, now());
        self.apply();
    }

    /// Does what the session decided, in order.
    fn apply(&mut self) {
        for effect in self.session.take_effects() {
            match effect {
                Effect::View(command) => self.viewer.command(command),
                Effect::Signal(name, value) => signal(name, &value),
                Effect::Text(id, words) => set_text(id, &words),
                Effect::Say(words) => say(words),
                Effect::Gallery(gallery) => self.show(gallery),
                Effect::Title(title) => page::document().set_title(&title),
                Effect::Loaded(preset, spec) => {
                    set_text("title", &preset.name);
                    set_text("source", &preset.source);
                    show_speed(spec.growth.speed);
                    match (&self.panel, &self.on_change, element("panel-fields")) {
                        (Some(panel), _, _) if panel.fits(&spec) => panel.refresh(&spec),
                        (_, Some(on_change), Some(container)) => {
                            self.panel = Some(Panel::build(&container, &spec, on_change))
                        }
                        _ => {}
                    }
                }
                Effect::Panel(spec) => {
                    if let Some(panel) = &self.panel {
                        panel.refresh(&spec);
                    }
                }
                Effect::Share(fragment) => {
                    share_panel::show_qr(&format!("{}#{fragment}", share_panel::page_url()))
                }
                Effect::SpeedBox(speed) => show_speed(speed),
                Effect::Present(presentation) => present(presentation),
                Effect::StopRecording(why) => self.stop_recording(why),
                Effect::CloseMap => self
                    .map
                    .close(&mut self.workers.borrow_mut(), &mut self.pictures),
                Effect::Breed(breeding) => self.breed.open(
                    *breeding,
                    &mut self.workers.borrow_mut(),
                    &mut self.pictures,
                ),
                Effect::CloseBreeding => self
                    .breed
                    .close(&mut self.workers.borrow_mut(), &mut self.pictures),
                Effect::UpdateAddress => self.update_url(),
                Effect::Progress(done, total) => {
                    if let Some(bar) =
                        element("progress").and_then(|e| e.dyn_into::<HtmlProgressElement>().ok())
                    {
                        bar.set_max(total as f64);
                        bar.set_value(done as f64);
                    }
                    set_text("progress-text", &format!("{done} of {total} rows"));
                }
                Effect::Sizes => {
                    if let Some(shell) = &self.session.status().shell {
                        self.downloads.show_sizes(shell);
                    }
                }
                Effect::Backend(backend) => show_backend(Some(backend)),
            }
        }
    }

    /// Shows the gallery, or the viewer: the pictures are asked for or paused.
    fn show(&mut self, gallery: bool) {
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
    }

    /// A value changed in the panel: the session decides what it does.
    pub fn edit(&mut self, key: &str, value: String, edit: Edit) {
        activity::set(format!("applying {key}={value}"));
        self.session.edit(key, &value, edit, now());
        self.apply();
    }

    /// Between one view and Kawaguchi's four (the link follows).
    pub fn toggle_views(&mut self) {
        self.session.toggle_views();
        self.apply();
    }

    /// Writes what is shown in the address bar, in place of the current entry (Back still
    /// leaves the viewer).
    fn update_url(&mut self) {
        self.session.address_written();
        let Some(fragment) = self.session.fragment(self.breed.link()) else {
            return;
        };
        if let Some(history) = web_sys::window().and_then(|w| w.history().ok()) {
            let _ =
                history.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&fragment));
        }
    }

    pub fn toggle_playing(&mut self) {
        self.session.toggle_playing();
        self.apply();
    }

    pub fn restart(&mut self) {
        self.session.restart();
        self.apply();
    }

    /// Grows one row, paused.
    pub fn step(&mut self) {
        self.session.step();
        self.apply();
    }

    /// Grows the shell to its end at once.
    pub fn finish(&mut self) {
        self.session.finish();
        self.apply();
    }

    /// Sets the growth speed in rows per frame (part of the link; growth goes on).
    pub fn set_speed(&mut self, speed: f64) {
        self.session.set_speed(speed, now());
        self.apply();
    }

    pub fn speed(&self) -> f64 {
        self.session.speed()
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
        if let Some((preset, spec)) = self.session.current() {
            let presentation = Presentation {
                ui: share_panel::chosen_ui(),
                ..self.session.presentation()
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
            dom::attr(&button, "aria-disabled", &support.refused().to_string());
        }
    }

    /// Grows the shell from its apex again and records every frame of its growth as a video,
    /// with the options chosen in the panel.
    pub fn record(&mut self) {
        if self.recording.is_some() {
            return;
        }
        let support = self.support.borrow().clone();
        if !support.may_record() {
            set_text("record-status", &support.note());
            return;
        }
        let Some((preset, spec)) = self.session.record(now()) else {
            return;
        };
        self.apply();
        let plan = RecordingPlan::new(
            spec.growth.rows.max(2) as usize,
            spec.growth.speed,
            record::options(),
        );
        let size = (plan.width, plan.height);
        match Recording::start(plan, preset.id, &support) {
            Ok(recording) => {
                self.viewer.command(ViewCommand::RecordAt(Some(size)));
                fix_canvas(true);
                signal("record", "recording");
                record::show_recording(Some(&recording));
                self.recording = Some(recording);
            }
            Err(e) => self.ended(Ended::NotStarted(e)),
        }
    }

    /// Stops a recording under way, keeping nothing of it, and says why.
    pub fn stop_recording(&mut self, why: &str) {
        if let Some(recording) = self.recording.take() {
            recording.cancel();
            self.ended(Ended::Cancelled(why.into()));
        }
    }

    /// A recording ended (or never began): the view goes back to the page's size and the page
    /// says how it ended.
    fn ended(&mut self, ended: Ended) {
        self.viewer.command(ViewCommand::RecordAt(None));
        fix_canvas(false);
        record::show_recording(None);
        signal("record", ended.signal());
        set_text("record-status", &ended.words());
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
        signal("recordFrames", &recording.frames_done().to_string());
        let ended = match step {
            Step::Done => match recording.save() {
                Ok(name) => Ended::Saved {
                    name,
                    frames,
                    seconds,
                },
                Err(e) => Ended::Failed(e),
            },
            Step::Failed(e) => {
                recording.cancel();
                Ended::Failed(e)
            }
            Step::Working => unreachable!("handled above"),
        };
        self.ended(ended);
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
        let draws = self.session.device(device);
        self.apply();
        draws
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
        self.session.viewer_replaced(page::background());
        self.apply();
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
        let covered = self.covered();
        self.session.hold(covered, self.recording.is_some());
        self.apply();
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
        for (loads, message) in refused {
            // The refusal of a shell the page has left since is not said.
            if loads.is_none_or(|l| self.session.is_current(l)) {
                self.session.refused();
                page::show_error(&message);
            }
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
            if self.session.is_current(report.loads) {
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
        if self.session.in_gallery() {
            self.pictures.work(&mut self.workers.borrow_mut());
            signal("pictures", self.pictures.signal());
            return Ok(());
        }
        self.session.address_due(now());
        self.apply();
        if covered {
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
        self.session.viewed(status, drawn, now());
        self.apply();
        Ok(())
    }

    /// Takes in what the workers sent back: the shell's growth and pieces go to the viewer,
    /// gallery shells to the pictures; a worker replaced with the shell's session has it grown
    /// again where the page's copy stands once the replies it sent before are in.
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
        let mut shell = Vec::new();
        for (request, reply) in polled.replies {
            match (request, reply) {
                (Request::Whole { job, .. }, Reply::Grown { result, .. }) => {
                    if let Some((tile, why)) = self.pictures.take(job, result) {
                        self.map.shown(tile, Err(why.clone()));
                        self.breed.shown(tile, Err(why));
                    }
                }
                (_, Reply::Tiled { job, result }) => self.map.take(job, result),
                answered => shell.push(answered),
            }
        }
        if let Err(message) = self.viewer.take_all(shell, polled.sessions_lost) {
            self.session.refused();
            page::show_error(&message);
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
        let shown = self.session.open_map(now());
        self.apply();
        if let Some((preset, spec)) = shown {
            self.map.open(
                preset,
                &spec,
                &mut self.workers.borrow_mut(),
                &mut self.pictures,
            );
        }
    }

    /// Draws the map anew over the axes its controls now describe.
    pub fn draw_map(&mut self) {
        if let Some((preset, spec)) = self.session.current() {
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
        if let Some((preset, spec)) = self.session.current() {
            let link = breeding::bred_link(preset, spec, &Lineage::default());
            let _ = web_sys::window().map(|w| w.location().set_hash(&link));
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
