//! A map of a shell's parameter space: a grid of shells that differ from one shell in two
//! parameters only, each spread over a range in equal steps (equal ratios on a logarithmic
//! field). Every tile is a spec read exactly as a link's values would be, so choosing one opens
//! that shell.
//!
//! Over two parameters of the pattern model the map is Meinhardt's table of patterns: each tile
//! is the planar pattern, computed a row at a time so that a page fills the map within its
//! frames, and kept as a small picture (averaged blocks of cells and rows), not as its whole
//! pattern. Over a parameter of the form it is a morphospace, as Raup's cube of coiling
//! parameters is: each tile is the whole shell, grown and drawn as a gallery picture is.

use super::tile::{Picture, Tile, Variant};
use crate::forms::sweep::raup::{Coordinate, Raup};
use crate::generator::{RimLengths, pattern_alone};
use crate::pattern::run::PatternRun;
use crate::presets::{Preset, presets};
use crate::share::link::leaves;
use crate::spec::Problem;
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Kind, RAUP, display, fields};
use crate::spec::form::Form;
use serde_json::Value;
use std::collections::BTreeMap;

/// Tiles along each side of the page's map (its style sheet lays out eight columns).
pub const SIDE: usize = 8;
/// Tiles along each side of the map on a phone (the style sheet's narrow layout: five columns).
pub const PHONE_SIDE: usize = 5;
/// Longest a map of shells should take to fill, in seconds: on a machine that draws shells
/// slowly the next map has fewer tiles.
pub const PATIENCE_S: f64 = 20.0;

/// Tiles along each side of a map of shells on a machine that drew the last map's shells at
/// `seconds_per_shell` each: `widest`, or fewer (down to [`PHONE_SIDE`]) so that the map fills
/// within [`PATIENCE_S`].
pub fn side_for(seconds_per_shell: Option<f64>, widest: usize) -> usize {
    match seconds_per_shell {
        Some(s) if s > 0.0 => {
            ((PATIENCE_S / s).sqrt().floor() as usize).clamp(PHONE_SIDE.min(widest), widest)
        }
        _ => widest,
    }
}

/// Widest picture of a tile, in pixels: wider patterns are averaged down to it.
const PICTURE_WIDTH: usize = 100;

/// One parameter of the map and the values it takes along its side.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub field: &'static Field,
    pub values: Vec<f64>,
    /// What was clamped: a range asked beyond the field's limits is spread within them.
    pub note: Option<String>,
}

