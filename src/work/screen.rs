//! What a viewer draws on, as the viewer's driver ([`super::viewer_driver::ViewerDriver`])
//! uses it: a renderer and its canvas in the browser (`web/viewer/screen.rs`), a simulated
//! one in the tests (`tests/simulator.rs`). The driver decides when to load, upload, draw and
//! open a device again; a screen only does it and says how its device stands.

use super::device_survival::Loss;
use super::viewer_state::Growing;
use crate::generator::Advance;
use crate::share::presentation::Layout;
use crate::view::recording::FrameAsk;

/// A viewer's drawing surface and its graphics device.
pub trait Screen {
    /// A recording's frame, read from the drawing.
    type Video;
    /// A picture read back from the drawing (a gallery card's, a file's).
    type Picture;
    /// A fresh canvas the page makes when a lost device cannot be opened again on the old one.
    type Canvas;

    /// What it draws with ("WebGPU", "WebGL2"), or `None` where it draws nothing: where the
    /// browser draws no 3D, the shell grows all the same (for its pattern and its files).
    fn backend(&self) -> Option<&'static str>;
    /// Sets itself up for `growing`'s shell as its worker built it (buffers, pattern texture,
    /// look).
    fn load(&mut self, growing: &Growing);
    /// Takes the look of `growing`'s spec (colours, material).
    fn look(&mut self, growing: &Growing);
    /// Takes what `advance` added to `growing`'s shell; returns the bytes it uploaded.
    fn upload(&mut self, growing: &Growing, advance: &Advance) -> usize;
    /// The shell shown grew (the page notes what is being grown, for a crash's message).
    fn grew(&mut self, growing: &Growing);
    /// Sets the clear colour, as sRGB bytes.
    fn set_background(&mut self, srgb: [u8; 3]);
    /// Why it can draw no more, if it cannot: its renderer failed, or the frames it handed the
    /// GPU have stopped reaching the screen.
    fn failure(&mut self) -> Option<String>;
    /// What it says of its device when the browser took it away.
    fn lost(&self) -> Option<Loss>;
    /// Starts opening a renderer again on its own canvas.
    fn open_again(&mut self);
    /// Starts opening a renderer on `canvas`, a fresh one the page made.
    fn open_on(&mut self, canvas: Self::Canvas);
    /// The answer to the opening started, once the browser has given it; on `Ok` the screen
    /// now draws with the renderer opened (and holds no shell yet).
    fn opened(&mut self) -> Option<Result<(), String>>;
    /// Whether the GPU has caught up with the frames handed to it.
    fn ready(&self) -> bool;
    /// Hands the GPU what was uploaded, without drawing.
    fn flush(&mut self);
    /// The drawing buffer's size, pixels.
    fn size(&self) -> (u32, u32);
    fn resize(&mut self, size: (u32, u32));
    /// Draws the panes of `layout` of `growing`'s shell.
    fn draw(&mut self, growing: &Growing, layout: Layout) -> Result<(), String>;
    /// Reads what was just drawn as the recording's frame `ask`.
    fn video(&mut self, ask: &FrameAsk) -> Result<Self::Video, String>;
    /// Lets go of a recording's frame nobody will take.
    fn release(&mut self, video: Self::Video);
    /// Draws with several samples a pixel (smooth edges) or one (a small picture's sharp ones).
    fn multisample(&mut self, on: bool);
    /// Reads what was just drawn back as a picture.
    fn picture(&mut self) -> Result<Self::Picture, String>;
}
