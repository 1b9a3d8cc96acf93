//! The browser's [`Screen`]: a renderer and the canvas it draws on (none where the browser
//! draws no 3D), the shell's look and buffers loaded and uploaded as the driver asks, whether
//! the frames handed to the GPU reach the screen, and a renderer opened again in the
//! background after the browser took the device away (opening one takes the browser's time).

use crate::generator::Advance;
use crate::pattern::texture_layout::TextureLayout;
use crate::render::{Canvas, Renderer, ShellLook};
use crate::share::presentation::Layout;
use crate::view::draw_pacing::GpuWatch;
use crate::view::recording::FrameAsk;
use crate::web::canvases::{lose_context, png};
use crate::web::clock::now;
use crate::web::debug::Loss as DebugLoss;
use crate::web::webcodecs::{self, VideoFrame};
use crate::web::{activity, debug};
use crate::work::device_survival::Loss;
use crate::work::screen::Screen;
use crate::work::viewer_state::Growing;
use std::cell::RefCell;
use std::rc::Rc;

/// How `growing`'s spec draws its shell.
fn look(growing: &Growing) -> Option<ShellLook> {
    let spec = growing.spec();
    let shell = growing.replica().shell()?;
    Some(ShellLook::new(
        &spec.colours,
        &spec.material,
        crate::forms::rows_per_whorl(spec),
        shell.line_grid,
    ))
}

/// A renderer and the canvas it draws on.
struct Drawing {
    renderer: Renderer,
    /// An element of the page, or an offscreen canvas one handed its drawing to.
    canvas: Canvas,
    /// Whether the frames handed to the GPU reach the screen.
    watch: GpuWatch,
}

impl Drawing {
    /// Draws the panes of `layout` of `growing`'s shell.
    fn draw(&mut self, growing: &Growing, layout: Layout) -> Result<(), String> {
        let panes = growing.panes(layout, self.renderer.aspect());
        self.renderer.draw(&panes)
    }
}

/// A renderer being opened, answered in the background.
type Opening = Rc<RefCell<Option<Result<Drawing, String>>>>;

/// What a viewer in the browser draws on.
pub struct WebScreen {
    /// None where the browser draws no 3D.
    drawing: Option<Drawing>,
    /// The clear colour, as sRGB bytes (for a renderer opened again).
    background: [u8; 3],
    opening: Option<Opening>,
}

impl WebScreen {
    /// A screen on `canvas` with a renderer opened on it, or none that draws where no renderer
    /// opens.
    pub async fn on(canvas: Canvas, background: [u8; 3]) -> Self {
        let renderer = Renderer::new(&canvas).await.ok();
        Self::new(renderer.map(|r| (r, canvas)), background)
    }

    /// Test-only (see `debug.rs`): takes the graphics device away as a driver reset (WebGPU) or
    /// the browser (WebGL2) would.
    pub fn take_device(&self, loss: DebugLoss) -> Result<(), String> {
        let d = self.drawing.as_ref().ok_or("this viewer draws nothing")?;
        match loss {
            DebugLoss::Destroy => {
                d.renderer.destroy_device();
                Ok(())
            }
            DebugLoss::Context { restore_after_ms } => lose_context(&d.canvas, restore_after_ms),
        }
    }

    pub fn new(renderer: Option<(Renderer, Canvas)>, background: [u8; 3]) -> Self {
        let mut screen = Self {
            drawing: None,
            background,
            opening: None,
        };
        if let Some((renderer, canvas)) = renderer {
            screen.install(renderer, canvas);
        }
        screen
    }

    fn install(&mut self, mut renderer: Renderer, canvas: Canvas) {
        renderer.set_background(self.background);
        self.drawing = Some(Drawing {
            renderer,
            canvas,
            watch: GpuWatch::default(),
        });
    }

    /// Starts opening a renderer on `canvas`.
    fn open_renderer(&mut self, canvas: Canvas) {
        let slot: Opening = Rc::default();
        let filled = Rc::clone(&slot);
        wasm_bindgen_futures::spawn_local(async move {
            let opened = Renderer::new(&canvas).await.map(|renderer| Drawing {
                renderer,
                canvas,
                watch: GpuWatch::default(),
            });
            *filled.borrow_mut() = Some(opened);
        });
        self.opening = Some(slot);
    }
}

impl Screen for WebScreen {
    type Video = VideoFrame;
    /// The promise of a PNG `Blob` (asked for before the browser clears the drawing).
    type Picture = js_sys::Promise;
    type Canvas = Canvas;

