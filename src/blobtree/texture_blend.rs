//! Texturing an implicit surface by blending (Galbraith, Prusinkiewicz & Wyvill §3.4, after
//! Tigges & Wyvill 1999): every primitive carries its own texture, and where primitives blend,
//! the colour at a surface point is the linear combination of their colours, each weighted by
//! its field there. Three kinds of texture ([`Look`]): the shell's pattern, which the body whorl
//! keeps on its growing edge; a colour ramp along the primitive's own parameterisation (a
//! spine from its base to its tip, a bump from its rim to its top); and an image, a 2D texture
//! map ([`ImageMap`]) on that parameterisation or on the growth's.
//!
//! The pattern's colour is only known where the page or an export samples the pattern, so the
//! primitives showing it blend their pattern coordinates among themselves (growth time, and
//! position along the generating curve averaged as an angle on the unit circle: 0.99 and 0.01
//! blend to 0, not to 0.5), and the blend keeps their share of the field; the colours of
//! the ramps and images are summed, weighted, at once. A surface point's colour is then
//! share · pattern(coordinates) + Σ fᵢ·colourᵢ / Σ fⱼ, the first sum over the ramps and
//! images, the second over all: see [`Paint::tint`].

use super::image_map::ImageMap;
use super::primitive::Primitive;
use glam::{DAffine3, DVec3};
use std::f64::consts::TAU;

/// How a primitive is coloured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Look {
    /// The shell's pattern, at the primitive's pattern coordinates.
    Pattern,
    /// A ramp in linear light from `base` to `tip` along the primitive's own parameterisation
    /// t ([`Primitive::along`]): the colour at t is base + (tip − base)·s^shade, with
    /// s = (t − start)/(1 − start) clamped to [0, 1], so that the ramp starts where the part
    /// leaves the surface it stands on.
    Ramp {
        base: [f64; 3],
        tip: [f64; 3],
        shade: f64,
        start: f64,
    },
    /// The image `map`, in linear light, on the primitive ([`MapOn`]).
    Image { map: &'static ImageMap, on: MapOn },
}

/// Where an image lies on a primitive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MapOn {
    /// On the primitive's own parameterisation, as the paper maps textures onto spines and
    /// bumps ([`Primitive::mapped`]): across the image around it, along it from `start` of the
    /// way along the primitive to its tip, as a ramp runs.
    Part { start: f64 },
    /// On the growth's parameterisation, the pattern's own: across the image along the
    /// generating curve, along it the growth time over `rows` rows. The paper maps the body's
    /// image onto a bounding surface's parameterisation for the same end: one image running on
    /// over every generating surface.
    Growth { rows: f64 },
}

impl Look {
    /// How far t along a primitive lies from `start` to its tip, in [0, 1]: where a part's ramp
    /// or image runs from where it leaves the surface it stands on.
    fn past_start(start: f64, t: f64) -> f64 {
        if start < 1.0 {
            ((t - start) / (1.0 - start)).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    /// The ramp's colour (linear light) at t along its primitive.
    pub fn ramp(base: [f64; 3], tip: [f64; 3], shade: f64, start: f64, t: f64) -> [f64; 3] {
        let s = libm::pow(Self::past_start(start, t), shade);
        std::array::from_fn(|k| base[k] + (tip[k] - base[k]) * s)
    }
}

/// The texture a primitive carries: how it looks, and its pattern coordinates: its growth
/// time, and, for its position along the generating curve, the angle of a point about the w
/// axis of the generating surface, measured in the generating curve's plane from +u (towards
/// the shell axis, where whorls meet and the pattern's seam hides) through +v.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texture {
    /// Growth time, in pattern rows.
    pub time: f64,
    /// Carries the primitive's coordinates to the generating surface's.
    frame: DAffine3,
    pub look: Look,
}

impl Texture {
    /// Coordinates of a primitive in the generating surface's own space, showing the pattern.
    pub fn around(time: f64) -> Self {
        Self {
            time,
            frame: DAffine3::IDENTITY,
            look: Look::Pattern,
        }
    }

    /// The same texture with another look.
    pub fn looking(self, look: Look) -> Self {
        Self { look, ..self }
    }

