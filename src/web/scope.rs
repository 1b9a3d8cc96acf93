//! What the page's window and a worker's global scope both give, read from whichever the code
//! runs in (a worker has no `window`): the address's query, the processor count, a timer, and
//! which thread it is.

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// The scope's `setTimeout` (the window's or the worker's).
    #[wasm_bindgen(js_name = setTimeout)]
    fn set_timeout(handler: &js_sys::Function, ms: i32) -> JsValue;
}

/// The scope's property `name`, or `undefined`.
fn global(name: &str) -> JsValue {
    js_sys::Reflect::get(&js_sys::global(), &name.into()).unwrap_or(JsValue::UNDEFINED)
}

/// The query of the address the scope was loaded from (`?workers=2`), or "".
pub(crate) fn search() -> String {
    js_sys::Reflect::get(&global("location"), &"search".into())
        .ok()
        .and_then(|s| s.as_string())
        .unwrap_or_default()
}

/// The value of `key` in the address's query (`?workers=2&view=page`), if it is there.
pub(crate) fn query(key: &str) -> Option<String> {
    search()
        .trim_start_matches('?')
        .split('&')
        .find_map(|pair| {
            pair.strip_prefix(key)?
                .strip_prefix('=')
                .map(str::to_string)
        })
}

/// `navigator.hardwareConcurrency`: the logical processors the browser says it has (1 if it
/// says nothing).
pub(crate) fn cores() -> usize {
    js_sys::Reflect::get(&global("navigator"), &"hardwareConcurrency".into())
        .ok()
        .and_then(|n| n.as_f64())
        .map_or(1, |n| n.max(1.0) as usize)
}

/// Calls `f` once after `ms` milliseconds.
pub(crate) fn after(ms: i32, f: impl FnOnce() + 'static) {
    let f = Closure::once_into_js(f);
    set_timeout(f.unchecked_ref(), ms);
}

/// The thread the code runs on, in words: the page's, or the worker's that draws the view.
pub(crate) fn thread_name() -> &'static str {
    if js_sys::Reflect::has(&js_sys::global(), &"document".into()).unwrap_or(false) {
        "the page's own thread"
    } else {
        "the drawing worker's own thread"
    }
}
