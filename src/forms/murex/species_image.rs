//! Another species' pattern as a part's image: the paper paints its four 2D textures (fig. 12)
//! in a paint program; here a part may show the pattern a species' own model computes, so
//! that spines banded like an Oliva or bumps mottled like a Conus come from the same models as
//! the shells. The image is the species' preset pattern on a fixed edge (every row as wide),
//! run over all its rows, averaged down to at most [`ACROSS`] × [`ALONG`] texels in linear
//! light: a part's mesh shows its image at its vertices, and no grid we draw gives a spine more.

use crate::blobtree::image_map::ImageMap;
use crate::pattern::run::PatternRun;
use crate::presets::preset;
use crate::spec::colour::linear;
use crate::spec::form::textures::ImageOf;
use crate::spec::pattern::EdgeGrowth;
use std::sync::OnceLock;

/// Most texels across an image (around a part).
pub const ACROSS: usize = 64;
/// Most texels along an image (from a part's base to its tip).
pub const ALONG: usize = 128;

/// The image of each species, computed once, when first asked for.
static IMAGES: [OnceLock<ImageMap>; ImageOf::IDS.len()] =
    [const { OnceLock::new() }; ImageOf::IDS.len()];

/// The pattern of `species` as an image. Each species offered is a preset whose pattern runs
/// to its end (`tests/textures.rs` runs them all), so this cannot fail on a spec.
pub fn species_image(species: ImageOf) -> &'static ImageMap {
    IMAGES[species as usize].get_or_init(|| {
        let id = species.id();
        let mut spec = preset(id)
            .unwrap_or_else(|| panic!("{id} is a preset"))
            .spec
            .clone();
        spec.pattern.edge_growth = EdgeGrowth::Off;
        let mut run = PatternRun::new(&spec, |_| None)
            .ok()
            .flatten()
            .unwrap_or_else(|| panic!("{id} has a pattern"));
        let rows = spec.growth.rows_grown();
        while run.rows() < rows {
            run.advance()
                .unwrap_or_else(|e| panic!("{id}'s pattern runs to its end: {e}"));
        }
        averaged(run.rgba(), run.cells(), run.rows())
    })
}

/// The RGBA rows `rgba` (`cells` texels to a row, `rows` rows) averaged down to at most
/// [`ACROSS`] × [`ALONG`] texels, in linear light.
fn averaged(rgba: &[u8], cells: usize, rows: usize) -> ImageMap {
    let (width, height) = (cells.clamp(1, ACROSS), rows.clamp(1, ALONG));
    let span = |i: usize, n: usize, of: usize| i * of / n..((i + 1) * of / n).max(i * of / n + 1);
    let mut texels = Vec::with_capacity(width * height);
    for j in 0..height {
        for i in 0..width {
            let mut sum = [0.0f32; 3];
            let mut count = 0.0f32;
            for y in span(j, height, rows) {
                for x in span(i, width, cells) {
                    let at = (y * cells + x) * 4;
                    for (s, &c) in sum.iter_mut().zip(&rgba[at..at + 3]) {
                        *s += linear(c);
                    }
                    count += 1.0;
                }
            }
            texels.push(sum.map(|s| s / count));
        }
    }
    ImageMap::new(width, texels).expect("whole rows")
}