impl Axis {
    /// `count` values of the numeric field `key` of a shell whose form is of `kind`, from
    /// `from` to `to` (clamped to its range, and said in [`Self::note`]), in equal steps, or
    /// equal ratios on a logarithmic field; each rounded as the panel shows it (to a whole
    /// number on an integer field).
    pub fn new(kind: &str, key: &str, from: f64, to: f64, count: usize) -> Result<Self, String> {
        let field = mappable(kind).find(|f| f.key == key).ok_or_else(|| {
            format!("'{key}' is not a parameter of a {kind} shell's form or pattern model")
        })?;
        let (min, max, log, integer) = match field.kind {
            Kind::Real { min, max, log } => (min, max, log, false),
            Kind::Integer { min, max } => (min as f64, max as f64, false, true),
            _ => return Err(format!("{key} is not a number and cannot span a map")),
        };
        if !(from.is_finite() && to.is_finite()) || from == to {
            return Err(format!("{key} needs two different numbers to span a map"));
        }
        let (asked_from, asked_to) = (from, to);
        let (from, to) = (from.clamp(min, max), to.clamp(min, max));
        let range = format!("{key} runs from {} to {}", display(min), display(max));
        if from == to {
            return Err(format!(
                "{range}, and {} to {} lies beyond it",
                display(asked_from),
                display(asked_to)
            ));
        }
        let note = (from != asked_from || to != asked_to).then(|| {
            format!(
                "{range}: {} to {} was clamped to {} to {}",
                display(asked_from),
                display(asked_to),
                display(from),
                display(to)
            )
        });
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
                if integer {
                    v.round()
                } else {
                    display(v).parse().unwrap_or(v)
                }
            })
            .collect();
        Ok(Self {
            field,
            values,
            note,
        })
    }

    /// `value` on the scale the axis steps evenly along: its logarithm on a logarithmic field.
    fn scaled(&self, value: f64) -> f64 {
        if matches!(self.field.kind, Kind::Real { log: true, .. }) {
            value.max(f64::MIN_POSITIVE).ln()
        } else {
            value
        }
    }

    /// The value nearest `value`, by ratios on a logarithmic field, if `value` lies within the
    /// axis or less than half a step beyond an end.
    fn nearest(&self, value: f64) -> Option<usize> {
        let t = |v| self.scaled(v);
        let ts: Vec<f64> = self.values.iter().map(|&v| t(v)).collect();
        let half_step = (ts[ts.len() - 1] - ts[0]).abs() / (ts.len() - 1) as f64 / 2.0;
        let (low, high) = (ts[0].min(ts[ts.len() - 1]), ts[0].max(ts[ts.len() - 1]));
        let v = t(value);
        if v < low - half_step || v > high + half_step {
            return None;
        }
        (0..ts.len()).min_by(|&a, &b| (ts[a] - v).abs().total_cmp(&(ts[b] - v).abs()))
    }

    /// Where `value` falls along the axis, in steps from its first value (by ratios on a
    /// logarithmic field): a fraction, if it lies within the axis or less than half a step
    /// beyond an end.
    fn position(&self, value: f64) -> Option<f64> {
        let t = |v| self.scaled(v);
        let (first, last) = (t(self.values[0]), t(self.values[self.values.len() - 1]));
        let steps = (self.values.len() - 1) as f64;
        if first == last || steps == 0.0 {
            return None;
        }
        let at = (t(value) - first) / (last - first) * steps;
        (-0.5..=steps + 0.5).contains(&at).then_some(at)
    }

    /// Whether the tiles along this axis differ in shape, not in pattern only.
    pub fn shapes(&self) -> bool {
        !self.field.key.starts_with("pattern.")
    }

    /// The `key=value`s that set this axis's parameter of `spec` to `value`: the field itself,
    /// or for one of Raup's coordinates the spiral's and the curve's values that give it.
    fn pairs(&self, spec: &ShellSpec, value: f64) -> Result<Vec<(String, String)>, Problem> {
        let Some(c) = Coordinate::of_key(self.field.key) else {
            return Ok(vec![(self.field.key.to_string(), value.to_string())]);
        };
        let written = match &spec.form {
            Form::Sweep(sweep) => Raup::written(sweep, c, value),
            _ => None,
        };
        let refused = || {
            Problem::new(
                self.field.key,
                format!(
                    "{} = {} gives no shell of Raup's: its curve has no width or does not lie \
                     off the axis",
                    self.field.symbol,
                    display(value)
                ),
            )
        };
        let pairs = written.ok_or_else(refused)?;
        Ok(pairs
            .into_iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect())
    }

    /// The default span of a parameter whose value is `value`, kept within the field's range:
    /// half to twice it; for a growth ratio (a logarithmic field whose range holds 1, such as
    /// λ per step) its square root to its square, so that the growth per whorl halves and
    /// doubles in its logarithm; about 0, an eighth of the range either side (a quarter from its
    /// low end when that is 0).
    pub fn around(
        kind: &str,
        field: &'static Field,
        value: f64,
        count: usize,
    ) -> Result<Self, String> {
        let (min, max, log) = match field.kind {
            Kind::Real { min, max, log } => (min, max, log),
            Kind::Integer { min, max } => (min as f64, max as f64, false),
            _ => return Err(format!("{} is not a number", field.key)),
        };
        let ratio = log && min < 1.0 && 1.0 < max;
        let (from, to) = if ratio && value == 1.0 {
            (min.powf(1.0 / 16.0), max.powf(1.0 / 16.0))
        } else if ratio {
            let (a, b) = (value.sqrt(), value * value);
            (a.min(b), a.max(b))
        } else if value > 0.0 {
            (value / 2.0, value * 2.0)
        } else if value < 0.0 {
            (value * 2.0, value / 2.0)
        } else if min < 0.0 {
            (-(max - min) / 8.0, (max - min) / 8.0)
        } else {
            (min, min + (max - min) / 4.0)
        };
        let (from, to) = (from.max(min), to.min(max));
        Self::new(kind, field.key, from, to, count)
    }
}

