//! The browser adapter: the wasm entry, the requestAnimationFrame loop, and the events that
//! reach the viewer. Everything it shows comes from the pure core.

mod download;
mod page;
mod planar;
mod viewer;

use crate::export;
use crate::spec::link::{self, Decoded};
use std::cell::RefCell;
use std::rc::Rc;
use viewer::Viewer;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{HtmlCanvasElement, PointerEvent, WheelEvent};

/// Installs the panic hook: the console gets the full report, the page a sentence.
#[wasm_bindgen(start)]
pub fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        page::show_error(&format!(
            "Something went wrong inside the shell generator: {info}"
        ));
    }));
}

type Shared = Rc<RefCell<Viewer>>;

/// The benchmark's figures in this browser, as text (see `crate::bench`).
#[wasm_bindgen]
pub fn benchmark() -> String {
    let performance = web_sys::window().and_then(|w| w.performance());
    let now = || performance.as_ref().map_or(0.0, |p| p.now());
    crate::bench::report(&crate::bench::run(&now))
}

/// The shell the link's fragment asks for; what could not be used is said on the page.
fn requested_shell() -> Decoded {
    let hash = web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default();
    let decoded = link::decode(&hash);
    if !decoded.problems.is_empty() {
        let list: Vec<String> = decoded.problems.iter().map(ToString::to_string).collect();
        page::show_message(&format!(
            "Parts of this link could not be used: {}.",
            list.join("; ")
        ));
    }
    decoded
}

fn canvas(id: &str) -> Result<HtmlCanvasElement, JsValue> {
    page::element(id)
        .ok_or_else(|| JsValue::from_str(&format!("the page has no #{id}")))?
        .dyn_into()
        .map_err(|_| JsValue::from_str(&format!("#{id} is not a canvas")))
}

/// Sets up the renderer and starts growing the shell the link asks for.
#[wasm_bindgen]
pub async fn start() -> Result<(), JsValue> {
    page::signal("state", "loading");
    let viewer = match Viewer::new(canvas("shell")?, canvas("planar")?).await {
        Ok(v) => v,
        Err(message) => {
            page::set_text("backend", "Not drawn");
            page::show_error(&message);
            return Ok(());
        }
    };
    page::signal("backend", viewer.backend());
    page::set_text("backend", &format!("Drawn with {}", viewer.backend()));
    let viewer = Rc::new(RefCell::new(viewer));
    let Decoded { preset, spec, .. } = requested_shell();
    page::set_text("title", &preset.name);
    if let Err(message) = viewer.borrow_mut().load(preset, spec) {
        page::show_error(&message);
        return Ok(());
    }
    listen(&viewer)?;
    run(viewer);
    Ok(())
}

/// The frame callback, shared with itself so that each frame can schedule the next.
type FrameLoop = Rc<RefCell<Option<Closure<dyn FnMut()>>>>;

/// Runs the frame loop until a frame fails.
fn run(viewer: Shared) {
    let callback: FrameLoop = Rc::new(RefCell::new(None));
    let next = Rc::clone(&callback);
    *callback.borrow_mut() = Some(Closure::new(move || match viewer.borrow_mut().frame() {
        Ok(()) => request_frame(next.borrow().as_ref().expect("the loop holds its closure")),
        Err(message) => page::show_error(&message),
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
    target: &web_sys::EventTarget,
    kind: &str,
    viewer: &Shared,
    handler: impl Fn(&mut Viewer, E) + 'static,
) -> Result<(), JsValue> {
    let viewer = Rc::clone(viewer);
    let closure = Closure::<dyn FnMut(web_sys::Event)>::new(move |event: web_sys::Event| {
        if let Ok(event) = event.dyn_into::<E>() {
            handler(&mut viewer.borrow_mut(), event);
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

/// Pointer, wheel and double-click on the canvas; the download button.
fn listen(viewer: &Shared) -> Result<(), JsValue> {
    let canvas: web_sys::EventTarget = viewer.borrow().canvas().clone().into();
    on(&canvas, "pointerdown", viewer, |v, e: PointerEvent| {
        // Capture keeps the drag alive outside the canvas; failing that, it ends at the edge.
        let _ = v.canvas().set_pointer_capture(e.pointer_id());
        v.pointers
            .press(e.pointer_id(), e.client_x() as f32, e.client_y() as f32);
    })?;
    on(&canvas, "pointermove", viewer, |v, e: PointerEvent| {
        v.pointer_moved(e.pointer_id(), e.client_x() as f32, e.client_y() as f32);
    })?;
    for kind in ["pointerup", "pointercancel"] {
        on(&canvas, kind, viewer, |v, e: PointerEvent| {
            v.pointers.release(e.pointer_id())
        })?;
    }
    on(&canvas, "wheel", viewer, |v, e: WheelEvent| {
        e.prevent_default();
        v.wheel(e.delta_y());
    })?;
    on(&canvas, "dblclick", viewer, |v, _: web_sys::MouseEvent| {
        if let Some(camera) = v.camera_mut() {
            camera.reset();
        }
    })?;
    if let Some(button) = page::element("download-pattern") {
        on(
            &button.into(),
            "click",
            viewer,
            |v, _: web_sys::MouseEvent| {
                let Some(g) = v.growing() else { return };
                let Some(p) = g.generator.pattern() else {
                    return;
                };
                let png = export::png::encode(p.cells(), p.rows(), p.rgba());
                if let Err(e) =
                    download::offer(&format!("{}-pattern.png", g.preset.id), "image/png", &png)
                {
                    page::show_message(&format!("The pattern could not be downloaded: {e}."));
                }
            },
        )?;
    }
    Ok(())
}
