//! The page's canvases as the viewers draw on them: an element handed to the drawing worker as
//! an `OffscreenCanvas` (`transferControlToOffscreen`: the element stays in the page, laid out
//! and pointed at, and shows what the worker draws), or drawn on as it is from the page's
//! thread; a fresh copy of an element that cannot be drawn on again; what a canvas shows, read
//! back as a PNG.

use super::page;
use super::scope;
use crate::render::Canvas;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{HtmlCanvasElement, OffscreenCanvas};

/// Hands the drawing of `element` to an offscreen canvas (an element whose drawing was handed
/// over, or that has a context already, cannot be handed again: the reason is said).
pub fn hand_over(element: &HtmlCanvasElement) -> Result<OffscreenCanvas, String> {
    element.transfer_control_to_offscreen().map_err(|e| {
        format!(
            "the canvas #{} could not be drawn off the page's layout ({})",
            element.id(),
            js_sys::JSON::stringify(&e).map_or_else(|_| "no reason given".into(), String::from)
        )
    })
}

/// A copy of the page's canvas `#id` (its id, classes, size and label, but no context) in its
/// place: what draws after a context that cannot be had again, or after the drawing worker
/// could not draw on the one handed to it.
pub fn replace(id: &str) -> Result<HtmlCanvasElement, String> {
    let old = super::page::element(id).ok_or_else(|| format!("the page has no #{id}"))?;
    let copy: HtmlCanvasElement = old
        .clone_node()
        .ok()
        .and_then(|n| n.dyn_into().ok())
        .ok_or("the canvas could not be copied")?;
    old.replace_with_with_node_1(&copy)
        .map_err(|_| "the canvas could not be replaced")?;
    Ok(copy)
}

/// What `canvas` shows, as the promise of a PNG `Blob` (asked for in the task that drew it,
/// before the browser clears the drawing).
pub fn png(canvas: &Canvas) -> Result<js_sys::Promise, String> {
    let refused = |_| "the browser refused to read the canvas".to_string();
    match canvas {
        Canvas::Offscreen(c) => c.convert_to_blob().map_err(refused),
        Canvas::Element(c) => {
            let mut read = Ok(());
            let promise = js_sys::Promise::new(&mut |resolve, reject| {
                let callback = Closure::once_into_js(move |blob: JsValue| {
                    let _ = if blob.is_null() {
                        reject.call1(&JsValue::NULL, &"no picture".into())
                    } else {
                        resolve.call1(&JsValue::NULL, &blob)
                    };
                });
                read = c.to_blob(callback.unchecked_ref());
            });
            read.map(|()| promise).map_err(refused)
        }
    }
}

/// Test-only (see `debug.rs`): takes the canvas's WebGL context away with
/// `WEBGL_lose_context`, as the browser would, and gives it back after `restore_after_ms` if
/// asked. Says why when the canvas has no WebGL2 context.
pub fn lose_context(canvas: &Canvas, restore_after_ms: Option<i32>) -> Result<(), String> {
    let call = |target: &JsValue, method: &str, args: &js_sys::Array| {
        js_sys::Reflect::get(target, &method.into())
            .ok()
            .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
            .and_then(|f| f.apply(target, args).ok())
            .filter(|v| !v.is_null() && !v.is_undefined())
    };
    let context = call(
        canvas.as_js(),
        "getContext",
        &js_sys::Array::of1(&"webgl2".into()),
    )
    .ok_or("the canvas has no WebGL2 context")?;
    let lose = call(
        &context,
        "getExtension",
        &js_sys::Array::of1(&"WEBGL_lose_context".into()),
    )
    .ok_or("the browser has no WEBGL_lose_context")?;
    call(&lose, "loseContext", &js_sys::Array::new());
    if let Some(ms) = restore_after_ms {
        scope::after(ms, move || {
            call(&lose, "restoreContext", &js_sys::Array::new());
        });
    }
    Ok(())
}

/// The address of the `Blob` that `blob` (a promise, as [`png`] gives) resolves to, for a link
/// or an image to show.
pub async fn object_url(blob: js_sys::Promise) -> Result<String, String> {
    let blob: web_sys::Blob = wasm_bindgen_futures::JsFuture::from(blob)
        .await
        .ok()
        .and_then(|b| b.dyn_into().ok())
        .ok_or("the browser could not read the canvas")?;
    web_sys::Url::create_object_url_with_blob(&blob)
        .map_err(|_| "the browser refused the picture's address".to_string())
}

/// The canvas element of id `id`, or why the page has none.
pub fn canvas(id: &str) -> Result<HtmlCanvasElement, String> {
    page::element(id)
        .ok_or_else(|| format!("the page has no #{id}"))?
        .dyn_into()
        .map_err(|_| format!("#{id} is not a canvas"))
}
