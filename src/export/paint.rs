//! The one mapping from a point of the shell to its colour, as the page paints it, for every
//! export that carries colour (the GLB's texture and materials, the PLY's and the 3MF's vertex
//! colours).
//!
//! The page (shaders/shell.wgsl) paints the outer surface with the planar pattern, an sRGB
//! texture whose texel (cell c, row r) is `ground.mix(pigment, shade)` as [`PatternRun`]
//! records it; it samples that texture bilinearly, in linear light, at the vertex's pattern
//! coordinates (x along the growing edge in [0, 1], onto the centres of the first and last
//! cells; y in rows, on row centres), clamped at the edges. The outer surface of a shell
//! without a pattern is the ground colour. Where an implicit shell's parts blend (Galbraith et
//! al. §3.4), the vertex's tint adds the parts' ramp colours to the pattern's share of it, in
//! linear light. The inner surface and the edges (lip, caps) are the interior colour.
//! [`Paint::colour`] is that mapping, and [`Paint::uv`] places the same pattern coordinates on
//! [`Texture`], the image a glTF viewer filters to the same colours.

use crate::mesh::Vertex;
use crate::pattern::run::PatternRun;
use crate::spec::Colours;
use crate::spec::colour::{Rgb, linear};

/// The most rows the exported texture has: a longer pattern (only links with very few cells
/// can have one) is averaged a whole number of rows to a texel, so that every viewer can load
/// it. Every preset's pattern fits (the longest has 3,900 rows).
pub const MAX_TEXTURE_ROWS: usize = 4096;

/// The pattern as it stands: `rows` rows of `cells` RGBA texels, as [`PatternRun::rgba`].
#[derive(Clone, Copy, Debug)]
pub struct PatternImage<'a> {
    pub cells: usize,
    pub rows: usize,
    pub rgba: &'a [u8],
}

impl<'a> From<&'a PatternRun> for PatternImage<'a> {
    fn from(run: &'a PatternRun) -> Self {
        Self {
            cells: run.cells(),
            rows: run.rows(),
            rgba: run.rgba(),
        }
    }
}

/// The coloured pattern as an image, `width` cells by `height` texel rows, sRGB, three bytes a
/// texel; each texel row is `rows_per_texel` pattern rows (one, unless the pattern is longer
/// than [`MAX_TEXTURE_ROWS`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub width: usize,
    pub height: usize,
    pub rgb: Vec<u8>,
    pub rows_per_texel: usize,
}

/// How a shell is painted.
#[derive(Clone, Debug, PartialEq)]
pub struct Paint {
    ground: Rgb,
    interior: Rgb,
    texture: Option<Texture>,
    /// sRGB byte to linear light.
    linear: [f32; 256],
}

impl Paint {
    /// The paint of a shell with these colours and, when it has one, this pattern.
    pub fn new(colours: &Colours, pattern: Option<PatternImage>) -> Self {
        let linear = std::array::from_fn(|i| linear(i as u8));
        let texture = pattern
            .filter(|p| p.cells > 0 && p.rows > 0)
            .map(|p| texture(p, &linear));
        Self {
            ground: colours.ground,
            interior: colours.interior,
            texture,
            linear,
        }
    }

    /// The pattern as an image, when the shell has one.
    pub fn texture(&self) -> Option<&Texture> {
        self.texture.as_ref()
    }

    /// The ground colour (the outer surface where no pattern paints it), sRGB.
    pub fn ground(&self) -> [u8; 3] {
        self.ground.0
    }

    /// The interior colour (inner surface, lip and caps), sRGB.
    pub fn interior(&self) -> [u8; 3] {
        self.interior.0
    }

    /// An sRGB colour in linear light, as a viewer reads a material's colour factor.
    pub fn linear(&self, srgb: [u8; 3]) -> [f32; 3] {
        srgb.map(|c| self.linear[usize::from(c)])
    }

