//! A 2D texture map, the BlobTree's node m (Galbraith, Prusinkiewicz & Wyvill §2 and §3.4,
//! after Tigges & Wyvill): an image in linear light, read at (across, along) in [0, 1]²:
//! across wraps (it goes around a part), along is held at the image's first and last rows (it
//! runs from a part's base to its tip), and a point between texel centres blends the four
//! around it.

/// An image of `width` × `height` texels in linear light, row by row from along = 0.
#[derive(PartialEq)]
pub struct ImageMap {
    width: usize,
    height: usize,
    texels: Vec<[f32; 3]>,
}

/// Its size, not its thousands of texels (a tree printed names its images so).
impl std::fmt::Debug for ImageMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ImageMap({} × {})", self.width, self.height)
    }
}

impl ImageMap {
    /// The image of `texels`, `width` to a row; `None` unless they fill whole rows, at least
    /// one.
    pub fn new(width: usize, texels: Vec<[f32; 3]>) -> Option<Self> {
        let height = texels.len().checked_div(width)?;
        (height > 0 && height * width == texels.len()).then_some(Self {
            width,
            height,
            texels,
        })
    }

    /// The colour at (`across`, `along`), bilinearly between the texels' centres.
    pub fn at(&self, across: f64, along: f64) -> [f64; 3] {
        let x = across.rem_euclid(1.0) * self.width as f64 - 0.5;
        let y =
            (along.clamp(0.0, 1.0) * self.height as f64 - 0.5).clamp(0.0, (self.height - 1) as f64);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let column = |i: f64| (i as i64).rem_euclid(self.width as i64) as usize;
        let row = |j: f64| (j as usize).min(self.height - 1);
        let texel = |i: f64, j: f64| self.texels[row(j) * self.width + column(i)].map(f64::from);
        let (a, b) = (texel(x0, y0), texel(x0 + 1.0, y0));
        let (c, d) = (texel(x0, y0 + 1.0), texel(x0 + 1.0, y0 + 1.0));
        std::array::from_fn(|k| {
            let low = a[k] + (b[k] - a[k]) * fx;
            let high = c[k] + (d[k] - c[k]) * fx;
            low + (high - low) * fy
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_image_wraps_across_is_held_along_and_blends_between_texels() {
        // Two columns, black and white; two rows, the second red where the first is black.
        let image = ImageMap::new(2, vec![[0.0; 3], [1.0; 3], [1.0, 0.0, 0.0], [1.0; 3]])
            .expect("whole rows");
        let close = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9);
        // Texel centres at across 0.25 and 0.75, along 0.25 and 0.75.
        assert!(close(image.at(0.25, 0.25), [0.0; 3]));
        assert!(close(image.at(0.75, 0.75), [1.0; 3]));
        // Across wraps: 0 is halfway between the last column and the first.
        assert!(close(image.at(0.0, 0.25), [0.5; 3]));
        assert!(close(image.at(1.25, 0.25), image.at(0.25, 0.25)));
        // Along is held beyond the first and last rows' centres.
        assert!(close(image.at(0.25, -3.0), [0.0; 3]));
        assert!(close(image.at(0.25, 0.9), [1.0, 0.0, 0.0]));
        assert!(close(image.at(0.25, 0.5), [0.5, 0.0, 0.0]));
        assert!(ImageMap::new(2, vec![[0.0; 3]; 3]).is_none());
        assert!(ImageMap::new(0, Vec::new()).is_none());
        assert!(ImageMap::new(2, Vec::new()).is_none());
    }
}
