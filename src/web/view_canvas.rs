//! A canvas of the page whose drawing is handed to an `OffscreenCanvas`
//! (`transferControlToOffscreen`): the element stays in the page, laid out and pointed at; the
//! viewer draws on the offscreen canvas, which a worker could hold as well as the page's
//! thread. The element then shows what is drawn there.

use super::scope;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{HtmlCanvasElement, OffscreenCanvas};

/// A canvas of the page and the offscreen canvas that draws it.
pub struct ViewCanvas {
    pub element: HtmlCanvasElement,
    pub offscreen: OffscreenCanvas,
}

impl ViewCanvas {
    /// Hands the drawing of `element` to an offscreen canvas (an element whose drawing was
    /// handed over, or that has a context already, cannot be handed again: the reason is said).
    pub fn hand_over(element: HtmlCanvasElement) -> Result<Self, String> {
        let offscreen = element.transfer_control_to_offscreen().map_err(|e| {
            format!(
                "the canvas #{} could not be drawn off the page's layout ({})",
                element.id(),
                js_sys::JSON::stringify(&e).map_or_else(|_| "no reason given".into(), String::from)
            )
        })?;
        Ok(Self { element, offscreen })
    }

    /// A copy of the page's canvas `#id` (its id, classes, size and label, but no context) in
    /// its place, handed over afresh: what draws after a context that cannot be had again.
    pub fn replace(id: &str) -> Result<Self, String> {
        let old = super::page::element(id).ok_or_else(|| format!("the page has no #{id}"))?;
        let copy: HtmlCanvasElement = old
            .clone_node()
            .ok()
            .and_then(|n| n.dyn_into().ok())
            .ok_or("the canvas could not be copied")?;
        old.replace_with_with_node_1(&copy)
            .map_err(|_| "the canvas could not be replaced")?;
        Self::hand_over(copy)
    }
}

/// Test-only (see `debug.rs`): takes the canvas's WebGL context away with
/// `WEBGL_lose_context`, as the browser would, and gives it back after `restore_after_ms` if
/// asked. Says why when the canvas has no WebGL2 context.
pub fn lose_context(canvas: &OffscreenCanvas, restore_after_ms: Option<i32>) -> Result<(), String> {
    let call = |target: &JsValue, method: &str, args: &js_sys::Array| {
        js_sys::Reflect::get(target, &method.into())
            .ok()
            .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
            .and_then(|f| f.apply(target, args).ok())
            .filter(|v| !v.is_null() && !v.is_undefined())
    };
    let context: JsValue = canvas
        .get_context("webgl2")
        .ok()
        .flatten()
        .ok_or("the canvas has no WebGL2 context")?
        .into();
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

/// The address of the `Blob` that `blob` (a promise, as `convertToBlob` gives) resolves to, for
/// a link or an image to show.
pub async fn object_url(blob: js_sys::Promise) -> Result<String, String> {
    let blob: web_sys::Blob = wasm_bindgen_futures::JsFuture::from(blob)
        .await
        .ok()
        .and_then(|b| b.dyn_into().ok())
        .ok_or("the browser could not read the canvas")?;
    web_sys::Url::create_object_url_with_blob(&blob)
        .map_err(|_| "the browser refused the picture's address".to_string())
}
