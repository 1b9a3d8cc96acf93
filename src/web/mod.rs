//! The browser adapter: the wasm entry, the requestAnimationFrame loop that asks the generator
//! for a few rows a frame and hands them to the renderer, and the pointer events that turn the
//! camera. Everything it shows comes from the pure core.

mod page;

use crate::camera::OrbitCamera;
use crate::generator::Generator;
use crate::gestures::{Pointers, wheel_zoom};
use crate::render::{Renderer, ShellLook};
use crate::spec::link::{self, Decoded};
use std::cell::RefCell;
use std::rc::Rc;
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

/// The state the frame loop and the event handlers share.
struct App {
    renderer: Renderer,
    generator: Generator,
    camera: OrbitCamera,
    pointers: Pointers,
    canvas: HtmlCanvasElement,
    speed: f64,
    carry: f64,
    dirty: bool,
    first_frame: bool,
}

impl App {
    /// Keeps the drawing buffer at the canvas's size in device pixels.
    fn fit_canvas(&mut self) {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let width = (f64::from(self.canvas.client_width()) * dpr).round() as u32;
        let height = (f64::from(self.canvas.client_height()) * dpr).round() as u32;
        if width > 0 && height > 0 && (width, height) != (self.canvas.width(), self.canvas.height())
        {
            self.canvas.set_width(width);
            self.canvas.set_height(height);
            self.renderer.resize(width, height);
            self.dirty = true;
        }
    }

    /// One animation frame: grow a few rows, upload them, draw if anything changed. Returns
    /// false when the loop must stop.
    fn frame(&mut self) -> bool {
        if let Some(failure) = self.renderer.failure() {
            page::show_error(&failure);
            return false;
        }
        self.fit_canvas();
        if !self.generator.is_done() {
            self.carry += self.speed;
            let rows = self.carry.floor();
            self.carry -= rows;
            let advance = self.generator.advance(rows as usize);
            self.renderer
                .upload(self.generator.mesh(), self.generator.edge(), &advance, &[]);
            page::signal("rows", &self.generator.rows_done().to_string());
            self.dirty = true;
        }
        if self.dirty {
            if let Err(e) = self.renderer.draw(&self.camera) {
                page::show_error(&e);
                return false;
            }
            self.dirty = false;
            if self.first_frame {
                self.first_frame = false;
                page::signal("state", "growing");
            }
            if self.generator.is_done() {
                page::signal("state", "grown");
            }
        }
        true
    }
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

/// Sets up the renderer and starts growing the shell the link asks for.
#[wasm_bindgen]
pub async fn start() -> Result<(), JsValue> {
    page::signal("state", "loading");
    let canvas: HtmlCanvasElement = page::element("shell")
        .ok_or("the page has no canvas")?
        .dyn_into()
        .map_err(|_| "#shell is not a canvas")?;
    let renderer = match Renderer::new(canvas.clone()).await {
        Ok(r) => r,
        Err(message) => {
            page::set_text("backend", "Not drawn");
            page::show_error(&message);
            return Ok(());
        }
    };
    page::signal("backend", renderer.backend());
    page::set_text("backend", &format!("Drawn with {}", renderer.backend()));
    let Decoded { preset, spec, .. } = requested_shell();
    let generator = match Generator::new(&spec) {
        Ok(g) => g,
        Err(e) => {
            page::show_error(&format!("The shell '{}' cannot be built: {e}", preset.id));
            return Ok(());
        }
    };
    page::set_text("title", &preset.name);
    let (bounds, front) = generator.framing();
    let mut app = App {
        camera: OrbitCamera::framing(
            &bounds,
            front,
            preset.view.yaw.to_radians(),
            preset.view.pitch.to_radians(),
        ),
        renderer,
        pointers: Pointers::default(),
        canvas,
        speed: spec.growth.speed,
        carry: 0.0,
        dirty: true,
        first_frame: true,
        generator,
    };
    app.renderer.set_background(background());
    app.renderer.load_shell(
        app.generator.capacity(),
        None,
        ShellLook::new(&spec.colours, spec.rows_per_whorl()),
    );
    let grown = app.generator.grown();
    app.renderer
        .upload(app.generator.mesh(), app.generator.edge(), &grown, &[]);
    let app = Rc::new(RefCell::new(app));
    listen(&app)?;
    run(app);
    Ok(())
}

/// The page's background colour (light or dark theme), from the CSS custom property.
fn background() -> [u8; 3] {
    let dark = web_sys::window()
        .and_then(|w| w.match_media("(prefers-color-scheme: dark)").ok().flatten())
        .is_some_and(|m| m.matches());
    if dark {
        [0x16, 0x17, 0x19]
    } else {
        [0xf4, 0xf1, 0xea]
    }
}

/// The frame callback, shared with itself so that each frame can schedule the next.
type FrameLoop = Rc<RefCell<Option<Closure<dyn FnMut()>>>>;

/// Runs the frame loop until a frame says stop.
fn run(app: Rc<RefCell<App>>) {
    let callback: FrameLoop = Rc::new(RefCell::new(None));
    let next = Rc::clone(&callback);
    *callback.borrow_mut() = Some(Closure::new(move || {
        if app.borrow_mut().frame() {
            request_frame(next.borrow().as_ref().expect("the loop holds its closure"));
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
    target: &web_sys::EventTarget,
    kind: &str,
    app: &Rc<RefCell<App>>,
    handler: impl Fn(&mut App, E) + 'static,
) -> Result<(), JsValue> {
    let app = Rc::clone(app);
    let closure = Closure::<dyn FnMut(web_sys::Event)>::new(move |event: web_sys::Event| {
        if let Ok(event) = event.dyn_into::<E>() {
            handler(&mut app.borrow_mut(), event);
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

/// Pointer, wheel and double-click handling on the canvas.
fn listen(app: &Rc<RefCell<App>>) -> Result<(), JsValue> {
    let canvas: web_sys::EventTarget = app.borrow().canvas.clone().into();
    on(&canvas, "pointerdown", app, |app, e: PointerEvent| {
        // Capture keeps the drag alive outside the canvas; failing that, it ends at the edge.
        let _ = app.canvas.set_pointer_capture(e.pointer_id());
        app.pointers
            .press(e.pointer_id(), e.client_x() as f32, e.client_y() as f32);
    })?;
    on(&canvas, "pointermove", app, |app, e: PointerEvent| {
        let height = app.canvas.client_height().max(1) as f32;
        if app.pointers.moved(
            e.pointer_id(),
            e.client_x() as f32,
            e.client_y() as f32,
            height,
            &mut app.camera,
        ) {
            app.dirty = true;
        }
    })?;
    for kind in ["pointerup", "pointercancel"] {
        on(&canvas, kind, app, |app, e: PointerEvent| {
            app.pointers.release(e.pointer_id())
        })?;
    }
    on(&canvas, "wheel", app, |app, e: WheelEvent| {
        e.prevent_default();
        app.camera.zoom_by(wheel_zoom(e.delta_y()));
        app.dirty = true;
    })?;
    on(&canvas, "dblclick", app, |app, _: web_sys::MouseEvent| {
        app.camera.reset();
        app.dirty = true;
    })?;
    Ok(())
}
