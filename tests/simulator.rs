//! The page simulated deterministically from a seed: the real session of the page
//! ([`Session`]), the real viewer of the drawing worker ([`ViewerDriver`]) on a simulated
//! screen, the real
//! pool and its rules for its workers' events ([`Pool`], [`Pool::take_events`]) and the real
//! host each Web Worker runs ([`Host`]), joined by simulated message channels and a simulated
//! clock, with faults and user input drawn from the seed. Every command crosses to the
//! drawing worker as the bytes it reads, late by a frame or more, and its frames come back as
//! late; every request and reply crosses as the bytes a worker reads.
//!
//! What a run may do, in any order: follow a link to a shell (one of several forms) or back to
//! the gallery, edit a material value, drag a pattern slider (a preview) and let go of it,
//! step, finish, restart, pause and play, change the speed (beyond its range too), switch
//! between one view and four, cover the shell with the map or breeding, record frames; a worker's replies reach the page late
//! and out of step with other workers' (each worker's own in the order it sent them, as a
//! worker's messages do), some twice; workers throw, hang, send bytes nobody can read, or
//! never start; the tab sleeps for seconds between frames; the browser takes the graphics
//! device away (a WebGL context it may give back, once or twice, or a WebGPU device), and an
//! opening of a renderer again fails; the GPU falls behind (drawing waits) or its frames stop
//! reaching the screen (the drawing worker says so); the drawing worker fails, or spins until
//! the page finds it out by its silence, and the view moves to the page's thread, clicks going
//! on meanwhile. The gallery's pictures are drawn on the page's thread by the real
//! [`PictureDrawer`] from shells the page's own pool grows, its workers faulty too and its
//! device lost and given back. Lost messages are not simulated: a
//! worker's channel to the page loses nothing while the worker lives, and one that dies is
//! simulated.
//!
//! After every step: no panic; every reply of a shell the page has left changes nothing (the
//! page's copy never falls out of step with its worker, the renderer only ever takes the
//! shell shown, its rows in order, and the page never shows the status of a shell it left);
//! the shell shown is the last asked for; the work held is bounded; the gallery's shells are
//! asked only while it is shown, none twice at a time, and each picture shows the shell it is
//! for. At the end of a run, with the faults over: the shell grows whole within a bounded
//! simulated time, its mesh and pattern hashes those of the native core growing it alone, and
//! a frame a recording asked for is drawn; or, in the gallery, every card shows a picture of
//! its whole shell and the page says so. A failure prints its seed and the shortest run
//! that still fails; `SEASHELLS_SIM_SEED=N` replays one seed, `SEASHELLS_SIM_RUNS=N` runs more
//! (`make fuzz`).

use crate::simulated_workers::{Workers, within_copy};
use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use seashells_core::generator::{Advance, GROWTH_BUDGET_MS, Generator};
use seashells_core::presets::{Preset, presets};
use seashells_core::share::link;
use seashells_core::share::presentation::Layout;
use seashells_core::spec::ShellSpec;
use seashells_core::view::recording::FrameAsk;
use seashells_core::work::device_survival::Loss;
use seashells_core::work::message::{Reply, Request};
use seashells_core::work::picture_drawer::PictureDrawer;
use seashells_core::work::picture_queue::Place;
use seashells_core::work::pool::{JOBS_PER_WORKER, Polled, Pool, PoolPlan};
use seashells_core::work::screen::Screen;
use seashells_core::work::session::{Edit, Effect, FrameTask, Session};
use seashells_core::work::status_readout::Say;
use seashells_core::work::viewer_command::ViewCommand;
use seashells_core::work::viewer_driver::{PoolWorkers, ViewerDriver};
use seashells_core::work::viewer_inbox::{Inbox, Unheard};
use seashells_core::work::viewer_message::{
    ViewerNews, decode_command, encode_command, encode_news,
};
use seashells_core::work::viewer_state::Growing;
use seashells_core::work::viewer_status::{Device, FrameReport};
use std::collections::{HashMap, HashSet, VecDeque};
use std::sync::{Mutex, OnceLock};

/// The shells a run opens: one of each kind of growth (a swept shell with its pattern, one
/// whose pattern diverges and stops it, one whose pattern grows on its edge, the automaton,
/// Kawaguchi's chambers and branches, an implicit shell whose finish is shared out among the
/// pool in pieces), made small to be quick.
const SHELLS: [(&str, &str); 7] = [
    ("stripes", "&growth.rows=90&pattern.cells=64"),
    // A pattern that diverges: growth stops, and says why once.
    (
        "oliva-porphyria",
        "&growth.rows=120&pattern.cells=64&pattern.model.kappa=0&pattern.model.rho=5",
    ),
    ("stripes-growing-edge", "&growth.rows=90"),
    ("ca-waves", "&growth.rows=90"),
    ("kawaguchi-horn", ""),
    ("kawaguchi-coral", ""),
    ("implicit-whorl", "&form.resolution=24"),
];

/// The page's frame interval, milliseconds.
const FRAME_MS: f64 = 16.7;

