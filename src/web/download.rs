//! Offering bytes made by the core as a file download.

use wasm_bindgen::JsCast;
use web_sys::{Blob, BlobPropertyBag, HtmlAnchorElement, Url};

/// Starts the download of the resource at `url` (an object or data URL) as `name`.
pub fn offer_url(name: &str, url: &str) -> Result<(), String> {
    let anchor: HtmlAnchorElement = super::page::document()
        .create_element("a")
        .map_err(|_| "cannot create a link".to_string())?
        .dyn_into()
        .map_err(|_| "cannot create a link".to_string())?;
    anchor.set_href(url);
    anchor.set_download(name);
    anchor.click();
    Ok(())
}

/// Starts the download of `bytes` as `name`.
pub fn offer(name: &str, mime: &str, bytes: &[u8]) -> Result<(), String> {
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = BlobPropertyBag::new();
    options.set_type(mime);
    let blob = Blob::new_with_u8_array_sequence_and_options(&parts, &options)
        .map_err(|_| "the browser refused to make the file".to_string())?;
    let url = Url::create_object_url_with_blob(&blob)
        .map_err(|_| "the browser refused the file's address".to_string())?;
    let result = offer_url(name, &url);
    // The object URL is no longer needed once the click has started the download.
    let _ = Url::revoke_object_url(&url);
    result
}
