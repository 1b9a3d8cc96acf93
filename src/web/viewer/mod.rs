//! A viewer: one canvas (a canvas element of the page, or an `OffscreenCanvas` one handed its
//! drawing to) and its renderer, a shell growing on it, what its planar pattern shows, and the
//! camera the pointer turns. It touches nothing of the page, so that it runs in the worker that
//! draws the main view (`drawing_worker.rs`) as well as on the page's thread (`viewer_handle.rs`).
//! Loading another spec restarts growth without reloading the page. The page's main view is one
//! viewer, whose camera follows the growing shell; the gallery's pictures are drawn by another,
//! framed on the whole shell. While a pattern slider is dragged, the planar view previews the
//! whole pattern of its values instead. When the browser takes the graphics device away, the
//! viewer opens another (`recovery.rs`) and uploads the shell grown so far to it: growth goes
//! on from where it was. Where the browser draws no 3D, a viewer without a renderer grows the
//! shell all the same, for its pattern and its files; and one whose frames the GPU stops
//! finishing says so, for the page to move it where it can draw.

mod drawing;
mod output;

use drawing::{Drawing, load_into, look, upload};

use super::activity;
use super::canvases::lose_context;
use super::clock::now;
use super::debug::{self, Loss};
use super::recovery::{Attempt, Reopened, attempt};
use super::webcodecs::VideoFrame;
use super::workers::Workers;
use crate::generator::GROWTH_BUDGET_MS;
use crate::presets::Preset;
use crate::render::{Canvas, Renderer};
use crate::spec::ShellSpec;
use crate::view::draw_pacing::{DrawPacing, FrameDraw};
use crate::work::device_survival::{Loss as DeviceLoss, Open, Survival};
use crate::work::file_writer::FileWriter;
use crate::work::message::{Reply, Request, WholeShell};
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_inbox::ViewFrame;
use crate::work::viewer_state::{ScreenChange, ViewerState};
use crate::work::viewer_status::{Device, FrameReport};
use std::cell::RefCell;
use std::rc::Rc;

/// Why a viewer that draws nothing gives no picture.
const NO_DRAWING: &str = "this browser draws no 3D here";

