//! The page's main viewer: the core's [`ViewerDriver`] on one canvas (a canvas element of the
//! page, or an `OffscreenCanvas` one handed its drawing to) and its renderer (`screen.rs`),
//! with its pool of workers and the files it writes. It touches nothing of the page, so that it
//! runs in the worker that draws the main view (`drawing_worker.rs`) as well as on the page's
//! thread (`viewer_handle.rs`). The driver decides what the viewer grows and draws, how it
//! keeps its graphics device when the browser takes it away (the screen opens another, and the
//! driver uploads the shell grown so far to it: growth goes on from where it was), and says
//! when the GPU stops finishing its frames, for the page to move the view where it can draw.
//! Where the browser draws no 3D, a viewer without a renderer grows the shell all the same,
//! for its pattern and its files.

mod output;
mod screen;

use super::activity;
use super::clock::now;
use super::debug::Loss;
use super::webcodecs::VideoFrame;
use super::workers::Workers;
use crate::generator::GROWTH_BUDGET_MS;
use crate::render::{Canvas, Renderer};
use crate::work::file_writer::FileWriter;
use crate::work::message::{Reply, Request};
use crate::work::screen::Screen;
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_driver::{PoolWorkers, Tick, ViewerDriver};
use crate::work::viewer_inbox::ViewFrame;
use crate::work::viewer_status::Device;
pub use screen::WebScreen;
use std::cell::RefCell;
use std::rc::Rc;

pub struct Viewer {
    /// Its core state applied to its canvas (none where the browser draws no 3D: the shell
    /// still grows, its pattern is shown and its files written).
    driver: ViewerDriver<WebScreen>,
    /// Where the shells grow.
    workers: Rc<RefCell<Workers>>,
    /// The picture asked for as a file, once the browser has read it from the canvas.
    picture_read: Rc<RefCell<Option<Result<String, String>>>>,
    /// A file of the shell being written.
    writer: FileWriter,
}

impl Viewer {
    pub async fn new(
        canvas: Canvas,
        planar: bool,
        background: [u8; 3],
        follows: bool,
        workers: Rc<RefCell<Workers>>,
    ) -> Result<Self, String> {
        let renderer = Renderer::new(&canvas).await?;
        Ok(Self::with(
            WebScreen::new(Some((renderer, canvas)), background),
            planar,
            follows,
            workers,
        ))
    }

    /// A viewer that draws nothing, where the browser cannot draw in 3D: the shell grows, its
    /// pattern shows in the planar view and its files are written all the same.
    pub fn without_drawing(
        planar: bool,
        background: [u8; 3],
        workers: Rc<RefCell<Workers>>,
    ) -> Self {
        Self::with(WebScreen::new(None, background), planar, true, workers)
    }

    fn with(screen: WebScreen, planar: bool, follows: bool, workers: Rc<RefCell<Workers>>) -> Self {
        Self {
            driver: ViewerDriver::new(screen, planar, follows, now()),
            workers,
            picture_read: Rc::default(),
            writer: FileWriter::default(),
        }
    }

    /// Loads the page asked for ([`crate::work::viewer_status::FrameReport::loads`]).
    pub fn loads(&self) -> u32 {
        self.driver.state().loads()
    }

    /// "WebGPU" or "WebGL2", or `None` where it draws nothing.
    pub fn backend(&self) -> Option<&'static str> {
        self.driver.screen().backend()
    }

    /// Does what the page asks (see [`ViewCommand`]): the core decides, and this viewer
    /// writes the files asked for.
    pub fn command(&mut self, command: ViewCommand) {
        if let ViewCommand::Load { shell, .. } = &command {
            activity::set(format!("loading {}", shell.preset.id));
        }
        let left = {
            let mut workers = self.workers.borrow_mut();
            self.driver.command(command, workers.pool())
        };
        if let Some(ViewCommand::WriteFile { what, size }) = left {
            self.write_file(what, size);
        }
    }

    /// Takes in what the pool's workers sent back and resumes the shell of a worker replaced
    /// ([`ViewerDriver::take_all`]). Fails with the words to show when the shell cannot be
    /// built or grown (it is dropped).
    pub fn take_all(
        &mut self,
        replies: Vec<(Request, Reply)>,
        sessions_lost: Option<Vec<Request>>,
    ) -> Result<(), String> {
        let mut workers = self.workers.borrow_mut();
        self.driver.take_all(replies, sessions_lost, workers.pool())
    }

    /// Keeps a graphics device ([`ViewerDriver::survive`]). Called once a frame before
    /// anything is drawn.
    pub fn survive(&mut self) -> Device {
        self.driver.survive(now())
    }

    /// The fresh canvas the viewer asked for ([`Device::NeedsCanvas`]), to open a renderer
    /// on.
    pub fn give_canvas(&mut self, canvas: Canvas) {
        self.driver.give_canvas(canvas);
    }

    /// Test-only (see `debug.rs`): takes the graphics device away ([`WebScreen::take_device`]).
    pub fn take_device(&self, loss: Loss) -> Result<(), String> {
        self.driver.screen().take_device(loss)
    }

    /// One animation frame, once the device is ready ([`Self::survive`]) and the shell's
    /// replies are taken in ([`Self::take_all`]): works on a file asked for, grows and draws
    /// ([`ViewerDriver::run_frame`]), and says what the page is to show. Fails with the words
    /// to show when the renderer failed.
    pub fn run_frame(&mut self) -> Result<ViewFrame<VideoFrame>, String> {
        let mut frame = {
            let mut workers = self.workers.borrow_mut();
            let floor = workers.min_growth_ms();
            (self.driver).run_frame(now(), GROWTH_BUDGET_MS, floor, workers.pool())?
        };
        frame.report.file = self.work_file();
        Ok(frame)
    }

    /// A whole frame of the drawing worker ([`ViewerDriver::tick`]), with its own pool; works
    /// on a file asked for when the frame ran.
    pub fn tick(&mut self) -> Tick<VideoFrame> {
        let mut tick = {
            let mut workers = self.workers.borrow_mut();
            self.driver.tick(now(), GROWTH_BUDGET_MS, &mut *workers)
        };
        if let Some(Ok(frame)) = &mut tick.frame {
            frame.report.file = self.work_file();
        }
        tick
    }
}
