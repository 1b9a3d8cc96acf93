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
mod listen;
mod map;
mod page;
mod panel;
mod planar;
mod record;
mod scope;
mod share_panel;
mod shown_size;
mod tile_grid;
mod viewer;
mod viewer_handle;
mod webcodecs;
mod worker_host;
mod workers;

use crate::render::Canvas;
use crate::view::drawn_in::DrawnIn;
use app::{App, Shared};
use std::cell::RefCell;
use std::rc::Rc;
use viewer::Viewer;
use viewer_handle::{DrawingWorker, ViewerHandle};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

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

/// Builds the gallery, sets up both renderers and shows what the link asks for.
#[wasm_bindgen]
pub async fn start() -> Result<(), JsValue> {
    signal_loading();
    if let Some(groups) = page::element("gallery-groups") {
        dom::build(&groups, &crate::markup::gallery());
    }
    if let Some(list) = page::element("figures-list") {
        dom::build(&list, &crate::markup::figures());
    }
    let background = page::background();
    let workers = workers::Workers::start(crate::generator::GROWTH_BUDGET_MS);
    page::signal("workers", &workers.count().to_string());
    page::set_text("workers-status", workers.status());
    let workers = Rc::new(RefCell::new(workers));
    let shared = || Rc::clone(&workers);
    let (shell, pictures) = match (
        canvases::canvas("shell"),
        canvases::canvas("picture-canvas"),
    ) {
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
            let moved = DrawnIn::Page.fall_back(&why, false);
            page::show_no_3d(moved.no_3d.as_deref().unwrap_or(&why));
            ViewerHandle::Here(Box::new(Viewer::without_drawing(
                true,
                background,
                shared(),
            )))
        }
    };
    let pictures = viewer::WebScreen::on(Canvas::Element(pictures), background).await;
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
    listen::listen(&app)?;
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
    let asked_page = scope::query("view").as_deref() == Some("page");
    let first = DrawnIn::first(viewer_handle::worker_draws(), asked_page);
    let (element, note) = if first == DrawnIn::Worker {
        let started = match canvases::hand_over(&element) {
            Ok(offscreen) => DrawingWorker::start(offscreen, true, background).await,
            Err(e) => Err(e),
        };
        match started {
            Ok(worker) => return Ok(ViewerHandle::Worker(worker)),
            Err(e) => {
                let moved = first.fall_back(&e, false);
                if let Some(log) = &moved.log {
                    web_sys::console::info_1(&log.into());
                }
                let status = workers.borrow().status().to_string();
                let note = moved.status.map(|words| format!("{status} {words}"));
                (canvases::replace("shell")?, note)
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
            && let Err(e) = listen::listen_canvas(&app, &canvas.into())
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
