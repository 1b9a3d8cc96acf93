//! The browser adapter: the wasm entry, the requestAnimationFrame loop, and the events that
//! reach the app. Everything it shows comes from the pure core.

mod activity;
mod app;
mod breed;
mod canvases;
mod clock;
mod debug;
mod dom;
mod download;
mod drawing_worker;
mod gallery;
mod map;
mod page;
mod panel;
mod planar;
mod record;
mod recovery;
mod scope;
mod share_panel;
mod shown_size;
mod tile_grid;
mod viewer;
mod viewer_handle;
mod webcodecs;
mod worker_host;
mod workers;

use crate::export::Download;
use crate::render::Canvas;
use crate::work::recording::Support;
use crate::work::shortcuts::{self, Press, Shortcut, Target};
use crate::work::viewer_command::{PointerChange, ViewCommand};
use app::App;
use std::cell::RefCell;
use std::rc::Rc;
use viewer::Viewer;
use viewer_handle::{DrawingWorker, ViewerHandle};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{
    Event, EventTarget, HtmlCanvasElement, HtmlInputElement, KeyboardEvent, PointerEvent,
    WheelEvent,
};

/// Installs the panic hook: the console gets the full report, the page a sentence saying what
/// was being done ("while growing murex-pecten, row 312") and a button that reloads the link.
#[wasm_bindgen(start)]
pub fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        page::show_crash(&activity::crash_words(info));
    }));
}

/// The benchmark's figures in this browser, as text (see `crate::bench`).
#[wasm_bindgen]
pub fn benchmark() -> Result<String, JsValue> {
    let performance = web_sys::window()
        .and_then(|w| w.performance())
        .ok_or("this browser has no clock to time with (window.performance)")?;
    Ok(crate::bench::report(&crate::bench::run(&|| {
        performance.now()
    })))
}

/// The pattern spec of preset `id` as JSON, for the benchmark page's JavaScript reference
/// solver to run on the same sizes and parameters.
#[wasm_bindgen]
pub fn preset_pattern(id: &str) -> Option<String> {
    crate::presets::preset(id).and_then(|p| serde_json::to_string(&p.spec.pattern).ok())
}

type Shared = Rc<RefCell<App>>;

fn canvas(id: &str) -> Result<HtmlCanvasElement, String> {
    page::element(id)
        .ok_or_else(|| format!("the page has no #{id}"))?
        .dyn_into()
        .map_err(|_| format!("#{id} is not a canvas"))
}

/// Builds the gallery, sets up both renderers and shows what the link asks for.
#[wasm_bindgen]
pub async fn start() -> Result<(), JsValue> {
    signal_loading();
    if let Some(groups) = page::element("gallery-groups") {
        gallery::build(&groups);
    }
    let background = page::background();
    let workers = workers::Workers::start(crate::generator::GROWTH_BUDGET_MS);
    page::signal("workers", &workers.count().to_string());
    page::set_text("workers-status", workers.status());
    let workers = Rc::new(RefCell::new(workers));
    let shared = || Rc::clone(&workers);
    let (shell, pictures) = match (canvas("shell"), canvas("picture-canvas")) {
        (Ok(shell), Ok(pictures)) => (shell, pictures),
        (Err(e), _) | (_, Err(e)) => {
            page::show_error(&format!("The page is incomplete: {e}."));
            return Ok(());
        }
    };
    // Where no renderer opens, the viewers draw nothing and the page says so: the gallery
    // lists every shell, and a shell still grows its pattern and gives its files.
    let main = match main_viewer(shell, background, shared()).await {
        Ok(main) => main,
        Err(why) => {
            page::show_no_3d(&why);
            ViewerHandle::Here(Box::new(Viewer::without_drawing(
                true,
                background,
                shared(),
            )))
        }
    };
    let pictures = Viewer::new(
        Canvas::Element(pictures),
        false,
        background,
        false,
        shared(),
    )
    .await
    .unwrap_or_else(|_| Viewer::without_drawing(false, background, shared()));
    let app: Shared = Rc::new(RefCell::new(App::new(
        main,
        gallery::Pictures::new(pictures),
        workers,
    )));
    let weak = Rc::downgrade(&app);
    debug::register(Box::new(move |loss| {
        let app = weak.upgrade().ok_or("the page has ended")?;
        let app = app.try_borrow().map_err(|_| "the page is busy")?;
        app.take_devices(loss)
    }));
    let weak = Rc::downgrade(&app);
    debug::register_forward(Box::new(move |ask| {
        if let Some(app) = weak.upgrade()
            && let Ok(app) = app.try_borrow()
        {
            app.forward_debug(ask);
        }
    }));
    let weak = Rc::downgrade(&app);
    app.borrow_mut()
        .set_on_change(Rc::new(move |key: &str, value: String, change| {
            if let Some(app) = weak.upgrade() {
                app.borrow_mut().edit(key, value, change);
            }
        }));
    app.borrow_mut().route();
    listen(&app)?;
    app.borrow().show_support();
    run(app);
    Ok(())
}