/// What happens next: a user's input, a fault, or time passing. Each carries what randomness
/// it needs, so that a run with steps left out still means the same by the steps it keeps.
#[derive(Clone, Debug)]
enum Step {
    /// A link to a shell followed (or, with `finish`, an embed for a reader who asked for less
    /// motion: the shell grown whole, still).
    Open {
        shell: usize,
        finish: bool,
    },
    /// Back to the gallery.
    Gallery,
    Restyle {
        gloss: u8,
    },
    /// A pattern slider dragged, and (`set`) let go.
    Drag {
        iterations: u16,
        set: bool,
    },
    /// One row, paused.
    OneRow,
    Finish,
    Restart,
    Play,
    Speed {
        tenths: u16,
    },
    Views,
    /// The map or breeding covers the shell, or not.
    Cover(bool),
    /// A step of the coiling story followed (its shells swept, quick to grow; its last step
    /// opens the map over the shell).
    Story {
        step: u8,
    },
    Record(bool),
    AskFrame {
        row: u16,
    },
    /// Animation frames: each worker's replies reach the page up to `lag` frames late, and
    /// the messages between the page and the drawing worker as late.
    Frames {
        count: u8,
        lag: u8,
        salt: u64,
    },
    /// The tab sleeps this many seconds before its next frame.
    Sleep {
        seconds: u8,
    },
    /// A worker throws (after the replies it has sent).
    Throw {
        slot: u8,
    },
    /// A worker spins for ever on what it holds.
    Hang {
        slot: u8,
    },
    /// A worker's next reply arrives as bytes nobody can read.
    Garble {
        slot: u8,
    },
    /// A worker's next reply reaches the page twice.
    Twice {
        slot: u8,
    },
    /// The browser takes the drawing worker's graphics device away (a WebGL context, which it
    /// may give back after `restore` frames, or a WebGPU device).
    LoseDevice {
        webgl: bool,
        restore: u8,
    },
    /// The browser gives a lost WebGL context back (again, maybe).
    Restore,
    /// The next renderer opened again fails.
    FailOpen,
    /// The drawing worker fails: the view moves to a viewer on the page's thread, with the
    /// page's own pool, which opens `frames` frames later; what is asked meanwhile goes to the
    /// worker that failed.
    Fallback {
        frames: u8,
    },
    /// The drawing worker spins for ever: the page must find it out by its silence.
    HangDrawing,
    /// The GPU falls `frames` frames behind: drawing waits for it, uploads go on.
    GpuBehind {
        frames: u8,
    },
    /// The frames handed to the GPU stop reaching the screen: the drawing worker says so and
    /// stops, and the view moves to the page's thread.
    GpuStops,
    /// The browser takes the gallery's pictures' graphics device away (a WebGL context, which
    /// it may give back after `restore` frames, or a WebGPU device).
    LosePictures {
        webgl: bool,
        restore: u8,
    },
    /// A worker of the page's own pool, which grows the gallery's shells, throws (`fault` 0),
    /// hangs (1), sends bytes nobody can read (2) or has its next reply reach the page twice
    /// (3).
    PictureWorker {
        slot: u8,
        fault: u8,
    },
}

/// A recording's video frame, posted beside the frame's news that says it was drawn.
struct VideoFrame;

/// The page: its session, the drawing worker's viewer and pool, the workers, the messages
/// between them, and what the checks remember.
struct Page {
    session: Session,
    viewer: ViewerDriver<SimScreen>,
    /// The drawing worker's pool and its workers.
    workers: Workers,
    /// Commands on their way to the drawing worker, and frames on their way back, with the
    /// frame they arrive in.
    to_viewer: VecDeque<(u64, Vec<u8>)>,
    to_page: VecDeque<(u64, Vec<u8>, Option<VideoFrame>)>,
    now: f64,
    frame: u64,
    /// The shell of each session the viewer opened (its preset).
    sessions: HashMap<u32, &'static str>,
    /// Whether the map or breeding covers the shell.
    covered: bool,
    /// Whether a recording holds the viewer, and its frames asked and drawn.
    recording: bool,
    asked_frames: usize,
    drawn_frames: usize,
    /// The page said the device is gone for good.
    gone: bool,
    /// The words the page said while each shell (by its viewer and session) was shown.
    said: Vec<(u32, u32, String)>,
    /// Viewers that took the drawing worker's place so far (each numbers its sessions afresh).
    viewers: u32,
    /// What the page last said of the shell's state (`data-state`).
    shown_state: String,
    /// The frame a viewer on the page's thread opens in, after the drawing worker failed.
    moving: Option<u64>,
    /// Frames the viewers replaced so far held back for the GPU.
    deferred: usize,
    /// Views moved to the page's thread because the drawing worker said its frames stopped
    /// reaching the screen.
    failed_over: u32,
    /// What the page has heard of the drawing worker, and whether the worker hangs.
    inbox: Inbox<VideoFrame>,
    drawing_hung: bool,
    /// The gallery's pictures, drawn on the page's thread ([`PictureDrawer`]) from the shells
    /// the page's own pool grows (which, unlike the page's, grows nothing else here).
    pictures: PictureDrawer<SimScreen>,
    picture_workers: Workers,
    /// The presets whose card shows a picture of its whole shell (one drawn just before the
    /// pictures' device was lost may be blank, and is drawn again).
    cards: HashSet<&'static str>,
}

/// The drawing worker's screen, simulated: its graphics device, which the browser takes away
/// and gives back as the steps say, and what its renderer has taken of the shell shown, which
/// must be the shell last asked for, its rows in order from the first.
#[derive(Default)]
struct SimScreen {
    /// The drawing worker's frame now (the browser answers an opening two frames later).
    frame: u64,
    /// Lost, and how (a WebGL context may come back).
    lost: Option<Loss>,
    /// The frame a lost context comes back in.
    restore_at: Option<u64>,
    /// A renderer being opened again: the frame the browser answers in, and its answer.
    opening: Option<(u64, Result<(), String>)>,
    /// The next opening fails.
    fail_next: bool,
    /// Renderers opened again so far.
    reopened: usize,
    /// The rows the renderer has taken of the shell shown (`None`: not built yet).
    uploaded: Option<usize>,
    size: (u32, u32),
    /// The first thing handed to it that breaks the rules above.
    fault: Option<Failure>,
    /// The frame until which the GPU is behind (drawing waits).
    behind_until: u64,
    /// Its frames stopped reaching the screen.
    stopped: bool,
    /// Frames the driver held back for the GPU to catch up.
    deferred: usize,
    /// The preset of the shell built last.
    shown: Option<&'static str>,
}

impl SimScreen {
    /// The drawing worker's frame `frame` begins: a lost context due back comes back.
    fn tick(&mut self, frame: u64) {
        self.frame = frame;
        if let (Some(at), Some(lost)) = (self.restore_at, &mut self.lost)
            && at <= frame
        {
            lost.restored = true;
            self.restore_at = None;
        }
    }

    /// The browser takes the device away in frame `frame` (a WebGL context, which it gives
    /// back `restore` frames later unless that is 0, or a WebGPU device).
    fn lose(&mut self, webgl: bool, restore: u8, frame: u64) {
        self.lost = Some(Loss {
            reason: "taken by the browser".into(),
            restored: false,
            webgl,
        });
        self.restore_at = (webgl && restore > 0).then(|| frame + u64::from(restore));
    }

    fn fault(&mut self, failure: Failure) {
        self.fault.get_or_insert(failure);
    }

    /// Starts opening a renderer: the browser answers two frames later.
    fn open(&mut self) {
        let answer = if std::mem::take(&mut self.fail_next) {
            Err("the browser would not open a device".to_string())
        } else {
            Ok(())
        };
        self.opening = Some((self.frame + 2, answer));
    }
}

impl Screen for SimScreen {
    type Video = VideoFrame;
    type Picture = ();
    type Canvas = ();

