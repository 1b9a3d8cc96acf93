//! A viewer's frames, driven: its core state ([`ViewerState`]) applied to a [`Screen`] each
//! animation frame, in the order the browser's viewer and the simulator's both run. The driver
//! hands the screen what changed of the shell, keeps its graphics device as [`Survival`]
//! decides (a renderer opened again takes everything grown so far), paces drawing after large
//! uploads ([`DrawPacing`]), fits the drawing buffer, draws when a picture is due and draws a
//! recording's frames. The web runner (`web/viewer/`) gives it the browser's renderer and
//! canvas; `tests/simulator.rs` a simulated one, so that the simulator runs this code and not
//! a copy of it.

use super::device_survival::{Open, Survival};
use super::message::{Reply, Request, WholeShell};
use super::pool::{Polled, Pool, Replaced};
use super::screen::Screen;
use super::viewer_command::ViewCommand;
use super::viewer_inbox::ViewFrame;
use super::viewer_state::{ScreenChange, ViewerState};
use super::viewer_status::{Device, FrameReport};
use crate::presets::Preset;
use crate::spec::ShellSpec;
use crate::view::draw_pacing::{DrawPacing, FrameDraw};
use crate::view::recording::FrameAsk;

/// Why a viewer that draws nothing gives no picture.
const NO_DRAWING: &str = "this browser draws no 3D here";

/// The workers a viewer's shells grow on, as its frame uses them: the web's pool of Web
/// Workers (`web/workers.rs`), or the simulator's.
pub trait PoolWorkers {
    /// Takes in what the workers sent back and what became of them.
    fn poll(&mut self) -> Polled;
    fn pool(&mut self) -> &mut Pool;
    /// The least milliseconds one request grows the shell for.
    fn min_growth_ms(&self) -> f64;
    /// Sends what was asked this frame, to be worked on before the next.
    fn send(&mut self);
}

/// What one frame of a viewer came to ([`ViewerDriver::tick`]), for its runner to tell the
/// page.
#[derive(Debug)]
pub struct Tick<V> {
    /// Where its graphics device stands.
    pub device: Device,
    /// The last worker replaced in this frame, if any.
    pub replaced: Option<Replaced>,
    /// Why the shell was dropped (it could not be built or grown), if it was.
    pub refused: Option<String>,
    /// The frame run (none while the device is not ready), or why the screen can draw no more.
    pub frame: Option<Result<ViewFrame<V>, String>>,
}

/// A viewer: its core state and the screen it is applied to.
pub struct ViewerDriver<S: Screen> {
    screen: S,
    state: ViewerState,
    /// Whether this frame draws or leaves it to the next (after megabytes of uploads).
    pacing: DrawPacing,
    /// How its graphics device is kept.
    survival: Survival,
    /// A recording's frame drawn and not yet taken.
    recorded: Option<Result<S::Video, String>>,
}

impl<S: Screen> ViewerDriver<S> {
    /// A viewer on `screen` at `now` (milliseconds): with a planar view of the pattern or not,
    /// its camera following the growing shell or framing it whole.
    pub fn new(screen: S, planar: bool, follows: bool, now: f64) -> Self {
        Self {
            screen,
            state: ViewerState::new(planar, follows, now),
            pacing: DrawPacing::default(),
            survival: Survival::default(),
            recorded: None,
        }
    }

    pub fn state(&self) -> &ViewerState {
        &self.state
    }

    pub fn screen(&self) -> &S {
        &self.screen
    }

    pub fn screen_mut(&mut self) -> &mut S {
        &mut self.screen
    }

    /// Does what the page asks (see [`ViewCommand`]). Returns what is left for the runner: a
    /// file to write ([`ViewCommand::WriteFile`]).
    pub fn command(&mut self, command: ViewCommand, pool: &mut Pool) -> Option<ViewCommand> {
        let left = self.state.command(command, pool);
        self.apply();
        match left {
            Some(ViewCommand::Background(srgb)) => {
                self.screen.set_background(srgb);
                None
            }
            Some(ViewCommand::RecordAt(None)) => {
                if let Some(Ok(video)) = self.recorded.take() {
                    self.screen.release(video);
                }
                None
            }
            left => left,
        }
    }