pub struct Viewer {
    /// What it draws with; none where the browser draws no 3D: the shell still grows, its
    /// pattern is shown and its files written.
    drawing: Option<Drawing>,
    /// What it decides without its canvas: the shell, the playback, the preview, the camera.
    state: ViewerState,
    /// Whether this frame draws or leaves it to the next (after megabytes of uploads).
    pacing: DrawPacing,
    /// A recording's video frame drawn and not yet taken.
    recorded: Option<Result<VideoFrame, String>>,
    /// Where the shells grow.
    workers: Rc<RefCell<Workers>>,
    /// The clear colour, as sRGB bytes (for a renderer opened again).
    background: [u8; 3],
    /// How its graphics device is kept (the core decides), and a renderer being opened again.
    survival: Survival,
    reopening: Option<Attempt>,
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
            Some(Drawing::new(renderer, canvas)),
            planar,
            background,
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
        Self::with(None, planar, background, true, workers)
    }

    fn with(
        mut drawing: Option<Drawing>,
        planar: bool,
        background: [u8; 3],
        follows: bool,
        workers: Rc<RefCell<Workers>>,
    ) -> Self {
        if let Some(d) = &mut drawing {
            d.renderer.set_background(background);
        }
        Self {
            drawing,
            state: ViewerState::new(planar, follows, now()),
            pacing: DrawPacing::default(),
            recorded: None,
            workers,
            background,
            survival: Survival::default(),
            reopening: None,
            picture_read: Rc::default(),
            writer: FileWriter::default(),
        }
    }

    /// Loads the page asked for ([`FrameReport::loads`]).
    pub fn loads(&self) -> u32 {
        self.state.loads()
    }

    /// "WebGPU" or "WebGL2", or `None` where it draws nothing.
    pub fn backend(&self) -> Option<&'static str> {
        self.drawing.as_ref().map(|d| d.renderer.backend())
    }

    /// Does what the page asks (see [`ViewCommand`]): the core state decides, and this viewer
    /// does the part that needs its canvas.
    pub fn command(&mut self, command: ViewCommand) {
        if let ViewCommand::Load { shell, .. } = &command {
            activity::set(format!("loading {}", shell.preset.id));
        }
        let left = {
            let mut workers = self.workers.borrow_mut();
            self.state.command(command, workers.pool())
        };
        self.apply_screen();
        match left {
            Some(ViewCommand::Background(srgb)) => {
                self.background = srgb;
                if let Some(d) = &mut self.drawing {
                    d.renderer.set_background(srgb);
                }
            }
            Some(ViewCommand::RecordAt(None)) => {
                if let Some(Ok(frame)) = self.recorded.take() {
                    frame.close();
                }
            }
            Some(ViewCommand::WriteFile { what, size }) => self.write_file(what, size),
            _ => {}
        }
    }

    /// Hands the renderer what the core state changed (see [`ScreenChange`]), and notes what is
    /// being grown when growth was asked for (for a crash's message; a test may ask for a
    /// panic here).
    fn apply_screen(&mut self) {
        let changes = self.state.take_screen();
        if self.state.take_grew()
            && let Some(g) = self.state.shell()
        {
            activity::set(format!(
                "growing {}, row {}",
                g.preset().id,
                g.replica().rows_done() + 1
            ));
            debug::panic_if_asked();
        }
        let (Some(d), Some(g)) = (&mut self.drawing, self.state.shell()) else {
            return;
        };
        for change in changes {
            match change {
                ScreenChange::Shell => load_into(&mut d.renderer, g),
                ScreenChange::Look => {
                    if let Some(look) = look(g) {
                        d.renderer.set_look(look);
                    }
                }
                ScreenChange::Rows(advance) => {
                    self.pacing.uploaded(upload(&mut d.renderer, g, &advance));
                }
            }
        }
    }

    /// Shows a shell grown whole on a worker (a gallery picture), at rest.
    pub fn show_whole(&mut self, preset: &'static Preset, spec: &ShellSpec, whole: WholeShell) {
        self.state.show_whole(preset, spec, whole);
        self.apply_screen();
    }

    /// Takes in what the pool's workers sent back and resumes the shell of a worker replaced,
    /// in the core state's order ([`ViewerState::take_all`]). Fails with the words to show
    /// when the shell cannot be built or grown (it is dropped).
    pub fn take_all(
        &mut self,
        replies: Vec<(Request, Reply)>,
        sessions_lost: Option<Vec<Request>>,
    ) -> Result<(), String> {
        let taken = {
            let mut workers = self.workers.borrow_mut();
            self.state.take_all(replies, sessions_lost, workers.pool())
        };
        self.apply_screen();
        taken
    }

    /// Keeps a graphics device as the core's [`Survival`] decides: when the browser took the
    /// renderer's away, opens another in the background (on the same canvas, or a fresh one the
    /// page gives) and, once it is open, uploads the shell grown so far to it. Called once a
    /// frame before anything is drawn.
    pub fn survive(&mut self) -> Device {
        let loss = self.drawing.as_ref().and_then(|d| {
            d.renderer.lost().map(|lost| DeviceLoss {
                reason: lost.reason,
                restored: lost.restored,
                webgl: d.renderer.backend() == "WebGL2",
            })
        });
        let answer = self.reopening.as_ref().and_then(|a| a.borrow_mut().take());
        if answer.is_some() {
            self.reopening = None;
        }
        let (said, reopened) = match answer {
            Some(Ok(reopened)) => (Some(Ok(())), Some(reopened)),
            Some(Err(e)) => (Some(Err(e)), None),
            None => (None, None),
        };
        let (device, open) = self.survival.frame(now(), loss.as_ref(), said);
        if let (Some(Open::Same), Some(d)) = (open, &self.drawing) {
            self.reopening = Some(attempt(d.canvas.clone()));
        }
        match (device, reopened) {
            (Device::Reopened(_), Some(reopened)) => {
                let backend = reopened.renderer.backend().to_string();
                self.install(reopened);
                Device::Reopened(backend)
            }
            (device, _) => device,
        }
    }

    /// Draws with a renderer opened again: the shell's buffers and texture are made anew and
    /// take everything grown so far (mesh, edge and pattern rows), which the page's copy of the
    /// shell kept.
    fn install(&mut self, reopened: Reopened) {
        let Reopened {
            mut renderer,
            canvas,
        } = reopened;
        renderer.set_background(self.background);
        let drawing = self.drawing.insert(Drawing::new(renderer, canvas));
        if let Some(g) = self.state.shell()
            && g.replica().shell().is_some()
        {
            load_into(&mut drawing.renderer, g);
            self.pacing
                .uploaded(upload(&mut drawing.renderer, g, &g.replica().everything()));
        }
        self.state.touch();
    }

    /// The fresh canvas the viewer asked for ([`Device::NeedsCanvas`]), to open a renderer
    /// on.
    pub fn give_canvas(&mut self, canvas: Canvas) {
        if self.survival.canvas_given() == Some(Open::Fresh) {
            self.reopening = Some(attempt(canvas));
        }
    }

    /// Test-only (see `debug.rs`): takes the graphics device away as a driver reset (WebGPU) or
    /// the browser (WebGL2) would.
    pub fn take_device(&self, loss: Loss) -> Result<(), String> {
        let d = self.drawing.as_ref().ok_or("this viewer draws nothing")?;
        match loss {
            Loss::Destroy => {
                d.renderer.destroy_device();
                Ok(())
            }
            Loss::Context { restore_after_ms } => lose_context(&d.canvas, restore_after_ms),
        }
    }

    /// Keeps the drawing buffer at the size the core state asks for.
    fn fit_canvas(&mut self) {
        if let (Some(d), Some(size)) = (&mut self.drawing, self.state.drawing_size())
            && size != d.canvas.size()
        {
            d.canvas.set_size(size);
            d.renderer.resize(size.0, size.1);
            self.state.touch();
        }
    }

    /// One animation frame, once the device is ready ([`Self::survive`]) and the shell's
    /// replies are taken in ([`Self::take_all`]): works on a file asked for, grows and draws
    /// (unless held, [`ViewCommand::Hold`]: the page shows something else over the shell), and
    /// says what the page is to show. Fails with the words to show when the renderer failed.
    pub fn run_frame(&mut self) -> Result<ViewFrame<VideoFrame>, String> {
        let file = self.work_file();
        let drawn = !self.state.held() && self.frame(GROWTH_BUDGET_MS)?;
        let picture = self.drawing.as_ref().map_or((0, 0), |d| d.canvas.size());
        Ok(ViewFrame {
            report: FrameReport {
                loads: self.state.loads(),
                file,
                drawn,
                status: self.state.status(picture),
                notice: self.state.take_notice(),
                planar: self.state.take_planar(),
            },
            recorded: self.recorded.take(),
        })
    }

    /// Grows as the core state decides within `budget_ms`, or towards a recording's frame, and
    /// draws if anything changed. Returns whether a frame was drawn.
    fn frame(&mut self, budget_ms: f64) -> Result<bool, String> {
        if let Some(d) = &mut self.drawing {
            if let Some(failure) = d.renderer.failure() {
                return Err(failure);
            }
            if let Some(why) = d.unseen() {
                return Err(format!("Nothing drawn reaches the screen: {why}."));
            }
            if self.survival.reopening() || d.renderer.lost().is_some() {
                return Ok(false);
            }
        }
        if self.state.recording() {
            let asked = {
                let mut workers = self.workers.borrow_mut();
                self.state.recording_frame(budget_ms, workers.pool())
            };
            self.apply_screen();
            if let Some(ask) = asked {
                self.recorded = Some(ask.and_then(|ask| self.draw_recorded(&ask)));
            }
            return Ok(false);
        }
        self.fit_canvas();
        let due = {
            let mut workers = self.workers.borrow_mut();
            let floor = workers.min_growth_ms();
            self.state.frame(now(), budget_ms, floor, workers.pool())
        };
        self.apply_screen();
        let pacing = self.pacing.frame(self.state.dirty());
        if !due {
            return Ok(false);
        }
        let Some(d) = &mut self.drawing else {
            // Nothing to draw on: what changed is shown all the same (the planar view, the
            // status).
            self.state.drawn();
            return Ok(true);
        };
        // After megabytes of uploads, or while the GPU still works on earlier frames, the
        // drawing waits (the uploads go to the GPU meanwhile).
        if pacing == FrameDraw::Defer || !d.renderer.ready() {
            d.renderer.flush();
            return Ok(false);
        }
        if let Some(g) = self.state.shell() {
            d.draw(g, self.state.layout())?;
        }
        self.state.drawn();
        Ok(true)
    }
}
