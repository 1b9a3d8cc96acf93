//! The panes of the viewer's canvas: one perspective view, or Kawaguchi's four (*A
//! morphological study of the form of nature*: "besides a three-dimensional picture consisting
//! of a front-view picture, a side-view picture, and an overview, a picture done by perspective
//! transformation is prepared", figs 2–4), laid out as a first-angle drawing: the front view,
//! the side view seen from its left placed to its right, the overview from above placed below it
//! with the shell's front towards the bottom, and the perspective view the pointer orbits.
//!
//! The three orthographic views share one scale and line up with each other (the front and side
//! views' heights, the front and top views' widths), framed on what has grown so far, so they
//! read as one drawing while the shell grows.

use super::camera::{OrbitCamera, display_from_shell};
use crate::mesh::Bounds;
use crate::share::presentation::Layout;
use glam::camera::rh::{proj::directx, view};
use glam::{Mat4, Vec3, Vec4};

/// The most panes a layout has.
pub const MAX_PANES: usize = 4;

/// Room left around the shell in an orthographic pane, as a fraction of its half-size.
const MARGIN: f32 = 1.08;

/// One pane of the canvas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pane {
    /// What the pane shows, as its label on the page says.
    pub name: &'static str,
    /// Left, top, width and height as fractions of the canvas.
    pub viewport: [f32; 4],
    /// Display space to clip space.
    pub view_projection: Mat4,
    /// The eye in display space: a point (w = 1) for a perspective view, the direction
    /// towards the viewer (w = 0) for an orthographic one, whose rays are parallel.
    pub eye: Vec4,
}

/// Where a pane lies on the canvas and what it shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Place {
    pub name: &'static str,
    /// Left, top, width and height as fractions of the canvas.
    pub viewport: [f32; 4],
}

const fn place(name: &'static str, viewport: [f32; 4]) -> Place {
    Place { name, viewport }
}

const SINGLE: [Place; 1] = [place("Perspective", [0.0, 0.0, 1.0, 1.0])];
const FOUR: [Place; 4] = [
    place("Front", [0.0, 0.0, 0.5, 0.5]),
    place("Side", [0.5, 0.0, 0.5, 0.5]),
    place("Top", [0.0, 0.5, 0.5, 0.5]),
    place("Perspective", [0.5, 0.5, 0.5, 0.5]),
];

/// Where each pane of `layout` lies: the perspective view last.
pub fn arrangement(layout: Layout) -> &'static [Place] {
    match layout {
        Layout::Single => &SINGLE,
        Layout::Four => &FOUR,
    }
}

/// An orthographic view: where it lies, the direction it looks from and the direction that is
/// up in it.
struct Orthographic {
    place: Place,
    from: Vec3,
    up: Vec3,
}

/// The panes of `layout` on a canvas of aspect `aspect` (width / height), for `camera` (the
/// perspective view) and `grown`, the part of the shell grown so far in shell space.
pub fn panes(layout: Layout, camera: &OrbitCamera, grown: &Bounds, aspect: f32) -> Vec<Pane> {
    let places = arrangement(layout);
    let (views, [perspective]) = places.split_at(places.len() - 1) else {
        unreachable!("every layout ends with its perspective view")
    };
    let mut panes = match views {
        [front, side, top] => orthographic_views(camera, grown, aspect, [*front, *side, *top]),
        _ => Vec::new(),
    };
    let [_, _, width, height] = perspective.viewport;
    panes.push(Pane {
        name: perspective.name,
        viewport: perspective.viewport,
        view_projection: camera.view_projection(aspect * width / height),
        eye: camera.eye().extend(1.0),
    });
    panes
}