/// What a map can span on a shell whose form is of `kind`: the numbers of the form (its shape)
/// and of the pattern model, and for a swept shell Raup's coordinates.
fn mappable(kind: &str) -> impl Iterator<Item = &'static Field> {
    let raup = if kind == "sweep" { RAUP } else { &[] };
    fields(kind)
        .filter(|f| {
            (f.key.starts_with("form.") || f.key.starts_with("pattern.model."))
                && matches!(f.kind, Kind::Real { .. } | Kind::Integer { .. })
        })
        .chain(raup)
}

/// The value of `field` in `spec`, whose leaves are `leaves`: the spec's own, or one of Raup's
/// coordinates read from it.
fn value_of(spec: &ShellSpec, leaves: &BTreeMap<String, Value>, field: &Field) -> Option<f64> {
    match (Coordinate::of_key(field.key), &spec.form) {
        (Some(c), Form::Sweep(sweep)) => Some(Raup::of(sweep)?.get(c)),
        (Some(_), _) => None,
        (None, _) => leaves.get(field.key)?.as_f64(),
    }
}

/// The numeric parameters of the form of `spec` and of its pattern model, in the panel's order,
/// and Raup's coordinates of a swept shell, with their values: what a map can span.
pub fn parameters(spec: &ShellSpec) -> Vec<(&'static Field, f64)> {
    let leaves = leaves(spec);
    mappable(spec.form.kind())
        .filter_map(|f| Some((f, value_of(spec, &leaves, f)?)))
        .collect()
}

