//! What a viewer gives besides the screen: pictures of the shell (a gallery card, the file
//! offered) and the files written where its copy of the shell is.

use super::Viewer;
use crate::web::canvases::object_url;
use crate::web::clock::now;
use crate::work::file_writer::{FileStage, Needs};
use crate::work::viewer_driver::PoolWorkers;
use crate::work::viewer_state::Growing;
use std::rc::Rc;

impl Viewer {
    /// Draws now and reads the canvas back: the promise of a PNG `Blob`
    /// ([`crate::work::viewer_driver::ViewerDriver::picture`]).
    pub fn picture(&mut self) -> Result<js_sys::Promise, String> {
        self.driver.picture()
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