    /// Shows a shell grown whole on a worker (a gallery picture), at rest.
    pub fn show_whole(&mut self, preset: &'static Preset, spec: &ShellSpec, whole: WholeShell) {
        self.state.show_whole(preset, spec, whole);
        self.apply();
    }

    /// Takes in what the pool's workers sent back ([`ViewerState::take_all`]). Fails with the
    /// words to show when the shell cannot be built or grown (it is dropped).
    pub fn take_all(
        &mut self,
        replies: Vec<(Request, Reply)>,
        sessions_lost: Option<Vec<Request>>,
        pool: &mut Pool,
    ) -> Result<(), String> {
        let taken = self.state.take_all(replies, sessions_lost, pool);
        self.apply();
        taken
    }

    /// Asks the shell's worker to grow the rest of the shell at once (before a file of it is
    /// written).
    pub fn finish(&mut self, pool: &mut Pool) {
        self.state.finish(pool);
        self.apply();
    }

    /// Hands the screen what the core state changed (see [`ScreenChange`]).
    fn apply(&mut self) {
        let changes = self.state.take_screen();
        let grew = self.state.take_grew();
        let Some(g) = self.state.shell() else { return };
        if grew {
            self.screen.grew(g);
        }
        if !self.draws() {
            return;
        }
        for change in changes {
            match change {
                ScreenChange::Shell => self.screen.load(g),
                ScreenChange::Look => self.screen.look(g),
                ScreenChange::Rows(advance) => {
                    let bytes = self.screen.upload(g, &advance);
                    self.pacing.uploaded(bytes);
                }
            }
        }
    }

    /// Keeps the graphics device as [`Survival`] decides, once a frame before anything is
    /// drawn, at `now`: when the browser took it away, opens another (on the same canvas, or a
    /// fresh one the page gives, [`Self::give_canvas`]) and, once it is open, hands it the
    /// shell grown so far.
    pub fn survive(&mut self, now: f64) -> Device {
        let loss = self.screen.lost();
        let answer = self.screen.opened();
        let (device, open) = self.survival.frame(now, loss.as_ref(), answer);
        if open == Some(Open::Same) {
            self.screen.open_again();
        }
        if let Device::Reopened(_) = device {
            let backend = self.screen.backend().unwrap_or_default();
            if let Some(g) = self.state.shell()
                && g.replica().shell().is_some()
            {
                self.screen.load(g);
                let bytes = self.screen.upload(g, &g.replica().everything());
                self.pacing.uploaded(bytes);
            }
            self.state.touch();
            return Device::Reopened(backend.to_string());
        }
        device
    }

    /// The fresh canvas asked for ([`Device::NeedsCanvas`]), to open a renderer on; one given
    /// when none was asked for is let go.
    pub fn give_canvas(&mut self, canvas: S::Canvas) {
        if self.survival.canvas_given() == Some(Open::Fresh) {
            self.screen.open_on(canvas);
        }
    }

    /// A whole animation frame at `now`, as the drawing worker runs it: keeps the device
    /// ([`Self::survive`]) and, if it is ready, takes in the workers' replies
    /// ([`Self::take_all`]), runs the frame ([`Self::run_frame`]) and sends what it asked.
    pub fn tick(
        &mut self,
        now: f64,
        budget_ms: f64,
        workers: &mut impl PoolWorkers,
    ) -> Tick<S::Video> {
        let device = self.survive(now);
        if !matches!(device, Device::Ready | Device::Reopened(_)) {
            return Tick {
                device,
                replaced: None,
                refused: None,
                frame: None,
            };
        }
        let polled = workers.poll();
        let refused = (self.take_all(polled.replies, polled.sessions_lost, workers.pool())).err();
        let floor = workers.min_growth_ms();
        let frame = self.run_frame(now, budget_ms, floor, workers.pool());
        workers.send();
        Tick {
            device,
            replaced: polled.replaced,
            refused,
            frame: Some(frame),
        }
    }

