//! Breeding shells by choosing among offspring, as Dawkins bred his biomorphs and Latham his
//! Mutator's forms: the current shell stands among eight offspring, each a copy of it with a
//! few numbers of its form or its pattern model moved a random step; the one a person chooses
//! becomes the parent of the next eight.
//!
//! Every random choice comes from the parent itself (its seed and its link), so the offspring of
//! a shell are always the same: a lineage is shared as one link, the first shell's with the
//! choices made from it and the mutation rate each generation was bred at
//! (`&breed=0.4/3,0.4/7,0.5`: the third offspring at rate 0.4, then the seventh, and the next
//! offspring at 0.5), and replayed from it.

use super::parameter_map::{Axis, PATIENCE_S, parameters};
use super::tile::{Tile, Variant};
use crate::fnv::Fnv;
use crate::forms::sweep::raup::Coordinate;
use crate::pattern::noise::Noise;
use crate::presets::Preset;
use crate::share::lineage::{KEY, Lineage, OFFSPRING};
use crate::share::link;
use crate::spec::fields::{Field, Kind, Section, display};
use crate::spec::{Problem, ShellSpec};

/// Where the parent stands among its offspring: the middle of three rows of three.
pub const PARENT: usize = 4;
/// Draws tried for an offspring whose values the link refuses before it is shown refused.
const TRIES: usize = 8;

/// One number an offspring changed, from its parent's value to its own.
#[derive(Clone, Debug, PartialEq)]
pub struct Change {
    pub field: &'static Field,
    pub from: f64,
    pub to: f64,
}

impl std::fmt::Display for Change {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} {} → {}",
            self.field.short_name(),
            display(self.from),
            display(self.to)
        )
    }
}

/// Numbers of a form that set how finely it is drawn, not its shape: never mutated.
const FINENESS: &[&str] = &[
    "form.spiral.subdivisions",
    "form.curve.segments",
    "form.trunk.sides",
    "form.pixels",
    "form.resolution",
];

/// Numbers that show only while another is not at a value: ribs of no height or of no number,
/// a lip of no length (the numbers, by key or by the prefix of their group; the other; the
/// value at which they do not show). A mutation of one of them moves the other too, so that
/// what it changes shows.
const SHOWN_WITH: &[(&str, &str, f64)] = &[
    (
        "form.sculpture.growth_ribs.",
        "form.sculpture.growth_ribs.amplitude",
        0.0,
    ),
    (
        "form.sculpture.growth_ribs.",
        "form.sculpture.growth_ribs.count",
        0.0,
    ),
    (
        "form.sculpture.curve_ribs.",
        "form.sculpture.curve_ribs.amplitude",
        0.0,
    ),
    (
        "form.sculpture.curve_ribs.",
        "form.sculpture.curve_ribs.count",
        0.0,
    ),
    ("form.wall.lip_", "form.wall.lip_length", 0.0),
];

/// The numbers breeding may change in `spec`: those of its form and its pattern model, as the
/// parameter map offers them, with their values; not Raup's coordinates (read from them, not
/// set apart), nor how finely the form is drawn.
fn genes(spec: &ShellSpec) -> Vec<(&'static Field, f64)> {
    parameters(spec)
        .into_iter()
        .filter(|(f, _)| Coordinate::of_key(f.key).is_none() && !FINENESS.contains(&f.key))
        .collect()
}