    /// Where pattern coordinates `at` fall on [`Texture`], in texture coordinates (0 to 1
    /// across, 0 to 1 down): x = 0 and 1 on the centres of the first and last cells, row y on
    /// the centre of its row, as the page's shader samples them.
    pub fn uv(&self, at: [f32; 2]) -> [f32; 2] {
        let Some(t) = &self.texture else {
            return [0.5, 0.5];
        };
        let cells = t.width as f32;
        let rows = (t.height * t.rows_per_texel) as f32;
        [(at[0] * (cells - 1.0) + 0.5) / cells, (at[1] + 0.5) / rows]
    }

    /// The colour of a vertex of the shell (sRGB), as the page paints it: the pattern on the
    /// outer surface, sampled at the vertex's pattern coordinates (the ground colour there
    /// when there is no pattern), times the pattern's share of the vertex's tint, plus the
    /// tint's blended colours; the interior colour on the inner surface and the edges.
    pub fn colour(&self, vertex: &Vertex) -> [u8; 3] {
        if !vertex.is_outer() {
            return self.interior.0;
        }
        let pattern = match &self.texture {
            Some(t) => self.sample(t, self.uv(vertex.pattern)),
            None => self.linear(self.ground.0),
        };
        let [r, g, b, share] = vertex.tint;
        let tint = [r, g, b];
        std::array::from_fn(|k| to_srgb(share * pattern[k] + tint[k]))
    }

    /// Whether some vertex of `vertices` on the outer surface is not the pattern alone: its
    /// colour is not the texture's (a viewer multiplies a texture by vertex colours, it
    /// cannot add them), so the export carries colours per vertex.
    pub fn tinted(vertices: &[Vertex]) -> bool {
        vertices
            .iter()
            .any(|v| v.is_outer() && v.tint != [0.0, 0.0, 0.0, 1.0])
    }

    /// The texture filtered bilinearly in linear light at `uv`, clamped at its edges, as a
    /// viewer's sampler (and the page's shader) filters it.
    fn sample(&self, t: &Texture, [u, v]: [f32; 2]) -> [f32; 3] {
        let x = (u * t.width as f32 - 0.5).clamp(0.0, (t.width - 1) as f32);
        let y = (v * t.height as f32 - 0.5).clamp(0.0, (t.height - 1) as f32);
        let (x0, y0) = (x as usize, y as usize);
        let (fx, fy) = (x - x0 as f32, y - y0 as f32);
        let (x1, y1) = ((x0 + 1).min(t.width - 1), (y0 + 1).min(t.height - 1));
        let texel = |cx: usize, ry: usize, k: usize| {
            self.linear[usize::from(t.rgb[(ry * t.width + cx) * 3 + k])]
        };
        std::array::from_fn(|k| {
            let top = texel(x0, y0, k) * (1.0 - fx) + texel(x1, y0, k) * fx;
            let bottom = texel(x0, y1, k) * (1.0 - fx) + texel(x1, y1, k) * fx;
            top * (1.0 - fy) + bottom * fy
        })
    }
}

/// The pattern's texels as RGB, `rows_per_texel` rows averaged (in linear light) to a texel row.
fn texture(p: PatternImage, linear: &[f32; 256]) -> Texture {
    let rows_per_texel = p.rows.div_ceil(MAX_TEXTURE_ROWS);
    let height = p.rows.div_ceil(rows_per_texel);
    let mut rgb = Vec::with_capacity(p.cells * height * 3);
    if rows_per_texel == 1 {
        rgb.extend(
            p.rgba[..p.cells * p.rows * 4]
                .chunks_exact(4)
                .flat_map(|px| [px[0], px[1], px[2]]),
        );
    } else {
        for texel_row in 0..height {
            let rows = texel_row * rows_per_texel..((texel_row + 1) * rows_per_texel).min(p.rows);
            let n = rows.len() as f32;
            for cell in 0..p.cells {
                for k in 0..3 {
                    let sum: f32 = rows
                        .clone()
                        .map(|r| linear[usize::from(p.rgba[(r * p.cells + cell) * 4 + k])])
                        .sum();
                    rgb.push(to_srgb(sum / n));
                }
            }
        }
    }
    Texture {
        width: p.cells,
        height,
        rgb,
        rows_per_texel,
    }
}

