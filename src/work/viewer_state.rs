//! The viewer's core state: everything a viewer decides without a canvas. It holds the shell
//! being grown (its [`GrowthSession`], camera and planar view), the playback, the preview of a
//! pattern being dragged and a recording's frame asked for; it takes the page's
//! [`ViewCommand`]s and the workers' replies, asks the pool for rows, and says what the
//! renderer is to take ([`ScreenChange`]) and when a picture is due. The web runner
//! (`web/viewer/`) owns the renderer and applies what this returns, on the page's thread or
//! in the drawing worker; the simulator (`tests/simulator.rs`) runs this same state against
//! simulated workers, clocks and faults.

use super::file_writer::Source;
use super::growth_session::{GrowthSession, Took};
use super::message::{Reply, Request, ShellInfo, WholeShell};
use super::planar_update::PlanarUpdate;
use super::pool::Pool;
use super::replica::Replica;
use super::viewer_command::{PointerChange, ViewCommand};
use super::viewer_status::{ShellStatus, ViewStatus};
use crate::export::estimate::Counts;
use crate::generator::{Advance, EdgeRuns};
use crate::mesh::Bounds;
use crate::pattern::run::planar_rows;
use crate::presets::{Preset, View};
use crate::share::link;
use crate::share::presentation::Layout;
use crate::spec::ShellSpec;
use crate::view::camera::OrbitCamera;
use crate::view::gestures::{Pointers, wheel_zoom};
use crate::view::panes::{Pane, panes};
use crate::view::playback::{Playback, growth_budget};
use crate::view::preview::PreviewState;
use crate::view::recording::FrameAsk;
use glam::DVec3;

/// What the renderer is to take from the shell shown, in the order it changed, read from the
/// state as it stands when it is applied (after the call that made it: growth taken in from
/// several replies is one [`ScreenChange::Rows`]).
#[derive(Clone, Debug, PartialEq)]
pub enum ScreenChange {
    /// The shell was built: buffers of its capacity, its pattern texture and its look.
    Shell,
    /// Its material changed: the same geometry in another look.
    Look,
    /// Growth moved on by this: upload it.
    Rows(Advance),
}

/// The shell being grown (on a worker; the page holds its copy, the [`Replica`]).
pub struct Growing {
    preset: &'static Preset,
    spec: ShellSpec,
    /// The worker's session growing it, and the page's copy of it.
    growth: GrowthSession,
    camera: OrbitCamera,
    /// The first view, relative to the opening: the preset's, or the one asked for.
    view: View,
    /// Whether the planar view shows a pattern (this shell's, or the one previewed).
    planar_open: bool,
    /// The planar view's cells and rows for this shell's pattern.
    planar_size: Option<(u32, u32)>,
    /// The pattern of values being dragged, computed by a worker and shown in the planar view
    /// while growth waits.
    preview: Option<Previewing>,
}