/// The two of `parameters` a map starts with: the activator's diffusion D_a across (it sets
/// the spacing of stripes and the speed of waves), and down the next parameter of the equations
/// (one with a symbol) after it. Without a pattern, Raup's whorl expansion W across and his
/// translation T down (how fast the whorls widen, and how far they are drawn out along the
/// axis), or where a swept shell has none the helico-spiral's λᵣ and λ_z; the first two
/// otherwise.
pub fn first_axes(parameters: &[(&'static Field, f64)]) -> (usize, usize) {
    let at = |key: &str| parameters.iter().position(|(f, _)| f.key == key);
    let Some(x) = at("pattern.model.d_a") else {
        let pairs = [
            ("raup.w", "raup.t"),
            ("form.spiral.lambda_r", "form.spiral.lambda_z"),
        ];
        return pairs
            .iter()
            .find_map(|&(x, y)| at(x).zip(at(y)))
            .unwrap_or((0, 1));
    };
    let y = (x + 1..parameters.len())
        .chain(0..x)
        .find(|&i| !parameters[i].0.symbol.is_empty())
        .unwrap_or(usize::from(x == 0));
    (x, y)
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

/// A preset of the gallery where its own values fall on a map.
#[derive(Clone, Copy, Debug)]
pub struct Landmark {
    pub preset: &'static Preset,
    /// The tile nearest it.
    pub tile: usize,
    /// Where in that tile it falls, across and down, from 0 (the tile's left or top edge) to 1.
    pub within: (f64, f64),
}

/// The map: `y.values.len()` rows of `x.values.len()` tiles, the first row at the first value
/// of y, each row from the first value of x. Only the tile being computed holds its pattern.
pub struct ParameterMap {
    /// The tile nearest the shell mapped, when its values fall within the map.
    pub current: Option<usize>,
    /// The presets of the same form whose values fall within the map, each where it falls:
    /// where the shells of the gallery stand in this plane (Raup's cube with its real shells).
    pub landmarks: Vec<Landmark>,
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
        let shells = x.shapes() || y.shapes();
        let mut tiles = Vec::with_capacity(x.values.len() * y.values.len());
        for &vy in &y.values {
            for &vx in &x.values {
                let mut variant = Variant::of(preset, spec);
                for (axis, value) in [(&x, vx), (&y, vy)] {
                    let pairs = axis.pairs(&variant.spec, value);
                    variant.set(pairs);
                }
                tiles.push(variant.tile(shells));
            }
        }
        let rows = (spec.growth.rows as usize).min(spec.pattern.cells.max(1) as usize);
        let tile_of = |spec: &ShellSpec| {
            let leaves = leaves(spec);
            let at = |axis: &Axis| axis.nearest(value_of(spec, &leaves, axis.field)?);
            at(&x).zip(at(&y)).map(|(i, j)| j * x.values.len() + i)
        };
        let current = tile_of(spec);
        let landmarks = presets()
            .iter()
            .filter(|p| p.spec.form.kind() == spec.form.kind())
            .filter_map(|preset| {
                let leaves = leaves(&preset.spec);
                // The tile nearest, and how far off its centre the value falls.
                let at = |axis: &Axis| {
                    let value = value_of(&preset.spec, &leaves, axis.field)?;
                    let nearest = axis.nearest(value)?;
                    let off = axis.position(value)? - nearest as f64;
                    Some((nearest, (off + 0.5).clamp(0.0, 1.0)))
                };
                let ((column, across), (row, down)) = at(&x).zip(at(&y))?;
                Some(Landmark {
                    preset,
                    tile: row * x.values.len() + column,
                    within: (across, down),
                })
            })
            .collect();
        Self {
            current,
            landmarks,
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

    /// The values of x and y of tile `index`.
    pub fn values(&self, index: usize) -> (f64, f64) {
        let side = self.x.values.len();
        (self.x.values[index % side], self.y.values[index / side])
    }

    /// The tile at column `i` (value i of x) of row `j` (value j of y).
    pub fn tile(&self, i: usize, j: usize) -> &Tile {
        &self.tiles[j * self.x.values.len() + i]
    }

    /// Whether the tiles show whole shells (an axis spans a parameter of the form), not
    /// patterns: those are grown and drawn by the page, [`Self::shown`] as they are.
    pub fn shells(&self) -> bool {
        self.x.shapes() || self.y.shapes()
    }

    /// Whether every tile is computed (or has failed).
    pub fn finished(&self) -> bool {
        self.tiles.iter().all(Tile::done)
    }

    /// The tiles still to compute, by index: what may be computed elsewhere ([`TileWork`] on
    /// each tile's spec and [`Self::rows`], or the whole shell) and [`Self::place`]d.
    pub fn to_compute(&self) -> Vec<usize> {
        (0..self.tiles.len())
            .filter(|&i| !self.tiles[i].done())
            .collect()
    }

    /// Keeps what computing tile `index` gave: its picture, or why it has none.
    pub fn place(&mut self, index: usize, result: Result<Picture, String>) {
        self.tiles[index].place(result);
    }

    /// Tile `index`'s shell was drawn, or could not be grown for the reason given.
    pub fn shown(&mut self, index: usize, result: Result<(), String>) {
        self.tiles[index].shown(result);
    }

    /// Computes the patterns, row after row and tile after tile, while `more()` says so;
    /// returns the tiles it finished. A map of shells is not computed here ([`Self::shells`]).
    pub fn work(&mut self, mut more: impl FnMut() -> bool) -> std::ops::Range<usize> {
        let first = self.next;
        while self.next < self.tiles.len() && !self.shells() && more() {
            let tile = &self.tiles[self.next];
            if tile.done() {
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
