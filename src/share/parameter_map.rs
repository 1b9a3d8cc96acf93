//! A map of a pattern model's parameter space, as Meinhardt's tables of patterns show it: the
//! planar patterns of a grid of shells that differ from one shell in two parameters only, each
//! spread over a range in equal steps (equal ratios on a logarithmic field). Every tile is a
//! spec read exactly as a link's values would be, so choosing one opens that shell. Tiles are
//! computed a row at a time, so that a page fills the map within its frames, and each is kept
//! as a small picture (averaged blocks of cells and rows), not as its whole pattern.

use crate::generator::{RimLengths, pattern_alone};
use crate::pattern::run::PatternRun;
use crate::presets::Preset;
use crate::share::link::{self, flatten};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Kind, SHELL, Section, display};
use serde::{Deserialize, Serialize};

/// Tiles along each side of the page's map (its style sheet lays out eight columns).
pub const SIDE: usize = 8;
/// Widest picture of a tile, in pixels: wider patterns are averaged down to it.
const PICTURE_WIDTH: usize = 100;

/// One parameter of the map and the values it takes along its side.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub field: &'static Field,
    pub values: Vec<f64>,
}

impl Axis {
    /// `count` values of the real field `key` from `from` to `to` (both within its range), in
    /// equal steps, or equal ratios on a logarithmic field; each rounded as the panel shows it.
    pub fn new(key: &str, from: f64, to: f64, count: usize) -> Result<Self, String> {
        let field = SHELL
            .iter()
            .find(|f| f.key == key && f.section == Section::Pattern)
            .ok_or_else(|| format!("'{key}' is not a parameter of a pattern model"))?;
        let Kind::Real { min, max, log } = field.kind else {
            return Err(format!("{key} is not a real number and cannot span a map"));
        };
        if !(from.is_finite() && to.is_finite()) || from == to {
            return Err(format!("{key} needs two different numbers to span a map"));
        }
        if [from, to].iter().any(|v| !(min..=max).contains(v)) {
            return Err(format!(
                "{key} runs from {} to {}, and {} to {} leaves that range",
                display(min),
                display(max),
                display(from),
                display(to)
            ));
        }
        if log && from.min(to) <= 0.0 {
            return Err(format!("{key} is spread by ratios and needs positive ends"));
        }
        if count < 2 {
            return Err("a map needs at least two values of each parameter".into());
        }
        let values = (0..count)
            .map(|i| {
                let t = i as f64 / (count - 1) as f64;
                let v = if log {
                    from * (to / from).powf(t)
                } else {
                    from + (to - from) * t
                };
                display(v).parse().unwrap_or(v)
            })
            .collect();
        Ok(Self { field, values })
    }

    /// The default span of a parameter whose value is `value`: half to twice it, kept within
    /// the field's range (a quarter of the range from its low end when the value is 0).
    pub fn around(field: &'static Field, value: f64, count: usize) -> Result<Self, String> {
        let Kind::Real { min, max, .. } = field.kind else {
            return Err(format!("{} is not a real number", field.key));
        };
        let (from, to) = if value > 0.0 {
            ((value / 2.0).max(min), (value * 2.0).min(max))
        } else {
            (min, min + (max - min) / 4.0)
        };
        Self::new(field.key, from, to, count)
    }
}

/// The real parameters of the pattern model of `spec`, in the panel's order, with their values:
/// what a map can span.
pub fn parameters(spec: &ShellSpec) -> Vec<(&'static Field, f64)> {
    let leaves = flatten(&serde_json::to_value(spec).expect("a spec always serialises"));
    SHELL
        .iter()
        .filter(|f| f.key.starts_with("pattern.model.") && matches!(f.kind, Kind::Real { .. }))
        .filter_map(|f| Some((f, leaves.get(f.key)?.as_f64()?)))
        .collect()
}

