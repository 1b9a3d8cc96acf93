//! The orbit camera: pure arithmetic, so that the renderer only uploads its matrices.
//!
//! While a shell grows the camera follows it: it frames what has grown so far, easing towards
//! it as the shell gets larger, so that the first rows already fill the view (a logarithmic
//! spiral puts most of its size in the last whorl, and a view framed for the final shell shows
//! a speck for most of the growth). Once the user orbits or zooms, their view stays until they
//! reset it.
//!
//! Shells are modelled with their axis along z and the apex towards −z (the helico-spiral
//! grows towards +z). They are shown apex up: the display turns shell space by 90° about x so
//! that −z becomes up, then the camera orbits the shell's centre.

use crate::mesh::Bounds;
use glam::camera::rh::{proj::directx, view};
use glam::{DVec3, Mat4, Vec3};

/// Vertical field of view, radians.
const FOV_Y: f32 = 0.6;
/// Closest and farthest zoom, as multiples of the distance that frames the whole shell.
const ZOOM_RANGE: (f32, f32) = (0.15, 6.0);
/// How far above the horizon the camera looks at first, radians.
const DEFAULT_PITCH: f32 = 0.2;
/// Time constant of the easing towards the grown part, seconds: smooth, yet close behind.
const FOLLOW_TIME: f32 = 0.35;
/// The longest step of the easing one frame takes, seconds. A frame of software rendering can
/// take most of a second, and the view then settles in about the wall time it takes at 60 frames
/// a second (with a quarter of a second a frame, it took four times as long); a longer gap (a tab
/// in the background) moves the view most of the way at once.
const LONGEST_STEP: f32 = 1.0;
/// The smallest framing while following, as a fraction of the final one (the first rims of a
/// shell can be a point).
const SMALLEST_FRAME: f32 = 0.02;
/// How close the easing comes to its framing, as a fraction of the framing's radius, before it
/// ends on it exactly: the view then rests, and a picture of the grown shell is the same
/// however fast the frames came.
const SETTLE: f32 = 1e-3;

/// Turns shell space into display space (apex up).
pub fn display_from_shell() -> Mat4 {
    Mat4::from_rotation_x(std::f32::consts::FRAC_PI_2)
}

/// The yaw (radians, about the display's vertical, from its +z) from which the page first sees
/// a shell whose opening faces `front` (a direction in shell space); the exporters turn files
/// to face the same way. `libm`, so that native and wasm agree bit for bit.
pub fn facing(front: DVec3) -> f64 {
    // Display space is shell space turned by 90° about x: display x is shell x, display z is
    // shell y.
    if front.x == 0.0 && front.y == 0.0 {
        0.0
    } else {
        libm::atan2(front.x, front.y)
    }
}

/// An orbit around the fully grown shell's centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    target: Vec3,
    radius: f32,
    /// The framing of the fully grown shell.
    whole: (Vec3, f32),
    /// Whether the camera follows the growing shell (until the user moves it).
    following: bool,
    /// The yaw that looks into the shell's front (its opening).
    facing: f32,
    default_yaw: f32,
    default_pitch: f32,
    /// Angle around the vertical axis.
    pub yaw: f32,
    /// Angle above the horizon, within ±85°.
    pub pitch: f32,
    /// Distance as a multiple of the one that frames the whole shell.
    pub zoom: f32,
}

impl OrbitCamera {
    /// Frames `bounds`, seen from `front` (a direction in shell space, e.g. where the opening
    /// faces), turned by `yaw` and raised by `pitch` (radians).
    pub fn framing(bounds: &Bounds, front: DVec3, yaw: f32, pitch: f32) -> Self {
        let target = display_from_shell().transform_point3(bounds.center().as_vec3());
        let facing = facing(front) as f32;
        let default_pitch = (DEFAULT_PITCH + pitch).clamp(-1.48, 1.48);
        let radius = (bounds.radius() as f32).max(1e-6);
        Self {
            target,
            radius,
            whole: (target, radius),
            following: false,
            facing,
            default_yaw: facing + yaw,
            default_pitch,
            yaw: facing + yaw,
            pitch: default_pitch,
            zoom: 1.0,
        }
    }