/// The front, side and top views, each a quarter of a canvas of aspect `aspect`, at one scale.
fn orthographic_views(
    camera: &OrbitCamera,
    grown: &Bounds,
    aspect: f32,
    [front_place, side_place, top_place]: [Place; 3],
) -> Vec<Pane> {
    let yaw = camera.front_yaw();
    let front = Vec3::new(yaw.sin(), 0.0, yaw.cos());
    let left = Vec3::new(-yaw.cos(), 0.0, yaw.sin());
    let views = [
        Orthographic {
            place: front_place,
            from: front,
            up: Vec3::Y,
        },
        Orthographic {
            place: side_place,
            from: left,
            up: Vec3::Y,
        },
        Orthographic {
            place: top_place,
            from: Vec3::Y,
            up: -front,
        },
    ];
    let (centre, corners, radius) = match display_box(grown) {
        Some(corners) => {
            let centre = corners.iter().sum::<Vec3>() / 8.0;
            let radius = corners
                .iter()
                .map(|c| c.distance(centre))
                .fold(0.0, f32::max);
            (centre, corners, radius.max(1e-6))
        }
        None => {
            let (centre, radius) = camera.frame();
            let corners = std::array::from_fn(|i| {
                centre + Vec3::new(sign(i, 1), sign(i, 2), sign(i, 4)) * radius
            });
            (centre, corners, radius)
        }
    };
    let looks: Vec<Mat4> = views
        .iter()
        .map(|v| view::look_at_mat4(centre + v.from * radius * 2.0, centre, v.up))
        .collect();
    // One scale for all three: the largest half-size any of them needs.
    let extents: Vec<(Vec3, Vec3)> = looks
        .iter()
        .map(|look| {
            corners.iter().fold(
                (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
                |(lo, hi), c| {
                    let p = look.transform_point3(*c);
                    (lo.min(p), hi.max(p))
                },
            )
        })
        .collect();
    let half = extents
        .iter()
        .map(|(lo, hi)| ((hi.x - lo.x) / aspect).max(hi.y - lo.y) * 0.5)
        .fold(0.0, f32::max)
        .max(1e-6)
        * MARGIN;
    views
        .iter()
        .zip(looks.iter().zip(&extents))
        .map(|(v, (look, (lo, hi)))| {
            let mid = (*lo + *hi) * 0.5;
            let (near, far) = (-hi.z - radius, -lo.z + radius);
            Pane {
                name: v.place.name,
                viewport: v.place.viewport,
                view_projection: directx::orthographic(
                    mid.x - half * aspect,
                    mid.x + half * aspect,
                    mid.y - half,
                    mid.y + half,
                    near,
                    far,
                ) * *look,
                eye: v.from.extend(0.0),
            }
        })
        .collect()
}

fn sign(i: usize, bit: usize) -> f32 {
    if i & bit == 0 { -1.0 } else { 1.0 }
}

/// The corners of `grown` in display space, when anything has grown.
fn display_box(grown: &Bounds) -> Option<[Vec3; 8]> {
    (!grown.is_empty()).then(|| {
        grown
            .corners()
            .map(|c| display_from_shell().transform_point3(c.as_vec3()))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn tusk() -> Bounds {
        Bounds {
            min: DVec3::new(-0.5, -0.5, 0.0),
            max: DVec3::new(0.5, 0.5, 6.0),
        }
    }

    fn camera() -> OrbitCamera {
        OrbitCamera::framing(&tusk(), DVec3::X, 0.0, 0.0)
    }

    /// Where a point of shell space lands in a pane, in normalised device coordinates.
    fn project(pane: &Pane, p: DVec3) -> Vec3 {
        let clip = pane.view_projection
            * display_from_shell()
                .transform_point3(p.as_vec3())
                .extend(1.0);
        clip.truncate() / clip.w
    }

    #[test]
    fn one_pane_is_the_perspective_view() {
        let panes = panes(Layout::Single, &camera(), &tusk(), 1.5);
        assert_eq!(panes.len(), 1);
        assert_eq!(panes[0].viewport, [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(panes[0].eye, camera().eye().extend(1.0));
    }

    #[test]
    fn four_panes_tile_the_canvas() {
        let panes = panes(Layout::Four, &camera(), &tusk(), 1.5);
        let names: Vec<_> = panes.iter().map(|p| p.name).collect();
        assert_eq!(names, ["Front", "Side", "Top", "Perspective"]);
        let area: f32 = panes.iter().map(|p| p.viewport[2] * p.viewport[3]).sum();
        assert!((area - 1.0).abs() < 1e-6);
        for (i, a) in panes.iter().enumerate() {
            for b in &panes[i + 1..] {
                let apart = a.viewport[0] + a.viewport[2] <= b.viewport[0]
                    || b.viewport[0] + b.viewport[2] <= a.viewport[0]
                    || a.viewport[1] + a.viewport[3] <= b.viewport[1]
                    || b.viewport[1] + b.viewport[3] <= a.viewport[1];
                assert!(apart, "{} overlaps {}", a.name, b.name);
            }
        }
    }

    #[test]
    fn orthographic_views_keep_parallel_lines_parallel_and_frame_the_shell() {
        let panes = panes(Layout::Four, &camera(), &tusk(), 1.0);
        for pane in &panes[..3] {
            assert_eq!(pane.eye.w, 0.0, "{} is orthographic", pane.name);
            // The two sides of a straight tusk, near its base and near its tip: an orthographic
            // view draws them the same distance apart however far they are from the eye.
            let width = |z: f64| {
                let a = project(pane, DVec3::new(0.5, 0.5, z));
                let b = project(pane, DVec3::new(-0.5, -0.5, z));
                (a - b).truncate().length()
            };
            assert!(
                (width(0.0) - width(6.0)).abs() < 1e-5,
                "{}: {} against {}",
                pane.name,
                width(0.0),
                width(6.0)
            );
            for c in tusk().corners() {
                let p = project(pane, c);
                assert!(
                    p.x.abs() <= 1.0 && p.y.abs() <= 1.0,
                    "{}: {c} at {p}",
                    pane.name
                );
                assert!(
                    (0.0..=1.0).contains(&p.z),
                    "{}: {c} clipped at {p}",
                    pane.name
                );
            }
        }
        // The perspective view does make them converge: the comparison above can fail.
        let perspective = &panes[3];
        let width = |z: f64| {
            let a = project(perspective, DVec3::new(0.5, 0.0, z));
            let b = project(perspective, DVec3::new(-0.5, 0.0, z));
            (a - b).truncate().length()
        };
        assert!((width(0.0) - width(6.0)).abs() > 1e-3);
    }

    #[test]
    fn the_three_views_share_one_scale_and_line_up() {
        let panes = panes(Layout::Four, &camera(), &tusk(), 1.3);
        let [front, side, top] = [&panes[0], &panes[1], &panes[2]];
        let (apex, mouth) = (DVec3::ZERO, DVec3::new(0.0, 0.0, 6.0));
        // Front and side: the same heights (the shell's axis is vertical on screen).
        for p in [apex, mouth] {
            assert!((project(front, p).y - project(side, p).y).abs() < 1e-5);
        }
        // Front and top: the same widths, one above the other.
        for p in [DVec3::new(0.0, 0.5, 3.0), DVec3::new(0.0, -0.5, 3.0)] {
            assert!((project(front, p).x - project(top, p).x).abs() < 1e-5);
        }
        // The tusk stands upright in the front view, apex up, and is seen end on from the top.
        assert!(project(front, apex).y > project(front, mouth).y);
        let on_top = (project(top, apex) - project(top, mouth))
            .truncate()
            .length();
        assert!(
            on_top < 1e-5,
            "the axis is a point from above, not {on_top}"
        );
    }

    #[test]
    fn nothing_grown_yet_still_frames_the_views() {
        let panes = panes(Layout::Four, &camera(), &Bounds::EMPTY, 1.0);
        for pane in &panes {
            assert!(pane.view_projection.is_finite(), "{}", pane.name);
        }
    }
}
