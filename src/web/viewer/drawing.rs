//! What a viewer draws with: a renderer and the canvas it draws on, the shell's look and its
//! buffers loaded and uploaded as it grows, and whether the frames handed to the GPU reach the
//! screen.

use crate::generator::Advance;
use crate::pattern::texture_layout::TextureLayout;
use crate::render::{Canvas, Renderer, ShellLook};
use crate::share::presentation::Layout;
use crate::view::draw_pacing::GpuWatch;
use crate::web::clock::now;
use crate::work::viewer_state::Growing;

/// How `growing`'s spec draws its shell.
pub(super) fn look(growing: &Growing) -> Option<ShellLook> {
    let spec = growing.spec();
    let shell = growing.replica().shell()?;
    Some(ShellLook::new(
        &spec.colours,
        &spec.material,
        crate::forms::rows_per_whorl(spec),
        shell.line_grid,
    ))
}

/// Sets `renderer` up for `growing`'s shell as its worker built it: buffers, pattern texture
/// and look. A renderer opened again after a lost device is set up the same way.
pub(super) fn load_into(renderer: &mut Renderer, growing: &Growing) {
    let (Some(shell), Some(look)) = (growing.replica().shell(), look(growing)) else {
        return;
    };
    renderer.load_shell(
        shell.capacity,
        growing
            .pattern_size()
            .and_then(|(cells, rows)| TextureLayout::new(cells, rows)),
        look,
    );
}

/// Uploads what `advance` added to `growing`'s shell; returns the bytes uploaded.
pub(super) fn upload(renderer: &mut Renderer, growing: &Growing, advance: &Advance) -> usize {
    let replica = growing.replica();
    let row = replica.cells() * 4;
    let rgba = &replica.rgba()[advance.rows.start * row..advance.rows.end * row];
    renderer.set_ground(replica.grown());
    renderer.upload(replica.mesh(), replica.edge().mesh(), advance, rgba)
}

/// A renderer and the canvas it draws on.
pub(super) struct Drawing {
    pub(super) renderer: Renderer,
    /// An element of the page, or an offscreen canvas one handed its drawing to.
    pub(super) canvas: Canvas,
    /// Whether the frames handed to the GPU reach the screen.
    watch: GpuWatch,
}

impl Drawing {
    pub(super) fn new(renderer: Renderer, canvas: Canvas) -> Self {
        Self {
            renderer,
            canvas,
            watch: GpuWatch::default(),
        }
    }

    /// Draws the panes of `layout` of `growing`'s shell.
    pub(super) fn draw(&mut self, growing: &Growing, layout: Layout) -> Result<(), String> {
        let panes = growing.panes(layout, self.renderer.aspect());
        self.renderer.draw(&panes)
    }

    /// Why the screen shows nothing more of what is drawn, if frames have waited too long.
    pub(super) fn unseen(&mut self) -> Option<String> {
        let (finished, unfinished) = self.renderer.frames();
        self.watch
            .check(finished, unfinished, now(), self.renderer.backend())
    }
}
