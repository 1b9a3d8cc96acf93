//! The download menu: every file the page offers for the shell shown (GLB first, then PLY,
//! 3MF, OBJ, STL, the picture and the pattern), each with its size, and the size that GLB
//! and 3MF files are made at. The viewer writes a file where its copy of the shell is
//! (`work/file_writer.rs`), a frame's budget at a time; the page shows where it stands, with a
//! progress bar while it takes longer than a frame, then offers it as a download. What cannot
//! be exported (nothing grown yet, a shell that stopped, an open surface as 3MF, a size out
//! of bounds) is said in words. `<body data-download>`: finishing (an implicit shell still
//! growing is grown whole first), writing, offered, refused (empty before any).

use super::clock::now;
use super::page::{self, element, set_text, show_message, signal};
use crate::export::Download;
use crate::export::estimate::{Counts, Size};
use crate::export::print_size::PrintSize;
use crate::work::file_writer::{Body, FileStage};
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_status::ShellStatus;
use wasm_bindgen::JsCast;
use web_sys::{
    Blob, BlobPropertyBag, HtmlAnchorElement, HtmlButtonElement, HtmlInputElement,
    HtmlProgressElement, Url,
};

/// Least time between two updates of the sizes shown while the shell grows.
const SIZES_EVERY_MS: f64 = 500.0;
/// What the size field is called in messages.
const SIZE: &str = "Size";

/// The download menu, and whether a file is under way.
#[derive(Default)]
pub struct Downloads {
    busy: bool,
    /// The counts the sizes shown were estimated from, and when.
    shown: Option<(Counts, f64)>,
}

impl Downloads {
    /// What to ask the viewer for the file `what` of the shell it shows, at the size the
    /// field asks for; a message says why when it cannot be made.
    pub fn start(&mut self, what: Download) -> Option<ViewCommand> {
        if self.busy {
            return None;
        }
        let size = match what {
            Download::Mesh(format) if format.sized() => size(),
            _ => Ok(PrintSize::default()),
        };
        match size {
            Ok(size) => {
                self.busy = true;
                set_buttons_enabled(false);
                Some(ViewCommand::WriteFile { what, size })
            }
            Err(e) => {
                refuse(&e);
                None
            }
        }
    }

    /// Shows where the file asked for stands (`None`: none is asked for), and offers it once it
    /// is written.
    pub fn show(&mut self, writing: Option<FileStage>) {
        let Some(writing) = writing else {
            return;
        };
        let offered = match writing {
            FileStage::Finishing => {
                signal("download", "finishing");
                page::hide_message();
                return;
            }
            FileStage::Writing { name, done } => {
                signal("download", "writing");
                page::hide_message();
                show_progress(Some((&name, done)));
                return;
            }
            FileStage::Written(file) => match file.body {
                Body::Bytes(bytes) => {
                    show_size(file.what, &format!("{} MB", megabytes(bytes.len() as f64)));
                    offer(&file.name, file.what.mime(), &bytes)
                }
                Body::Url(url) => {
                    let offered = offer_url(&file.name, &url);
                    // The picture's object URL is no longer needed once the click has started
                    // the download.
                    let _ = Url::revoke_object_url(&url);
                    offered
                }
            },
            FileStage::Refused(e) => Err(e),
        };
        self.busy = false;
        show_progress(None);
        set_buttons_enabled(true);
        match offered {
            Ok(()) => {
                page::hide_message();
                signal("download", "offered");
            }
            Err(e) => refuse(&e),
        }
    }

    /// The viewer that was writing a file is gone (it moved to another thread): the file is
    /// refused with `why`, and may be asked again.
    pub fn abandon(&mut self, why: &str) {
        if self.busy {
            self.show(Some(FileStage::Refused(why.to_string())));
        }
    }

    /// Shows each file's size for the shell `shell`, when it has changed (at most every half
    /// second while the shell grows).
    pub fn show_sizes(&mut self, shell: &ShellStatus) {
        let counts = shell.counts;
        let t = now();
        if self
            .shown
            .is_some_and(|(c, at)| c == counts || (!shell.done && t - at < SIZES_EVERY_MS))
            || self.busy
        {
            return;
        }
        self.shown = Some((counts, t));
        for what in Download::ALL {
            let text = match what.estimate(&counts) {
                Some(Size::Bytes(bytes)) => format!("≈ {} MB", megabytes(bytes as f64)),
                Some(Size::Pixels(w, h)) => format!("{w} × {h}"),
                None => "none".to_string(),
            };
            show_size(what, &text);
        }
    }
}

/// Says why the download could not be made.
fn refuse(why: &str) {
    signal("download", "refused");
    show_message(&format!("The download could not be made: {why}."));
}

/// Shows `text` as the size of the file `what`.
fn show_size(what: Download, text: &str) {
    set_text(&format!("size-{}", what.name()), text);
}

/// Bytes in megabytes, to two significant figures (three from 10 MB).
fn megabytes(bytes: f64) -> String {
    let mb = bytes / 1e6;
    if mb >= 10.0 {
        format!("{mb:.0}")
    } else if mb >= 0.1 {
        format!("{mb:.1}")
    } else {
        format!("{mb:.2}")
    }
}

/// The size (largest side) the field asks for, refused out of bounds by name.
fn size() -> Result<PrintSize, String> {
    let input = element("download-size").and_then(|e| e.dyn_into::<HtmlInputElement>().ok());
    let mm = input.map_or(PrintSize::DEFAULT_MM, |i| i.value_as_number());
    PrintSize::new(mm, SIZE).map_err(|e| e.to_string())
}

fn set_buttons_enabled(enabled: bool) {
    for what in Download::ALL {
        if let Some(b) = element(&format!("download-{}", what.name()))
            .and_then(|e| e.dyn_into::<HtmlButtonElement>().ok())
        {
            b.set_disabled(!enabled);
        }
    }
}

/// Shows the progress of the file `name` (from 0 to 1), or hides it.
fn show_progress(progress: Option<(&str, f64)>) {
    let bar = element("download-progress").and_then(|e| e.dyn_into::<HtmlProgressElement>().ok());
    match progress {
        Some((name, done)) => {
            if let Some(bar) = bar {
                bar.set_value(done);
                bar.set_hidden(false);
            }
            set_text(
                "download-status",
                &format!("Writing {name}… {:.0} %", done * 100.0),
            );
        }
        None => {
            if let Some(bar) = bar {
                bar.set_hidden(true);
            }
            set_text("download-status", "");
        }
    }
}

/// Starts the download of the resource at `url` (an object or data URL) as `name`.
pub fn offer_url(name: &str, url: &str) -> Result<(), String> {
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
    let url = Url::create_object_url_with_blob(&blob)
        .map_err(|_| "the browser refused the file's address".to_string())?;
    let result = offer_url(name, &url);
    // The object URL is no longer needed once the click has started the download.
    let _ = Url::revoke_object_url(&url);
    result
}
