//! When a frame draws the shell, and when it leaves the drawing to the next. A reply that shows
//! an instance of the implicit shell brings megabytes of re-meshed edge, and each stage of it
//! takes a frame's share of the page's thread on its own: reading it (its `message` event copies
//! and decodes it), taking it in (the copies into the page's copy, wgpu's staging and the GL
//! buffers) and drawing. Past [`HEAVY_BYTES`] they go to three frames: the page takes in a reply
//! that heavy a frame after the one it was read in (`web/workers.rs`), and a frame that hands the
//! GPU that much only hands it over, the next frame drawing. The shell shows two frames later
//! instead of one frame taking three times as long. A frame never leaves its drawing to the next
//! twice in a row, so a page taking such replies one after another still draws every other frame.

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

#[cfg(test)]
mod tests {
    use super::*;

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