/// Linear light to the nearest sRGB byte.
fn to_srgb(x: f32) -> u8 {
    let x = x.clamp(0.0, 1.0);
    let s = if x <= 0.003_130_8 {
        x * 12.92
    } else {
        1.055 * libm::powf(x, 1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5) as u8
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Surface;
    use glam::DVec3;

    fn colours() -> Colours {
        Colours {
            ground: Rgb([250, 240, 220]),
            pigment: Rgb([40, 20, 10]),
            interior: Rgb([200, 120, 150]),
        }
    }

    fn vertex(surface: Surface, at: [f64; 2]) -> Vertex {
        Vertex::new(DVec3::ZERO, DVec3::Z, at, surface)
    }

    /// Two cells by three rows: black, white / white, black / red, blue.
    fn image() -> Vec<u8> {
        [
            [0, 0, 0],
            [255, 255, 255],
            [255, 255, 255],
            [0, 0, 0],
            [255, 0, 0],
            [0, 0, 255],
        ]
        .iter()
        .flat_map(|c| [c[0], c[1], c[2], 255])
        .collect()
    }

    #[test]
    fn every_byte_survives_linear_light_and_back() {
        for c in 0..=255u8 {
            assert_eq!(to_srgb(linear(c)), c);
        }
    }

    #[test]
    fn texel_centres_give_their_texels_and_between_them_a_mix_in_linear_light() {
        let rgba = image();
        let image = PatternImage {
            cells: 2,
            rows: 3,
            rgba: &rgba,
        };
        let paint = Paint::new(&colours(), Some(image));
        let at = |x, y| paint.colour(&vertex(Surface::Outer, [x, y]));
        assert_eq!(at(0.0, 0.0), [0, 0, 0]);
        assert_eq!(at(1.0, 0.0), [255, 255, 255]);
        assert_eq!(at(0.0, 1.0), [255, 255, 255]);
        assert_eq!(at(1.0, 2.0), [0, 0, 255]);
        // Half way between black and white is half the light: sRGB 188, not 128.
        assert_eq!(at(0.5, 0.0), [188, 188, 188]);
        assert_eq!(at(0.0, 0.5), [188, 188, 188]);
        // Outside the pattern the edge texels hold (clamped), as in the shader.
        assert_eq!(at(-0.3, 5.0), [255, 0, 0]);
        assert_eq!(paint.uv([0.0, 0.0]), [0.25, 0.5 / 3.0]);
        assert_eq!(paint.uv([1.0, 2.0]), [0.75, 2.5 / 3.0]);
    }

    #[test]
    fn parts_without_a_pattern_take_the_ground_or_the_interior_colour() {
        let plain = Paint::new(&colours(), None);
        assert_eq!(
            plain.colour(&vertex(Surface::Outer, [0.3, 2.0])),
            [250, 240, 220]
        );
        let rgba = image();
        let patterned = Paint::new(
            &colours(),
            Some(PatternImage {
                cells: 2,
                rows: 3,
                rgba: &rgba,
            }),
        );
        for paint in [&plain, &patterned] {
            for surface in [Surface::Inner, Surface::Edge] {
                assert_eq!(paint.colour(&vertex(surface, [0.0, 0.0])), [200, 120, 150]);
            }
        }
    }

    #[test]
    fn a_pattern_longer_than_a_texture_is_averaged_a_few_rows_to_a_texel() {
        let rows = MAX_TEXTURE_ROWS * 2 + 2;
        // One cell, alternating black and white rows.
        let rgba: Vec<u8> = (0..rows)
            .flat_map(|r| {
                let c = if r % 2 == 0 { 0 } else { 255 };
                [c, c, c, 255]
            })
            .collect();
        let paint = Paint::new(
            &colours(),
            Some(PatternImage {
                cells: 1,
                rows,
                rgba: &rgba,
            }),
        );
        let t = paint.texture().unwrap();
        assert_eq!((t.width, t.height, t.rows_per_texel), (1, 2732, 3));
        // Rows 0–2 are black, white, black: a third of the light.
        assert_eq!(&t.rgb[..3], &[to_srgb(1.0 / 3.0); 3]);
        // The last texel holds the last row (white) alone.
        assert_eq!(&t.rgb[t.rgb.len() - 3..], &[255; 3]);
    }
}