/// The genes that hide `field` at their present values ([`SHOWN_WITH`]).
fn hidden_by(genes: &[(&'static Field, f64)], field: &Field) -> Vec<(&'static Field, f64)> {
    SHOWN_WITH
        .iter()
        .filter(|(group, other, _)| field.key.starts_with(group) && field.key != *other)
        .filter_map(|&(_, other, hides)| {
            genes
                .iter()
                .find(|(g, v)| g.key == other && *v == hides)
                .copied()
        })
        .collect()
}

/// How a value is measured for a step: itself; its logarithm (a positive size, changed by
/// ratios); or the logarithm of its logarithm (a growth ratio such as λ per step, whose growth
/// per whorl a step multiplies; above 1, or below it). Through `libm`, so that every platform
/// gives the same bits.
#[derive(Clone, Copy)]
enum Scale {
    Linear,
    Log,
    GrowthAbove,
    GrowthBelow,
}

impl Scale {
    fn of(field: &Field, value: f64) -> Self {
        let Kind::Real { min, max, log } = field.kind else {
            return Scale::Linear;
        };
        let ratio = min < 1.0 && 1.0 < max;
        if !log || value <= 0.0 {
            Scale::Linear
        } else if ratio && value > 1.0 {
            Scale::GrowthAbove
        } else if ratio && value < 1.0 {
            Scale::GrowthBelow
        } else {
            Scale::Log
        }
    }

    fn there(self, v: f64) -> f64 {
        match self {
            Scale::Linear => v,
            Scale::Log => libm::log(v),
            Scale::GrowthAbove => libm::log(libm::log(v)),
            Scale::GrowthBelow => libm::log(-libm::log(v)),
        }
    }

    fn back(self, c: f64) -> f64 {
        match self {
            Scale::Linear => c,
            Scale::Log => libm::exp(c),
            Scale::GrowthAbove => libm::exp(libm::exp(c)),
            Scale::GrowthBelow => libm::exp(-libm::exp(c)),
        }
    }
}

/// `value` of `field` moved `shift` standard steps: a step is half the span the map gives the
/// value ([`Axis::around`]), on the field's scale; kept in the field's range and
/// written as the panel shows it; an integer moves by one at least. None if it cannot move.
fn step(kind: &str, field: &'static Field, value: f64, shift: f64) -> Option<f64> {
    let span = Axis::around(kind, field, value, 2).ok()?;
    let (from, to) = (span.values[0], span.values[1]);
    let scale = Scale::of(field, value);
    let moved =
        scale.back(scale.there(value) + shift * (scale.there(to) - scale.there(from)) / 2.0);
    let (min, max, integer) = match field.kind {
        Kind::Real { min, max, .. } => (min, max, false),
        Kind::Integer { min, max } => (min as f64, max as f64, true),
        _ => return None,
    };
    let moved = if integer {
        let whole = moved.round();
        if whole == value {
            value + shift.signum()
        } else {
            whole
        }
    } else {
        display(moved).parse().ok()?
    };
    let moved = moved.clamp(min, max);
    (moved.is_finite() && moved != value).then_some(moved)
}

/// The seed of the offspring of the shell whose link is `link`: its pattern's seed and its
/// link, so that another parent has other offspring and the same parent the same.
fn seed_of(spec: &ShellSpec, link: &str) -> u64 {
    let mut hash = Fnv::default();
    hash.write(link.as_bytes());
    spec.seed ^ hash.value()
}

/// Offspring `child` (1 to 8) of `parent` (a variant of `preset`, whose [`genes`] are `genes`)
/// at `rate`: one to three of its genes, chosen at random (a section, then a gene in it), each
/// moved a normal step times `rate` (with what hides it); drawn again, up to [`TRIES`] times,
/// while the link refuses the values or its repair undoes them. With the changes it made.
fn offspring(
    preset: &'static Preset,
    parent: &ShellSpec,
    genes: &[(&'static Field, f64)],
    seed: u64,
    child: usize,
    rate: f64,
) -> (Tile, Vec<Change>) {
    let mut sections: Vec<Section> = Vec::new();
    for (field, _) in genes {
        if !sections.contains(&field.section) {
            sections.push(field.section);
        }
    }
    let kind = parent.form.kind();
    let mut noise = Noise::new(seed, child as u64);
    let mut last = None;
    for _ in 0..TRIES {
        let count = 1 + noise.below(3);
        let mut changes: Vec<Change> = Vec::new();
        for _ in 0..count.min(genes.len()) {
            // A section of the panel first, then a number in it: the shape is as likely to
            // change as its many numbers of sculpture.
            let section = sections[noise.below(sections.len())];
            let within: Vec<&(&Field, f64)> =
                genes.iter().filter(|(f, _)| f.section == section).collect();
            let &(field, value) = within[noise.below(within.len())];
            let shift = noise.normal(0.0, rate);
            // What hides this gene moves too, at least a whole step, so that the change shows.
            let woken = hidden_by(genes, field)
                .into_iter()
                .map(|(other, v)| (other, v, 1.0 + shift.abs()));
            for (field, value, shift) in std::iter::once((field, value, shift)).chain(woken) {
                if changes.iter().any(|c| c.field.key == field.key) {
                    continue;
                }
                if let Some(to) = step(kind, field, value, shift) {
                    changes.push(Change {
                        field,
                        from: value,
                        to,
                    });
                }
            }
        }
        let pairs = changes
            .iter()
            .map(|c| (c.field.key.to_string(), c.to.to_string()))
            .collect();
        let mut variant = Variant::of(preset, parent);
        variant.set(Ok(pairs));
        // A repair that undid a change (the preset's whole form put back where it would have
        // too many trunks, say) leaves the parent: drawn again.
        let leaves = link::leaves(&variant.spec);
        let undone = changes
            .iter()
            .any(|c| leaves.get(c.field.key).and_then(|v| v.as_f64()) != Some(c.to));
        let refused = variant.refused() || undone || changes.is_empty();
        last = Some((variant, changes, undone));
        if !refused {
            break;
        }
    }
    let (variant, changes, undone) = last.expect("at least one try");
    let mut tile = variant.tile(true);
    if undone && tile.failure.is_none() {
        tile.failure = Some(
            tile.note
                .take()
                .unwrap_or_else(|| "its changes cannot be kept".into()),
        );
    }
    (tile, changes)
}

/// A lineage replayed: the first shell, the choices that could be followed, and the generation
/// they lead to, its parent among its offspring.
pub struct Breeding {
    first: (&'static Preset, ShellSpec),
    pub lineage: Lineage,
    /// The parent (at [`PARENT`]) among its offspring, in reading order.
    tiles: Vec<Tile>,
    /// What each tile changed from its parent (nothing for the parent).
    changes: Vec<Vec<Change>>,
    /// The offspring drawn, when a slow machine draws fewer than all, and the pace that made
    /// it so (seconds a shell).
    fewer: Option<(usize, f64)>,
}

/// The fewest offspring a slow machine is shown.
const FEWEST: usize = 2;

/// How many offspring a machine that drew the last shells at `seconds_per_shell` each draws:
/// all of them, or fewer (down to [`FEWEST`]) so that a generation, parent and offspring, is
/// drawn within [`PATIENCE_S`], as a map of shells has fewer tiles.
pub fn offspring_for(seconds_per_shell: Option<f64>) -> usize {
    match seconds_per_shell {
        Some(s) if s > 0.0 => ((PATIENCE_S / s).floor() as usize)
            .saturating_sub(1)
            .clamp(FEWEST, OFFSPRING),
        _ => OFFSPRING,
    }
}

impl Breeding {
    /// Replays `lineage` from `spec` (a variant of `preset`). A choice of an offspring whose
    /// values could not be kept ends it there, said in a problem.
    pub fn new(
        preset: &'static Preset,
        spec: &ShellSpec,
        lineage: &Lineage,
    ) -> (Self, Vec<Problem>) {
        let mut problems = Vec::new();
        let mut parent = Variant::of(preset, spec).tile(true);
        let mut followed = Lineage {
            chosen: Vec::new(),
            rate: lineage.rate,
        };
        for (generation, &(rate, child)) in lineage.chosen.iter().enumerate() {
            let seed = seed_of(&parent.spec, &parent.link);
            let genes = genes(&parent.spec);
            let (tile, _) = offspring(parent.preset, &parent.spec, &genes, seed, child, rate);
            if let Some(why) = tile.failure {
                problems.push(Problem::new(
                    KEY,
                    format!(
                        "offspring {child} of generation {} cannot grow ({why}); showed that \
                         generation",
                        generation + 1
                    ),
                ));
                followed.rate = rate;
                break;
            }
            followed.chosen.push((rate, child));
            parent = tile;
        }
        let seed = seed_of(&parent.spec, &parent.link);
        let genes = genes(&parent.spec);
        let (mut tiles, mut changes): (Vec<Tile>, Vec<Vec<Change>>) = (1..=OFFSPRING)
            .map(|child| {
                offspring(
                    parent.preset,
                    &parent.spec,
                    &genes,
                    seed,
                    child,
                    followed.rate,
                )
            })
            .unzip();
        tiles.insert(PARENT, parent);
        changes.insert(PARENT, Vec::new());
        let breeding = Self {
            first: (preset, spec.clone()),
            lineage: followed,
            tiles,
            changes,
            fewer: None,
        };
        (breeding, problems)
    }

    /// On a machine that drew the last generation's shells at `seconds_per_shell` each, draws
    /// only the offspring [`offspring_for`] allows (the first ones) and those whose pictures
    /// are at hand (`at_hand`: drawn lately, shown at once); the others are not drawn, and say
    /// why, as does the status line.
    pub fn pace(&mut self, seconds_per_shell: Option<f64>, at_hand: impl Fn(&Tile) -> bool) {
        let count = offspring_for(seconds_per_shell);
        let Some(seconds) = seconds_per_shell.filter(|_| count < OFFSPRING) else {
            return;
        };
        self.fewer = Some((count, seconds));
        for (index, tile) in self.tiles.iter_mut().enumerate() {
            let beyond = Self::child(index).is_some_and(|child| child > count);
            if beyond && tile.failure.is_none() && !at_hand(tile) {
                tile.failure = Some(format!(
                    "not drawn: this machine drew the last generation's shells at {seconds:.1} s \
                     each, so {count} of the {OFFSPRING} offspring are drawn"
                ));
            }
        }
    }

    /// The generation shown: 1 for the first shell's offspring.
    pub fn generation(&self) -> usize {
        self.lineage.chosen.len() + 1
    }

    /// The parent among its offspring, in reading order (the parent at [`PARENT`]).
    pub fn tiles(&self) -> &[Tile] {
        &self.tiles
    }

    /// What tile `index` says of itself, and the link it opens (`None` for an offspring whose
    /// values cannot grow): the parent keeps itself; an offspring, what it changed from the
    /// parent, breeds the next generation from it.
    pub fn label(&self, index: usize) -> (String, Option<String>) {
        let tile = &self.tiles[index];
        match Self::child(index) {
            None => (
                format!(
                    "The parent, generation {}: open it to keep it",
                    self.generation()
                ),
                Some(tile.link.clone()),
            ),
            Some(child) => {
                let changes: Vec<String> = self
                    .changes(index)
                    .iter()
                    .map(ToString::to_string)
                    .collect();
                let href = tile
                    .failure
                    .is_none()
                    .then(|| self.link(&self.lineage.choose(child)));
                (format!("Offspring {child}: {}", changes.join("; ")), href)
            }
        }
    }

    /// The status line under the offspring.
    pub fn status(&self) -> String {
        let mut status = format!(
            "Generation {}. Choose an offspring to breed from it; the parent is in the middle.",
            self.generation()
        );
        if let Some((count, seconds)) = self.fewer {
            status.push_str(&format!(
                " {count} of {OFFSPRING} offspring drawn: this machine drew the last \
                 generation's shells at {seconds:.1} s each."
            ));
        }
        status
    }

    /// The parent: the shell the lineage has come to.
    pub fn parent(&self) -> &Tile {
        &self.tiles[PARENT]
    }

    /// What tile `index` changed from the parent.
    pub fn changes(&self, index: usize) -> &[Change] {
        &self.changes[index]
    }

    /// The offspring number (1 to 8) of tile `index`; none for the parent.
    pub fn child(index: usize) -> Option<usize> {
        match index {
            PARENT => None,
            i if i < PARENT => Some(i + 1),
            i if i <= OFFSPRING => Some(i),
            _ => None,
        }
    }

    /// Tile `index`'s shell was drawn, or could not be grown for the reason given.
    pub fn shown(&mut self, index: usize, result: Result<(), String>) {
        self.tiles[index].shown(result);
    }

    /// Whether every tile is drawn (or has failed).
    pub fn finished(&self) -> bool {
        self.tiles.iter().all(Tile::done)
    }

    /// The link of `lineage` bred from this one's first shell (without '#').
    pub fn link(&self, lineage: &Lineage) -> String {
        bred_link(self.first.0, &self.first.1, lineage)
    }
}

/// The link of `lineage` bred from the shell `spec` of `preset` (without '#'); the empty
/// lineage opens breeding on it.
pub fn bred_link(preset: &Preset, spec: &ShellSpec, lineage: &Lineage) -> String {
    format!("{}&{KEY}={}", link::encode(preset, spec), lineage.write())
}