    fn backend(&self) -> Option<&'static str> {
        Some("simulated")
    }

    fn load(&mut self, growing: &Growing) {
        self.uploaded = Some(0);
        self.shown = Some(growing.preset().id);
    }

    fn look(&mut self, _: &Growing) {
        if self.uploaded.is_none() {
            self.fault("a look for a shell not built".into());
        }
    }

    fn upload(&mut self, growing: &Growing, advance: &Advance) -> usize {
        let Some(rows) = self.uploaded else {
            self.fault("rows of a shell not built".into());
            return 0;
        };
        if advance.rows.start != rows {
            self.fault(format!(
                "the renderer holds {rows} rows and was handed rows {:?}",
                advance.rows
            ));
        } else if !within_copy(advance, growing.replica()) {
            // What the renderer reads, as the copy stands now, must be there.
            self.fault(format!(
                "the renderer was handed {advance:?}, beyond the copy"
            ));
        }
        self.uploaded = Some(advance.rows.end);
        // What a renderer would upload: vertices, indices and the pattern's rows.
        advance.vertices.len() * 24
            + advance.indices.len() * 4
            + advance.rows.len() * growing.replica().cells() * 4
    }

    fn grew(&mut self, _: &Growing) {}

    fn set_background(&mut self, _: [u8; 3]) {}

    fn failure(&mut self) -> Option<String> {
        self.stopped
            .then(|| "Nothing drawn reaches the screen: the GPU stopped.".to_string())
    }

    fn lost(&self) -> Option<Loss> {
        self.lost.clone()
    }

    fn open_again(&mut self) {
        self.open();
    }

    fn open_on(&mut self, (): ()) {
        self.open();
    }

    fn opened(&mut self) -> Option<Result<(), String>> {
        let (_, answer) = self.opening.take_if(|(at, _)| *at <= self.frame)?;
        if answer.is_ok() {
            // A fresh renderer, on a device of its own, holding no shell yet.
            self.reopened += 1;
            self.lost = None;
            self.restore_at = None;
            self.uploaded = None;
        }
        Some(answer)
    }

    fn ready(&self) -> bool {
        self.frame >= self.behind_until
    }

    fn flush(&mut self) {
        if self.frame < self.behind_until {
            self.deferred += 1;
        }
    }

    fn size(&self) -> (u32, u32) {
        self.size
    }

    fn resize(&mut self, size: (u32, u32)) {
        self.size = size;
    }

    fn draw(&mut self, _: &Growing, _: Layout) -> Result<(), String> {
        Ok(())
    }

    fn video(&mut self, _: &FrameAsk) -> Result<VideoFrame, String> {
        Ok(VideoFrame)
    }

    fn release(&mut self, _: VideoFrame) {}

    fn multisample(&mut self, _: bool) {}

    fn picture(&mut self) -> Result<(), String> {
        Ok(())
    }
}

/// The drawing worker's viewer, freshly opened at `now`, on a screen that has opened
/// `reopened` renderers again so far.
fn viewer(now: f64, reopened: usize) -> ViewerDriver<SimScreen> {
    let screen = SimScreen {
        reopened,
        ..screen()
    };
    ViewerDriver::new(screen, true, true, now)
}

/// A fresh simulated screen, its device ready.
fn screen() -> SimScreen {
    SimScreen {
        size: (1, 1),
        ..SimScreen::default()
    }
}

/// The drawing worker's pool as its frame `frame` at `now` uses it: what was asked is sent
/// as the bytes a worker reads, and whether it could be read is kept.
struct Polling<'a> {
    workers: &'a mut Workers,
    frame: u64,
    now: f64,
    rng: &'a mut Pcg64,
    sent: Result<(), Failure>,
}

impl PoolWorkers for Polling<'_> {
    fn poll(&mut self) -> Polled {
        self.workers.poll(self.frame, self.now, self.rng)
    }

    fn pool(&mut self) -> &mut Pool {
        &mut self.workers.pool
    }

    /// A worker's least growth, as the page's plan sets it.
    fn min_growth_ms(&self) -> f64 {
        PoolPlan::from_query(|_| None, 1).worker_growth_ms
    }

    fn send(&mut self) {
        self.sent = self.workers.dispatch(self.now);
    }
}

/// A failed check, in words.
type Failure = String;

impl Page {
    fn new(size: usize) -> Self {
        Self {
            session: Session::default(),
            viewer: viewer(0.0, 0),
            workers: Workers::new(size),
            to_viewer: VecDeque::new(),
            to_page: VecDeque::new(),
            now: 0.0,
            frame: 0,
            sessions: HashMap::new(),
            covered: false,
            recording: false,
            asked_frames: 0,
            drawn_frames: 0,
            gone: false,
            said: Vec::new(),
            viewers: 0,
            shown_state: String::new(),
            moving: None,
            deferred: 0,
            failed_over: 0,
            inbox: Inbox::default(),
            drawing_hung: false,
            pictures: PictureDrawer::new(screen(), 0.0),
            picture_workers: Workers::new(size),
            cards: HashSet::new(),
        }
    }

    /// Does what the session decided: commands go to the drawing worker (arriving `lag`
    /// frames late); the rest is the DOM's.
    fn apply(&mut self, lag: u8) {
        for effect in self.session.take_effects() {
            match effect {
                Effect::View(command) => self.send(command, lag),
                Effect::StopRecording(_) => self.stop_recording(lag),
                // The map a story's step opens covers the shell, as the page's does; a link
                // followed closes it.
                Effect::OpenMap(_) => self.covered = true,
                Effect::CloseMap => self.covered = false,
                Effect::Signal("state", state) => self.shown_state = state,
                Effect::Gallery(shown) => {
                    let (queue, pool) = (self.pictures.queue_mut(), &mut self.picture_workers.pool);
                    if shown {
                        queue.ask_cards(pool);
                    } else {
                        queue.pause(pool);
                    }
                }
                Effect::Say(Say::Show(words)) => {
                    if let Some(shell) = &self.session.status().shell {
                        self.said.push((self.viewers, shell.session, words));
                    }
                }
                _ => {}
            }
        }
    }

    /// Sends `command` to the drawing worker, as the bytes it reads.
    fn send(&mut self, command: ViewCommand, lag: u8) {
        let at = self.frame + u64::from(lag);
        let at = at.max(self.to_viewer.back().map_or(0, |(a, _)| *a));
        self.to_viewer.push_back((at, encode_command(&command)));
    }