    /// The same coordinates for a primitive expressed in new coordinates, `inverse` carrying
    /// the new coordinates to the old (the inverse of the map that moved it).
    pub fn moved(self, inverse: DAffine3) -> Self {
        Self {
            frame: self.frame * inverse,
            ..self
        }
    }

    /// The direction of the point `p` about the w axis, as (cos, sin) of its angle from +u:
    /// the position along the curve, without trigonometry. (1, 0) on the axis itself.
    fn direction_at(&self, p: DVec3) -> (f64, f64) {
        let q = self.frame.transform_point3(p);
        let length = (q.x * q.x + q.y * q.y).sqrt();
        if length > 0.0 {
            (q.x / length, q.y / length)
        } else {
            (1.0, 0.0)
        }
    }
}

/// Field-weighted sums of the primitives' textures around a point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Paint {
    /// Σ f over every primitive.
    weight: f64,
    /// Σ f over the primitives showing the pattern.
    shown: f64,
    /// Σ f·(cos, sin, time) over the primitives showing the pattern.
    pattern: [f64; 3],
    /// The same over the others, whose coordinates serve only where no pattern shows (for the
    /// growth lines and the depth into the opening).
    rest: [f64; 3],
    /// Σ f·colour over the ramps and images, linear light.
    rgb: [f64; 3],
    /// Whether the point lies on a surface carved by a CSG difference: the inside of a wall.
    pub inner: bool,
}

impl Paint {
    /// The texture of `primitive` at its local point `p`, weighted by its field `f`.
    pub fn of(texture: &Texture, primitive: &Primitive, p: DVec3, f: f64) -> Self {
        let (cos, sin) = texture.direction_at(p);
        let coordinates = [f * cos, f * sin, f * texture.time];
        match texture.look {
            Look::Pattern => Self {
                weight: f,
                shown: f,
                pattern: coordinates,
                ..Self::default()
            },
            Look::Ramp {
                base,
                tip,
                shade,
                start,
            } => Self::coloured(
                Look::ramp(base, tip, shade, start, primitive.along(p)),
                coordinates,
                f,
            ),
            Look::Image { map, on } => {
                let (across, along) = match on {
                    MapOn::Part { start } => {
                        let [around, t] = primitive.mapped(p);
                        (around, Look::past_start(start, t))
                    }
                    MapOn::Growth { rows } => (
                        (libm::atan2(sin, cos) / TAU).rem_euclid(1.0),
                        texture.time / rows.max(1.0),
                    ),
                };
                Self::coloured(map.at(across, along), coordinates, f)
            }
        }
    }

    /// A colour known here, `colour`, weighted by the field `f`, with the pattern
    /// `coordinates` serving where no pattern shows.
    fn coloured(colour: [f64; 3], coordinates: [f64; 3], f: f64) -> Self {
        Self {
            weight: f,
            rest: coordinates,
            rgb: colour.map(|c| f * c),
            ..Self::default()
        }
    }

    /// The same contribution, on a carved surface.
    pub fn carved(self) -> Paint {
        Paint {
            inner: true,
            ..self
        }
    }

    /// (position along the curve in [0, 1), growth time): the weighted averages over the
    /// primitives showing the pattern, or where none does, over all.
    pub fn coordinates(&self) -> [f64; 2] {
        let ([cos, sin, time], weight) = if self.shown > 0.0 {
            (self.pattern, self.shown)
        } else {
            (self.rest, self.weight)
        };
        if weight <= 0.0 {
            return [0.0, 0.0];
        }
        let along = (libm::atan2(sin, cos) / TAU).rem_euclid(1.0);
        [along, time / weight]
    }

    /// The blend of colours that are known here, as (r, g, b, share): the ramps' and images' colours
    /// summed in linear light, each weighted by its field over the sum of all fields, and the
    /// pattern's share of the fields. The colour at the point is share · pattern + (r, g, b).
    /// A point no primitive reaches shows the pattern alone.
    pub fn tint(&self) -> [f64; 4] {
        if self.weight <= 0.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let [r, g, b] = self.rgb.map(|c| c / self.weight);
        [r, g, b, self.shown / self.weight]
    }
}

impl std::ops::Add for Paint {
    type Output = Paint;

