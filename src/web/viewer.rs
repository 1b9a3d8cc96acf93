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

use super::activity;
use super::canvases::{lose_context, object_url, png};
use super::clock::now;
use super::debug::{self, Loss};
use super::recovery::{RESTORE_WAIT_MS, Reopened, Reopening};
use super::webcodecs::{self, VideoFrame};
use super::workers::Workers;
use crate::export::Download;
use crate::export::estimate::Counts;
use crate::export::print_size::PrintSize;
use crate::generator::{Advance, GROWTH_BUDGET_MS};
use crate::mesh::Bounds;
use crate::pattern::run::planar_rows;
use crate::pattern::texture_layout::TextureLayout;
use crate::presets::Preset;
use crate::render::{Canvas, Renderer, ShellLook};
use crate::share::link;
use crate::share::presentation::Layout;
use crate::spec::ShellSpec;
use crate::view::camera::OrbitCamera;
use crate::view::draw_pacing::{DrawPacing, FrameDraw};
use crate::view::gestures::{Pointers, wheel_zoom};
use crate::view::panes::{Pane, panes};
use crate::view::playback::{Playback, growth_budget};
use crate::view::preview::PreviewState;
use crate::view::recording::FrameAsk;
use crate::work::file_writer::{FileStage, FileWriter, Needs, Source};
use crate::work::growth_session::{GrowthSession, Took};
use crate::work::message::{Reply, Request, ShellInfo, WholeShell};
use crate::work::planar_update::PlanarUpdate;
use crate::work::replica::Replica;
use crate::work::viewer_command::{PointerChange, ViewCommand};
use crate::work::viewer_status::{Device, FrameReport, ShellStatus, ViewStatus};
use glam::DVec3;
use std::cell::RefCell;
use std::rc::Rc;

/// A shell being grown (on a worker; the page holds its copy, the [`Replica`]).
struct Growing {
    preset: &'static Preset,
    spec: ShellSpec,
    /// The worker's session growing it, and the page's copy of it.
    growth: GrowthSession,
    camera: OrbitCamera,
    /// Whether the planar view shows a pattern (this shell's, or the one previewed).
    planar_open: bool,
    /// The planar view's cells and rows for this shell's pattern.
    planar_size: Option<(u32, u32)>,
    /// The pattern of values being dragged, computed by a worker and shown in the planar
    /// view while growth waits.
    preview: Option<Previewing>,
}

impl Growing {
    /// Records what is being grown, for a panic's message; a test may ask for a panic here.
    fn note_activity(&self) {
        activity::set(format!(
            "growing {}, row {}",
            self.preset.id,
            self.growth.replica().rows_done() + 1
        ));
        debug::panic_if_asked();
    }

    /// Sets `renderer` up for this shell as its worker built it: buffers, pattern texture and
    /// look. A renderer opened again after a lost device is set up the same way.
    fn load_into(&self, renderer: &mut Renderer, shell: &ShellInfo) {
        renderer.load_shell(
            shell.capacity,
            self.planar_size
                .and_then(|(cells, rows)| TextureLayout::new(cells, rows)),
            self.look(shell),
        );
    }

    /// How its spec draws this shell.
    fn look(&self, shell: &ShellInfo) -> ShellLook {
        ShellLook::new(
            &self.spec.colours,
            &self.spec.material,
            crate::forms::rows_per_whorl(&self.spec),
            shell.line_grid,
        )
    }

    /// Whether the view rests on what has grown (or where the user left it).
    fn view_at_rest(&self) -> bool {
        self.camera.settled(self.growth.replica().grown())
    }

    /// The panes of `layout` on a canvas of aspect `aspect`.
    fn panes(&self, layout: Layout, aspect: f32) -> Vec<Pane> {
        panes(layout, &self.camera, self.growth.replica().grown(), aspect)
    }

    /// What a file of it is written from.
    fn source(&self) -> Source<'_> {
        Source {
            preset: self.preset,
            spec: &self.spec,
            replica: self.growth.replica(),
        }
    }
}

/// A pattern being previewed: its session on the worker that computes it, where it stands,
/// and whether rows were asked for and not yet sent.
struct Previewing {
    session: u32,
    /// The link of the values previewed, to ask again of a fresh worker.
    link: String,
    state: PreviewState,
    pending: bool,
}