    fn stop_recording(&mut self, lag: u8) {
        if std::mem::take(&mut self.recording) {
            self.asked_frames = self.drawn_frames;
            self.send(ViewCommand::RecordAt(None), lag);
        }
    }

    /// Fails with what the screen was handed against its rules, if anything.
    fn screen(&mut self) -> Result<(), Failure> {
        self.viewer.screen_mut().fault.take().map_or(Ok(()), Err)
    }

    /// One animation frame: the page holds growth or not and takes in the drawing worker's
    /// frames that reached it; the drawing worker takes in the commands that reached it, its
    /// workers' replies, runs the viewer's frame and sends it back; what it asked is sent to
    /// the workers, who work till the next.
    fn run_frame(&mut self, lag: u8, rng: &mut Pcg64) -> Result<(), Failure> {
        self.frame += 1;
        self.now += FRAME_MS;
        let outcome = self.page_frame(lag, rng);
        // What the frame asked of the page's pool goes out; each worker grows a whole shell
        // to its end, as a Web Worker does (its reply late by up to `lag` frames).
        self.picture_workers.dispatch(self.now)?;
        (self.picture_workers).work(self.frame, f64::INFINITY, lag, rng);
        outcome
    }

    /// The page's pool's replies that reached it: each gallery shell waits to be drawn.
    fn take_pictures(&mut self, rng: &mut Pcg64) -> Result<(), Failure> {
        let polled = self.picture_workers.poll(self.frame, self.now, rng);
        for (request, reply) in polled.replies {
            match (request, reply) {
                (Request::Whole { job, .. }, Reply::Grown { result, .. }) => {
                    if let Err(why) = &result {
                        return Err(format!("a card's shell could not be grown: {why}"));
                    }
                    self.pictures.queue_mut().take(job, result);
                }
                (request, reply) => {
                    return Err(format!(
                        "the page's pool answered {request:?} with {reply:?}"
                    ));
                }
            }
        }
        Ok(())
    }

    /// The gallery's next picture, drawn as the page's frame draws it; it must show the whole
    /// shell of the card it is for.
    fn draw_picture(&mut self) -> Result<(), Failure> {
        self.pictures.screen_mut().tick(self.frame);
        let pool = &mut self.picture_workers.pool;
        let drew = self.pictures.work(self.now, pool, || Some(()));
        if let Some(fault) = self.pictures.screen_mut().fault.take() {
            return Err(format!("the pictures' screen: {fault}"));
        }
        for wanted in drew.forgotten {
            self.cards.remove(wanted.preset.id);
        }
        let Some((wanted, ())) = drew.drawn else {
            return Ok(());
        };
        let shown = self.pictures.screen().shown;
        if shown != Some(wanted.preset.id) {
            return Err(format!(
                "the picture of the {} drew {shown:?}",
                wanted.preset.id
            ));
        }
        if wanted.place == Place::Card {
            self.cards.insert(wanted.preset.id);
        }
        Ok(())
    }

    /// The page's frame, but its own pool's traffic.
    fn page_frame(&mut self, lag: u8, rng: &mut Pcg64) -> Result<(), Failure> {
        if let Some(opens) = self.moving {
            if self.frame < opens {
                // The page waits for the viewer it is opening; the old pool's workers go on.
                self.workers.work(self.frame, FRAME_MS, lag, rng);
                return Ok(());
            }
            self.install();
        }
        self.page_takes_frames(lag, rng)?;
        if self.moving.is_none() {
            // The page sends its drawing worker the frame (not once it is moving the view).
            self.inbox.ticked(self.now);
        }
        if self.drawing_hung || self.moving.is_some() {
            // The drawing worker spins, or is being replaced: its workers go on.
            self.workers.work(self.frame, FRAME_MS, lag, rng);
            return Ok(());
        }
        while let Some((_, bytes)) = self.to_viewer.front().filter(|(at, _)| *at <= self.frame) {
            let command = decode_command(bytes).map_err(|e| e.to_string())?;
            self.to_viewer.pop_front();
            let load = matches!(command, ViewCommand::Load { .. });
            if load {
                // Whatever the renderer held, the shell to come is not built yet.
                self.viewer.screen_mut().uploaded = None;
            }
            self.viewer.command(command, &mut self.workers.pool);
            if load && let Some(shell) = self.viewer.state().shell() {
                self.sessions
                    .insert(shell.replica().session(), shell.preset().id);
            }
            self.screen()?;
        }
        self.viewer.screen_mut().tick(self.frame);
        let mut polling = Polling {
            workers: &mut self.workers,
            frame: self.frame,
            now: self.now,
            rng,
            sent: Ok(()),
        };
        let tick = self.viewer.tick(self.now, GROWTH_BUDGET_MS, &mut polling);
        polling.sent?;
        if let Device::NeedsCanvas(_) = tick.device {
            // The page makes the fresh canvas asked for at once.
            self.viewer.give_canvas(());
        }
        self.screen()?;
        if let Some(message) = tick.refused {
            return Err(format!("the shell was dropped: {message}"));
        }
        let (report, recorded) = match tick.frame {
            // The drawing worker says where its device stands and does nothing else; its
            // workers go on with what they hold.
            None => (None, false),
            Some(Err(failure)) if !self.viewer.screen().stopped => {
                return Err(format!("the viewer's frame failed: {failure}"));
            }
            Some(Err(failure)) => {
                // The drawing worker says why it can draw no more, and draws no more.
                let at =
                    (self.frame + u64::from(lag)).max(self.to_page.back().map_or(0, |(a, ..)| *a));
                self.to_page
                    .push_back((at, encode_news(&ViewerNews::Failed(failure)), None));
                self.drawing_hung = true;
                self.workers.work(self.frame, FRAME_MS, lag, rng);
                return Ok(());
            }
            Some(Ok(frame)) => {
                let recorded = match frame.recorded {
                    Some(Err(e)) => return Err(format!("a recording's frame was refused: {e}")),
                    Some(Ok(VideoFrame)) => true,
                    None => false,
                };
                (Some(frame.report), recorded)
            }
        };
        self.post(lag, tick.device, report, recorded);
        self.workers.work(self.frame, FRAME_MS, lag, rng);
        Ok(())
    }