    fn backend(&self) -> Option<&'static str> {
        self.drawing.as_ref().map(|d| d.renderer.backend())
    }

    fn load(&mut self, growing: &Growing) {
        let (Some(d), Some(shell), Some(look)) =
            (&mut self.drawing, growing.replica().shell(), look(growing))
        else {
            return;
        };
        d.renderer.load_shell(
            shell.capacity,
            growing
                .pattern_size()
                .and_then(|(cells, rows)| TextureLayout::new(cells, rows)),
            look,
        );
    }

    fn look(&mut self, growing: &Growing) {
        if let (Some(d), Some(look)) = (&mut self.drawing, look(growing)) {
            d.renderer.set_look(look);
        }
    }

    fn upload(&mut self, growing: &Growing, advance: &Advance) -> usize {
        let Some(d) = &mut self.drawing else { return 0 };
        let replica = growing.replica();
        let row = replica.cells() * 4;
        let rgba = &replica.rgba()[advance.rows.start * row..advance.rows.end * row];
        d.renderer.set_ground(replica.grown());
        d.renderer
            .upload(replica.mesh(), replica.edge().mesh(), advance, rgba)
    }

    /// Notes what is being grown, for a crash's message (a test may ask for a panic here).
    fn grew(&mut self, growing: &Growing) {
        activity::set(format!(
            "growing {}, row {}",
            growing.preset().id,
            growing.replica().rows_done() + 1
        ));
        debug::panic_if_asked();
    }

    fn set_background(&mut self, srgb: [u8; 3]) {
        self.background = srgb;
        if let Some(d) = &mut self.drawing {
            d.renderer.set_background(srgb);
        }
    }

    fn failure(&mut self) -> Option<String> {
        let d = self.drawing.as_mut()?;
        if let Some(failure) = d.renderer.failure() {
            return Some(failure);
        }
        let (finished, unfinished) = d.renderer.frames();
        let why = d
            .watch
            .check(finished, unfinished, now(), d.renderer.backend())?;
        Some(format!("Nothing drawn reaches the screen: {why}."))
    }

    fn lost(&self) -> Option<Loss> {
        let d = self.drawing.as_ref()?;
        d.renderer.lost().map(|lost| Loss {
            reason: lost.reason,
            restored: lost.restored,
            webgl: d.renderer.backend() == "WebGL2",
        })
    }

    fn open_again(&mut self) {
        if let Some(canvas) = self.drawing.as_ref().map(|d| d.canvas.clone()) {
            self.open_renderer(canvas);
        }
    }

    fn open_on(&mut self, canvas: Canvas) {
        self.open_renderer(canvas);
    }

    fn opened(&mut self) -> Option<Result<(), String>> {
        let answer = self.opening.as_ref()?.borrow_mut().take()?;
        self.opening = None;
        Some(answer.map(|d| self.install(d.renderer, d.canvas)))
    }

    fn ready(&self) -> bool {
        self.drawing.as_ref().is_some_and(|d| d.renderer.ready())
    }

    fn flush(&mut self) {
        if let Some(d) = &mut self.drawing {
            d.renderer.flush();
        }
    }

    fn size(&self) -> (u32, u32) {
        self.drawing.as_ref().map_or((0, 0), |d| d.canvas.size())
    }

    fn resize(&mut self, size: (u32, u32)) {
        if let Some(d) = &mut self.drawing {
            d.canvas.set_size(size);
            d.renderer.resize(size.0, size.1);
        }
    }

    fn draw(&mut self, growing: &Growing, layout: Layout) -> Result<(), String> {
        match &mut self.drawing {
            Some(d) => d.draw(growing, layout),
            None => Ok(()),
        }
    }

    fn video(&mut self, ask: &FrameAsk) -> Result<VideoFrame, String> {
        let d = self.drawing.as_ref().ok_or("nothing was drawn")?;
        let init = webcodecs::object(&[
            ("timestamp", (ask.timestamp_us as f64).into()),
            ("duration", (ask.duration_us as f64).into()),
        ]);
        VideoFrame::new(d.canvas.as_js(), &init)
            .map_err(|e| format!("the canvas could not be read ({})", webcodecs::describe(&e)))
    }

    fn release(&mut self, video: VideoFrame) {
        video.close();
    }

    fn multisample(&mut self, on: bool) {
        if let Some(d) = &mut self.drawing {
            d.renderer.multisample(on);
        }
    }

    fn picture(&mut self) -> Result<js_sys::Promise, String> {
        png(&self.drawing.as_ref().ok_or("nothing was drawn")?.canvas)
    }
}
