//! The download menu on the page: the core's [`DownloadMenu`] decides (one file at a time,
//! its progress, its size, what cannot be exported and why); this applies what it returns and
//! offers each file written as a download.

use super::clock::now;
use super::page::{self, element_as, set_text, show_message, signal};
use crate::export::Download;
use crate::export::print_size::PrintSize;
use crate::work::download_menu::{DownloadMenu, MenuShown, Message};
use crate::work::file_writer::{Body, FileStage};
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_status::ShellStatus;
use wasm_bindgen::JsCast;
use web_sys::{
    Blob, BlobPropertyBag, HtmlAnchorElement, HtmlButtonElement, HtmlInputElement,
    HtmlProgressElement, Url,
};

/// The download menu.
#[derive(Default)]
pub struct Downloads(DownloadMenu);

impl Downloads {
    /// What to ask the viewer for the file `what` of the shell it shows, at the size the
    /// field asks for; a message says why when it cannot be made.
    pub fn start(&mut self, what: Download) -> Option<ViewCommand> {
        let size_mm = element_as::<HtmlInputElement>("download-size")
            .map_or(PrintSize::DEFAULT_MM, |i| i.value_as_number());
        let (command, shown) = self.0.start(what, size_mm);
        apply(shown);
        command
    }

    /// Shows where the file asked for stands (`None`: none is asked for), and offers it once it
    /// is written.
    pub fn show(&mut self, stage: Option<FileStage>) {
        let Some(stage) = stage else { return };
        let mut shown = self.0.stage(stage);
        let file = shown.offer.take();
        apply(shown);
        if let Some(file) = file {
            let offered = match file.body {
                Body::Bytes(bytes) => offer(&file.name, file.what.mime(), &bytes),
                Body::Url(url) => {
                    let offered = offer_url(&file.name, &url);
                    // The picture's object URL is no longer needed once the click has started
                    // the download.
                    let _ = Url::revoke_object_url(&url);
                    offered
                }
            };
            apply(self.0.offered(offered));
        }
    }

    /// The viewer that was writing a file is gone (it moved to another thread): the file is
    /// refused with `why`, and may be asked again.
    pub fn abandon(&mut self, why: &str) {
        apply(self.0.abandon(why));
    }

    /// Shows each file's size for the shell `shell`, when it has changed.
    pub fn show_sizes(&mut self, shell: &ShellStatus) {
        show_sizes(&self.0.sizes(shell, now()));
    }
}

fn show_sizes(sizes: &[(Download, String)]) {
    for (what, text) in sizes {
        set_text(&format!("size-{}", what.name()), text);
    }
}

/// Shows what the menu decided.
fn apply(shown: MenuShown) {
    if let Some(value) = shown.signal {
        signal("download", value);
    }
    match shown.message {
        Some(Message::Show(words)) => show_message(&words),
        Some(Message::Hide) => page::hide_message(),
        None => {}
    }
    show_sizes(&shown.sizes);
    if let Some(progress) = shown.progress {
        let bar = element_as::<HtmlProgressElement>("download-progress");
        if let Some(bar) = bar {
            bar.set_value(progress.as_ref().map_or(0.0, |p| p.0));
            bar.set_hidden(progress.is_none());
        }
        set_text("download-status", progress.as_ref().map_or("", |p| &p.1));
    }
    if let Some(enabled) = shown.buttons {
        for what in Download::ALL {
            if let Some(b) = element_as::<HtmlButtonElement>(&format!("download-{}", what.name())) {
                b.set_disabled(!enabled);
            }
        }
    }
}

/// Starts the download of the resource at `url` (an object or data URL) as `name`.
fn offer_url(name: &str, url: &str) -> Result<(), String> {
    let anchor: HtmlAnchorElement = page::document()
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
    offer_blob(name, &blob)
}

/// Starts the download of `blob` as `name`.
pub fn offer_blob(name: &str, blob: &Blob) -> Result<(), String> {
    let url = Url::create_object_url_with_blob(blob)
        .map_err(|_| "the browser refused the file's address".to_string())?;
    let result = offer_url(name, &url);
    // The object URL is no longer needed once the click has started the download.
    let _ = Url::revoke_object_url(&url);
    result
}