    /// The drawing worker posts a frame's news to the page, as the bytes it reads, arriving
    /// `lag` frames later; a recording's video frame goes beside it.
    fn post(&mut self, lag: u8, device: Device, report: Option<FrameReport>, recorded: bool) {
        let at = (self.frame + u64::from(lag)).max(self.to_page.back().map_or(0, |(a, ..)| *a));
        let news = ViewerNews::Frame {
            device,
            report: report.map(Box::new),
            recorded: recorded.then_some(Ok(())),
        };
        let video = recorded.then_some(VideoFrame);
        self.to_page.push_back((at, encode_news(&news), video));
    }

    /// The viewer on the page's thread takes the failed drawing worker's place: a fresh
    /// renderer and the page's own pool, nothing of the old worker's messages, and the session
    /// tells it what it told the old one (the shell grows again from its apex).
    fn install(&mut self) {
        self.moving = None;
        self.drawing_hung = false;
        self.inbox = Inbox::default();
        self.viewers += 1;
        self.deferred += self.viewer.screen().deferred;
        self.viewer = viewer(self.now, self.viewer.screen().reopened);
        self.workers = Workers::new(self.workers.count().max(1));
        self.to_viewer.clear();
        self.to_page.clear();
        self.stop_recording(0);
        self.session.viewer_replaced([255, 255, 255]);
        self.apply(0);
    }

    /// The page takes in the drawing worker's frames that reached it, in the order of the
    /// page's frame (`web/app/frame.rs`): the device first (a frame whose device is not ready
    /// takes nothing in), then its own pool's replies, the hold on growth, and the frames (the
    /// status of a frame made before the last load reached the viewer is not of the shell
    /// shown).
    fn page_takes_frames(&mut self, lag: u8, rng: &mut Pcg64) -> Result<(), Failure> {
        while let Some((_, bytes, video)) = self.to_page.pop_front_if(|(at, ..)| *at <= self.frame)
        {
            self.inbox.heard(&bytes, video, self.now)?;
        }
        let Ok(draws) = self.session.device(self.inbox.device()) else {
            // No device can be opened again: the page says so, and draws no more.
            self.gone = true;
            return Ok(());
        };
        self.apply(0);
        if !draws {
            // The page's frame waits for the device and takes nothing in, but finds out a
            // drawing worker that failed or fell silent meanwhile.
            return match self.inbox.answering(self.now) {
                Ok(()) => Ok(()),
                Err(unheard) => self.unheard(unheard),
            };
        }
        self.take_pictures(rng)?;
        self.session.hold(self.covered, self.recording);
        self.apply(lag);
        let taken = match self.inbox.take(self.now) {
            Ok(taken) => taken,
            Err(unheard) => return self.unheard(unheard),
        };
        let now = self.now;
        let hearing = (self.session).hear(taken, self.covered, self.recording, now);
        if let Some(recorded) = hearing.recorded {
            recorded?;
            if self.recording {
                self.drawn_frames += 1;
            }
        }
        self.apply(0);
        if matches!(hearing.task, FrameTask::Pictures | FrameTask::Tiles) {
            self.draw_picture()?;
        }
        // What the page shows is of the shell it shows.
        if let (Some(shell), Some((preset, _))) =
            (&self.session.status().shell, self.session.current())
            && self.sessions.get(&shell.session) != Some(&preset.id)
        {
            return Err(format!(
                "the page shows the status of {:?} as the {}'s",
                self.sessions.get(&shell.session),
                preset.id
            ));
        }
        Ok(())
    }

    /// The page hears no more of its drawing worker: the view moves to the page's thread.
    fn unheard(&mut self, unheard: Unheard) -> Result<(), Failure> {
        match unheard {
            Unheard::Silent(_) => {
                // The drawing worker is taken for hung.
                self.moving.get_or_insert(self.frame + 1);
            }
            Unheard::Failed(why) => {
                // The drawing worker's renderer failed: the view moves at once (not after the
                // worker's silence).
                if !why.contains("Nothing drawn reaches the screen") {
                    return Err(format!("the page heard an unexpected failure: {why}"));
                }
                if self.moving.is_none() {
                    self.failed_over += 1;
                    self.moving = Some(self.frame + 1);
                }
            }
        }
        Ok(())
    }

    /// Does `step`.
    fn step(&mut self, step: &Step) -> Result<(), Failure> {
        let now = self.now;
        match step {
            Step::Open { shell, finish } => {
                let (id, extra) = SHELLS[*shell % SHELLS.len()];
                let ui = if *finish { "&ui=none" } else { "" };
                self.session
                    .route(&format!("#v=1&preset={id}{extra}{ui}"), *finish, now);
            }
            Step::Gallery => self.session.route("", false, now),
            Step::Story { step } => {
                let link = format!("#story=coiling&step={}", 1 + step % 8);
                self.session.route(&link, false, now);
            }
            Step::Restyle { gloss } => {
                let gloss = format!("{}", f64::from(*gloss % 11) / 10.0);
                self.session.edit("material.gloss", &gloss, Edit::Set, now);
            }
            Step::Drag { iterations, set } => {
                let value = (1 + iterations % 40).to_string();
                let edit = if *set { Edit::Set } else { Edit::Moving };
                self.session.edit("pattern.iterations", &value, edit, now);
            }
            Step::OneRow => self.session.step(),
            Step::Finish => self.session.finish(),
            Step::Restart => self.session.restart(),
            Step::Play => self.session.toggle_playing(),
            Step::Speed { tenths } => {
                self.session
                    .set_speed(&(f64::from(*tenths) / 10.0).to_string(), now);
            }
            Step::Views => self.session.toggle_views(),
            Step::Cover(covered) => self.covered = *covered,
            Step::Record(on) => {
                if *on && !self.recording && self.session.record(now).is_some() {
                    self.apply(0);
                    self.recording = true;
                    self.asked_frames = self.drawn_frames;
                    self.send(ViewCommand::RecordAt(Some((64, 48))), 0);
                } else if !on {
                    self.stop_recording(0);
                }
            }
            Step::AskFrame { row } => {
                // A recording asks for its next frame once the last is drawn, as the page's
                // does.
                if self.recording && self.asked_frames == self.drawn_frames {
                    self.asked_frames += 1;
                    self.send(
                        ViewCommand::AskFrame(FrameAsk {
                            row: usize::from(*row % 100),
                            dt: 0.04,
                            turn: 0.0,
                            timestamp_us: 0,
                            duration_us: 40_000,
                        }),
                        0,
                    );
                }
            }
            Step::Frames { count, lag, salt } => {
                let mut rng = Pcg64::seed_from_u64(*salt);
                for _ in 0..*count {
                    self.run_frame(*lag, &mut rng)?;
                }
            }
            Step::Sleep { seconds } => {
                self.now += f64::from(*seconds) * 1000.0;
            }
            Step::Throw { slot } => self.workers.throw(usize::from(*slot), self.frame + 1),
            Step::Hang { slot } => self.workers.hang(usize::from(*slot)),
            Step::Garble { slot } => self.workers.garble(usize::from(*slot)),
            Step::Twice { slot } => self.workers.twice(usize::from(*slot)),
            Step::LoseDevice { webgl, restore } => {
                self.viewer.screen_mut().lose(*webgl, *restore, self.frame)
            }
            Step::Restore => {
                if let Some(lost) = &mut self.viewer.screen_mut().lost
                    && lost.webgl
                {
                    lost.restored = true;
                }
            }
            Step::FailOpen => self.viewer.screen_mut().fail_next = true,
            Step::HangDrawing => self.drawing_hung = true,
            Step::GpuBehind { frames } => {
                self.viewer.screen_mut().behind_until = self.frame + u64::from(*frames);
            }
            Step::GpuStops => self.viewer.screen_mut().stopped = true,
            Step::LosePictures { webgl, restore } => self
                .pictures
                .screen_mut()
                .lose(*webgl, *restore, self.frame),
            Step::PictureWorker { slot, fault } => {
                let (workers, slot) = (&mut self.picture_workers, usize::from(*slot));
                match fault % 4 {
                    0 => workers.throw(slot, self.frame + 1),
                    1 => workers.hang(slot),
                    2 => workers.garble(slot),
                    _ => workers.twice(slot),
                }
            }
            Step::Fallback { frames } => {
                if self.moving.is_none() {
                    self.moving = Some(self.frame + 1 + u64::from(*frames));
                }
            }
        }
        self.apply(0);
        self.check()
    }

