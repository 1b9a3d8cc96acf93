//! Test-only hooks, exported from the wasm module for the page tests
//! (`tests/page/survive.test.mjs`, `tests/page/workers.test.mjs`, `tests/page/map.test.mjs`) to
//! force what a user's machine does rarely: a destroyed graphics device, a lost WebGL context, a
//! panic, a worker that throws, shells drawn slowly. They are
//! not part of the page's interface; calling one does to the page what the event itself would,
//! and the page must survive it.

use std::cell::{Cell, RefCell};
use wasm_bindgen::prelude::*;

/// How a test takes the page's graphics devices away.
#[derive(Clone, Copy, Debug)]
pub enum Loss {
    /// `GPUDevice.destroy()`, as a driver reset would (WebGPU; nothing on WebGL2).
    Destroy,
    /// `WEBGL_lose_context`'s `loseContext()`, given back after this many milliseconds if
    /// asked (WebGL2).
    Context { restore_after_ms: Option<i32> },
}

/// Takes the page's graphics devices away; says why it could not.
pub type Destroy = Box<dyn Fn(Loss) -> Result<(), String>>;

/// Passes a hook that acts where the main viewer grows ("panic", "crash-on-fill") on to a
/// viewer drawing in a worker.
pub type Forward = Box<dyn Fn(&str)>;

thread_local! {
    static DESTROY: RefCell<Option<Destroy>> = const { RefCell::new(None) };
    static FORWARD: RefCell<Option<Forward>> = const { RefCell::new(None) };
    static PANIC_WHILE_GROWING: Cell<bool> = const { Cell::new(false) };
    static CRASH_ON_FILL: Cell<bool> = const { Cell::new(false) };
    static PACE: Cell<Option<f64>> = const { Cell::new(None) };
}

/// Remembers how to reach the page's devices, for [`debug_destroy_device`] and
/// [`debug_lose_context`].
pub fn register(destroy: Destroy) {
    DESTROY.with(|d| *d.borrow_mut() = Some(destroy));
}

/// Test-only: destroys the page's graphics devices, the main viewer's and the gallery
/// pictures' (`GPUDevice.destroy()`, as a driver reset would lose them). On WebGL2 this does nothing: tests lose the context with
/// `WEBGL_lose_context` instead.
#[wasm_bindgen]
pub fn debug_destroy_device() -> Result<(), JsValue> {
    take_devices(Loss::Destroy)
}

/// Test-only: takes the WebGL contexts of the page's canvases away (`WEBGL_lose_context`, as
/// the browser would), the main viewer's and the gallery pictures', and gives them back after
/// `restore_after_ms` if given. The canvases draw off the page's layout, so a test cannot ask
/// their contexts itself.
#[wasm_bindgen]
pub fn debug_lose_context(restore_after_ms: Option<i32>) -> Result<(), JsValue> {
    take_devices(Loss::Context { restore_after_ms })
}

/// Remembers how to reach a viewer drawing in a worker, for the hooks that act where the
/// viewer grows.
pub fn register_forward(forward: Forward) {
    FORWARD.with(|f| *f.borrow_mut() = Some(forward));
}

fn forward(ask: &str) {
    FORWARD.with(|f| {
        if let Some(forward) = f.borrow().as_ref() {
            forward(ask);
        }
    });
}

fn take_devices(loss: Loss) -> Result<(), JsValue> {
    DESTROY.with(|d| match d.borrow().as_ref() {
        Some(destroy) => destroy(loss).map_err(JsValue::from),
        None => Err("the page has not started".into()),
    })
}

/// Test-only: from now on the browser has no WebGPU adapter to give (`navigator.gpu`'s
/// `requestAdapter` answers none), on the page's thread and in a worker drawing the view: a
/// device lost then can only be opened again with WebGL2.
#[wasm_bindgen]
pub fn debug_take_webgpu_away() -> Result<(), JsValue> {
    let global = js_sys::global();
    let navigator = js_sys::Reflect::get(&global, &"navigator".into())?;
    let gpu = js_sys::Reflect::get(&navigator, &"gpu".into())?;
    if gpu.is_undefined() {
        return Err("this browser has no WebGPU to take away".into());
    }
    let none =
        Closure::<dyn Fn() -> js_sys::Promise>::new(|| js_sys::Promise::resolve(&JsValue::NULL));
    js_sys::Reflect::set(&gpu, &"requestAdapter".into(), none.as_ref())?;
    none.forget();
    forward("no-webgpu");
    Ok(())
}

/// Test-only: makes the next growth step panic, inside the frame loop, as a bug would.
#[wasm_bindgen]
pub fn debug_panic_while_growing() {
    PANIC_WHILE_GROWING.with(|p| p.set(true));
    forward("panic");
}

/// Panics if a test asked for it with [`debug_panic_while_growing`].
pub fn panic_if_asked() {
    if PANIC_WHILE_GROWING.with(|p| p.replace(false)) {
        panic!("a panic forced by the page tests' hook (debug_panic_while_growing)");
    }
}

/// Test-only: makes the worker holding the sessions throw when it is next asked for rows of a
/// previewed pattern (`Fill`), as a worker that fails mid-preview would
/// (`tests/page/workers.test.mjs`).
#[wasm_bindgen]
pub fn debug_crash_worker_on_fill() {
    CRASH_ON_FILL.with(|c| c.set(true));
    forward("crash-on-fill");
}

/// Whether a test asked with [`debug_crash_worker_on_fill`] (once).
pub fn crash_on_fill_asked() -> bool {
    CRASH_ON_FILL.with(|c| c.replace(false))
}

/// Test-only: the next map of shells or generation of offspring is drawn as if this machine
/// had drawn the last shells at `seconds` each, as a slow machine would
/// (`tests/page/map.test.mjs`, `tests/page/breed.test.mjs`).
#[wasm_bindgen]
pub fn debug_pace_of_shells(seconds: f64) {
    PACE.with(|p| p.set(Some(seconds)));
}

/// The pace a test asked for with [`debug_pace_of_shells`] (once).
pub fn forced_pace() -> Option<f64> {
    PACE.with(Cell::take)
}