    /// The sum of two blended contributions.
    fn add(self, other: Paint) -> Paint {
        Paint {
            weight: self.weight + other.weight,
            shown: self.shown + other.shown,
            pattern: std::array::from_fn(|k| self.pattern[k] + other.pattern[k]),
            rest: std::array::from_fn(|k| self.rest[k] + other.rest[k]),
            rgb: std::array::from_fn(|k| self.rgb[k] + other.rgb[k]),
            inner: self.inner || other.inner,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const POINT: Primitive = Primitive::Point {
        centre: DVec3::ZERO,
        radius: 1.0,
    };

    #[test]
    fn coordinates_blend_by_weight_and_wrap_around_the_curve() {
        let (a, b) = (Texture::around(10.0), Texture::around(20.0));
        let at = |turn: f64| DVec3::new((turn * TAU).cos(), (turn * TAU).sin(), 0.3);
        let (pa, pb) = (at(0.98), at(0.04));
        let blend = Paint::of(&a, &POINT, pa, 1.0) + Paint::of(&b, &POINT, pb, 1.0);
        let [along, time] = blend.coordinates();
        assert!((time - 15.0).abs() < 1e-12);
        assert!((along - 0.01).abs() < 1e-9, "{along}");
        let weighted =
            Paint::of(&a, &POINT, DVec3::ZERO, 3.0) + Paint::of(&b, &POINT, DVec3::ZERO, 1.0);
        assert!((weighted.coordinates()[1] - 12.5).abs() < 1e-12);
    }

    #[test]
    fn the_angle_runs_around_the_local_w_axis_from_u() {
        let t = Texture::around(0.0);
        let at = |p: DVec3| Paint::of(&t, &POINT, p, 1.0).coordinates()[0];
        assert!(at(DVec3::new(1.0, 0.0, 5.0)).abs() < 1e-12);
        assert!((at(DVec3::new(0.0, 1.0, 0.0)) - 0.25).abs() < 1e-12);
        assert!((at(DVec3::new(-1.0, 1e-9, 0.0)) - 0.5).abs() < 1e-6);
    }

    #[test]
    fn ramps_blend_as_colours_and_leave_the_pattern_its_share() {
        let cone = Primitive::Cone {
            from: DVec3::ZERO,
            to: DVec3::X * 2.0,
            radii: [1.0, 0.5],
        };
        let look = Look::Ramp {
            base: [1.0, 0.5, 0.0],
            tip: [0.0, 0.5, 1.0],
            shade: 1.0,
            start: 0.0,
        };
        let spine = Texture::around(7.0).looking(look);
        let body = Texture::around(3.0);
        // A quarter of the way along the spine, its colour is a quarter of the way to the tip.
        let [r, g, b, share] = Paint::of(&spine, &cone, DVec3::X * 0.5, 0.8).tint();
        assert!((r - 0.75).abs() < 1e-12 && (g - 0.5).abs() < 1e-12 && (b - 0.25).abs() < 1e-12);
        assert_eq!(share, 0.0);
        // Blended 3 : 1 with the body: three quarters of the ramp's colour, a quarter of the
        // pattern, whose coordinates are the body's alone.
        let blend =
            Paint::of(&spine, &cone, DVec3::X * 0.5, 0.6) + Paint::of(&body, &POINT, DVec3::X, 0.2);
        let [r, _, b, share] = blend.tint();
        assert!((r - 0.5625).abs() < 1e-12 && (b - 0.1875).abs() < 1e-12);
        assert!((share - 0.25).abs() < 1e-12);
        assert!((blend.coordinates()[1] - 3.0).abs() < 1e-12);
        // On the spine alone, its own coordinates.
        let alone = Paint::of(&spine, &cone, DVec3::X * 0.5, 0.6);
        assert!((alone.coordinates()[1] - 7.0).abs() < 1e-12);
        // Nothing here: the pattern alone.
        assert_eq!(Paint::default().tint(), [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn a_ramp_starts_where_its_part_leaves_the_surface_and_bends_by_its_shade() {
        let ramp = |shade, t| Look::ramp([0.0; 3], [1.0; 3], shade, 0.2, t)[0];
        assert_eq!(ramp(1.0, 0.1), 0.0);
        assert!((ramp(1.0, 0.6) - 0.5).abs() < 1e-12);
        assert!((ramp(2.0, 0.6) - 0.25).abs() < 1e-12);
        assert_eq!(ramp(2.0, 1.0), 1.0);
    }
}