    /// What must hold after every step: the viewer shows the shell the page shows, once the
    /// commands on their way have reached it; the work held is bounded.
    fn check(&self) -> Result<(), Failure> {
        if self.to_viewer.is_empty()
            && let (Some((preset, spec)), Some(shell)) =
                (self.session.current(), self.viewer.state().shell())
            && (shell.preset().id != preset.id || !shell.spec().grows_like(spec))
        {
            return Err(format!(
                "the viewer shows {} where the page shows {}",
                shell.preset().id,
                preset.id
            ));
        }
        let pool = &self.workers.pool;
        let held = pool.in_flight() + pool.waiting() + self.workers.unheard();
        if held > 64 {
            return Err(format!("the page holds {held} requests and replies"));
        }
        // The gallery's shells are asked only while it is shown (a worker that dies holding
        // some has them wait again), each at most once at a time.
        let pictures = &self.picture_workers.pool;
        // (Where the workers were given up, the page's thread stands in for one.)
        let held_by_workers = self.picture_workers.count().max(1) * JOBS_PER_WORKER;
        if !self.session.in_gallery() && pictures.waiting() > held_by_workers {
            return Err(format!(
                "{} cards' shells wait for the page's pool while the gallery is not shown",
                pictures.waiting()
            ));
        }
        let held = pictures.in_flight() + pictures.waiting();
        let undrawn = presets().len() - self.cards.len();
        if held > undrawn {
            return Err(format!(
                "the page's pool holds {held} requests for {undrawn} cards not drawn"
            ));
        }
        Ok(())
    }

    /// With the faults over, the user lets the shell grow: it must grow whole within a
    /// bounded simulated time, as the native core grows it alone, the page must say so
    /// (`grown`), and a recording's frame asked for must be drawn.
    fn settle(&mut self) -> Result<(), Failure> {
        if self.session.in_gallery() {
            return self.settle_gallery();
        }
        if self.session.current().is_none() {
            return Ok(());
        }
        if self.recording {
            self.step(&Step::AskFrame { row: 40 })?;
        }
        self.step(&Step::Cover(false))?;
        if !self.session.playing() {
            self.step(&Step::Play)?;
        }
        let mut rng = Pcg64::seed_from_u64(0);
        // The longest a worker may keep a request (a minute to build or regrow a shell),
        // doubled by each hang, and the growth itself.
        let deadline = self.now + 20.0 * 60_000.0;
        let mut finished = false;
        loop {
            if self.gone {
                // The page said why it draws no more.
                return Ok(());
            }
            let status = self.session.status();
            let drawn_all = !self.recording || self.drawn_frames >= self.asked_frames;
            // Grown whole, every answer in, the view at rest, and the page says so.
            let said = matches!(self.shown_state.as_str(), "grown" | "stopped");
            if let Some(shell) = &status.shell
                && shell.finished()
                && drawn_all
                && said
            {
                break;
            }
            if self.now > deadline {
                return Err(format!(
                    "the shell did not grow whole within twenty simulated minutes: the page shows {status:?}, {} of {} recorded frames drawn",
                    self.drawn_frames, self.asked_frames
                ));
            }
            if !finished && self.recording && drawn_all {
                self.step(&Step::Record(false))?;
            } else if !finished && !self.recording {
                self.step(&Step::Finish)?;
                finished = true;
            }
            self.run_frame(1, &mut rng)?;
            self.check()?;
        }
        let (preset, spec) = self.session.current().ok_or("no shell")?;
        let shell = (self.viewer.state().shell()).ok_or("the viewer shows no shell")?;
        let replica = shell.replica();
        let (mesh, pattern) = reference(preset, spec);
        if replica.mesh_hash() != Some(mesh) || replica.pattern_hash() != pattern {
            return Err(format!(
                "{} grown on the page has mesh {:?} and pattern {:?}; alone, {mesh} and {pattern:?}",
                preset.id,
                replica.mesh_hash(),
                replica.pattern_hash()
            ));
        }
        let shown = self.session.status().shell.as_ref().ok_or("no status")?;
        if (shown.mesh_hash, shown.pattern_hash) != (Some(mesh), pattern) {
            return Err(format!("the page says {shown:?}"));
        }
        if let Some(failure) = &shown.failure {
            let times = self
                .said
                .iter()
                .filter(|(viewer, session, words)| {
                    (*viewer, *session) == (self.viewers, shown.session) && words == failure
                })
                .count();
            if times != 1 {
                return Err(format!("\"{failure}\" was said {times} times"));
            }
        }
        let uploaded = self.viewer.screen().uploaded;
        if uploaded != Some(replica.rows_done()) {
            return Err(format!(
                "the renderer holds {uploaded:?} rows of the {} grown",
                replica.rows_done()
            ));
        }
        Ok(())
    }
}

