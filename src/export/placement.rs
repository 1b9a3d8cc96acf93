//! Where an exported shell stands: turned apex up and facing the way the page first shows it,
//! scaled to the size asked for, standing on the ground centred on the vertical axis. glTF's
//! up is +y and its front +z; 3MF's up is +z and a slicer's front −y.

use super::print_size::PrintSize;
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

/// The scale and translation that make the turned shell `bounds` `size` long along the side
/// it names (in units of `unit_mm` millimetres) in a file whose up axis is `up` (1 for y, 2
/// for z), standing at 0 on it and centred on the other two axes: a point p of the turned shell
/// goes to `translation + scale · p`.
pub(crate) fn fit(bounds: &Bounds, size: PrintSize, unit_mm: f64, up: usize) -> (f64, DVec3) {
    let sides = bounds.max - bounds.min;
    let extent = match size.side().file_axis(up) {
        Some(axis) => sides[axis],
        None => sides.max_element(),
    };
    let length = size.mm() / unit_mm;
    let scale = if extent > 0.0 { length / extent } else { 1.0 };
    let mut anchor = bounds.center();
    anchor[up] = bounds.min[up];
    (scale, -anchor * scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::print_size::Along;

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
    fn a_fitted_shell_stands_on_the_ground_at_its_size() {
        let bounds = Bounds {
            min: DVec3::new(1.0, 2.0, 3.0),
            max: DVec3::new(3.0, 6.0, 5.0),
        };
        let size = PrintSize::new(80.0, "size").unwrap();
        // The largest side (y, 4 long) is 80 mm.
        let (scale, t) = fit(&bounds, size, 1.0, 2);
        assert_eq!(scale, 20.0);
        assert!(close(t + bounds.min * scale, DVec3::new(-20.0, -40.0, 0.0)));
        assert!(close(t + bounds.max * scale, DVec3::new(20.0, 40.0, 40.0)));
        // Up (z in a 3MF, 2 long) is 80 mm; in metres for a glTF, whose up is y (4 long).
        assert_eq!(fit(&bounds, size.along(Along::Z), 1.0, 2).0, 40.0);
        assert_eq!(fit(&bounds, size.along(Along::Z), 1000.0, 1).0, 0.02);
        // Across is x in both; the depth is y in a 3MF and z in a glTF.
        assert_eq!(fit(&bounds, size.along(Along::X), 1.0, 2).0, 40.0);
        assert_eq!(fit(&bounds, size.along(Along::Y), 1.0, 2).0, 20.0);
        assert_eq!(fit(&bounds, size.along(Along::Y), 1.0, 1).0, 40.0);
    }
}
