//! How fast a shell grows on screen: play and pause, a speed in pattern rows per animation
//! frame that may be fractional (at 0.3 rows per frame a row grows every third or fourth
//! frame), and the time a frame may spend on growth, stretched when frames come slowly.

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
}

impl Playback {
    /// Playing at `speed` rows per frame, from no fraction carried.
    pub fn new(speed: f64) -> Self {
        Self {
            playing: true,
            speed,
            carry: 0.0,
        }
    }

    /// Starts a new growth at `speed`: the fraction carried from the last one is dropped.
    pub fn restart(&mut self, speed: f64) {
        self.speed = speed;
        self.carry = 0.0;
    }

    /// The whole rows this frame grows: the speed's fractions add up from frame to frame, so
    /// that over n frames n × speed rows grow (to the rounding of the sum), whatever the speed.
    pub fn rows_this_frame(&mut self) -> usize {
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