/// The main viewer, on the canvas `element`: in a worker where one draws (see
/// `viewer_handle.rs`), else, or when the worker cannot start or open a renderer on the canvas
/// handed to it (WebKit's offscreen canvases give no WebGL2), on the page's thread, on the
/// element itself (a fresh copy of it, if it was handed to the worker). The page says where,
/// in words; the worker's reason goes to the console.
async fn main_viewer(
    element: HtmlCanvasElement,
    background: [u8; 3],
    workers: Rc<RefCell<workers::Workers>>,
) -> Result<ViewerHandle, String> {
    let (element, note) = if viewer_handle::in_worker() {
        let started = match canvases::hand_over(&element) {
            Ok(offscreen) => DrawingWorker::start(offscreen, true, background).await,
            Err(e) => Err(e),
        };
        match started {
            Ok(worker) => return Ok(ViewerHandle::Worker(worker)),
            Err(e) => {
                web_sys::console::info_1(
                    &format!("The view is drawn on the page's thread: {e}").into(),
                );
                let note = format!(
                    "{} Drawn on the page's thread: this browser cannot draw in a worker.",
                    workers.borrow().status()
                );
                (canvases::replace("shell")?, Some(note))
            }
        }
    } else {
        (element, None)
    };
    let viewer = Viewer::new(Canvas::Element(element), true, background, true, workers).await?;
    if let Some(note) = note {
        page::set_text("workers-status", &note);
    }
    Ok(ViewerHandle::Here(Box::new(viewer)))
}

/// Record: records the growth; the first time, asks the browser what it can record video
/// with, shows the answer, and records once it has one.
/// (After a panic the app stays borrowed, and the click does nothing.)
fn record(app: &Shared) {
    let Ok(mut held) = app.try_borrow_mut() else {
        return;
    };
    let support = held.support();
    if *support.borrow() != Support::Unasked {
        held.record();
        return;
    }
    *support.borrow_mut() = Support::Checking;
    held.show_support();
    drop(held);
    let app = Rc::downgrade(app);
    wasm_bindgen_futures::spawn_local(async move {
        let found = record::probe().await;
        *support.borrow_mut() = found;
        if let Some(app) = app.upgrade()
            && let Ok(mut app) = app.try_borrow_mut()
        {
            app.show_support();
            app.record();
        }
    });
}

fn signal_loading() {
    page::signal("state", "loading");
}

/// The frame callback, shared with itself so that each frame can schedule the next.
type FrameLoop = Rc<RefCell<Option<Closure<dyn FnMut()>>>>;

/// Runs the frame loop until a frame fails.
fn run(app: Shared) {
    let callback: FrameLoop = Rc::new(RefCell::new(None));
    let next = Rc::clone(&callback);
    *callback.borrow_mut() = Some(Closure::new(move || {
        let outcome = app.borrow_mut().frame();
        // A fresh canvas took the old one's place (a lost device opened again): listen to it.
        let replaced = app.borrow_mut().take_replaced_canvas();
        if let Some(canvas) = replaced
            && let Err(e) = listen_canvas(&app, &canvas.into())
        {
            page::show_error(&format!("The new canvas could not be listened to: {e:?}"));
            return;
        }
        match outcome {
            Ok(()) => request_frame(next.borrow().as_ref().expect("the loop holds its closure")),
            Err(message) => page::show_error(&message),
        }
    }));
    request_frame(callback.borrow().as_ref().expect("just set"));
}

