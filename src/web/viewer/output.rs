//! What a viewer gives besides the screen: pictures of the shell (a gallery card, the file
//! offered) and the files written where its copy of the shell is.

use super::Viewer;
use crate::web::canvases::{object_url, png};
use crate::web::clock::now;
use crate::work::file_writer::{FileStage, Needs};
use crate::work::screen::Screen;
use crate::work::viewer_driver::NO_DRAWING;
use crate::work::viewer_driver::PoolWorkers;
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
        let screen = self.driver.screen_mut();
        if screen.size() != (pixels, pixels) {
            screen.resize((pixels, pixels));
        }
        if let Some(d) = &mut screen.drawing {
            d.renderer.multisample(multisampled);
        }
        self.picture()
    }

    /// Draws now and reads the canvas back: the promise of a PNG `Blob` (asked for before the
    /// browser clears the drawing).
    pub fn picture(&mut self) -> Result<js_sys::Promise, String> {
        let (state, screen) = self.driver.parts();
        let d = screen.drawing.as_mut().ok_or(NO_DRAWING)?;
        if let Some(loss) = d.renderer.lost() {
            return Err(format!("the graphics device was lost ({})", loss.reason));
        }
        let Some(g) = state.shell() else {
            return Err("nothing is drawn yet".into());
        };
        d.draw(g, state.layout())?;
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
        let source = self.driver.state().shell().map(Growing::source);
        match self.writer.start(what, size, source) {
            Needs::Nothing => {}
            Needs::Finish => {
                let mut workers = self.workers.borrow_mut();
                self.driver.finish(workers.pool());
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
            .work(self.driver.state().shell().map(Growing::source), &now)
    }
}
