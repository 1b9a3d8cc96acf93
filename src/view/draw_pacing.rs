//! When a frame draws the shell, and when it leaves the drawing to the next. A reply that shows
//! an instance of the implicit shell brings megabytes of re-meshed edge, and each stage of it
//! takes a frame's share of the page's thread on its own: reading it (its `message` event copies
//! and decodes it), taking it in (the copies into the page's copy, wgpu's staging and the GL
//! buffers) and drawing. Past [`HEAVY_BYTES`] they go to three frames: the page takes in a reply
//! that heavy a frame after the one it was read in (`web/workers.rs`), and a frame that hands the
//! GPU that much only hands it over, the next frame drawing. The shell shows two frames later
//! instead of one frame taking three times as long. A frame never leaves its drawing to the next
//! twice in a row, so a page taking such replies one after another still draws every other frame.
//! A [`GpuWatch`] says when frames handed to the GPU stop reaching the screen.

/// Bytes of a reply read, or handed to the GPU in a frame, beyond which the work is spread over
/// frames.
pub const HEAVY_BYTES: usize = 1 << 20;

/// Bytes handed to the GPU since the last frame, and whether the last frame left its drawing
/// to this one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawPacing {
    uploaded: usize,
    deferred: bool,
}

/// What a frame with something to draw does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameDraw {
    /// Draws.
    Draw,
    /// Hands what it uploaded to the GPU and draws in the next frame.
    Defer,
}

impl DrawPacing {
    /// `bytes` were handed to the GPU in this frame.
    pub fn uploaded(&mut self, bytes: usize) {
        self.uploaded = self.uploaded.saturating_add(bytes);
    }

    /// Ends the frame: what it does when it has something to draw (`dirty`). A frame with
    /// nothing to draw defers nothing.
    pub fn frame(&mut self, dirty: bool) -> FrameDraw {
        let heavy = std::mem::take(&mut self.uploaded) > HEAVY_BYTES;
        let defer = dirty && heavy && !self.deferred;
        self.deferred = defer;
        if defer {
            FrameDraw::Defer
        } else {
            FrameDraw::Draw
        }
    }
}

/// How long frames may wait for the GPU without one of them finished before the viewer says
/// the screen shows none of them, milliseconds (a frame takes well under a second, even on a
/// software rasterizer).
const UNSEEN_MS: f64 = 10_000.0;

/// Watches that the frames handed to the GPU reach the screen: while some wait, how many it
/// had finished when it last finished one, and when. A device that opened and finishes none of
/// the frames handed to it for [`UNSEEN_MS`] draws nothing on the screen.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GpuWatch {
    progress: Option<(u64, f64)>,
}

impl GpuWatch {
    /// The GPU of `backend` has `finished` frames in all and `unfinished` waiting, at `now`
    /// (milliseconds): why the screen shows nothing more of what is drawn, once frames have
    /// waited [`UNSEEN_MS`] without one of them finished.
    pub fn check(
        &mut self,
        finished: u64,
        unfinished: u64,
        now: f64,
        backend: &str,
    ) -> Option<String> {
        if unfinished == 0 {
            self.progress = None;
            return None;
        }
        match self.progress {
            Some((seen, since)) if seen == finished => (now - since > UNSEEN_MS).then(|| {
                format!(
                    "the {backend} device has finished none of the frames handed to it in {} s",
                    UNSEEN_MS / 1000.0
                )
            }),
            _ => {
                self.progress = Some((finished, now));
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_that_wait_ten_seconds_without_one_finished_are_said_unseen() {
        let mut watch = GpuWatch::default();
        assert_eq!(watch.check(5, 0, 0.0, "WebGL2"), None, "nothing waits");
        assert_eq!(watch.check(5, 2, 1000.0, "WebGL2"), None, "the wait starts");
        assert_eq!(
            watch.check(5, 3, 1000.0 + UNSEEN_MS, "WebGL2"),
            None,
            "not yet past"
        );
        assert_eq!(
            watch.check(5, 3, 1001.0 + UNSEEN_MS, "WebGL2").as_deref(),
            Some("the WebGL2 device has finished none of the frames handed to it in 10 s")
        );
        let mut slow = GpuWatch::default();
        slow.check(5, 2, 0.0, "WebGPU");
        assert_eq!(
            slow.check(6, 2, 9000.0, "WebGPU"),
            None,
            "one finished: the wait starts again"
        );
        assert_eq!(slow.check(6, 2, 18_000.0, "WebGPU"), None);
        assert_eq!(slow.check(7, 0, 30_000.0, "WebGPU"), None, "all finished");
        assert_eq!(slow.check(7, 1, 30_001.0, "WebGPU"), None);
    }

    #[test]
    fn a_heavy_frame_leaves_its_drawing_to_the_next_but_never_two_in_a_row() {
        let mut pacing = DrawPacing::default();
        pacing.uploaded(64 << 10);
        assert_eq!(pacing.frame(true), FrameDraw::Draw, "a light frame draws");
        pacing.uploaded(HEAVY_BYTES / 2);
        pacing.uploaded(HEAVY_BYTES / 2 + 1);
        assert_eq!(pacing.frame(true), FrameDraw::Defer, "uploads add up");
        pacing.uploaded(8 << 20);
        assert_eq!(
            pacing.frame(true),
            FrameDraw::Draw,
            "the frame after a deferred one draws, heavy or not"
        );
        pacing.uploaded(8 << 20);
        assert_eq!(pacing.frame(true), FrameDraw::Defer);
        assert_eq!(pacing.frame(true), FrameDraw::Draw, "and the next draws");
        assert_eq!(pacing.frame(true), FrameDraw::Draw, "the count starts anew");
    }

    #[test]
    fn a_frame_with_nothing_to_draw_defers_nothing() {
        let mut pacing = DrawPacing::default();
        pacing.uploaded(8 << 20);
        assert_eq!(pacing.frame(false), FrameDraw::Draw);
        pacing.uploaded(8 << 20);
        assert_eq!(
            pacing.frame(true),
            FrameDraw::Defer,
            "a frame with nothing to draw did not count as deferred"
        );
    }
}