fn request_frame(f: &Closure<dyn FnMut()>) {
    if let Some(window) = web_sys::window() {
        // Failing to schedule a frame only stops the animation; nothing else to do.
        let _ = window.request_animation_frame(f.as_ref().unchecked_ref());
    }
}

/// Adds an event listener that lives as long as the page.
fn on<E: JsCast + 'static>(
    target: &EventTarget,
    kind: &str,
    app: &Shared,
    handler: impl Fn(&mut App, E) + 'static,
) -> Result<(), JsValue> {
    let app = Rc::clone(app);
    let closure = Closure::<dyn FnMut(Event)>::new(move |event: Event| {
        // After a panic the app stays borrowed: events then do nothing, and the page shows
        // the panic's message.
        if let (Ok(event), Ok(mut app)) = (event.dyn_into::<E>(), app.try_borrow_mut()) {
            handler(&mut app, event);
        }
    });
    let options = web_sys::AddEventListenerOptions::new();
    options.set_passive(false);
    target.add_event_listener_with_callback_and_add_event_listener_options(
        kind,
        closure.as_ref().unchecked_ref(),
        &options,
    )?;
    closure.forget();
    Ok(())
}

/// A click on the element with this id.
fn on_click(id: &str, app: &Shared, handler: impl Fn(&mut App) + 'static) -> Result<(), JsValue> {
    match page::element(id) {
        Some(e) => on(&e.into(), "click", app, move |a, _: Event| handler(a)),
        None => Ok(()),
    }
}

/// Listens to the shell's canvas: orbit, zoom, reset (again on a fresh canvas that replaced it).
fn listen_canvas(app: &Shared, canvas: &EventTarget) -> Result<(), JsValue> {
    on(canvas, "pointerdown", app, |a, e: PointerEvent| {
        // Capture keeps the drag alive outside the canvas; failing that, it ends at the edge.
        if let Some(canvas) = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
        {
            let _ = canvas.set_pointer_capture(e.pointer_id());
        }
        a.viewer()
            .command(ViewCommand::Pointer(PointerChange::Down {
                id: e.pointer_id(),
                x: e.client_x() as f32,
                y: e.client_y() as f32,
            }));
    })?;
    on(canvas, "pointermove", app, |a, e: PointerEvent| {
        a.viewer()
            .command(ViewCommand::Pointer(PointerChange::Move {
                id: e.pointer_id(),
                x: e.client_x() as f32,
                y: e.client_y() as f32,
            }));
    })?;
    for kind in ["pointerup", "pointercancel"] {
        on(canvas, kind, app, |a, e: PointerEvent| {
            a.viewer().command(ViewCommand::Pointer(PointerChange::Up {
                id: e.pointer_id(),
            }));
        })?;
    }
    on(canvas, "wheel", app, |a, e: WheelEvent| {
        // An embedded shell leaves the wheel to the page around it; a pinch (or the wheel with
        // Ctrl) still zooms.
        if a.embedded() && !e.ctrl_key() {
            return;
        }
        e.prevent_default();
        a.viewer().command(ViewCommand::Wheel(e.delta_y()));
    })?;
    on(canvas, "dblclick", app, |a, _: Event| a.reset_camera())?;
    Ok(())
}