/// The two of `parameters` a map starts with: the activator's diffusion D_a across (it sets
/// the spacing of stripes and the speed of waves), and down the next parameter of the equations
/// (one with a symbol) after it; the first two where there is no D_a.
pub fn first_axes(parameters: &[(&'static Field, f64)]) -> (usize, usize) {
    let Some(x) = parameters
        .iter()
        .position(|(f, _)| f.key == "pattern.model.d_a")
    else {
        return (0, 1);
    };
    let y = (x + 1..parameters.len())
        .chain(0..x)
        .find(|&i| !parameters[i].0.symbol.is_empty())
        .unwrap_or(usize::from(x == 0));
    (x, y)
}

/// A tile's picture: RGBA pixels, each the mean of a block of cells and rows.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Picture {
    pub width: usize,
    pub height: usize,
    #[serde(with = "crate::pod_bytes")]
    pub rgba: Vec<u8>,
}

impl Picture {
    /// The pattern of `run` as the planar view shows it, averaged over blocks of `block` ×
    /// `block` cells and rows.
    fn of(run: &PatternRun, block: usize) -> Self {
        let (cells, rows, rgba) = (run.cells(), run.rows(), run.planar());
        let (width, height) = (cells.div_ceil(block), rows.div_ceil(block));
        let mut out = vec![0u8; width * height * 4];
        for (py, line) in out.chunks_exact_mut(width * 4).enumerate() {
            for (px, pixel) in line.chunks_exact_mut(4).enumerate() {
                let mut sum = [0u32; 4];
                let mut count = 0;
                for r in py * block..((py + 1) * block).min(rows) {
                    for c in px * block..((px + 1) * block).min(cells) {
                        let at = (r * cells + c) * 4;
                        for (s, &v) in sum.iter_mut().zip(&rgba[at..at + 4]) {
                            *s += u32::from(v);
                        }
                        count += 1;
                    }
                }
                for (p, s) in pixel.iter_mut().zip(sum) {
                    *p = ((s + count / 2) / count) as u8;
                }
            }
        }
        Self {
            width,
            height,
            rgba: out,
        }
    }
}

/// One tile: its shell, its link, and its picture once computed (or why there is none).
pub struct Tile {
    /// The values of x and y.
    pub values: (f64, f64),
    pub spec: ShellSpec,
    pub link: String,
    pub picture: Option<Picture>,
    pub failure: Option<String>,
}

/// One tile's pattern being computed, a row at a time: `rows` rows of a shell's pattern, kept
/// as a picture once all are computed.
pub struct TileWork {
    run: PatternRun,
    rows: usize,
}

impl TileWork {
    /// The first `rows` rows of the pattern of `spec`, or why it has none; `rims` keeps the
    /// rim's lengths of the last form for the next tile.
    pub fn new(spec: &ShellSpec, rows: usize, rims: &mut RimLengths) -> Result<Self, String> {
        // Only this map's rows are kept while computing, not the shell's.
        let mut spec = spec.clone();
        spec.growth.rows = rows as u32;
        match pattern_alone(&spec, rims) {
            Ok(Some(run)) => Ok(Self { run, rows }),
            Ok(None) => Err("this shell has no pattern".into()),
            Err(e) => Err(e.to_string()),
        }
    }

    /// Computes rows while `more()` says so (at least one); the tile's picture once all its
    /// rows are computed, or why the pattern stopped.
    pub fn work(&mut self, mut more: impl FnMut() -> bool) -> Option<Result<Picture, String>> {
        let mut first = true;
        while first || more() {
            first = false;
            if self.run.rows() >= self.rows {
                let block = self.run.cells().div_ceil(PICTURE_WIDTH);
                return Some(Ok(Picture::of(&self.run, block)));
            }
            if let Err(e) = self.run.advance() {
                return Some(Err(format!("the pattern stops {e}")));
            }
        }
        None
    }
}

/// The map: `y.values.len()` rows of `x.values.len()` tiles, the first row at the first value
/// of y, each row from the first value of x. Only the tile being computed holds its pattern.
pub struct ParameterMap {
    pub x: Axis,
    pub y: Axis,
    /// Pattern rows computed for every tile.
    pub rows: usize,
    tiles: Vec<Tile>,
    /// The tile being computed here, and its pattern so far.
    next: usize,
    work: Option<TileWork>,
    rims: RimLengths,
}

impl ParameterMap {
    /// The map of `spec` (a variant of `preset`) over the axes, with tiles of as many rows as
    /// the pattern has cells (a square of the planar view), fewer if the shell has fewer.
    pub fn new(preset: &'static Preset, spec: &ShellSpec, x: Axis, y: Axis) -> Self {
        let mut tiles = Vec::with_capacity(x.values.len() * y.values.len());
        for &vy in &y.values {
            for &vx in &x.values {
                let across = link::with(preset, spec, x.field.key, &vx.to_string());
                let tile = link::with(preset, &across.spec, y.field.key, &vy.to_string());
                let problems: Vec<String> = across
                    .problems
                    .iter()
                    .chain(&tile.problems)
                    .map(ToString::to_string)
                    .collect();
                tiles.push(Tile {
                    values: (vx, vy),
                    link: link::encode(tile.preset, &tile.spec),
                    spec: tile.spec,
                    picture: None,
                    failure: (!problems.is_empty()).then(|| problems.join("; ")),
                });
            }
        }
        let rows = (spec.growth.rows as usize).min(spec.pattern.cells.max(1) as usize);
        Self {
            x,
            y,
            rows,
            tiles,
            next: 0,
            work: None,
            rims: RimLengths::default(),
        }
    }

    pub fn tiles(&self) -> &[Tile] {
        &self.tiles
    }

    /// The tile at column `i` (value i of x) of row `j` (value j of y).
    pub fn tile(&self, i: usize, j: usize) -> &Tile {
        &self.tiles[j * self.x.values.len() + i]
    }

    /// Whether every tile is computed (or has failed).
    pub fn finished(&self) -> bool {
        self.tiles
            .iter()
            .all(|t| t.picture.is_some() || t.failure.is_some())
    }

    /// The tiles still to compute, by index: what may be computed elsewhere ([`TileWork`] on
    /// each tile's spec and [`Self::rows`]) and [`Self::place`]d.
    pub fn to_compute(&self) -> Vec<usize> {
        (0..self.tiles.len())
            .filter(|&i| self.tiles[i].picture.is_none() && self.tiles[i].failure.is_none())
            .collect()
    }

    /// Keeps what computing tile `index` gave: its picture, or why it has none.
    pub fn place(&mut self, index: usize, result: Result<Picture, String>) {
        let tile = &mut self.tiles[index];
        match result {
            Ok(picture) => tile.picture = Some(picture),
            Err(why) => tile.failure = Some(why),
        }
    }

    /// Computes rows, tile after tile, while `more()` says so; returns the tiles it finished.
    pub fn work(&mut self, mut more: impl FnMut() -> bool) -> std::ops::Range<usize> {
        let first = self.next;
        while self.next < self.tiles.len() && more() {
            let tile = &self.tiles[self.next];
            if tile.failure.is_some() || tile.picture.is_some() {
                self.next += 1;
                continue;
            }
            let work = match &mut self.work {
                Some(work) => work,
                None => match TileWork::new(&tile.spec, self.rows, &mut self.rims) {
                    Ok(work) => self.work.insert(work),
                    Err(why) => {
                        self.place(self.next, Err(why));
                        continue;
                    }
                },
            };
            if let Some(result) = work.work(|| false) {
                self.work = None;
                self.place(self.next, result);
                self.next += 1;
            }
        }
        first..self.next
    }
}
