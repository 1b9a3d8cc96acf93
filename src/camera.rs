//! The orbit camera: pure arithmetic, so that the renderer only uploads its matrices.
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

/// Turns shell space into display space (apex up).
pub fn display_from_shell() -> Mat4 {
    Mat4::from_rotation_x(std::f32::consts::FRAC_PI_2)
}

/// An orbit around the fully grown shell's centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    target: Vec3,
    radius: f32,
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
        let display = display_from_shell();
        let target = display.transform_point3(bounds.center().as_vec3());
        let f = display.transform_vector3(front.as_vec3());
        let facing = if f.x == 0.0 && f.z == 0.0 {
            0.0
        } else {
            f.x.atan2(f.z)
        };
        let default_pitch = (DEFAULT_PITCH + pitch).clamp(-1.48, 1.48);
        Self {
            target,
            radius: (bounds.radius() as f32).max(1e-6),
            default_yaw: facing + yaw,
            default_pitch,
            yaw: facing + yaw,
            pitch: default_pitch,
            zoom: 1.0,
        }
    }

    /// Back to the first view.
    pub fn reset(&mut self) {
        self.yaw = self.default_yaw;
        self.pitch = self.default_pitch;
        self.zoom = 1.0;
    }

    /// Turns the orbit by a drag of (dx, dy) in fractions of the view's height.
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.yaw -= dx * std::f32::consts::PI;
        self.pitch = (self.pitch + dy * std::f32::consts::PI).clamp(-1.48, 1.48);
    }

    /// Zooms by `factor` (> 1 moves closer).
    pub fn zoom_by(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
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
        cam.reset();
        assert_eq!(cam.zoom, 1.0);
    }
}