    /// The same framing seen from another first view, turned by `yaw` and raised by `pitch`
    /// (radians) from the front as [`Self::framing`] takes them; the view goes there, as a
    /// reset would take it, and follows the growth if it did.
    pub fn turned(mut self, yaw: f32, pitch: f32) -> Self {
        self.default_yaw = self.facing + yaw;
        self.default_pitch = (DEFAULT_PITCH + pitch).clamp(-1.48, 1.48);
        let following = self.following;
        self.reset(following);
        self
    }

    /// The same view, following the growing shell from `grown`, the part grown so far.
    pub fn following(mut self, grown: &Bounds) -> Self {
        (self.target, self.radius) = self.framing_of(grown);
        self.following = true;
        self
    }

    /// The centre and radius that frame `grown`, in display space.
    fn framing_of(&self, grown: &Bounds) -> (Vec3, f32) {
        if grown.min.x > grown.max.x {
            return self.whole;
        }
        let target = display_from_shell().transform_point3(grown.center().as_vec3());
        let radius = (grown.radius() as f32).max(self.whole.1 * SMALLEST_FRAME);
        (target, radius)
    }

    /// Eases the framing towards `grown` over `dt` seconds (at most [`LONGEST_STEP`]); returns
    /// whether the view changed. Does nothing once the user has moved the camera.
    pub fn follow(&mut self, grown: &Bounds, dt: f32) -> bool {
        if !self.following {
            return false;
        }
        let (target, radius) = self.framing_of(grown);
        let k = 1.0 - (-dt.clamp(0.0, LONGEST_STEP) / FOLLOW_TIME).exp();
        let (t0, r0) = (self.target, self.radius);
        self.target += (target - self.target) * k;
        self.radius += (radius - self.radius) * k;
        let close = SETTLE * radius;
        if self.target.distance(target) < close && (self.radius - radius).abs() < close {
            (self.target, self.radius) = (target, radius);
        }
        self.target != t0 || self.radius != r0
    }

    /// The yaw of the first view: the direction the shell's front faces.
    pub fn front_yaw(&self) -> f32 {
        self.default_yaw
    }

    /// The centre and radius the view frames now, in display space.
    pub fn frame(&self) -> (Vec3, f32) {
        (self.target, self.radius)
    }

    /// Whether the view rests: on its framing of `grown`, or where the user left it.
    pub fn settled(&self, grown: &Bounds) -> bool {
        !self.following || self.framing_of(grown) == (self.target, self.radius)
    }

    /// Back to the first view; a camera that followed the growth follows it again.
    pub fn reset(&mut self, follow: bool) {
        self.yaw = self.default_yaw;
        self.pitch = self.default_pitch;
        self.zoom = 1.0;
        self.following = follow;
        if !follow {
            (self.target, self.radius) = self.whole;
        }
    }