impl Page {
    /// With the faults over, the gallery shown: every card must show a picture of its whole
    /// shell within a bounded simulated time, and the page must say so (`done`).
    fn settle_gallery(&mut self) -> Result<(), Failure> {
        let mut rng = Pcg64::seed_from_u64(0);
        let deadline = self.now + 20.0 * 60_000.0;
        loop {
            if self.gone {
                // The page said why it draws no more.
                return Ok(());
            }
            let done = self.pictures.queue().signal(self.pictures.draws()) == "done";
            if done && self.cards.len() == presets().len() {
                return Ok(());
            }
            if self.now > deadline {
                let missing: Vec<&str> = presets()
                    .iter()
                    .map(|p| p.id)
                    .filter(|id| !self.cards.contains(id))
                    .collect();
                return Err(format!(
                    "the gallery's pictures were not all drawn within twenty simulated minutes \
                     (the page says {}): no picture of {missing:?}",
                    if done { "done" } else { "drawing" }
                ));
            }
            self.run_frame(1, &mut rng)?;
            self.check()?;
        }
    }
}

/// A shell's mesh hash and pattern hash.
type Hashes = (u64, Option<u64>);

/// The mesh and pattern hashes of `spec` grown alone by the native core (each shell once).
fn reference(preset: &Preset, spec: &ShellSpec) -> Hashes {
    static GROWN: OnceLock<Mutex<HashMap<String, Hashes>>> = OnceLock::new();
    let key = link::encode(preset, spec);
    let grown = GROWN.get_or_init(Mutex::default);
    if let Some(hashes) = grown.lock().unwrap().get(&key) {
        return *hashes;
    }
    let mut generator = Generator::new(spec).expect("a preset builds");
    generator.finish();
    let hashes = (generator.mesh_hash(), generator.pattern().map(|p| p.hash()));
    grown.lock().unwrap().insert(key, hashes);
    hashes
}

/// A run's steps, drawn from `seed`: mostly frames, with input and faults between them.
fn steps(seed: u64) -> (usize, Vec<Step>) {
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut pick = |n: u32| rng.next_u32() % n;
    let workers = 1 + pick(3) as usize;
    let count = 10 + pick(50);
    let mut steps = vec![Step::Open {
        shell: pick(SHELLS.len() as u32) as usize,
        finish: false,
    }];
    for _ in 0..count {
        let byte = pick(256) as u8;
        let step = match pick(50) {
            0..=14 => Step::Frames {
                count: 1 + pick(12) as u8,
                lag: pick(4) as u8,
                salt: u64::from(pick(u32::MAX)),
            },
            15..=16 => Step::Open {
                shell: pick(SHELLS.len() as u32) as usize,
                finish: pick(4) == 0,
            },
            17 => Step::Gallery,
            18 => Step::Restyle { gloss: byte },
            19..=20 => Step::Drag {
                iterations: pick(1000) as u16,
                set: pick(3) == 0,
            },
            21 => Step::OneRow,
            22 => Step::Finish,
            23 => Step::Restart,
            24 => Step::Play,
            25 => Step::Speed {
                tenths: pick(3000) as u16,
            },
            26 => Step::Views,
            27 => Step::Cover(pick(2) == 0),
            28 => Step::Record(pick(2) == 0),
            29..=30 => Step::AskFrame {
                row: pick(200) as u16,
            },
            31 => Step::Sleep {
                seconds: pick(20) as u8,
            },
            32..=33 => Step::Throw { slot: byte },
            34 => Step::Hang { slot: byte },
            35 => Step::Garble { slot: byte },
            36 => Step::Twice { slot: byte },
            37..=38 => Step::LoseDevice {
                webgl: pick(2) == 0,
                restore: pick(150) as u8,
            },
            39 => Step::Restore,
            40 => Step::FailOpen,
            41 => Step::Fallback {
                frames: pick(30) as u8,
            },
            42 => Step::HangDrawing,
            43 => Step::Story { step: byte },
            44 => Step::GpuBehind {
                frames: 1 + pick(60) as u8,
            },
            45 => Step::GpuStops,
            46 => Step::LosePictures {
                webgl: pick(2) == 0,
                restore: pick(150) as u8,
            },
            47 => Step::PictureWorker {
                slot: byte,
                fault: pick(4) as u8,
            },
            _ => Step::Twice { slot: byte },
        };
        steps.push(step);
    }
    (workers, steps)
}

/// What a run went through: renderers opened again, workers replaced, views moved to the
/// page's thread.
#[derive(Default)]
struct Went {
    reopened: usize,
    replaced: usize,
    moved: u32,
    /// Frames whose drawing waited for the GPU to catch up.
    deferred: usize,
    /// Views moved because the drawing worker said its frames stopped reaching the screen.
    failed_over: u32,
}

/// Runs `steps` on a page of `workers` workers, and lets it settle.
fn run(workers: usize, steps: &[Step]) -> Result<Went, Failure> {
    let mut page = Page::new(workers);
    for (i, step) in steps.iter().enumerate() {
        page.step(step)
            .map_err(|e| format!("at step {i} ({step:?}): {e}"))?;
    }
    page.settle().map_err(|e| format!("settling: {e}"))?;
    Ok(Went {
        reopened: page.viewer.screen().reopened,
        deferred: page.deferred + page.viewer.screen().deferred,
        failed_over: page.failed_over,
        replaced: page.workers.pool.deaths(),
        moved: page.viewers,
    })
}

/// How `steps` fail on a page of `workers` workers, a panic included; `None` if they pass.
fn failure(workers: usize, steps: &[Step]) -> Option<Failure> {
    outcome(workers, steps).err()
}

/// What `steps` went through on a page of `workers` workers, or how they failed, a panic
/// included.
fn outcome(workers: usize, steps: &[Step]) -> Result<Went, Failure> {
    match std::panic::catch_unwind(|| run(workers, steps)) {
        Ok(went) => went,
        Err(panic) => Err(format!(
            "a panic: {}",
            panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default()
        )),
    }
}

