//! The clock of the thread it is called on: `performance.now()` of the page's global scope or
//! of a worker's (which has no `window`).

use wasm_bindgen::JsCast;

thread_local! {
    /// The scope's `performance`, looked up once: a lookup is several calls out of wasm, and a
    /// frame of the page reads the clock about a dozen times.
    static PERFORMANCE: Option<web_sys::Performance> =
        js_sys::Reflect::get(&js_sys::global(), &"performance".into())
            .ok()
            .and_then(|p| p.dyn_into().ok());
}

/// Milliseconds since the thread's time origin (0 in a scope without a clock).
pub(crate) fn now() -> f64 {
    PERFORMANCE.with(|p| p.as_ref().map_or(0.0, web_sys::Performance::now))
}
