//! How a pattern of cells × rows is folded into a texture no side of which exceeds 2048
//! texels (the WebGL2 limit): rows are laid out in blocks of `block_rows`, side by side. The
//! shader unfolds them with the same arithmetic.

/// Side of the texture that every backend supports.
pub const MAX_SIDE: u32 = 2048;

/// The folding of one pattern.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TextureLayout {
    pub cells: u32,
    pub rows: u32,
    pub block_rows: u32,
}

impl TextureLayout {
    /// The folding of a cells × rows pattern, or `None` when it cannot fit.
    pub fn new(cells: u32, rows: u32) -> Option<Self> {
        if cells == 0 || cells > MAX_SIDE || rows == 0 {
            return None;
        }
        let blocks_per_row = MAX_SIDE / cells;
        let block_rows = rows.div_ceil(blocks_per_row);
        (block_rows <= MAX_SIDE).then_some(Self {
            cells,
            rows,
            block_rows,
        })
    }

    /// The most rows a pattern of `cells` cells can have (none when cells do not fit a row).
    pub fn max_rows(cells: u32) -> u32 {
        if cells == 0 || cells > MAX_SIDE {
            0
        } else {
            MAX_SIDE / cells * MAX_SIDE
        }
    }

    /// Width and height of the texture.
    pub fn size(&self) -> (u32, u32) {
        (
            self.cells * self.rows.div_ceil(self.block_rows),
            self.block_rows,
        )
    }

    /// Texel where pattern row `row` starts.
    pub fn origin(&self, row: u32) -> (u32, u32) {
        let block = row / self.block_rows;
        (block * self.cells, row - block * self.block_rows)
    }

    /// Splits rows `first..end` into runs that lie one under the other in the texture, so each
    /// run is one copy: (first row of the run, number of rows).
    pub fn runs(&self, first: u32, end: u32) -> impl Iterator<Item = (u32, u32)> + '_ {
        let mut row = first;
        std::iter::from_fn(move || {
            (row < end).then(|| {
                let block_end = (row / self.block_rows + 1) * self.block_rows;
                let run = (row, block_end.min(end) - row);
                row += run.1;
                run
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_gets_its_own_place_inside_the_limit() {
        for (cells, rows) in [
            (1, 1),
            (256, 5000),
            (600, 6000),
            (2048, 2048),
            (100, 40_000),
        ] {
            let layout = TextureLayout::new(cells, rows).expect("fits");
            let (w, h) = layout.size();
            assert!(w <= MAX_SIDE && h <= MAX_SIDE);
            let mut seen = std::collections::HashSet::new();
            for row in 0..rows {
                let (x, y) = layout.origin(row);
                assert!(x + cells <= w && y < h);
                assert!(seen.insert((x, y)));
            }
        }
    }

    #[test]
    fn too_large_patterns_are_refused() {
        assert!(TextureLayout::new(2049, 10).is_none());
        assert!(TextureLayout::new(2048, 2049).is_none());
        assert!(TextureLayout::new(0, 10).is_none());
        for cells in [1, 100, 700, 2048] {
            let rows = TextureLayout::max_rows(cells);
            assert!(TextureLayout::new(cells, rows).is_some());
            assert!(TextureLayout::new(cells, rows + 1).is_none());
        }
    }

    #[test]
    fn runs_cover_the_rows_without_crossing_blocks() {
        let layout = TextureLayout::new(700, 4000).unwrap();
        let runs: Vec<_> = layout.runs(2400, 2600).collect();
        assert_eq!(runs.iter().map(|r| r.1).sum::<u32>(), 200);
        for (first, count) in runs {
            assert_eq!(
                first / layout.block_rows,
                (first + count - 1) / layout.block_rows
            );
        }
    }
}