/// The shortest run found that fails as `steps` do (`failed`): steps left out, a chunk at a
/// time, for as long as the run still fails.
fn shrink(workers: usize, mut steps: Vec<Step>, mut failed: Failure) -> (Vec<Step>, Failure) {
    let mut chunk = steps.len().div_ceil(2);
    while chunk >= 1 {
        let mut at = 1;
        let mut shrunk = false;
        while at < steps.len() {
            let mut fewer = steps.clone();
            fewer.drain(at..(at + chunk).min(steps.len()));
            match failure(workers, &fewer) {
                Some(e) => {
                    steps = fewer;
                    failed = e;
                    shrunk = true;
                }
                None => at += chunk,
            }
        }
        if !shrunk {
            chunk /= 2;
        }
    }
    (steps, failed)
}

/// A number from the environment.
fn env(key: &str) -> Option<u64> {
    std::env::var(key).ok().and_then(|v| v.parse().ok())
}

#[test]
fn any_interleaving_of_replies_faults_and_input_grows_the_shell_asked_for() {
    let seeds: Vec<u64> = match env("SEASHELLS_SIM_SEED") {
        Some(seed) => vec![seed],
        None => {
            let first = env("SEASHELLS_SIM_FIRST").unwrap_or(1);
            (first..first + env("SEASHELLS_SIM_RUNS").unwrap_or(60)).collect()
        }
    };
    let mut went = Went::default();
    for &seed in &seeds {
        let (workers, steps) = steps(seed);
        match outcome(workers, &steps) {
            Ok(run) => {
                went.reopened += run.reopened;
                went.replaced += run.replaced;
                went.moved += run.moved;
                went.deferred += run.deferred;
                went.failed_over += run.failed_over;
            }
            Err(failed) => {
                // Quiet while the runs that shrink it panic in their turn.
                let hook = std::panic::take_hook();
                std::panic::set_hook(Box::new(|_| {}));
                let (shortest, failure) = shrink(workers, steps, failed);
                std::panic::set_hook(hook);
                panic!(
                    "seed {seed} fails ({workers} workers): {failure}\nthe shortest run that \
                     fails ({} steps; SEASHELLS_SIM_SEED={seed} replays it):\n{shortest:#?}",
                    shortest.len()
                );
            }
        }
    }
    if seeds.len() >= 60 {
        // The faults happen: runs that never lose a device, a worker or the drawing worker
        // would prove nothing.
        assert!(
            went.reopened > 0
                && went.replaced > 0
                && went.moved > 0
                && went.deferred > 0
                && went.failed_over > 0,
            "{} renderers opened again, {} workers replaced, {} views moved ({} when the GPU's \
             frames stopped), {} frames waited for the GPU in {} runs",
            went.reopened,
            went.replaced,
            went.moved,
            went.failed_over,
            went.deferred,
            seeds.len()
        );
    }
}

/// The shortest runs of the seeds that found bugs, kept as they were printed: each failed
/// before its fix.
#[test]
fn the_runs_that_found_bugs_grow_their_shell() {
    let frames = |count, lag, salt| Step::Frames { count, lag, salt };
    let runs = [
        // The sessions' worker's Load reply came as bytes nobody could read, and its reply to
        // the Grow sent beside the Load was still taken in: rows of a shell never built.
        (
            2,
            vec![
                Step::Open {
                    shell: 2,
                    finish: false,
                },
                Step::Garble { slot: 0 },
                Step::OneRow,
            ],
        ),
        // The sessions' worker threw before the shell's Load was sent: the Load still waiting
        // went to the fresh worker beside the one the shell asked again, and the second
        // Loaded reply took the count of answers owed below zero.
        (
            3,
            vec![
                Step::Open {
                    shell: 3,
                    finish: false,
                },
                Step::Throw { slot: 0 },
            ],
        ),
        // The worker died holding the Finish of a shell left: the shell shown was finished
        // on the fresh worker unasked, and still grown row by row after it.
        (
            1,
            vec![
                Step::Open {
                    shell: 5,
                    finish: false,
                },
                Step::Finish,
                Step::Throw { slot: 0 },
                Step::Open {
                    shell: 5,
                    finish: false,
                },
                frames(7, 1, 1_806_241_684),
            ],
        ),
    ];
    let runs = runs.into_iter().chain([
        // The only worker hung at the end of growth: the fresh one's answer that settled the
        // shell changed nothing drawn, so no frame was drawn to show it, and the page never
        // said the shell was grown.
        (
            1,
            vec![
                Step::Open {
                    shell: 2,
                    finish: false,
                },
                frames(11, 0, 1_474_110_732),
                frames(10, 2, 1_211_070_541),
                Step::Twice { slot: 212 },
                frames(12, 3, 1_837_117_431),
                frames(3, 3, 3_316_333_614),
                frames(1, 3, 1_364_195_196),
                Step::Throw { slot: 238 },
                frames(5, 0, 1_165_351_009),
                frames(8, 0, 1_236_702_955),
                Step::Hang { slot: 47 },
            ],
        ),
    ]);
    let runs = runs.into_iter().chain([
        // The drawing worker's device was lost, and its frames then stopped reaching the
        // screen: it said so and drew no more, so it never said its device was back, and the
        // page, which takes nothing in while the device is not ready, never heard the
        // failure and waited for ever.
        (
            2,
            vec![
                Step::Open {
                    shell: 4,
                    finish: false,
                },
                Step::LoseDevice {
                    webgl: true,
                    restore: 100,
                },
                Step::GpuStops,
            ],
        ),
        // A card's shell a worker still held when the gallery was left was asked again when
        // it was shown again: more requests than cards not drawn.
        (
            1,
            vec![
                Step::Open {
                    shell: 1,
                    finish: false,
                },
                Step::Gallery,
                frames(7, 0, 3_233_772_908),
                Step::Open {
                    shell: 5,
                    finish: false,
                },
                Step::Gallery,
            ],
        ),
        // The pictures' device was lost just after cards were drawn, with a shell shown under
        // the map: the cards that might be blank were asked of the pool again at once, though
        // the gallery was not shown.
        (
            3,
            vec![
                Step::Open {
                    shell: 0,
                    finish: false,
                },
                Step::Gallery,
                frames(12, 2, 1_854_103_342),
                frames(7, 2, 420_226_940),
                Step::LosePictures {
                    webgl: false,
                    restore: 15,
                },
                Step::Open {
                    shell: 5,
                    finish: true,
                },
                Step::Cover(true),
                frames(6, 1, 1_707_448_879),
            ],
        ),
    ]);
    for (workers, steps) in runs {
        assert_eq!(failure(workers, &steps), None, "{steps:#?}");
    }
}