/// A renderer and the canvas it draws on.
struct Drawing {
    renderer: Renderer,
    /// An element of the page, or an offscreen canvas one handed its drawing to.
    canvas: Canvas,
    /// While frames wait for the GPU: how many it had finished when it last finished one, and
    /// when. A device that opened and finishes none of the frames handed to it for long draws
    /// nothing on the screen.
    progress: Option<(u64, f64)>,
}

impl Drawing {
    fn new(renderer: Renderer, canvas: Canvas) -> Self {
        Self {
            renderer,
            canvas,
            progress: None,
        }
    }

    /// Draws the panes of `layout` of `growing`'s shell.
    fn draw(&mut self, growing: &Growing, layout: Layout) -> Result<(), String> {
        let panes = growing.panes(layout, self.renderer.aspect());
        self.renderer.draw(&panes)
    }

    /// Why the screen shows nothing more of what is drawn: frames have waited for the GPU for
    /// [`UNSEEN_MS`] without one of them finished.
    fn unseen(&mut self) -> Option<String> {
        let (finished, unfinished) = self.renderer.frames();
        if unfinished == 0 {
            self.progress = None;
            return None;
        }
        let t = now();
        match self.progress {
            Some((seen, since)) if seen == finished => (t - since > UNSEEN_MS).then(|| {
                format!(
                    "the {} device has finished none of the frames handed to it in {} s",
                    self.renderer.backend(),
                    UNSEEN_MS / 1000.0
                )
            }),
            _ => {
                self.progress = Some((finished, t));
                None
            }
        }
    }
}

/// How long frames may wait for the GPU without one of them finished before the viewer says
/// the screen shows none of them (a frame takes well under a second, even on a software
/// rasterizer).
const UNSEEN_MS: f64 = 10_000.0;

/// Why a viewer that draws nothing gives no picture.
const NO_DRAWING: &str = "this browser draws no 3D here";

pub struct Viewer {
    /// What it draws with; none where the browser draws no 3D: the shell still grows, its
    /// pattern is shown and its files written.
    drawing: Option<Drawing>,
    /// The size the canvas is shown at, in CSS pixels, as the page last laid it out (none
    /// said yet: the drawing keeps its size).
    shown: (u32, u32),
    /// Device pixels per CSS pixel.
    pixel_ratio: f64,
    /// Whether this viewer has a planar view beside it, and what it is to show next.
    planar: bool,
    planar_updates: Vec<PlanarUpdate>,
    pointers: Pointers,
    growing: Option<Growing>,
    /// Whether the page shows something else over the shell (the gallery, the map): growth
    /// waits.
    held: bool,
    /// Whether growth advances each frame, and how fast.
    playback: Playback,
    dirty: bool,
    /// Whether this frame draws or leaves it to the next (after megabytes of uploads).
    pacing: DrawPacing,
    /// Whether the camera follows the growing shell (else it frames the whole).
    follows: bool,
    /// One view, or Kawaguchi's four.
    layout: Layout,
    /// When the last frame was drawn, milliseconds.
    last_frame: f64,
    /// The drawing size a recording asks for, instead of the canvas's own: while it is set,
    /// the viewer grows and draws only the frames the recording asks for.
    fixed_size: Option<(u32, u32)>,
    /// A recording's video frame asked for and not yet drawn.
    asked: Option<FrameAsk>,
    /// A recording's video frame drawn and not yet taken.
    recorded: Option<Result<VideoFrame, String>>,
    /// Where the shells grow.
    workers: Rc<RefCell<Workers>>,
    /// The last session started (each load starts one; replies of older ones are dropped).
    session: u32,
    /// Loads the page asked for ([`FrameReport::loads`]).
    loads: u32,
    /// The clear colour, as sRGB bytes (for a renderer opened again).
    background: [u8; 3],
    /// A renderer being opened after the device was lost, and when the loss was seen.
    reopening: Option<Reopening>,
    lost_at: Option<f64>,
    /// Why no renderer could be opened again: the viewer draws no more.
    gone: Option<String>,
    /// The picture asked for as a file, once the browser has read it from the canvas.
    picture_read: Rc<RefCell<Option<Result<String, String>>>>,
    /// Words for the page to show, until it takes them (the viewer writes no words on the page
    /// itself).
    notice: Option<String>,
    /// A file of the shell being written.
    writer: FileWriter,
}

