//! What a viewer gives besides the screen: pictures of the shell (a gallery card, the file
//! offered), the files written where its copy of the shell is, and a recording's frames.

use super::{NO_DRAWING, Viewer};
use crate::view::recording::FrameAsk;
use crate::web::canvases::{object_url, png};
use crate::web::clock::now;
use crate::web::webcodecs::{self, VideoFrame};
use crate::work::file_writer::{FileStage, Needs};
use crate::work::viewer_state::Growing;
use std::rc::Rc;

impl Viewer {
    /// [`Self::picture`], drawn on a canvas of `pixels` × `pixels`, `multisampled` or with one
    /// sample a pixel (a viewer of pictures only, whose canvas is not laid out on the page).
    pub fn picture_at(
        &mut self,
        pixels: u32,
        multisampled: bool,
    ) -> Result<js_sys::Promise, String> {
        if let Some(d) = &mut self.drawing {
            if d.canvas.size() != (pixels, pixels) {
                d.canvas.set_size((pixels, pixels));
                d.renderer.resize(pixels, pixels);
            }
            d.renderer.multisample(multisampled);
        }
        self.picture()
    }

    /// Draws now and reads the canvas back: the promise of a PNG `Blob` (asked for before the
    /// browser clears the drawing).
    pub fn picture(&mut self) -> Result<js_sys::Promise, String> {
        let d = self.drawing.as_mut().ok_or(NO_DRAWING)?;
        if let Some(loss) = d.renderer.lost() {
            return Err(format!("the graphics device was lost ({})", loss.reason));
        }
        let Some(g) = self.state.shell() else {
            return Err("nothing is drawn yet".into());
        };
        d.draw(g, self.state.layout())?;
        png(&d.canvas)
    }

    /// Starts writing the file `what` of the shell shown (GLB and 3MF at `size`), over the
    /// next frames ([`Self::work_file`]); an implicit shell still growing is finished first.
    pub(super) fn write_file(
        &mut self,
        what: crate::export::Download,
        size: crate::export::print_size::PrintSize,
    ) {
        if self.writer.busy() {
            return;
        }
        let source = self.state.shell().map(Growing::source);
        match self.writer.start(what, size, source) {
            Needs::Nothing => {}
            Needs::Finish => {
                {
                    let mut workers = self.workers.borrow_mut();
                    self.state.finish(workers.pool());
                }
                self.apply_screen();
            }
            Needs::Picture => {
                let slot = Rc::clone(&self.picture_read);
                let read = self.picture();
                wasm_bindgen_futures::spawn_local(async move {
                    let url = match read {
                        Ok(blob) => object_url(blob).await,
                        Err(e) => Err(e),
                    };
                    *slot.borrow_mut() = Some(url);
                });
            }
        }
    }

    /// Works on the file asked for by [`Self::write_file`] for a frame's budget: where it
    /// stands, or `None` when none is asked for.
    pub(super) fn work_file(&mut self) -> Option<FileStage> {
        if let Some(read) = self.picture_read.borrow_mut().take() {
            self.writer.picture_taken(read);
        }
        self.writer
            .work(self.state.shell().map(Growing::source), &now)
    }

    /// Draws the frame `ask` asks for (the core state posed the camera for it) and reads it
    /// as a video frame.
    pub(super) fn draw_recorded(&mut self, ask: &FrameAsk) -> Result<VideoFrame, String> {
        self.fit_canvas();
        let g = self.state.shell().ok_or("no shell is loaded")?;
        let d = self.drawing.as_mut().ok_or(NO_DRAWING)?;
        d.draw(g, self.state.layout())?;
        self.state.recorded(now());
        let init = webcodecs::object(&[
            ("timestamp", (ask.timestamp_us as f64).into()),
            ("duration", (ask.duration_us as f64).into()),
        ]);
        VideoFrame::new(d.canvas.as_js(), &init)
            .map_err(|e| format!("the canvas could not be read ({})", webcodecs::describe(&e)))
    }
}
