//! The download menu: every file the page offers for the shell shown (GLB first, then PLY,
//! 3MF, OBJ, STL, the picture and the pattern), each with its size, and the height that GLB
//! and 3MF files are made at. A file is written by the core in steps ([`Export`]), a frame's
//! budget at a time, so that the page never freezes, with a progress bar while it takes
//! longer than a frame; then it is offered as a download. What cannot be exported (nothing
//! grown yet, a shell that stopped, an open surface as 3MF, a height out of bounds) is said
//! in words. A mesh of an implicit shell still growing is of the whole shell: the page first
//! finishes it, its chunks shared by the pool of workers as the Finish control shares them,
//! then writes it (`finishing` until then). `<body data-download>`: finishing, writing,
//! offered, refused (empty before any).

use super::clock::now;
use super::page::{self, element, set_text, show_message, signal};
use super::viewer::Viewer;
use crate::export::Download;
use crate::export::estimate::{Counts, Size};
use crate::export::job::Export;
use crate::export::print_size::PrintSize;
use crate::export::shell::Shell;
use crate::generator::within;
use crate::presets::Preset;
use crate::spec::ShellSpec;
use crate::spec::form::Form;
use wasm_bindgen::JsCast;
use web_sys::{
    Blob, BlobPropertyBag, HtmlAnchorElement, HtmlButtonElement, HtmlInputElement,
    HtmlProgressElement, Url,
};

/// Milliseconds of a frame an export may take.
const EXPORT_BUDGET_MS: f64 = 8.0;
/// Least time between two updates of the sizes shown while the shell grows.
const SIZES_EVERY_MS: f64 = 500.0;
/// What the height field is called in messages.
const HEIGHT: &str = "Height";

/// A file being written.
struct Job {
    export: Export,
    name: String,
    mime: &'static str,
    what: Download,
    /// The longest step lately (see [`within`]).
    longest: f64,
}

/// A download waiting for the shell of session `session` to be finished.
struct AfterFinish {
    what: Download,
    session: u32,
}

/// The download menu and the file under way.
#[derive(Default)]
pub struct Downloads {
    job: Option<Job>,
    after_finish: Option<AfterFinish>,
    /// The counts the sizes shown were estimated from, and when.
    shown: Option<(Counts, f64)>,
}

