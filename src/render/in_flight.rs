//! The frames handed to the GPU and not yet finished by it. A browser may take a frame's
//! commands much faster than its GPU draws them: Firefox queues a WebGL context's commands for
//! another process without ever making the page wait, so a page that draws on every animation
//! frame while the GPU (a software rasterizer, a weak integrated GPU) needs several frames' time
//! for each falls further behind every second. Seen on llvmpipe: after ten seconds of growth the
//! diskoid's frames were 70 s behind, the canvas showed a shell from a minute before (or nothing
//! yet), and anything that must wait for the GPU — a screenshot, `getError`, reading a picture —
//! waited that long. The viewer therefore draws only when fewer than [`MAX_IN_FLIGHT`] frames
//! are unfinished, and the frames finished tell the page that drawing really happens.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

/// Frames the GPU may have on hand: one drawing while the next is recorded.
pub(super) const MAX_IN_FLIGHT: u64 = 2;

/// Counts of the frames submitted and of those the GPU has finished.
#[derive(Default)]
pub(super) struct InFlight {
    submitted: u64,
    finished: Arc<AtomicU64>,
}

impl InFlight {
    /// A frame's work was just submitted to `queue`: counted as finished once the GPU has done
    /// it (wgpu calls back when a later `Device::poll` finds it done, or, on WebGPU, when the
    /// browser's promise resolves).
    pub(super) fn submitted(&mut self, queue: &wgpu::Queue) {
        self.submitted += 1;
        let (frame, finished) = (self.submitted, Arc::clone(&self.finished));
        queue.on_submitted_work_done(move || {
            finished.fetch_max(frame, Ordering::AcqRel);
        });
    }

    /// Frames the GPU has finished since the renderer opened.
    pub(super) fn finished(&self) -> u64 {
        self.finished.load(Ordering::Acquire)
    }

    /// Frames handed to the GPU and not finished yet.
    pub(super) fn unfinished(&self) -> u64 {
        self.submitted - self.finished()
    }

    /// Whether another frame may be handed to the GPU now.
    pub(super) fn has_room(&self) -> bool {
        self.unfinished() < MAX_IN_FLIGHT
    }
}