fn listen(app: &Shared) -> Result<(), JsValue> {
    let window: EventTarget = web_sys::window().ok_or("no window")?.into();
    on(&window, "hashchange", app, |a, _: Event| a.route())?;
    if let Some(query) =
        web_sys::window().and_then(|w| w.match_media("(prefers-color-scheme: dark)").ok().flatten())
    {
        on(&query.into(), "change", app, |a, _: Event| {
            a.theme_changed()
        })?;
    }
    listen_canvas(app, &canvas("shell")?.into())?;
    on_click("play", app, App::toggle_playing)?;
    on_click("restart", app, App::restart)?;
    on_click("step", app, App::step)?;
    on_click("finish", app, App::finish)?;
    on_click("reset-camera", app, App::reset_camera)?;
    on_click("views", app, App::toggle_views)?;
    on_click("fullscreen", app, |a| a.toggle_fullscreen())?;
    on_click("copy-link", app, App::copy_link)?;
    on_click("copy-embed", app, App::copy_embed)?;
    if let Some(button) = page::element("record") {
        let shared = Rc::clone(app);
        let closure = Closure::<dyn FnMut()>::new(move || record(&shared));
        button.add_event_listener_with_callback("click", closure.as_ref().unchecked_ref())?;
        closure.forget();
    }
    on_click("record-cancel", app, |a| {
        a.stop_recording("you cancelled it")
    })?;
    for what in Download::ALL {
        on_click(&format!("download-{}", what.name()), app, move |a| {
            a.download(what)
        })?;
    }
    on_click("map-open", app, App::open_map)?;
    on_click("map-draw", app, App::draw_map)?;
    on_click("map-close", app, App::close_map)?;
    on_click("breed-open", app, App::open_breeding)?;
    on_click("breed-back", app, App::breed_back)?;
    on_click("breed-keep", app, App::breed_keep)?;
    if let Some(rate) = page::element("breed-rate") {
        on(&rate.clone().into(), "input", app, |_, e: Event| {
            if let Some(input) = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
            {
                page::set_text("breed-rate-value", &input.value());
            }
        })?;
        on(&rate.into(), "change", app, |a, e: Event| {
            let value = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                .and_then(|i| i.value().parse::<f64>().ok());
            if let Some(rate) = value {
                a.breed_rate(rate);
            }
        })?;
    }
    for name in ["x", "y"] {
        if let Some(select) = page::element(&format!("map-{name}")) {
            on(&select.into(), "change", app, move |a, _: Event| {
                a.map_chose(name)
            })?;
        }
    }
    on_click("panel-toggle", app, |_| {
        if let (Some(panel), Some(button)) = (page::element("panel"), page::element("panel-toggle"))
        {
            let open = panel.class_list().toggle("open").unwrap_or(false);
            dom::attr(
                &button,
                "aria-expanded",
                if open { "true" } else { "false" },
            );
        }
    })?;
    if let Some(speed) = page::element("speed") {
        on(&speed.into(), "change", app, |a, e: Event| {
            let value = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                .map(|i| i.value());
            if let Some(v) = value.and_then(|v| v.parse::<f64>().ok()) {
                a.set_speed(v);
            }
        })?;
    }
    let document: EventTarget = page::document().into();
    on(&document, "visibilitychange", app, |a, _: Event| {
        if page::document().hidden() {
            a.stop_recording("the tab was hidden");
        }
    })?;
    on(&document, "keydown", app, |a, e: KeyboardEvent| {
        let target = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
            .map_or(Target::Page, |t| Target::of_tag(&t.tag_name()));
        let key = e.key();
        let press = Press {
            key: &key,
            modified: e.ctrl_key() || e.meta_key() || e.alt_key(),
            target,
            shell_shown: a.has_shell(),
            covered: a.covered(),
        };
        let Some(shortcut) = shortcuts::shortcut(press) else {
            return;
        };
        match shortcut {
            Shortcut::Tiles(dx, dy) => a.step_tiles(dx, dy),
            Shortcut::Leave => a.escape(),
            Shortcut::PlayPause => a.toggle_playing(),
            Shortcut::Restart => a.restart(),
            Shortcut::Step => a.step(),
            Shortcut::Finish => a.finish(),
            Shortcut::ResetCamera => a.reset_camera(),
            Shortcut::ToggleViews => a.toggle_views(),
            Shortcut::Fullscreen => a.toggle_fullscreen(),
            Shortcut::Speed(change) => a.set_speed(change.of(a.speed())),
        }
        e.prevent_default();
    })?;
    Ok(())
}