    /// One animation frame at `now`, once the device is ready ([`Self::survive`]) and the
    /// replies are taken in ([`Self::take_all`]): grows and draws (unless held: the page shows
    /// something else over the shell), growth taking `budget_ms` and at least
    /// `min_growth_ms`, and says what the page is to show. Fails with the words to show when
    /// the screen can draw no more.
    pub fn run_frame(
        &mut self,
        now: f64,
        budget_ms: f64,
        min_growth_ms: f64,
        pool: &mut Pool,
    ) -> Result<ViewFrame<S::Video>, String> {
        let drawn = !self.state.held() && self.frame(now, budget_ms, min_growth_ms, pool)?;
        Ok(ViewFrame {
            report: FrameReport {
                loads: self.state.loads(),
                file: None,
                drawn,
                status: self.state.status(self.picture_size()),
                notice: self.state.take_notice(),
                planar: self.state.take_planar(),
            },
            recorded: self.recorded.take(),
        })
    }

    /// Whether it draws at all ([`Screen::backend`]).
    fn draws(&self) -> bool {
        self.screen.backend().is_some()
    }

    /// The size of the picture drawn ((0, 0) where nothing is).
    fn picture_size(&self) -> (u32, u32) {
        if self.draws() {
            self.screen.size()
        } else {
            (0, 0)
        }
    }

    /// Grows as the core state decides, or towards a recording's frame, and draws if anything
    /// changed. Returns whether a frame was drawn.
    fn frame(
        &mut self,
        now: f64,
        budget_ms: f64,
        min_growth_ms: f64,
        pool: &mut Pool,
    ) -> Result<bool, String> {
        if self.draws() {
            if let Some(failure) = self.screen.failure() {
                return Err(failure);
            }
            if self.survival.reopening() || self.screen.lost().is_some() {
                return Ok(false);
            }
        }
        if self.state.recording() {
            let asked = self.state.recording_frame(budget_ms, pool);
            self.apply();
            if let Some(ask) = asked {
                self.recorded = Some(ask.and_then(|ask| self.draw_recorded(now, &ask)));
            }
            return Ok(false);
        }
        self.fit();
        let due = self.state.frame(now, budget_ms, min_growth_ms, pool);
        self.apply();
        let pacing = self.pacing.frame(self.state.dirty());
        if !due {
            return Ok(false);
        }
        if !self.draws() {
            // Nothing to draw on: what changed is shown all the same (the planar view, the
            // status).
            self.state.drawn();
            return Ok(true);
        }
        // After megabytes of uploads, or while the GPU still works on earlier frames, the
        // drawing waits (the uploads go to the GPU meanwhile).
        if pacing == FrameDraw::Defer || !self.screen.ready() {
            self.screen.flush();
            return Ok(false);
        }
        if let Some(g) = self.state.shell() {
            self.screen.draw(g, self.state.layout())?;
        }
        self.state.drawn();
        Ok(true)
    }

    /// Keeps the drawing buffer at the size the core state asks for.
    fn fit(&mut self) {
        if let Some(size) = self.state.drawing_size()
            && self.draws()
            && size != self.screen.size()
        {
            self.screen.resize(size);
            self.state.touch();
        }
    }

    /// Draws the shell now and reads it back as a picture (a gallery card's, a file's).
    pub fn picture(&mut self) -> Result<S::Picture, String> {
        if !self.draws() {
            return Err(NO_DRAWING.into());
        }
        if let Some(loss) = self.screen.lost() {
            return Err(format!("the graphics device was lost ({})", loss.reason));
        }
        let g = self.state.shell().ok_or("nothing is drawn yet")?;
        self.screen.draw(g, self.state.layout())?;
        self.screen.picture()
    }

    /// [`Self::picture`], on a drawing buffer of `pixels` × `pixels`, `multisampled` or with
    /// one sample a pixel (a viewer of pictures only, whose canvas is not laid out on the page).
    pub fn picture_at(&mut self, pixels: u32, multisampled: bool) -> Result<S::Picture, String> {
        if self.draws() {
            if self.screen.size() != (pixels, pixels) {
                self.screen.resize((pixels, pixels));
            }
            self.screen.multisample(multisampled);
        }
        self.picture()
    }

    /// Draws the recording's frame `ask` (the core state posed the camera for it) and reads it.
    fn draw_recorded(&mut self, now: f64, ask: &FrameAsk) -> Result<S::Video, String> {
        self.fit();
        let g = self.state.shell().ok_or("no shell is loaded")?;
        if !self.draws() {
            return Err(NO_DRAWING.into());
        }
        self.screen.draw(g, self.state.layout())?;
        self.state.recorded(now);
        self.screen.video(ask)
    }
}