/// What a frame of the viewer gives the page (see [`Viewer::run_frame`]): what a worker would
/// post of it, and a recording's video frame.
pub struct ViewFrame {
    pub report: FrameReport,
    /// A recording's video frame asked for, drawn (or why it could not be).
    pub recorded: Option<Result<VideoFrame, String>>,
    /// Made after the page's last load reached the viewer ([`FrameReport::loads`]): its status
    /// and drawing are of the shell the page shows. Always so on the page's thread.
    pub current: bool,
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
            shown: (0, 0),
            pixel_ratio: 1.0,
            planar,
            planar_updates: Vec::new(),
            pointers: Pointers::default(),
            growing: None,
            held: false,
            playback: Playback::new(1.0),
            dirty: true,
            pacing: DrawPacing::default(),
            follows,
            layout: Layout::Single,
            last_frame: now(),
            fixed_size: None,
            asked: None,
            recorded: None,
            workers,
            session: 0,
            loads: 0,
            background,
            reopening: None,
            lost_at: None,
            gone: None,
            picture_read: Rc::default(),
            notice: None,
            writer: FileWriter::default(),
        }
    }

    /// Loads the page asked for ([`FrameReport::loads`]).
    pub fn loads(&self) -> u32 {
        self.loads
    }

    /// "WebGPU" or "WebGL2", or `None` where it draws nothing.
    pub fn backend(&self) -> Option<&'static str> {
        self.drawing.as_ref().map(|d| d.renderer.backend())
    }

    /// Follows a change of the page's theme.
    fn set_background(&mut self, srgb: [u8; 3]) {
        self.background = srgb;
        if let Some(d) = &mut self.drawing {
            d.renderer.set_background(srgb);
        }
        self.dirty = true;
    }

    /// Does what the page asks (see [`ViewCommand`]).
    pub fn command(&mut self, command: ViewCommand) {
        match command {
            ViewCommand::Load { shell, finish } => {
                self.loads = self.loads.wrapping_add(1);
                self.load(shell.preset, &shell.spec);
                if finish {
                    self.finish();
                }
            }
            ViewCommand::Restyle(shell) => self.restyle(&shell.spec),
            ViewCommand::Preview(link) => self.preview(link),
            ViewCommand::EndPreview => self.end_preview(),
            ViewCommand::Grow(rows) => self.grow(rows, GROWTH_BUDGET_MS),
            ViewCommand::Finish => self.finish(),
            ViewCommand::Play(playing) => self.playback.playing = playing,
            ViewCommand::Hold(held) => self.held = held,
            ViewCommand::Speed(speed) => self.playback.speed = speed,
            ViewCommand::Layout(layout) => {
                self.layout = layout;
                self.dirty = true;
            }
            ViewCommand::ResetCamera => self.reset_camera(),
            ViewCommand::Pointer(change) => self.pointer(change),
            ViewCommand::Wheel(delta) => {
                if let Some(camera) = self.camera_mut() {
                    camera.zoom_by(wheel_zoom(delta));
                }
            }
            ViewCommand::Shown {
                width,
                height,
                pixel_ratio,
            } => {
                self.shown = (width, height);
                self.pixel_ratio = pixel_ratio;
            }
            ViewCommand::Background(srgb) => self.set_background(srgb),
            ViewCommand::RecordAt(size) => self.record_at(size),
            ViewCommand::AskFrame(ask) => self.asked = Some(ask),
            ViewCommand::WriteFile { what, size } => self.write_file(what, size),
        }
    }

    /// Drops the shell (after one that could not be built): nothing is drawn or grown.
    pub fn unload(&mut self) {
        self.growing = None;
    }

    /// Starts growing `spec` from its apex on a worker, dropping the shell grown before and
    /// the work still waiting for it; nothing more of it reaches the screen. The worker's
    /// answer comes in a later frame ([`Self::take`]).
    fn load(&mut self, preset: &'static Preset, spec: &ShellSpec) {
        activity::set(format!("loading {}", preset.id));
        self.session = self.session.wrapping_add(1);
        let link = link::encode(preset, spec);
        let mut workers = self.workers.borrow_mut();
        workers.cancel(|r| matches!(r, Request::Pieces { .. }));
        let growth = GrowthSession::load(self.session, link, &mut |r| workers.submit(r));
        self.playback.restart(spec.growth.speed);
        // Framed on a unit box until the worker says what the shell is.
        let placeholder = Bounds {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        };
        self.growing = Some(Growing {
            preset,
            spec: spec.clone(),
            growth,
            camera: OrbitCamera::framing(&placeholder, DVec3::Z, 0.0, 0.0),
            planar_open: false,
            planar_size: None,
            preview: None,
        });
        self.dirty = true;
    }

    /// Draws the shell grown so far in the material of `spec` (which grows it as the loaded
    /// spec does). The worker's link stays: the worker never reads the material.
    fn restyle(&mut self, spec: &ShellSpec) {
        let Some(g) = &mut self.growing else { return };
        g.spec.material = spec.material.clone();
        if let (Some(d), Some(shell)) = (&mut self.drawing, g.growth.replica().shell()) {
            d.renderer.set_look(g.look(shell));
        }
        self.dirty = true;
    }

    /// Shows a shell grown whole on a worker (a gallery picture), at rest.
    pub fn show_whole(&mut self, preset: &'static Preset, spec: &ShellSpec, whole: WholeShell) {
        self.session = self.session.wrapping_add(1);
        let shell = whole.shell.clone();
        let replica = Replica::whole(self.session, whole);
        let everything = replica.everything();
        self.growing = Some(Growing {
            preset,
            spec: spec.clone(),
            growth: GrowthSession::whole(replica),
            camera: OrbitCamera::framing(&shell.bounds, shell.front, 0.0, 0.0),
            planar_open: false,
            planar_size: None,
            preview: None,
        });
        self.loaded(shell, everything);
    }

    /// The shell is built on its worker: sets up the renderer, the camera and the planar view
    /// for it, and shows its first step.
    fn loaded(&mut self, shell: ShellInfo, advance: Advance) {
        let Some(g) = &mut self.growing else { return };
        let pattern = (shell.cells > 0).then_some((shell.cells, g.spec.growth.rows));
        g.planar_size = pattern;
        if let Some(d) = &mut self.drawing {
            g.load_into(&mut d.renderer, &shell);
        }
        let grown = *g.growth.replica().grown();
        let mut camera = OrbitCamera::framing(
            &shell.bounds,
            shell.front,
            g.preset.view.yaw.to_radians(),
            g.preset.view.pitch.to_radians(),
        );
        if self.follows {
            camera = camera.following(&grown);
        }
        g.camera = camera;
        g.planar_open = self.planar && pattern.is_some();
        if self.planar {
            self.planar_updates.push(PlanarUpdate::Open(pattern));
        }
        self.upload(&advance);
    }

    /// Takes in a worker's reply to `request`: a reply about another shell than this one's is
    /// dropped. Fails with the words to show when the shell cannot be built or grown.
    pub fn take(&mut self, request: &Request, reply: Reply) -> Result<(), String> {
        let Some(g) = &mut self.growing else {
            return Ok(());
        };
        let mut workers = self.workers.borrow_mut();
        let took = g.growth.take(request, reply, &mut |r| workers.submit(r))?;
        drop(workers);
        match took {
            Took::Nothing => return Ok(()),
            Took::Loaded(shell, advance) => self.loaded(shell, advance),
            Took::Advanced(advance) => self.upload(&advance),
            Took::Previewed(reply) => {
                let rows = g.spec.growth.rows;
                self.previewed(*reply, rows);
            }
        }
        self.dirty = true;
        Ok(())
    }

    /// The worker holding the shell was replaced, losing `lost` unanswered: the shell is grown
    /// again on the fresh one to where the page's copy stands, a pattern being previewed is
    /// previewed again from its first row, and what was lost asked again.
    pub fn resume(&mut self, lost: Vec<Request>) {
        let Some(g) = &mut self.growing else { return };
        let mut workers = self.workers.borrow_mut();
        if let Some(p) = &mut g.preview
            && p.state == PreviewState::Filling
        {
            workers.submit(Request::Preview {
                session: p.session,
                link: p.link.clone(),
            });
            p.pending = true;
        }
        g.growth.resume(&lost, &mut |r| workers.submit(r));
    }

    fn upload(&mut self, advance: &Advance) {
        let Some(g) = &mut self.growing else { return };
        let replica = g.growth.replica();
        let row = replica.cells() * 4;
        let rgba = &replica.rgba()[advance.rows.start * row..advance.rows.end * row];
        if let Some(d) = &mut self.drawing {
            d.renderer.set_ground(replica.grown());
            self.pacing.uploaded(d.renderer.upload(
                replica.mesh(),
                replica.edge().mesh(),
                advance,
                rgba,
            ));
        }
        if g.planar_open {
            self.planar_updates.extend([
                PlanarUpdate::Rows {
                    first: advance.rows.start as u32,
                    rgba: replica.planar(advance.rows.clone()),
                },
                PlanarUpdate::Follow(advance.rows.end as u32),
            ]);
        }
    }

    /// Shows the whole pattern of the shell of `link` in the planar view, computed by a worker
    /// over the next frames, while the shell's growth waits (until [`Self::end_preview`] or
    /// another spec is loaded). Values that give no pattern at all are refused with the reason,
    /// in a message, when the worker answers.
    fn preview(&mut self, link: String) {
        let Some(g) = &mut self.growing else { return };
        self.session = self.session.wrapping_add(1);
        self.workers.borrow_mut().submit(Request::Preview {
            session: self.session,
            link: link.clone(),
        });
        g.preview = Some(Previewing {
            session: self.session,
            link,
            state: PreviewState::Filling,
            pending: true,
        });
    }

    /// Takes in rows of the pattern previewed (`first..` of `cells` cells, `rows` in all).
    fn previewed(&mut self, reply: Reply, rows: u32) {
        let Reply::Previewed {
            session,
            cells,
            first,
            rgba,
            widths,
            state,
            failure,
        } = reply
        else {
            return;
        };
        let Some(g) = &mut self.growing else { return };
        let Some(p) = g.preview.as_mut().filter(|p| p.session == session) else {
            return;
        };
        p.pending = false;
        p.state = state;
        if let Some(message) = failure {
            self.notice = Some(message);
        }
        if cells == 0 {
            return;
        }
        if !self.planar {
            return;
        }
        if first == 0 {
            g.planar_open = true;
            self.planar_updates
                .push(PlanarUpdate::Open(Some((cells, rows))));
        }
        let rgba = planar_rows(&rgba, &widths, cells as usize);
        self.planar_updates.push(PlanarUpdate::Rows { first, rgba });
    }

    /// Back from a preview to the growing shell's own pattern in the planar view.
    fn end_preview(&mut self) {
        let Some(g) = &mut self.growing else { return };
        if g.preview.take().is_none() {
            return;
        }
        if !self.planar {
            return;
        }
        g.planar_open = g.planar_size.is_some();
        self.planar_updates.push(PlanarUpdate::Open(g.planar_size));
        if g.planar_open {
            let replica = g.growth.replica();
            self.planar_updates.extend([
                PlanarUpdate::Rows {
                    first: 0,
                    rgba: replica.planar(0..replica.rgba().len() / (replica.cells() * 4).max(1)),
                },
                PlanarUpdate::Follow((replica.rgba().len() / (replica.cells() * 4).max(1)) as u32),
            ]);
        }
    }

    /// What the page shows of this viewer: where its shell stands, and the preview.
    fn status(&self) -> ViewStatus {
        let Some(g) = &self.growing else {
            return ViewStatus::default();
        };
        let r = g.growth.replica();
        let (mesh, edge) = (r.mesh(), r.edge());
        ViewStatus {
            shell: r.shell().map(|_| ShellStatus {
                session: r.session(),
                rows_done: r.rows_done(),
                rows: r.rows(),
                done: r.is_done(),
                settled: g.growth.settled(),
                at_rest: g.view_at_rest(),
                failure: r.failure().map(str::to_string),
                pattern_hash: r.pattern_hash(),
                mesh_hash: r.mesh_hash(),
                counts: Counts {
                    vertices: mesh.vertices.len() + edge.vertex_count(),
                    triangles: mesh.triangle_count() + edge.triangle_count(),
                    pattern: (r.cells() > 0).then(|| (r.cells(), r.rgba().len() / (r.cells() * 4))),
                    picture: {
                        let (width, height) =
                            self.drawing.as_ref().map_or((0, 0), |d| d.canvas.size());
                        (width as usize, height as usize)
                    },
                },
            }),
            preview: g.preview.as_ref().map(|p| p.state),
        }
    }

    /// Keeps a graphics device: when the browser took the renderer's away, opens another in
    /// the background (on the same canvas, or a fresh one; see `recovery.rs`) and, once it is
    /// open, uploads the shell grown so far to it. Called once a frame before anything is drawn.
    pub fn survive(&mut self) -> Device {
        if let Some(gone) = &self.gone {
            return Device::Gone(gone.clone());
        }
        let reason = self.loss_reason();
        if let Some(reopening) = &mut self.reopening {
            return match reopening.take() {
                None if reopening.needs_canvas() => Device::NeedsCanvas(reason),
                None => Device::Reopening(reason),
                Some(Ok(reopened)) => {
                    self.reopening = None;
                    self.lost_at = None;
                    let backend = reopened.renderer.backend().to_string();
                    self.install(reopened);
                    Device::Reopened(backend)
                }
                Some(Err(e)) => {
                    self.reopening = None;
                    let gone = format!(
                        "The graphics device was lost ({reason}) and none could be opened again: \
                         {e}"
                    );
                    self.gone = Some(gone.clone());
                    Device::Gone(gone)
                }
            };
        }
        let Some(d) = &self.drawing else {
            return Device::Ready;
        };
        let Some(loss) = d.renderer.lost() else {
            return Device::Ready;
        };
        let since = *self.lost_at.get_or_insert_with(now);
        let webgl = d.renderer.backend() == "WebGL2";
        if webgl && !loss.restored && now() - since < RESTORE_WAIT_MS {
            // The browser may give the context back (webglcontextrestored): wait a little.
            return Device::Reopening(loss.reason);
        }
        self.reopening = Some(Reopening::start(d.canvas.clone(), webgl && !loss.restored));
        Device::Reopening(loss.reason)
    }

    fn loss_reason(&self) -> String {
        self.drawing
            .as_ref()
            .and_then(|d| d.renderer.lost())
            .map_or_else(|| "no reason given".to_string(), |l| l.reason)
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
        let everything = self.growing.as_ref().and_then(|g| {
            let shell = g.growth.replica().shell()?;
            g.load_into(&mut drawing.renderer, shell);
            Some(g.growth.replica().everything())
        });
        if let Some(everything) = everything {
            self.upload(&everything);
        }
        self.dirty = true;
    }

    /// The fresh canvas the viewer asked for ([`Device::NeedsCanvas`]), to open a renderer
    /// on.
    pub fn give_canvas(&mut self, canvas: Canvas) {
        if let Some(reopening) = &mut self.reopening {
            reopening.give_canvas(canvas);
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

    /// Asks the shell's worker to grow up to `rows` rows, stopping early when `budget_ms`
    /// has passed.
    fn grow(&mut self, rows: usize, budget_ms: f64) {
        self.end_preview();
        let Some(g) = &mut self.growing else { return };
        if !g.growth.grows_on() {
            return;
        }
        g.note_activity();
        let rows = u32::try_from(rows).unwrap_or(u32::MAX);
        let mut workers = self.workers.borrow_mut();
        g.growth.grow(rows, budget_ms, &mut |r| workers.submit(r));
    }

    /// Asks the shell's worker to grow the rest of the shell at once (what splits is shared
    /// among the pool when it answers).
    fn finish(&mut self) {
        self.end_preview();
        let Some(g) = &mut self.growing else { return };
        if !g.growth.grows_on() {
            return;
        }
        g.note_activity();
        let mut workers = self.workers.borrow_mut();
        g.growth.finish(&mut |r| workers.submit(r));
    }

    /// Keeps the drawing buffer at the canvas's size in device pixels (its size as the page
    /// last said it was laid out).
    fn fit_canvas(&mut self) {
        let scale = |n: u32| (f64::from(n) * self.pixel_ratio).round() as u32;
        let (width, height) = self
            .fixed_size
            .unwrap_or((scale(self.shown.0), scale(self.shown.1)));
        if let Some(d) = &mut self.drawing
            && width > 0
            && height > 0
            && (width, height) != d.canvas.size()
        {
            d.canvas.set_size((width, height));
            d.renderer.resize(width, height);
            self.dirty = true;
        }
    }

    /// One animation frame, once the device is ready ([`Self::survive`]) and the shell's
    /// replies are taken in ([`Self::take`]): works on a file asked for, grows and draws (unless
    /// held, [`ViewCommand::Hold`]: the page shows something else over the shell), and says
    /// what the page is to show. Fails with the words to show when the renderer failed.
    pub fn run_frame(&mut self) -> Result<ViewFrame, String> {
        let file = self.work_file();
        let drawn = !self.held && self.frame(GROWTH_BUDGET_MS)?;
        Ok(ViewFrame {
            report: FrameReport {
                loads: self.loads,
                file,
                drawn,
                status: self.status(),
                notice: self.notice.take(),
                planar: std::mem::take(&mut self.planar_updates),
            },
            recorded: self.recorded.take(),
            current: true,
        })
    }

    /// Grows at the current speed within `budget_ms` (stretched when frames come slowly, see
    /// [`growth_budget`]), or towards a recording's frame, and draws if anything changed.
    /// Returns whether a frame was drawn.
    fn frame(&mut self, budget_ms: f64) -> Result<bool, String> {
        if let Some(d) = &mut self.drawing {
            if let Some(failure) = d.renderer.failure() {
                return Err(failure);
            }
            if let Some(why) = d.unseen() {
                return Err(format!("Nothing drawn reaches the screen: {why}."));
            }
            if self.reopening.is_some() || d.renderer.lost().is_some() {
                return Ok(false);
            }
        }
        if self.fixed_size.is_some() {
            self.work_recording(budget_ms);
            return Ok(false);
        }
        self.fit_canvas();
        if let Some(g) = &mut self.growing
            && let Some(preview) = &mut g.preview
            && preview.state == PreviewState::Filling
            && !preview.pending
        {
            self.workers.borrow_mut().submit(Request::Fill {
                session: preview.session,
                budget_ms,
            });
            preview.pending = true;
        }
        let growing = self.growing.as_ref().is_some_and(|g| {
            g.growth.replica().shell().is_some()
                && !g.growth.replica().is_done()
                && g.preview.is_none()
        });
        let settled = self.growing.as_ref().is_some_and(|g| g.growth.settled());
        if let Some(rows) = self.playback.rows_to_ask(growing, settled) {
            let frame = growth_budget(budget_ms, now() - self.last_frame);
            let budget = self.workers.borrow().growth_budget(frame);
            self.grow(rows, budget);
        }
        let time = now();
        let dt = ((time - self.last_frame) / 1000.0) as f32;
        self.last_frame = time;
        if let Some(g) = &mut self.growing
            && g.camera.follow(g.growth.replica().grown(), dt)
        {
            self.dirty = true;
        }
        let pacing = self.pacing.frame(self.dirty);
        if !self.dirty {
            return Ok(false);
        }
        let Some(g) = self
            .growing
            .as_ref()
            .filter(|g| g.growth.replica().shell().is_some())
        else {
            return Ok(false);
        };
        let Some(d) = &mut self.drawing else {
            // Nothing to draw on: what changed is shown all the same (the planar view, the
            // status).
            self.dirty = false;
            return Ok(true);
        };
        // After megabytes of uploads, or while the GPU still works on earlier frames, the
        // drawing waits (the uploads go to the GPU meanwhile).
        if pacing == FrameDraw::Defer || !d.renderer.ready() {
            d.renderer.flush();
            return Ok(false);
        }
        d.draw(g, self.layout)?;
        self.dirty = false;
        Ok(true)
    }

    /// Back to the first view: following the growth again on the main view.
    fn reset_camera(&mut self) {
        let follows = self.follows;
        if let Some(camera) = self.camera_mut() {
            camera.reset(follows);
        }
    }

    /// The camera of the shell being grown.
    fn camera_mut(&mut self) -> Option<&mut OrbitCamera> {
        self.dirty = true;
        self.growing.as_mut().map(|g| &mut g.camera)
    }

    /// A pointer pressed, moved (turning or zooming the camera), or let go.
    fn pointer(&mut self, change: PointerChange) {
        match change {
            PointerChange::Down { id, x, y } => self.pointers.press(id, x, y),
            PointerChange::Move { id, x, y } => {
                let height = self.shown.1.max(1) as f32;
                if let Some(g) = &mut self.growing
                    && self.pointers.moved(id, x, y, height, &mut g.camera)
                {
                    self.dirty = true;
                }
            }
            PointerChange::Up { id } => self.pointers.release(id),
        }
    }

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
        let Some(g) = &self.growing else {
            return Err("nothing is drawn yet".into());
        };
        d.draw(g, self.layout)?;
        png(&d.canvas)
    }

    /// Starts writing the file `what` of the shell shown (GLB and 3MF at `size`), over the
    /// next frames ([`Self::work_file`]); an implicit shell still growing is finished first.
    fn write_file(&mut self, what: Download, size: PrintSize) {
        if self.writer.busy() {
            return;
        }
        let source = self.growing.as_ref().map(Growing::source);
        match self.writer.start(what, size, source) {
            Needs::Nothing => {}
            Needs::Finish => self.finish(),
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
    fn work_file(&mut self) -> Option<FileStage> {
        if let Some(read) = self.picture_read.borrow_mut().take() {
            self.writer.picture_taken(read);
        }
        self.writer
            .work(self.growing.as_ref().map(Growing::source), &now)
    }

    /// Records at `size` pixels, whatever the canvas's size on the page: growth and drawing follow the frames asked for
    /// ([`Self::ask_frame`]) instead of the playback. With `None`, back to the canvas's size
    /// and the playback; a frame asked for or drawn and not taken is dropped.
    fn record_at(&mut self, size: Option<(u32, u32)>) {
        self.fixed_size = size;
        if size.is_none() {
            self.asked = None;
            if let Some(Ok(frame)) = self.recorded.take() {
                frame.close();
            }
        }
        self.dirty = true;
    }

    /// A recording's part of an animation frame: grows towards the frame asked for within
    /// `budget_ms` and, once the shell stands exactly there (its shape caught up with the
    /// rows) or has ended, draws and reads it.
    fn work_recording(&mut self, budget_ms: f64) {
        let Some(ask) = self.asked else { return };
        let Some(g) = &self.growing else {
            self.asked = None;
            self.recorded = Some(Err("no shell is loaded".into()));
            return;
        };
        if !g.growth.settled() {
            return;
        }
        let r = g.growth.replica();
        let there = r.is_done() || (r.rows_done() >= ask.row && r.caught_up());
        if !there {
            let behind = ask.row.saturating_sub(r.rows_done());
            self.grow(behind, budget_ms);
            return;
        }
        self.asked = None;
        self.recorded = Some(self.draw_recorded(&ask));
    }

    /// Draws the frame `ask` asks for and reads it as a video frame.
    fn draw_recorded(&mut self, ask: &FrameAsk) -> Result<VideoFrame, String> {
        self.fit_canvas();
        let Some(g) = &mut self.growing else {
            return Err("no shell is loaded".into());
        };
        g.camera.follow(g.growth.replica().grown(), ask.dt);
        g.camera.yaw += ask.turn;
        let d = self.drawing.as_mut().ok_or(NO_DRAWING)?;
        d.draw(g, self.layout)?;
        self.last_frame = now();
        self.dirty = false;
        let init = webcodecs::object(&[
            ("timestamp", (ask.timestamp_us as f64).into()),
            ("duration", (ask.duration_us as f64).into()),
        ]);
        VideoFrame::new(d.canvas.as_js(), &init)
            .map_err(|e| format!("the canvas could not be read ({})", webcodecs::describe(&e)))
    }
}
