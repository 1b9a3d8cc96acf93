//! Gestures on the view: one pointer dragging orbits, two pinching zoom, a wheel zooms, and a
//! swipe across a story's card turns its page. Pure, so the web layer only forwards pointer
//! events (which cover mouse, pen and touch alike).

use crate::view::camera::OrbitCamera;
use std::collections::BTreeMap;

/// The pointers currently pressed on the canvas, by pointer id.
#[derive(Default)]
pub struct Pointers {
    down: BTreeMap<i32, (f32, f32)>,
}

impl Pointers {
    pub fn press(&mut self, id: i32, x: f32, y: f32) {
        self.down.insert(id, (x, y));
    }

    pub fn release(&mut self, id: i32) {
        self.down.remove(&id);
    }

    fn spread(&self) -> Option<f32> {
        let mut it = self.down.values();
        let (a, b) = (it.next()?, it.next()?);
        Some(((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt())
    }

    /// Moves pointer `id` to (x, y) in CSS pixels; one pointer orbits, two pinch. Returns
    /// whether the camera changed.
    pub fn moved(
        &mut self,
        id: i32,
        x: f32,
        y: f32,
        height: f32,
        camera: &mut OrbitCamera,
    ) -> bool {
        let Some(&(px, py)) = self.down.get(&id) else {
            return false;
        };
        let before = self.spread();
        self.down.insert(id, (x, y));
        match (self.down.len(), before, self.spread()) {
            (1, _, _) => camera.orbit((x - px) / height, (y - py) / height),
            (_, Some(a), Some(b)) if a > 1.0 && b > 1.0 => camera.zoom_by(b / a),
            _ => return false,
        }
        true
    }
}

/// The shortest stroke across that is a swipe, CSS pixels.
const SWIPE_DISTANCE: f32 = 48.0;
/// The longest a swipe takes, milliseconds: a slower stroke is reading or selecting text.
const SWIPE_TIME: f64 = 800.0;

/// Where a stroke of (`dx`, `dy`) CSS pixels over `ms` milliseconds across a story's card goes:
/// to the next step when it swipes leftwards (true), to the one before when rightwards
/// (false); none unless it is long, quick and mostly across.
pub fn swipe(dx: f32, dy: f32, ms: f64) -> Option<bool> {
    (dx.abs() >= SWIPE_DISTANCE && dx.abs() > 2.0 * dy.abs() && ms <= SWIPE_TIME)
        .then_some(dx < 0.0)
}

/// The zoom factor for a wheel movement of `delta` pixels.
pub fn wheel_zoom(delta: f64) -> f32 {
    (-delta * 0.0015).exp() as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quick_stroke_across_turns_a_storys_page_and_others_do_not() {
        assert_eq!(
            swipe(-120.0, 10.0, 200.0),
            Some(true),
            "leftwards: the next step"
        );
        assert_eq!(
            swipe(90.0, -20.0, 300.0),
            Some(false),
            "rightwards: the one before"
        );
        assert_eq!(swipe(-20.0, 0.0, 100.0), None, "too short: a tap");
        assert_eq!(swipe(-120.0, 100.0, 200.0), None, "mostly down: a scroll");
        assert_eq!(swipe(-120.0, 0.0, 2000.0), None, "slow: selecting words");
    }
    use crate::mesh::Bounds;
    use glam::DVec3;

    fn camera() -> OrbitCamera {
        let b = Bounds {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        };
        OrbitCamera::framing(&b, DVec3::X, 0.0, 0.0)
    }

    #[test]
    fn one_pointer_orbits_two_pinch() {
        let mut cam = camera();
        let mut p = Pointers::default();
        p.press(1, 100.0, 100.0);
        assert!(p.moved(1, 150.0, 100.0, 500.0, &mut cam));
        assert!(cam.yaw != camera().yaw && cam.zoom == 1.0);
        p.press(2, 200.0, 100.0);
        let zoom = cam.zoom;
        assert!(p.moved(2, 250.0, 100.0, 500.0, &mut cam));
        assert!(cam.zoom < zoom, "spreading the fingers comes closer");
        p.release(1);
        p.release(2);
        assert!(!p.moved(1, 0.0, 0.0, 500.0, &mut cam));
    }

    #[test]
    fn wheel_down_zooms_out() {
        assert!(wheel_zoom(100.0) < 1.0 && wheel_zoom(-100.0) > 1.0);
    }
}