impl Growing {
    pub fn preset(&self) -> &'static Preset {
        self.preset
    }

    /// The spec it is drawn in (its material follows restyles).
    pub fn spec(&self) -> &ShellSpec {
        &self.spec
    }

    /// The page's copy of the shell.
    pub fn replica(&self) -> &Replica {
        self.growth.replica()
    }

    /// The cells and rows of its pattern texture, if it has a pattern.
    pub fn pattern_size(&self) -> Option<(u32, u32)> {
        self.planar_size
    }

    /// The panes of `layout` on a canvas of aspect `aspect`.
    pub fn panes(&self, layout: Layout, aspect: f32) -> Vec<Pane> {
        panes(layout, &self.camera, self.growth.replica().grown(), aspect)
    }

    /// What a file of it is written from.
    pub fn source(&self) -> Source<'_> {
        Source {
            preset: self.preset,
            spec: &self.spec,
            replica: self.growth.replica(),
        }
    }

    /// Whether the view rests on what has grown (or where the user left it).
    fn view_at_rest(&self) -> bool {
        self.camera.settled(self.growth.replica().grown())
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

/// What a viewer decides, without its renderer.
pub struct ViewerState {
    growing: Option<Growing>,
    /// Whether this viewer has a planar view beside it, and what it is to show next.
    planar: bool,
    planar_updates: Vec<PlanarUpdate>,
    /// What the renderer is to take, until the runner applies it.
    screen: Vec<ScreenChange>,
    /// Whether the camera follows the growing shell (else it frames the whole).
    follows: bool,
    /// Whether the page shows something else over the shell (the gallery, the map): growth
    /// waits.
    held: bool,
    /// Whether growth advances each frame, and how fast.
    playback: Playback,
    /// Something changed since the last picture.
    dirty: bool,
    /// One view, or Kawaguchi's four.
    layout: Layout,
    pointers: Pointers,
    /// The size the canvas is shown at, in CSS pixels, as the page last laid it out, and the
    /// device pixels in each.
    shown: (u32, u32),
    pixel_ratio: f64,
    /// The drawing size a recording asks for, instead of the canvas's own: while it is set,
    /// the viewer grows and draws only the frames the recording asks for.
    recording: Option<(u32, u32)>,
    /// A recording's video frame asked for and not yet drawn.
    asked: Option<FrameAsk>,
    /// When the last frame was run, milliseconds.
    last_frame: f64,
    /// Loads the page asked for ([`super::viewer_status::FrameReport::loads`]).
    loads: u32,
    /// Words for the page to show, until it takes them.
    notice: Option<String>,
    /// Whether growth was asked of the shell's worker since the runner last looked.
    grew: bool,
}

impl ViewerState {
    /// A viewer with nothing loaded, with a planar view beside it or not, whose camera follows
    /// the growing shell or frames it whole; `now` is the clock's reading, milliseconds.
    pub fn new(planar: bool, follows: bool, now: f64) -> Self {
        Self {
            growing: None,
            planar,
            planar_updates: Vec::new(),
            screen: Vec::new(),
            follows,
            held: false,
            playback: Playback::new(1.0),
            dirty: true,
            layout: Layout::Single,
            pointers: Pointers::default(),
            shown: (0, 0),
            pixel_ratio: 1.0,
            recording: None,
            asked: None,
            last_frame: now,
            loads: 0,
            notice: None,
            grew: false,
        }
    }

    /// The shell shown, if any.
    pub fn shell(&self) -> Option<&Growing> {
        self.growing.as_ref()
    }

    /// Loads the page asked for.
    pub fn loads(&self) -> u32 {
        self.loads
    }

    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// Whether the page shows something else over the shell: nothing grows or is drawn.
    pub fn held(&self) -> bool {
        self.held
    }

    /// Whether something changed since the last picture.
    pub fn dirty(&self) -> bool {
        self.dirty
    }

    /// Something the renderer holds changed (a fresh device, a resized canvas, a new clear
    /// colour): the next frame draws.
    pub fn touch(&mut self) {
        self.dirty = true;
    }

    /// The picture was drawn as it stands. The time between frames still counts from the
    /// start of the last frame: where drawing holds the thread (WebGL on the page's thread, a
    /// software rasterizer), the camera eases by the wall time that passed, drawing included,
    /// and settles in as many seconds as it would at 60 frames a second.
    pub fn drawn(&mut self) {
        self.dirty = false;
    }

    /// A recording's frame was drawn at `now`: the next frame's interval counts from it, for
    /// a recording grows and turns the camera by its plan, not by the clock.
    pub fn recorded(&mut self, now: f64) {
        self.drawn();
        self.last_frame = self.last_frame.max(now);
    }

    /// Whether a recording holds the drawing size (see [`ViewCommand::RecordAt`]).
    pub fn recording(&self) -> bool {
        self.recording.is_some()
    }

    /// The size to keep the drawing buffer at, in device pixels: a recording's, or the canvas's
    /// as the page last laid it out (`None`: nothing said yet, or laid out empty).
    pub fn drawing_size(&self) -> Option<(u32, u32)> {
        let scale = |n: u32| (f64::from(n) * self.pixel_ratio).round() as u32;
        let (width, height) = self
            .recording
            .unwrap_or((scale(self.shown.0), scale(self.shown.1)));
        (width > 0 && height > 0).then_some((width, height))
    }

    /// What the renderer is to take, in order (see [`ScreenChange`]).
    pub fn take_screen(&mut self) -> Vec<ScreenChange> {
        std::mem::take(&mut self.screen)
    }

    /// What the planar view is to show next.
    pub fn take_planar(&mut self) -> Vec<PlanarUpdate> {
        std::mem::take(&mut self.planar_updates)
    }

    /// Words for the page to show (why a preview stopped).
    pub fn take_notice(&mut self) -> Option<String> {
        self.notice.take()
    }

    /// Whether growth was asked of the shell's worker since the last call: the runner notes
    /// what is being grown (for a crash's message).
    pub fn take_grew(&mut self) -> bool {
        std::mem::take(&mut self.grew)
    }

    /// Does what the page asks (see [`ViewCommand`]) of the state, asking `pool` for what it
    /// needs. A command the runner has its own part of (the clear colour, a recording's size,
    /// a file) is handed back after the state's part is done.
    pub fn command(&mut self, command: ViewCommand, pool: &mut Pool) -> Option<ViewCommand> {
        match command {
            ViewCommand::Load { shell, finish } => {
                self.loads = self.loads.wrapping_add(1);
                self.load(shell.preset, &shell.spec, pool);
                if finish {
                    self.finish(pool);
                }
            }
            ViewCommand::Restyle(shell) => self.restyle(&shell.spec),
            ViewCommand::Preview(link) => self.preview(link, pool),
            ViewCommand::EndPreview => self.end_preview(),
            ViewCommand::Grow(rows) => {
                let rows = u32::try_from(rows).unwrap_or(u32::MAX);
                self.grow(rows, crate::generator::GROWTH_BUDGET_MS, pool);
            }
            ViewCommand::Finish => self.finish(pool),
            ViewCommand::Play(playing) => self.playback.playing = playing,
            ViewCommand::Hold(held) => self.held = held,
            ViewCommand::Speed(speed) => {
                // The shell's spec follows, so that its files carry the speed it is shown at.
                self.playback.speed = speed;
                if let Some(g) = &mut self.growing {
                    g.spec.growth.speed = speed;
                }
            }
            ViewCommand::Layout(layout) => {
                self.layout = layout;
                self.dirty = true;
            }
            ViewCommand::ResetCamera => {
                let follows = self.follows;
                if let Some(g) = &mut self.growing {
                    g.camera.reset(follows);
                }
                self.dirty = true;
            }
            ViewCommand::Turn(view) => {
                if let Some(g) = &mut self.growing {
                    g.view = view;
                    if g.growth.replica().shell().is_some() {
                        let (yaw, pitch) = (view.yaw.to_radians(), view.pitch.to_radians());
                        g.camera = g.camera.turned(yaw, pitch);
                    }
                }
                self.dirty = true;
            }
            ViewCommand::Pointer(change) => self.pointer(change),
            ViewCommand::Wheel(delta) => {
                if let Some(g) = &mut self.growing {
                    g.camera.zoom_by(wheel_zoom(delta));
                }
                self.dirty = true;
            }
            ViewCommand::Shown {
                width,
                height,
                pixel_ratio,
            } => {
                self.shown = (width, height);
                self.pixel_ratio = pixel_ratio;
            }
            ViewCommand::AskFrame(ask) => self.asked = Some(ask),
            ViewCommand::RecordAt(size) => {
                self.recording = size;
                if size.is_none() {
                    self.asked = None;
                }
                self.dirty = true;
                return Some(ViewCommand::RecordAt(size));
            }
            ViewCommand::Background(srgb) => {
                self.dirty = true;
                return Some(ViewCommand::Background(srgb));
            }
            command @ ViewCommand::WriteFile { .. } => return Some(command),
        }
        None
    }

    /// Drops the shell (after one that could not be built): nothing is drawn or grown.
    pub fn unload(&mut self) {
        self.growing = None;
    }

    /// Starts growing `spec` from its apex on a worker under a session the pool never gave
    /// before, dropping the shell grown before and the pieces still waiting for it: nothing
    /// more of it reaches the screen. The worker's answer comes in a later frame.
    fn load(&mut self, preset: &'static Preset, spec: &ShellSpec, pool: &mut Pool) {
        let link = link::encode(preset, spec);
        pool.cancel(|r| matches!(r, Request::Pieces { .. }));
        let session = pool.open_session();
        let growth = GrowthSession::load(session, link, &mut |r| pool.submit(r));
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
            view: preset.view,
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
        if g.growth.replica().shell().is_some() {
            self.screen.push(ScreenChange::Look);
        }
        self.dirty = true;
    }

    /// Shows a shell grown whole on a worker (a gallery picture), at rest.
    pub fn show_whole(&mut self, preset: &'static Preset, spec: &ShellSpec, whole: WholeShell) {
        let shell = whole.shell.clone();
        let replica = Replica::whole(whole);
        let everything = replica.everything();
        self.growing = Some(Growing {
            preset,
            spec: spec.clone(),
            growth: GrowthSession::whole(replica),
            camera: OrbitCamera::framing(&shell.bounds, shell.front, 0.0, 0.0),
            view: preset.view,
            planar_open: false,
            planar_size: None,
            preview: None,
        });
        self.loaded(shell, everything);
    }

    /// The shell is built on its worker: the renderer, the camera and the planar view are set
    /// up for it, and its first step shown.
    fn loaded(&mut self, shell: ShellInfo, advance: Advance) {
        let Some(g) = &mut self.growing else { return };
        let pattern = (shell.cells > 0).then_some((shell.cells, g.spec.growth.rows));
        g.planar_size = pattern;
        self.screen.push(ScreenChange::Shell);
        let grown = *g.growth.replica().grown();
        let mut camera = OrbitCamera::framing(
            &shell.bounds,
            shell.front,
            g.view.yaw.to_radians(),
            g.view.pitch.to_radians(),
        );
        if self.follows {
            camera = camera.following(&grown);
        }
        g.camera = camera;
        g.planar_open = self.planar && pattern.is_some();
        if self.planar {
            self.planar_updates.push(PlanarUpdate::Open(pattern));
        }
        self.upload(advance);
    }

    /// Takes in a worker's reply to `request`: a reply about another shell than this one's is
    /// dropped. Fails with the words to show when the shell cannot be built or grown.
    fn take(&mut self, request: &Request, reply: Reply, pool: &mut Pool) -> Result<(), String> {
        let Some(g) = &mut self.growing else {
            return Ok(());
        };
        let took = g.growth.take(request, reply, &mut |r| pool.submit(r))?;
        match took {
            Took::Nothing => return Ok(()),
            Took::Loaded(shell, advance) => self.loaded(shell, advance),
            Took::Advanced(advance) => self.upload(advance),
            Took::Previewed(reply) => self.previewed(*reply),
        }
        self.dirty = true;
        Ok(())
    }

    /// Takes in what the pool's workers sent back, in the order they sent it, and then, when
    /// the worker holding the sessions was replaced (`sessions_lost`, what it lost unanswered),
    /// has the shell grown again on the fresh one from where its copy stands once those
    /// replies are in: resumed before, a shell whose Load was answered would be built twice,
    /// its second copy's rows starting again at 0. A shell that cannot be built or grown is
    /// dropped, with the words to show.
    pub fn take_all(
        &mut self,
        replies: Vec<(Request, Reply)>,
        sessions_lost: Option<Vec<Request>>,
        pool: &mut Pool,
    ) -> Result<(), String> {
        let settled = self.settled();
        for (request, reply) in replies {
            if let Err(message) = self.take(&request, reply, pool) {
                self.unload();
                return Err(message);
            }
        }
        if let Some(lost) = sessions_lost {
            self.resume(&lost, pool);
        }
        if self.settled() != settled {
            // Every answer is in, or one is owed again: a frame shows it, even when nothing
            // drawn changed (a fresh worker standing where the copy does, a worker replaced
            // that owed the last answer of a shell grown whole), or the page would never say
            // the shell is grown.
            self.dirty = true;
        }
        Ok(())
    }

    /// Whether the shell shown stands where its worker left it, nothing asked unanswered.
    fn settled(&self) -> bool {
        self.growing.as_ref().is_some_and(|g| g.growth.settled())
    }

    /// The worker holding the shell was replaced, losing `lost` unanswered: the shell is grown
    /// again on the fresh one to where the page's copy stands, a pattern being previewed is
    /// previewed again from its first row, and what was lost asked again.
    fn resume(&mut self, lost: &[Request], pool: &mut Pool) {
        let Some(g) = &mut self.growing else { return };
        if let Some(p) = &mut g.preview
            && p.state == PreviewState::Filling
        {
            pool.submit(Request::Preview {
                session: p.session,
                link: p.link.clone(),
            });
            p.pending = true;
        }
        g.growth.resume(lost, &mut |r| pool.submit(r));
    }

    /// Growth moved on by `advance`: the renderer and the planar view take it.
    fn upload(&mut self, advance: Advance) {
        let Some(g) = &mut self.growing else { return };
        if g.planar_open {
            let replica = g.growth.replica();
            self.planar_updates.extend([
                PlanarUpdate::Rows {
                    first: advance.rows.start as u32,
                    rgba: replica.planar(advance.rows.clone()),
                },
                PlanarUpdate::Follow(advance.rows.end as u32),
            ]);
        }
        // Advances not yet applied are merged into one, read from the copy as it stands when
        // applied: the copy only grows, so their ranges join, but the edge of an earlier one
        // may be gone (a shell finished apart has none), so a merged edge is the whole edge now.
        if let Some(ScreenChange::Rows(pending)) = self.screen.last_mut() {
            pending.vertices.end = advance.vertices.end;
            pending.indices.end = advance.indices.end;
            pending.rows.end = advance.rows.end;
            if pending.edge.is_some() || advance.edge.is_some() {
                pending.edge = Some(EdgeRuns::whole(g.growth.replica().edge().mesh()));
            }
            return;
        }
        self.screen.push(ScreenChange::Rows(advance));
    }

    /// Shows the whole pattern of the shell of `link` in the planar view, computed by a worker
    /// over the next frames, while the shell's growth waits (until [`Self::end_preview`] or
    /// another spec is loaded). Values that give no pattern at all are refused with the reason,
    /// in a notice, when the worker answers.
    fn preview(&mut self, link: String, pool: &mut Pool) {
        let Some(g) = &mut self.growing else { return };
        let session = pool.open_session();
        pool.submit(Request::Preview {
            session,
            link: link.clone(),
        });
        g.preview = Some(Previewing {
            session,
            link,
            state: PreviewState::Filling,
            pending: true,
        });
    }

    /// Takes in rows of the pattern previewed.
    fn previewed(&mut self, reply: Reply) {
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
        let rows = g.spec.growth.rows;
        let Some(p) = g.preview.as_mut().filter(|p| p.session == session) else {
            return;
        };
        p.pending = false;
        p.state = state;
        if let Some(message) = failure {
            self.notice = Some(message);
        }
        if cells == 0 || !self.planar {
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
        if g.preview.take().is_none() || !self.planar {
            return;
        }
        g.planar_open = g.planar_size.is_some();
        self.planar_updates.push(PlanarUpdate::Open(g.planar_size));
        if g.planar_open {
            let replica = g.growth.replica();
            let rows = replica.rgba().len() / (replica.cells() * 4).max(1);
            self.planar_updates.extend([
                PlanarUpdate::Rows {
                    first: 0,
                    rgba: replica.planar(0..rows),
                },
                PlanarUpdate::Follow(rows as u32),
            ]);
        }
    }

    /// What the page shows of this viewer: where its shell stands, and the preview; `picture`
    /// is the drawing's size in pixels (what a picture file would be).
    pub fn status(&self, picture: (u32, u32)) -> ViewStatus {
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
                    picture: (picture.0 as usize, picture.1 as usize),
                },
            }),
            preview: g.preview.as_ref().map(|p| p.state),
        }
    }

    /// Asks the shell's worker to grow up to `rows` rows, stopping early when `budget_ms` has
    /// passed; a preview shown ends.
    fn grow(&mut self, rows: u32, budget_ms: f64, pool: &mut Pool) {
        self.end_preview();
        let Some(g) = &mut self.growing else { return };
        self.grew |= g.growth.grow(rows, budget_ms, &mut |r| pool.submit(r));
    }

    /// Asks the shell's worker to grow the rest of the shell at once (what splits is shared
    /// among the pool when it answers); a preview shown ends.
    pub fn finish(&mut self, pool: &mut Pool) {
        self.end_preview();
        let Some(g) = &mut self.growing else { return };
        self.grew |= g.growth.finish(&mut |r| pool.submit(r));
    }

    /// One animation frame at `now` (unless held: the page shows something else over the
    /// shell), outside a recording: asks the previewing worker for more rows, asks the shell's
    /// worker for the rows the playback owes once it has answered the last (for a frame's
    /// growth `budget_ms`, stretched when frames come slowly, and at least `min_growth_ms`),
    /// and moves the camera. Returns whether a picture is due: something changed and the shell
    /// is built.
    pub fn frame(&mut self, now: f64, budget_ms: f64, min_growth_ms: f64, pool: &mut Pool) -> bool {
        if self.held {
            return false;
        }
        if let Some(g) = &mut self.growing
            && let Some(preview) = &mut g.preview
            && preview.state == PreviewState::Filling
            && !preview.pending
        {
            pool.submit(Request::Fill {
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
        let settled = self.settled();
        if let Some(rows) = self.playback.rows_to_ask(growing, settled) {
            let budget = growth_budget(budget_ms, now - self.last_frame).max(min_growth_ms);
            self.grow(u32::try_from(rows).unwrap_or(u32::MAX), budget, pool);
        }
        let dt = ((now - self.last_frame) / 1000.0) as f32;
        self.last_frame = now;
        if let Some(g) = &mut self.growing
            && g.camera.follow(g.growth.replica().grown(), dt)
        {
            self.dirty = true;
        }
        self.dirty
            && self
                .growing
                .as_ref()
                .is_some_and(|g| g.growth.replica().shell().is_some())
    }

    /// A recording's part of an animation frame: grows towards the frame asked for within
    /// `budget_ms` and, once the shell stands exactly there (its shape caught up with the rows)
    /// or has ended, hands the frame to draw, the camera posed for it. `None` while there is
    /// nothing to draw yet; the reason when nothing can be.
    pub fn recording_frame(
        &mut self,
        budget_ms: f64,
        pool: &mut Pool,
    ) -> Option<Result<FrameAsk, String>> {
        if self.held {
            return None;
        }
        let ask = self.asked?;
        let Some(g) = &self.growing else {
            self.asked = None;
            return Some(Err("no shell is loaded".into()));
        };
        if !g.growth.settled() {
            return None;
        }
        let r = g.growth.replica();
        let there = r.is_done() || (r.rows_done() >= ask.row && r.caught_up());
        if !there {
            let behind = ask.row.saturating_sub(r.rows_done());
            self.grow(u32::try_from(behind).unwrap_or(u32::MAX), budget_ms, pool);
            return None;
        }
        self.asked = None;
        let g = self.growing.as_mut()?;
        g.camera.follow(g.growth.replica().grown(), ask.dt);
        g.camera.yaw += ask.turn;
        Some(Ok(ask))
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
}