    /// Turns the orbit by a drag of (dx, dy) in fractions of the view's height.
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.following = false;
        self.yaw -= dx * std::f32::consts::PI;
        self.pitch = (self.pitch + dy * std::f32::consts::PI).clamp(-1.48, 1.48);
    }

    /// Zooms by `factor` (> 1 moves closer).
    pub fn zoom_by(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.following = false;
            self.zoom = (self.zoom / factor).clamp(ZOOM_RANGE.0, ZOOM_RANGE.1);
        }
    }

    /// Where the eye is, in display space.
    pub fn eye(&self) -> Vec3 {
        let distance = self.radius / (FOV_Y / 2.0).sin() * self.zoom;
        let dir = Vec3::new(
            self.pitch.cos() * self.yaw.sin(),
            self.pitch.sin(),
            self.pitch.cos() * self.yaw.cos(),
        );
        self.target + dir * distance
    }

    /// Projection × view for a viewport of the given aspect ratio (width / height).
    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        let eye = self.eye();
        let distance = (eye - self.target).length();
        let near = (distance - self.radius * 1.5).max(distance * 0.01);
        let far = distance + self.radius * 1.5;
        // Keep the whole shell in view on narrow (portrait) viewports too.
        let fov = if aspect < 1.0 {
            2.0 * ((FOV_Y / 2.0).tan() / aspect).atan()
        } else {
            FOV_Y
        };
        directx::perspective(fov, aspect.max(1e-3), near, far)
            * view::look_at_mat4(eye, self.target, Vec3::Y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> Bounds {
        Bounds {
            min: DVec3::new(-1.0, -1.0, 0.0),
            max: DVec3::new(1.0, 1.0, 4.0),
        }
    }

    #[test]
    fn the_whole_shell_is_in_view() {
        let b = unit_box();
        for aspect in [0.5, 1.0, 2.0] {
            let cam = OrbitCamera::framing(&b, DVec3::X, 0.0, 0.0);
            let m = cam.view_projection(aspect) * display_from_shell();
            for corner in 0..8 {
                let p = DVec3::new(
                    if corner & 1 == 0 { b.min.x } else { b.max.x },
                    if corner & 2 == 0 { b.min.y } else { b.max.y },
                    if corner & 4 == 0 { b.min.z } else { b.max.z },
                );
                let clip = m * p.as_vec3().extend(1.0);
                let ndc = clip.truncate() / clip.w;
                assert!(
                    ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0,
                    "corner {corner} at {ndc}"
                );
                assert!(ndc.z >= 0.0 && ndc.z <= 1.0);
            }
        }
    }

    #[test]
    fn apex_is_shown_up_and_the_front_faces_the_camera() {
        let b = unit_box();
        let cam = OrbitCamera::framing(&b, DVec3::X, 0.0, 0.0);
        let m = cam.view_projection(1.0) * display_from_shell();
        let project = |p: DVec3| {
            let c = m * p.as_vec3().extend(1.0);
            c.truncate() / c.w
        };
        assert!(project(DVec3::new(0.0, 0.0, 0.0)).y > project(DVec3::new(0.0, 0.0, 4.0)).y);
        // The +x side is nearer the eye than the −x side.
        assert!(project(DVec3::new(1.0, 0.0, 2.0)).z < project(DVec3::new(-1.0, 0.0, 2.0)).z);
    }

    #[test]
    fn zoom_and_pitch_stay_in_range() {
        let mut cam = OrbitCamera::framing(&unit_box(), DVec3::Y, 0.0, 0.0);
        cam.orbit(0.0, 10.0);
        assert!(cam.pitch < 1.5);
        cam.zoom_by(1e9);
        assert!(cam.zoom >= 0.15);
        cam.zoom_by(f32::NAN);
        assert!(cam.zoom.is_finite());
        cam.reset(false);
        assert_eq!(cam.zoom, 1.0);
    }

    #[test]
    fn a_turned_camera_looks_as_one_framed_from_that_side_and_resets_there() {
        let b = unit_box();
        let (yaw, pitch) = (1.2, 0.6);
        let asked = OrbitCamera::framing(&b, DVec3::Y, yaw, pitch);
        let mut moved = OrbitCamera::framing(&b, DVec3::Y, 0.0, 0.0);
        moved.orbit(0.3, -0.2);
        moved.zoom_by(2.0);
        let turned = moved.turned(yaw, pitch);
        assert_eq!(turned.eye(), asked.eye());
        let mut reset = turned;
        reset.orbit(0.5, 0.1);
        reset.reset(false);
        assert_eq!(
            reset.eye(),
            asked.eye(),
            "a reset returns to the turned view"
        );
        assert!(
            OrbitCamera::framing(&b, DVec3::Y, 0.0, 0.0)
                .following(&grown(0.1))
                .turned(yaw, pitch)
                .following,
            "a camera following the growth still follows it"
        );
    }

    fn grown(size: f64) -> Bounds {
        Bounds {
            min: DVec3::new(-size, -size, 0.0),
            max: DVec3::new(size, size, 2.0 * size),
        }
    }

    #[test]
    fn following_frames_what_has_grown_and_eases_without_overshoot() {
        let whole = grown(2.0);
        let mut cam = OrbitCamera::framing(&whole, DVec3::X, 0.0, 0.0).following(&grown(0.1));
        let first = cam.eye();
        // The small part grown so far fills the view: the eye is close to it.
        assert!(
            first.length()
                < OrbitCamera::framing(&whole, DVec3::X, 0.0, 0.0)
                    .eye()
                    .length()
                    / 5.0
        );
        let mut last = cam.radius;
        for frame in 0..240 {
            let size = 0.1 + 1.9 * f64::from(frame) / 239.0;
            cam.follow(&grown(size), 1.0 / 60.0);
            assert!(cam.radius >= last, "the framing never shrinks back");
            assert!(
                cam.radius <= grown(size).radius() as f32 + 1e-6,
                "nor overshoots"
            );
            last = cam.radius;
        }
        for _ in 0..120 {
            cam.follow(&whole, 1.0 / 60.0);
        }
        assert!(
            (cam.radius - whole.radius() as f32).abs() < 1e-3,
            "it settles on the whole"
        );
    }

    #[test]
    fn the_easing_comes_to_rest_on_the_framing_whatever_the_frame_rate() {
        let whole = grown(2.0);
        let mut views = Vec::new();
        for fps in [20.0, 60.0, 144.0] {
            let mut cam = OrbitCamera::framing(&whole, DVec3::X, 0.0, 0.0).following(&grown(0.1));
            let mut frames = 0;
            while cam.follow(&whole, 1.0 / fps) {
                frames += 1;
                assert!(
                    frames < 10_000,
                    "the easing never ends at {fps} frames a second"
                );
            }
            assert!(cam.settled(&whole));
            assert!(!cam.settled(&grown(1.0)), "a larger shell moves it again");
            views.push(cam.eye());
        }
        assert!(views.windows(2).all(|w| w[0] == w[1]), "{views:?}");
    }

    /// Frames `dt` seconds apart until the easing rests on the whole shell.
    fn frames_to_settle(dt: f32) -> u32 {
        let whole = grown(2.0);
        let mut cam = OrbitCamera::framing(&whole, DVec3::X, 0.0, 0.0).following(&grown(0.1));
        let mut frames = 0;
        while cam.follow(&whole, dt) {
            frames += 1;
        }
        frames
    }

    #[test]
    fn slow_frames_settle_in_about_the_wall_time_of_fast_ones() {
        let fast = frames_to_settle(1.0 / 60.0) as f32 / 60.0;
        let slow = frames_to_settle(0.7) as f32 * 0.7;
        assert!(
            slow < 1.5 * fast,
            "0.7 s frames settle in {slow} s, 60 fps in {fast} s"
        );
        let after_an_hour = frames_to_settle(3600.0);
        assert!(
            after_an_hour <= 3,
            "an hour in the background, then {after_an_hour} frames"
        );
    }

    #[test]
    fn the_users_view_wins_until_reset() {
        let whole = grown(2.0);
        let mut cam = OrbitCamera::framing(&whole, DVec3::X, 0.0, 0.0).following(&grown(0.1));
        cam.orbit(0.1, 0.0);
        let held = cam.radius;
        assert!(!cam.follow(&whole, 1.0) && cam.radius == held);
        cam.reset(true);
        assert!(cam.follow(&whole, 1.0) && cam.radius > held);
        let mut still = OrbitCamera::framing(&whole, DVec3::X, 0.0, 0.0);
        assert!(
            !still.follow(&grown(0.1), 1.0),
            "a camera made without following stays framed on the whole"
        );
    }
}
