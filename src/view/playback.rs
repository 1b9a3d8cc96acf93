//! How fast a shell grows on screen: play and pause, a speed in pattern rows per animation
//! frame that may be fractional (at 0.3 rows per frame a row grows every third or fourth
//! frame), the rows owed while the shell's worker is busy, and the time a frame may spend on
//! growth, stretched when frames come slowly.

/// How far a slow frame rate may stretch the growth budget of a frame.
pub const MAX_BUDGET_FACTOR: f64 = 4.0;

/// Whether growth advances, and by how much each frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Playback {
    pub playing: bool,
    /// Rows per frame.
    pub speed: f64,
    /// The fraction of a row carried to the next frame.
    carry: f64,
    /// Rows the frames asked for while the shell's worker was still busy.
    owed: usize,
}

impl Playback {
    /// Playing at `speed` rows per frame, from no fraction carried.
    pub fn new(speed: f64) -> Self {
        Self {
            playing: true,
            speed,
            carry: 0.0,
            owed: 0,
        }
    }

    /// Starts a new growth at `speed`: the fraction carried and the rows owed from the last
    /// one are dropped.
    pub fn restart(&mut self, speed: f64) {
        self.speed = speed;
        self.carry = 0.0;
        self.owed = 0;
    }

    /// The rows to ask the shell's worker for this frame, if any. While a shell `growing`
    /// plays, each frame's rows are owed; they are asked for together once the worker has
    /// answered what it was asked (`settled`), so growth keeps the speed it has on the page's
    /// thread however long the worker takes. Paused, or with nothing growing, nothing is owed.
    pub fn rows_to_ask(&mut self, growing: bool, settled: bool) -> Option<usize> {
        if !(growing && self.playing) {
            self.owed = 0;
            return None;
        }
        self.owed += self.rows_this_frame();
        (settled && self.owed > 0).then(|| std::mem::take(&mut self.owed))
    }

    /// The whole rows this frame grows: the speed's fractions add up from frame to frame, so
    /// that over n frames n × speed rows grow (to the rounding of the sum), whatever the speed.
    fn rows_this_frame(&mut self) -> usize {
        self.carry += self.speed;
        let rows = self.carry.floor();
        self.carry -= rows;
        rows as usize
    }
}

/// The milliseconds of growth a frame that comes `interval_ms` after the last may spend:
/// `budget_ms`, or, where drawing is slow (a software renderer), up to half the time between
/// frames so that growth keeps pace with the drawing, at most [`MAX_BUDGET_FACTOR`] times the
/// budget so that no frame freezes the tab.
pub fn growth_budget(budget_ms: f64, interval_ms: f64) -> f64 {
    (interval_ms * 0.5).clamp(budget_ms, budget_ms * MAX_BUDGET_FACTOR)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fractional_speeds_add_up_to_whole_rows() {
        for (speed, frames, rows) in [(0.25, 8, 2), (0.375, 16, 6), (1.0, 7, 7), (2.5, 4, 10)] {
            let mut p = Playback::new(speed);
            let grown: usize = (0..frames).map(|_| p.rows_this_frame()).sum();
            assert_eq!(grown, rows, "{speed} rows per frame over {frames} frames");
        }
        // A speed with no exact binary form: the carry's rounding costs at most a row.
        let mut p = Playback::new(0.3);
        let grown: usize = (0..1000).map(|_| p.rows_this_frame()).sum();
        assert!((299..=300).contains(&grown), "{grown}");
        // No frame grows more than the speed allows, rounded up.
        let mut p = Playback::new(0.3);
        assert!((0..100).all(|_| p.rows_this_frame() <= 1));
    }

    #[test]
    fn rows_owed_while_the_worker_is_busy_are_asked_for_together_once_it_answers() {
        let mut p = Playback::new(2.0);
        assert_eq!(p.rows_to_ask(true, true), Some(2));
        assert_eq!(p.rows_to_ask(true, false), None);
        assert_eq!(p.rows_to_ask(true, false), None);
        assert_eq!(p.rows_to_ask(true, true), Some(6), "three frames' rows");
        // Paused, nothing is owed, and nothing was kept from before.
        assert_eq!(p.rows_to_ask(true, false), None);
        p.playing = false;
        assert_eq!(p.rows_to_ask(true, true), None);
        p.playing = true;
        assert_eq!(p.rows_to_ask(true, true), Some(2));
        // Grown whole (or previewing), nothing is owed either.
        assert_eq!(p.rows_to_ask(true, false), None);
        assert_eq!(p.rows_to_ask(false, true), None);
        assert_eq!(p.rows_to_ask(true, true), Some(2));
        // A restart drops what was owed.
        assert_eq!(p.rows_to_ask(true, false), None);
        p.restart(1.0);
        assert_eq!(p.rows_to_ask(true, true), Some(1));
    }

    #[test]
    fn a_restart_drops_the_fraction_carried() {
        let mut p = Playback::new(0.9);
        assert_eq!(p.rows_this_frame(), 0);
        p.restart(0.5);
        assert_eq!(p.rows_this_frame(), 0, "0.9 carried would have made a row");
        assert_eq!(p.rows_this_frame(), 1);
    }

    #[test]
    fn slow_frames_stretch_the_budget_within_bounds() {
        assert_eq!(
            growth_budget(12.0, 16.7),
            12.0,
            "a fast frame keeps the budget"
        );
        assert_eq!(growth_budget(12.0, 60.0), 30.0, "half of a slow frame");
        assert_eq!(
            growth_budget(12.0, 1000.0),
            48.0,
            "at most four times the budget"
        );
        assert_eq!(growth_budget(12.0, 0.0), 12.0);
    }
}
