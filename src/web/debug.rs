//! Test-only hooks, exported from the wasm module for the page tests
//! (`tests/page/survive.test.mjs`) to force what a user's machine does rarely: a destroyed
//! graphics device and a panic. They are not part of the page's interface; calling one does to
//! the page what the event itself would, and the page must survive it.

use super::app::App;
use std::cell::{Cell, RefCell};
use std::rc::Weak;
use wasm_bindgen::prelude::*;

thread_local! {
    static APP: RefCell<Weak<RefCell<App>>> = RefCell::new(Weak::new());
    static PANIC_WHILE_GROWING: Cell<bool> = const { Cell::new(false) };
}

/// Remembers the app, for the hooks to reach it.
pub fn register(app: Weak<RefCell<App>>) {
    APP.with(|a| *a.borrow_mut() = app);
}

/// Test-only: destroys the main viewer's graphics device (`GPUDevice.destroy()`, as a driver
/// reset would lose it). On WebGL2 this does nothing: tests lose the context with
/// `WEBGL_lose_context` instead.
#[wasm_bindgen]
pub fn debug_destroy_device() -> Result<(), JsValue> {
    let app = APP
        .with(|a| a.borrow().upgrade())
        .ok_or("the page has not started")?;
    let mut app = app.try_borrow_mut().map_err(|_| "the page is busy")?;
    app.viewer().destroy_device();
    Ok(())
}

/// Test-only: makes the next growth step panic, inside the frame loop, as a bug would.
#[wasm_bindgen]
pub fn debug_panic_while_growing() {
    PANIC_WHILE_GROWING.with(|p| p.set(true));
}

/// Panics if a test asked for it with [`debug_panic_while_growing`].
pub fn panic_if_asked() {
    if PANIC_WHILE_GROWING.with(|p| p.replace(false)) {
        panic!("a panic forced by the page tests' hook (debug_panic_while_growing)");
    }
}
