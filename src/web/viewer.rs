//! A viewer: one canvas and its renderer, a shell growing on it, optionally its planar pattern,
//! and the camera the pointer turns. Loading another spec restarts growth without reloading the
//! page. The page's main view is one viewer, whose camera follows the growing shell; the
//! gallery's pictures are drawn by another, framed on the whole shell. While a pattern slider
//! is dragged, the planar view previews the whole pattern of its values instead. When the
//! browser takes the graphics device away, the viewer opens another (`recovery.rs`) and uploads
//! the shell grown so far to it: growth goes on from where it was.

use super::activity;
use super::debug;
use super::page::show_message;
use super::planar::Planar;
use super::recovery::{RESTORE_WAIT_MS, Reopened, Reopening};
use crate::generator::{Advance, Generator, within};
use crate::mesh::Bounds;
use crate::pattern::run::PatternRun;
use crate::pattern::texture_layout::TextureLayout;
use crate::presets::Preset;
use crate::render::{Renderer, ShellLook};
use crate::share::presentation::Layout;
use crate::spec::ShellSpec;
use crate::view::camera::OrbitCamera;
use crate::view::gestures::{Pointers, wheel_zoom};
use crate::view::panes::{Pane, panes};
use crate::view::playback::{Playback, growth_budget};
use crate::view::preview::Preview;
use web_sys::HtmlCanvasElement;

/// A shell being grown.
pub struct Growing {
    pub preset: &'static Preset,
    pub generator: Generator,
    camera: OrbitCamera,
    planar: Option<Planar>,
    /// The planar view's cells and rows for this shell's pattern.
    planar_size: Option<(u32, u32)>,
    /// The pattern of values being dragged, shown in the planar view while growth waits.
    preview: Option<Preview>,
    /// Bounds of what has grown so far, edge included.
    grown: Bounds,
    /// The longest growth step lately, in milliseconds (see [`within`]).
    longest_step: f64,
    /// The pattern texture's layout and the shader's look: what a new renderer needs to take
    /// the shell again.
    texture_layout: Option<TextureLayout>,
    look: ShellLook,
}

impl Growing {
    /// Records what is being grown, for a panic's message; a test may ask for a panic here.
    fn note_activity(&self) {
        activity::set(format!(
            "growing {}, row {}",
            self.preset.id,
            self.generator.rows_done() + 1
        ));
        debug::panic_if_asked();
    }

    /// Whether the view rests on what has grown (or where the user left it).
    pub fn view_at_rest(&self) -> bool {
        self.camera.settled(&self.grown)
    }

    /// The panes of `layout` on a canvas of aspect `aspect`.
    fn panes(&self, layout: Layout, aspect: f32) -> Vec<Pane> {
        panes(layout, &self.camera, &self.grown, aspect)
    }
}

pub struct Viewer {
    renderer: Renderer,
    canvas: HtmlCanvasElement,
    planar_canvas: Option<HtmlCanvasElement>,
    pub pointers: Pointers,
    growing: Option<Growing>,
    /// Whether growth advances each frame, and how fast.
    pub playback: Playback,
    dirty: bool,
    /// Whether the camera follows the growing shell (else it frames the whole).
    follows: bool,
    /// One view, or Kawaguchi's four.
    layout: Layout,
    /// When the last frame was drawn, milliseconds.
    last_frame: f64,
    /// The drawing size a recording asks for, instead of the canvas's own.
    fixed_size: Option<(u32, u32)>,
    /// The clear colour, as sRGB bytes (for a renderer opened again).
    background: [u8; 3],
    /// A renderer being opened after the device was lost, and when the loss was seen.
    reopening: Option<Reopening>,
    lost_at: Option<f64>,
    /// Why no renderer could be opened again: the viewer draws no more.
    gone: Option<String>,
    /// A fresh canvas that took the old one's place, until the page moves its listeners.
    replaced_canvas: Option<HtmlCanvasElement>,
}

