//! Where an exported shell stands: turned apex up and facing the way the page first shows it,
//! scaled to the height asked for, standing on the ground centred on the vertical axis. glTF's
//! up is +y and its front +z; 3MF's up is +z and a slicer's front −y.

use crate::mesh::Bounds;
use glam::{DQuat, DVec3};

/// The turn from shell space (axis along z, apex towards −z) to a file's axes.
pub(crate) fn turn(facing: f64, z_up: bool) -> DQuat {
    let half = std::f64::consts::FRAC_PI_4;
    let quaternion = |axis: DVec3, half_angle: f64| {
        let (s, c) = (libm::sin(half_angle), libm::cos(half_angle));
        DQuat::from_xyzw(axis.x * s, axis.y * s, axis.z * s, c)
    };
    // Apex up (y), as the page shows it (`display_from_shell`), then the page's first view
    // turned to the front.
    let apex_up = quaternion(DVec3::X, half);
    let y_up = quaternion(DVec3::Y, -facing / 2.0) * apex_up;
    if z_up {
        quaternion(DVec3::X, half) * y_up
    } else {
        y_up
    }
}

/// The scale and translation that make the turned shell `bounds` `height` tall along `up`
/// (1 for y, 2 for z), standing at 0 on it and centred on the other two axes: a point p of the
/// turned shell goes to `translation + scale · p`.
pub(crate) fn fit(bounds: &Bounds, height: f64, up: usize) -> (f64, DVec3) {
    let extent = bounds.max[up] - bounds.min[up];
    let scale = if extent > 0.0 { height / extent } else { 1.0 };
    let mut anchor = bounds.center();
    anchor[up] = bounds.min[up];
    (scale, -anchor * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        a.distance(b) < 1e-12
    }

    #[test]
    fn the_apex_goes_up_and_the_first_view_to_the_front() {
        // The apex is towards −z in shell space; the opening faces +x, where the page looks
        // from (facing = atan2(x, y) = 90°).
        let facing = std::f64::consts::FRAC_PI_2;
        let apex = DVec3::NEG_Z;
        let front = DVec3::X;
        let y_up = turn(facing, false);
        assert!(close(y_up * apex, DVec3::Y));
        assert!(close(y_up * front, DVec3::Z));
        let z_up = turn(facing, true);
        assert!(close(z_up * apex, DVec3::Z));
        assert!(close(z_up * front, DVec3::NEG_Y));
    }

    #[test]
    fn a_fitted_shell_stands_on_the_ground_at_its_height() {
        let bounds = Bounds {
            min: DVec3::new(1.0, 2.0, 3.0),
            max: DVec3::new(3.0, 6.0, 7.0),
        };
        let (scale, t) = fit(&bounds, 80.0, 2);
        assert_eq!(scale, 20.0);
        assert!(close(t + bounds.min * scale, DVec3::new(-20.0, -40.0, 0.0)));
        assert!(close(t + bounds.max * scale, DVec3::new(20.0, 40.0, 80.0)));
    }
}