impl Downloads {
    /// Starts the download `what` of the shell `viewer` shows (`current`: its preset and
    /// spec); a message says why when it cannot be made.
    pub fn start(
        &mut self,
        what: Download,
        viewer: &mut Viewer,
        current: Option<&(&'static Preset, ShellSpec)>,
    ) {
        if self.job.is_some() || self.after_finish.is_some() {
            return;
        }
        let implicit = current.is_some_and(|(_, spec)| matches!(spec.form, Form::Implicit(_)));
        let growing_implicit = viewer
            .growing()
            .filter(|g| implicit && g.replica.shell().is_some() && !g.replica.is_done());
        if let (Download::Mesh(_), Some(g)) = (what, growing_implicit) {
            let session = g.replica.session();
            viewer.finish();
            self.after_finish = Some(AfterFinish { what, session });
            signal("download", "finishing");
            set_buttons_enabled(false);
            page::hide_message();
            return;
        }
        if let Err(e) = self.begin(what, viewer, current) {
            signal("download", "refused");
            show_message(&format!("The download could not be made: {e}."));
        }
    }

    fn begin(
        &mut self,
        what: Download,
        viewer: &mut Viewer,
        current: Option<&(&'static Preset, ShellSpec)>,
    ) -> Result<(), String> {
        let (Some(g), Some((preset, spec))) = (viewer.growing(), current) else {
            return Err("no shell is shown".into());
        };
        let name = what.file_name(g.preset.id);
        let (export, mime) = match what {
            Download::Picture => {
                let url = viewer.picture()?;
                signal("download", "offered");
                return offer_url(&name, &url);
            }
            Download::Pattern => {
                let r = &g.replica;
                if r.cells() == 0 {
                    return Err("this shell has no pattern".into());
                }
                let rows = r.rgba().len() / (r.cells() * 4);
                let export = Export::pattern(r.cells(), rows, r.rgba().to_vec());
                (export, "image/png")
            }
            Download::Mesh(format) => {
                let size = if format.sized() {
                    height()?
                } else {
                    PrintSize::default()
                };
                let grown = g.replica.for_export().ok_or("the shell is not built yet")?;
                let shell = Shell::of(grown, spec, preset, size).map_err(|e| e.to_string())?;
                let export = Export::new(format, shell).map_err(|e| e.to_string())?;
                (export, format.mime())
            }
        };
        page::hide_message();
        signal("download", "writing");
        set_buttons_enabled(false);
        self.job = Some(Job {
            export,
            name,
            mime,
            what,
            longest: 0.0,
        });
        Ok(())
    }

    /// Writes the file under way for this frame's budget; offers it once it is whole. A
    /// download waiting for its shell to be finished starts once it is (and is dropped, with
    /// a message, when another shell took its place).
    pub fn work(&mut self, viewer: &mut Viewer, current: Option<&(&'static Preset, ShellSpec)>) {
        if let Some(waiting) = &self.after_finish {
            let replica = viewer.growing().map(|g| &g.replica);
            match replica {
                Some(r) if r.session() == waiting.session && !r.is_done() => return,
                Some(r) if r.session() == waiting.session => {
                    let what = waiting.what;
                    self.after_finish = None;
                    set_buttons_enabled(true);
                    self.start(what, viewer, current);
                }
                _ => {
                    self.after_finish = None;
                    set_buttons_enabled(true);
                    signal("download", "refused");
                    show_message(
                        "The download could not be made: the shell was changed before it was \
                         grown whole.",
                    );
                }
            }
        }
        let Some(job) = &mut self.job else {
            return;
        };
        let result = job
            .export
            .work(within(now, EXPORT_BUDGET_MS, &mut job.longest));
        let offered = match result {
            Ok(None) => {
                show_progress(Some((&job.name, job.export.progress())));
                return;
            }
            Ok(Some(bytes)) => {
                let (what, text) = (job.what, format!("{} MB", megabytes(bytes.len() as f64)));
                show_size(what, &text);
                offer(&job.name, job.mime, &bytes)
            }
            Err(e) => Err(e.to_string()),
        };
        show_progress(None);
        set_buttons_enabled(true);
        match offered {
            Ok(()) => signal("download", "offered"),
            Err(e) => {
                signal("download", "refused");
                show_message(&format!("The download could not be made: {e}."));
            }
        }
        self.job = None;
    }

    /// Shows each file's size for the shell `viewer` shows, when it has changed (at most every
    /// half second while the shell grows).
    pub fn show_sizes(&mut self, viewer: &Viewer) {
        let Some(g) = viewer.growing() else {
            return;
        };
        let (mesh, edge) = (g.replica.mesh(), g.replica.edge());
        let canvas = viewer.canvas();
        let counts = Counts {
            vertices: mesh.vertices.len() + edge.vertex_count(),
            triangles: mesh.triangle_count() + edge.triangle_count(),
            pattern: (g.replica.cells() > 0).then(|| {
                (
                    g.replica.cells(),
                    g.replica.rgba().len() / (g.replica.cells() * 4),
                )
            }),
            picture: (canvas.width() as usize, canvas.height() as usize),
        };
        let t = now();
        if self
            .shown
            .is_some_and(|(c, at)| c == counts || (!g.replica.is_done() && t - at < SIZES_EVERY_MS))
            || self.job.is_some()
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

/// The height the field asks for, refused out of bounds by name.
fn height() -> Result<PrintSize, String> {
    let input = element("download-height").and_then(|e| e.dyn_into::<HtmlInputElement>().ok());
    let mm = input.map_or(PrintSize::DEFAULT_MM, |i| i.value_as_number());
    PrintSize::new(mm, HEIGHT).map_err(|e| e.to_string())
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