/// The state of the viewer's graphics device.
#[derive(Clone, Debug, PartialEq)]
pub enum Device {
    /// Drawing.
    Ready,
    /// Lost (why, in words), and being opened again.
    Reopening(String),
    /// Opened again just now, with this backend.
    Reopened(&'static str),
    /// Lost for good: no device could be opened again (why, in words).
    Gone(String),
}

/// Milliseconds since the page started.
pub fn now() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}

impl Viewer {
    pub async fn new(
        canvas: HtmlCanvasElement,
        planar_canvas: Option<HtmlCanvasElement>,
        background: [u8; 3],
        follows: bool,
    ) -> Result<Self, String> {
        let mut renderer = Renderer::new(canvas.clone()).await?;
        renderer.set_background(background);
        Ok(Self {
            renderer,
            canvas,
            planar_canvas,
            pointers: Pointers::default(),
            growing: None,
            playback: Playback::new(1.0),
            dirty: true,
            follows,
            layout: Layout::Single,
            last_frame: now(),
            fixed_size: None,
            background,
            reopening: None,
            lost_at: None,
            gone: None,
            replaced_canvas: None,
        })
    }

    /// "WebGPU" or "WebGL2".
    pub fn backend(&self) -> &'static str {
        self.renderer.backend()
    }

    /// The shell being grown.
    pub fn growing(&self) -> Option<&Growing> {
        self.growing.as_ref()
    }

    /// Follows a change of the page's theme.
    pub fn set_background(&mut self, srgb: [u8; 3]) {
        self.background = srgb;
        self.renderer.set_background(srgb);
        self.dirty = true;
    }

    /// Drops the shell (after one that could not be built): nothing is drawn or grown.
    pub fn unload(&mut self) {
        self.growing = None;
    }

    /// Starts growing `spec` from its apex.
    pub fn load(&mut self, preset: &'static Preset, spec: &ShellSpec) -> Result<(), String> {
        activity::set(format!("loading {}", preset.id));
        let generator =
            Generator::new(spec).map_err(|e| format!("This shell cannot be built: {e}"))?;
        let pattern = generator
            .pattern()
            .map(|p| (p.cells() as u32, spec.growth.rows));
        let texture_layout = pattern.and_then(|(cells, rows)| TextureLayout::new(cells, rows));
        let look = ShellLook::new(
            &spec.colours,
            &spec.material,
            crate::forms::rows_per_whorl(spec),
            generator.line_grid(),
        );
        self.renderer
            .load_shell(generator.capacity(), texture_layout, look);
        let (bounds, front) = generator.framing();
        let mut grown = Bounds::EMPTY;
        grown.include_vertices(&generator.mesh().vertices);
        grown.include_vertices(&generator.edge().vertices);
        let mut camera = OrbitCamera::framing(
            &bounds,
            front,
            preset.view.yaw.to_radians(),
            preset.view.pitch.to_radians(),
        );
        if self.follows {
            camera = camera.following(&grown);
        }
        let planar = self
            .planar_canvas
            .clone()
            .and_then(|c| Planar::new(c, pattern));
        self.playback.restart(spec.growth.speed);
        self.growing = Some(Growing {
            preset,
            generator,
            camera,
            planar,
            planar_size: pattern,
            preview: None,
            grown,
            longest_step: 0.0,
            texture_layout,
            look,
        });
        let grown = self
            .growing
            .as_ref()
            .map(|g| g.generator.grown())
            .unwrap_or_default();
        self.upload(&grown);
        self.dirty = true;
        Ok(())
    }

    fn upload(&mut self, advance: &Advance) {
        let Some(g) = &mut self.growing else { return };
        g.grown
            .include_vertices(&g.generator.mesh().vertices[advance.vertices.clone()]);
        if advance.edge_changed {
            g.grown.include_vertices(&g.generator.edge().vertices);
        }
        self.renderer.set_ground(&g.grown);
        let rgba = g.generator.pattern().map_or(&[][..], |p| {
            let row = p.cells() * 4;
            &p.rgba()[advance.rows.start * row..advance.rows.end * row]
        });
        self.renderer
            .upload(g.generator.mesh(), g.generator.edge(), advance, rgba);
        if let Some(planar) = &g.planar {
            planar.draw_rows(advance.rows.start as u32, rgba);
            planar.follow(advance.rows.end as u32);
        }
    }

    /// Shows the whole pattern of `spec` in the planar view, computed over the next frames,
    /// while the shell's growth waits (until [`Self::end_preview`] or another spec is loaded).
    /// Values that give no pattern at all are refused with the reason.
    pub fn preview(&mut self, spec: &ShellSpec) -> Result<(), String> {
        let Some(g) = &mut self.growing else {
            return Ok(());
        };
        let run = match PatternRun::new(spec) {
            Ok(Some(run)) => run,
            Ok(None) => return Ok(()),
            Err(e) => return Err(format!("With these values there is no pattern: {e}.")),
        };
        g.planar = self
            .planar_canvas
            .clone()
            .and_then(|c| Planar::new(c, Some((run.cells() as u32, spec.growth.rows))));
        if let Some(planar) = &g.planar {
            planar.draw_rows(0, run.rgba());
        }
        g.preview = Some(Preview::new(run, spec.growth.rows as usize));
        Ok(())
    }

    /// Back from a preview to the growing shell's own pattern in the planar view.
    pub fn end_preview(&mut self) {
        let Some(g) = &mut self.growing else { return };
        if g.preview.take().is_none() {
            return;
        }
        g.planar = self
            .planar_canvas
            .clone()
            .and_then(|c| Planar::new(c, g.planar_size));
        if let (Some(planar), Some(pattern)) = (&g.planar, g.generator.pattern()) {
            planar.draw_rows(0, pattern.rgba());
            planar.follow(pattern.rows() as u32);
        }
    }

    /// The preview's state for the page's signal: "filling", "whole", "stopped", or "" for none.
    pub fn preview_state(&self) -> &'static str {
        self.growing
            .as_ref()
            .and_then(|g| g.preview.as_ref())
            .map_or("", |p| p.state().signal())
    }

    /// Keeps a graphics device: when the browser took the renderer's away, opens another in
    /// the background (on the same canvas, or a fresh one; see `recovery.rs`) and, once it is
    /// open, uploads the shell grown so far to it. Called once a frame before anything is drawn.
    pub fn survive(&mut self) -> Device {
        if let Some(gone) = &self.gone {
            return Device::Gone(gone.clone());
        }
        if let Some(reopening) = &self.reopening {
            return match reopening.take() {
                None => Device::Reopening(self.loss_reason()),
                Some(Ok(reopened)) => {
                    self.reopening = None;
                    self.lost_at = None;
                    self.install(reopened);
                    Device::Reopened(self.renderer.backend())
                }
                Some(Err(e)) => {
                    self.reopening = None;
                    let gone = format!(
                        "The graphics device was lost ({}) and none could be opened again: {e}",
                        self.loss_reason()
                    );
                    self.gone = Some(gone.clone());
                    Device::Gone(gone)
                }
            };
        }
        let Some(loss) = self.renderer.lost() else {
            return Device::Ready;
        };
        let since = *self.lost_at.get_or_insert_with(now);
        let webgl = self.renderer.backend() == "WebGL2";
        if webgl && !loss.restored && now() - since < RESTORE_WAIT_MS {
            // The browser may give the context back (webglcontextrestored): wait a little.
            return Device::Reopening(loss.reason);
        }
        self.reopening = Some(Reopening::start(
            self.canvas.clone(),
            webgl && !loss.restored,
        ));
        Device::Reopening(loss.reason)
    }

    fn loss_reason(&self) -> String {
        self.renderer
            .lost()
            .map_or_else(|| "no reason given".to_string(), |l| l.reason)
    }

    /// Draws with a renderer opened again: the shell's buffers and texture are made anew and
    /// take everything grown so far (mesh, edge and pattern rows), which the generator kept.
    fn install(&mut self, reopened: Reopened) {
        let Reopened {
            mut renderer,
            canvas,
        } = reopened;
        renderer.set_background(self.background);
        if canvas != self.canvas {
            self.replaced_canvas = Some(canvas.clone());
        }
        self.canvas = canvas;
        self.renderer = renderer;
        let grown = self.growing.as_ref().map(|g| {
            self.renderer
                .load_shell(g.generator.capacity(), g.texture_layout, g.look);
            g.generator.grown()
        });
        if let Some(grown) = grown {
            self.upload(&grown);
        }
        self.dirty = true;
    }

    /// A fresh canvas that took the old one's place since the last call: the page listens to
    /// it instead.
    pub fn take_replaced_canvas(&mut self) -> Option<HtmlCanvasElement> {
        self.replaced_canvas.take()
    }

    /// Test-only (see `debug.rs`): destroys the graphics device as a driver reset would.
    pub fn destroy_device(&self) {
        self.renderer.destroy_device();
    }

    /// Grows up to `rows` rows now, stopping early when `budget_ms` has passed.
    pub fn grow(&mut self, rows: usize, budget_ms: f64) {
        self.end_preview();
        let Some(g) = &mut self.growing else { return };
        g.note_activity();
        let advance = g
            .generator
            .advance_while(rows, within(now, budget_ms, &mut g.longest_step));
        self.upload(&advance);
        self.dirty = true;
    }

    /// Grows the rest of the shell at once.
    pub fn finish(&mut self) {
        self.end_preview();
        let Some(g) = &mut self.growing else { return };
        if g.generator.is_done() {
            return;
        }
        g.note_activity();
        g.generator.finish();
        let advance = g.generator.grown();
        self.upload(&advance);
        self.dirty = true;
    }

    /// Keeps the drawing buffer at the canvas's size in device pixels.
    fn fit_canvas(&mut self) {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let (width, height) = self.fixed_size.unwrap_or((
            (f64::from(self.canvas.client_width()) * dpr).round() as u32,
            (f64::from(self.canvas.client_height()) * dpr).round() as u32,
        ));
        if width > 0 && height > 0 && (width, height) != (self.canvas.width(), self.canvas.height())
        {
            self.canvas.set_width(width);
            self.canvas.set_height(height);
            self.renderer.resize(width, height);
            self.dirty = true;
        }
    }

    /// One animation frame: grow at the current speed within `budget_ms` (stretched when frames
    /// come slowly, see [`growth_budget`]), draw if anything changed. Returns whether a frame
    /// was drawn.
    pub fn frame(&mut self, budget_ms: f64) -> Result<bool, String> {
        if let Some(failure) = self.renderer.failure() {
            return Err(failure);
        }
        if self.reopening.is_some() || self.renderer.lost().is_some() {
            return Ok(false);
        }
        self.fit_canvas();
        if let Some(g) = &mut self.growing
            && let Some(preview) = &mut g.preview
        {
            let until = now() + budget_ms;
            let (first, failure) = preview.fill(|| now() < until);
            if let Some(e) = failure {
                show_message(&format!("With these values the pattern stops {e}."));
            }
            if let Some(planar) = &g.planar {
                let run = preview.run();
                planar.draw_rows(first as u32, &run.rgba()[first * run.cells() * 4..]);
            }
        }
        let growing = self
            .growing
            .as_ref()
            .is_some_and(|g| !g.generator.is_done() && g.preview.is_none());
        if growing && self.playback.playing {
            let rows = self.playback.rows_this_frame();
            if rows > 0 {
                self.grow(rows, growth_budget(budget_ms, now() - self.last_frame));
            }
        }
        let time = now();
        let dt = ((time - self.last_frame) / 1000.0).min(0.25) as f32;
        self.last_frame = time;
        if let Some(g) = &mut self.growing
            && g.camera.follow(&g.grown, dt)
        {
            self.dirty = true;
        }
        if !self.dirty {
            return Ok(false);
        }
        let Some(g) = &self.growing else {
            return Ok(false);
        };
        self.renderer
            .draw(&g.panes(self.layout, self.renderer.aspect()))?;
        self.dirty = false;
        Ok(true)
    }

    /// Shows one view or Kawaguchi's four.
    pub fn set_layout(&mut self, layout: Layout) {
        self.layout = layout;
        self.dirty = true;
    }

    /// Back to the first view: following the growth again on the main view.
    pub fn reset_camera(&mut self) {
        let follows = self.follows;
        if let Some(camera) = self.camera_mut() {
            camera.reset(follows);
        }
    }

    /// The camera of the shell being grown.
    pub fn camera_mut(&mut self) -> Option<&mut OrbitCamera> {
        self.dirty = true;
        self.growing.as_mut().map(|g| &mut g.camera)
    }

    /// A pointer moved to (x, y) CSS pixels.
    pub fn pointer_moved(&mut self, id: i32, x: f32, y: f32) {
        let height = self.canvas.client_height().max(1) as f32;
        if let Some(g) = &mut self.growing
            && self.pointers.moved(id, x, y, height, &mut g.camera)
        {
            self.dirty = true;
        }
    }

    /// A wheel turned by `delta` pixels.
    pub fn wheel(&mut self, delta: f64) {
        if let Some(camera) = self.camera_mut() {
            camera.zoom_by(wheel_zoom(delta));
        }
    }

    /// Draws now and returns the canvas as a PNG data URL (read before the browser clears it).
    pub fn picture(&mut self) -> Result<String, String> {
        if let Some(loss) = self.renderer.lost() {
            return Err(format!("the graphics device was lost ({})", loss.reason));
        }
        let Some(g) = &self.growing else {
            return Err("nothing is drawn yet".into());
        };
        self.renderer
            .draw(&g.panes(self.layout, self.renderer.aspect()))?;
        self.canvas
            .to_data_url_with_type("image/png")
            .map_err(|_| "the browser refused to read the canvas".to_string())
    }

    pub fn canvas(&self) -> &HtmlCanvasElement {
        &self.canvas
    }

    /// Draws at `size` pixels whatever the canvas's size on the page (a recording's frames;
    /// the page shows them scaled to fit), or, with `None`, at the canvas's size again.
    pub fn fix_size(&mut self, size: Option<(u32, u32)>) {
        self.fixed_size = size;
        let _ = self
            .canvas
            .class_list()
            .toggle_with_force("fixed", size.is_some());
        self.dirty = true;
    }

    /// Grows towards row `row` within `budget_ms`; says whether the shell now stands exactly
    /// there (its shape caught up with the rows), or has ended.
    pub fn grow_to(&mut self, row: usize, budget_ms: f64) -> bool {
        self.end_preview();
        let Some(g) = &mut self.growing else {
            return true;
        };
        let behind = row.saturating_sub(g.generator.rows_done());
        if behind > 0 || !g.generator.caught_up() {
            g.note_activity();
            let advance = g
                .generator
                .advance_while(behind, within(now, budget_ms, &mut g.longest_step));
            self.upload(&advance);
            self.dirty = true;
        }
        self.growing.as_ref().is_none_or(|g| {
            g.generator.is_done() || (g.generator.rows_done() >= row && g.generator.caught_up())
        })
    }

    /// Draws a recording's frame: the camera eased by `dt` seconds of video (not of the
    /// clock) and turned by `turn` radians about the vertical.
    pub fn draw_recorded(&mut self, dt: f32, turn: f32) -> Result<(), String> {
        if let Some(failure) = self.renderer.failure() {
            return Err(failure);
        }
        if let Some(loss) = self.renderer.lost() {
            return Err(format!("the graphics device was lost ({})", loss.reason));
        }
        self.fit_canvas();
        let Some(g) = &mut self.growing else {
            return Err("no shell is loaded".into());
        };
        g.camera.follow(&g.grown, dt);
        g.camera.yaw += turn;
        self.renderer
            .draw(&g.panes(self.layout, self.renderer.aspect()))?;
        self.last_frame = now();
        self.dirty = false;
        Ok(())
    }
}
