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

mod frame;
mod overlays;
mod placement;
mod recording;
mod show;

use show::{
    fix_canvas, location_hash, present, say, show_backend, show_drawn_in, show_speed, show_story,
};

use super::activity;
use super::breed::BreedView;
use super::clock::now;
use super::download::Downloads;
use super::gallery::Pictures;
use super::map::MapView;
use super::page::{self, element, element_as, set_text, signal};
use super::panel::{OnChange, Panel};
use super::planar::PlanarView;
use super::record::Recording;
use super::share_panel;
use super::shown_size::ShownSize;
use super::viewer::Viewer;
use super::viewer_handle::ViewerHandle;
use super::workers::Workers;
use crate::export::Download;
use crate::share::presentation::Presentation;
use crate::work::recording::Support;
use crate::work::session::{Edit, Effect, Session};
use crate::work::viewer_command::ViewCommand;
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use web_sys::{HtmlCanvasElement, HtmlProgressElement};

/// The app, shared by the frame loop and the page's listeners.
pub type Shared = Rc<RefCell<App>>;

pub struct App {
    viewer: ViewerHandle,
    /// What the page shows and every decision about it (see [`Session`]): this only applies
    /// its effects.
    session: Session,
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

    /// Whether a story's step is shown.
    pub fn in_story(&self) -> bool {
        self.session.in_story()
    }

    /// Goes to the story's next step (`forward`) or its previous one, as a link followed.
    pub fn story_step(&self, forward: bool) {
        if let (Some(fragment), Some(window)) =
            (self.session.story_step(forward), web_sys::window())
        {
            window.location().set_hash(&fragment).ok();
        }
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
                    if let Some(bar) = element_as::<HtmlProgressElement>("progress") {
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
                Effect::Story(at) => show_story(at.as_ref()),
                Effect::OpenMap(axes) => {
                    if let Some((preset, spec)) = self.session.current() {
                        self.map.open(
                            preset,
                            spec,
                            Some(&axes),
                            &mut self.workers.borrow_mut(),
                            &mut self.pictures,
                        );
                    }
                }
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

    /// Does what a button or a key asks of the session (play or pause, restart, step, finish,
    /// one view or four), and applies what it decided.
    pub fn act(&mut self, ask: impl FnOnce(&mut Session)) {
        ask(&mut self.session);
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

    /// Sets the growth speed in rows per frame from the text `speed` (part of the link; growth
    /// goes on).
    pub fn set_speed(&mut self, speed: &str) {
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
        if let (Some((preset, _)), Some(link)) = (self.session.current(), self.session.shown_link())
        {
            let presentation = Presentation {
                ui: share_panel::chosen_ui(),
                ..self.session.presentation()
            };
            let snippet = share_panel::snippet(&link, presentation, &preset.name);
            share_panel::copy_embed(snippet);
        }
    }

    /// Starts a download of the shell shown (written over the next frames).
    pub fn download(&mut self, what: Download) {
        if let Some(command) = self.downloads.start(what) {
            self.viewer.command(command);
        }
    }

    /// Follows a change of the page's light or dark theme.
    pub fn theme_changed(&mut self) {
        self.viewer
            .command(ViewCommand::Background(page::background()));
        self.pictures.set_background(page::background());
    }
}
