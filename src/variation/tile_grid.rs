//! A grid of tiles as the page lays them out, the parameter map's and breeding's alike: the job
//! numbers of each set of tiles (every set takes a fresh range shared by all grids, so that a
//! picture of an older set, or of another grid, finds no tile), where the arrow keys take the
//! focus, and what a tile's title says once its picture is in.

use super::tile::Tile;

/// Tiles of one set (the low bits of a tile's job number; a map's `SIDE × SIDE` fit).
const TILES_PER_SET: u32 = 256;

/// One set of tiles of a grid: its number, and how many tiles it has so far.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileSet {
    set: u32,
    tiles: usize,
}

impl TileSet {
    /// The set numbered `set` (taken from the page's count with [`Self::after`]), empty.
    pub fn new(set: u32) -> Self {
        Self { set, tiles: 0 }
    }

    /// The number of the set to take after `set`, wrapping before job numbers would overflow.
    pub fn after(set: u32) -> u32 {
        (set + 1) % (u32::MAX / TILES_PER_SET)
    }

    /// Adds a tile; returns its job number.
    pub fn add(&mut self) -> u32 {
        self.tiles += 1;
        self.job(self.tiles - 1)
    }

    /// The job number of tile `index` of this set.
    pub fn job(&self, index: usize) -> u32 {
        self.set * TILES_PER_SET + index as u32
    }

    /// The tile of this set a job number is for.
    pub fn index(&self, job: u32) -> Option<usize> {
        let index = (job % TILES_PER_SET) as usize;
        (job / TILES_PER_SET == self.set && index < self.tiles).then_some(index)
    }

    /// The tile the focus moves to, `dx` across and `dy` down a grid `side` tiles wide, from
    /// tile `from` (none: the first), kept within the grid.
    pub fn step(&self, from: Option<usize>, dx: i32, dy: i32, side: usize) -> usize {
        let Some(at) = from else { return 0 };
        let side = side.max(1) as i32;
        let (i, j) = (at as i32 % side, at as i32 / side);
        let rows = self.tiles.div_ceil(side as usize).max(1) as i32;
        ((j + dy).clamp(0, rows - 1) * side + (i + dx).clamp(0, side - 1)) as usize
    }
}

/// How a tile is marked once its picture is in: hatched as failed, marked as repaired, and
/// its title.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TileMarks {
    pub failed: bool,
    pub repaired: bool,
    pub title: String,
}

impl Tile {
    /// The marks of this tile, named `label`: a tile that failed says why; one whose link
    /// repaired another value says what.
    pub fn marks(&self, label: &str) -> TileMarks {
        match (&self.failure, &self.note) {
            (Some(why), _) => TileMarks {
                failed: true,
                repaired: false,
                title: format!("{label}: {why}"),
            },
            (None, Some(note)) => TileMarks {
                failed: false,
                repaired: true,
                title: format!("{label} (repaired: {note})"),
            },
            (None, None) => TileMarks {
                failed: false,
                repaired: false,
                title: label.to_string(),
            },
        }
    }
}

/// The page's signal of a grid whose tiles are all drawn (`finished`) or not yet.
pub fn filled(finished: bool) -> &'static str {
    if finished { "whole" } else { "filling" }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_job_finds_its_tile_only_in_its_own_set() {
        let mut old = TileSet::new(7);
        let jobs: Vec<u32> = (0..3).map(|_| old.add()).collect();
        assert_eq!(jobs, [7 * 256, 7 * 256 + 1, 7 * 256 + 2]);
        assert_eq!(old.index(jobs[2]), Some(2));
        assert_eq!(old.index(7 * 256 + 3), None, "no such tile yet");
        let fresh = TileSet::new(TileSet::after(7));
        assert_eq!(
            fresh.index(jobs[0]),
            None,
            "a picture of the old set finds nothing"
        );
        let last = u32::MAX / 256 - 1;
        assert_eq!(
            TileSet::after(last),
            0,
            "set numbers wrap before jobs overflow"
        );
        assert!(TileSet::new(last).job(255) > TileSet::new(last).job(0));
    }

    #[test]
    fn the_arrows_move_the_focus_within_the_grid() {
        let mut grid = TileSet::new(0);
        for _ in 0..9 {
            grid.add();
        }
        assert_eq!(grid.step(None, 1, 0, 3), 0, "from nowhere to the first");
        assert_eq!(grid.step(Some(4), 1, 0, 3), 5);
        assert_eq!(grid.step(Some(4), 0, 1, 3), 7);
        assert_eq!(grid.step(Some(5), 1, 0, 3), 5, "kept at the right edge");
        assert_eq!(grid.step(Some(1), 0, -1, 3), 1, "kept at the top");
        assert_eq!(grid.step(Some(7), 0, 5, 3), 7, "kept at the bottom");
    }

    #[test]
    fn a_tiles_title_says_why_it_failed_or_what_was_repaired() {
        let preset = crate::presets::preset("turbinate").expect("a preset");
        let mut tile = Tile {
            preset,
            spec: preset.spec.clone(),
            link: String::new(),
            picture: None,
            shown: true,
            failure: None,
            note: None,
            apart: false,
        };
        assert_eq!(tile.marks("W 2.0").title, "W 2.0");
        tile.note = Some("whorls 6 for 9".into());
        let repaired = tile.marks("W 2.0");
        assert!(repaired.repaired && !repaired.failed);
        assert_eq!(repaired.title, "W 2.0 (repaired: whorls 6 for 9)");
        tile.failure = Some("the shell cannot grow".into());
        let failed = tile.marks("W 2.0");
        assert!(
            failed.failed && !failed.repaired,
            "a failure is said, not a repair"
        );
        assert_eq!(failed.title, "W 2.0: the shell cannot grow");
    }

    #[test]
    fn filled_says_whole_or_filling() {
        assert_eq!(filled(true), "whole");
        assert_eq!(filled(false), "filling");
    }
}
