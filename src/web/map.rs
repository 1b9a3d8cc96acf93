//! The parameter map on the page: over the shell's view, a grid of shells that differ in two
//! parameters spread over ranges the reader chooses (the core's `ParameterMap`), its tiles
//! computed by the pool of workers and drawn as they come; every tile is a link that opens its
//! shell. Over two parameters of the pattern model a tile is the planar pattern; over one of the
//! form it is the whole shell, grown and drawn as a gallery card's picture is.

use super::debug;
use super::dom::{attr, build, clear};
use super::gallery::Pictures;
use super::page::{element, element_as, set_text, signal};
use super::tile_grid::{TileGrid, signal_filled};
use super::workers::Workers;
use crate::markup::{self, Shows};
use crate::presets::Preset;
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, display};
use crate::stories::MapAxes;
use crate::variation::map_plan::{self, MapPlan};
use crate::variation::parameter_map::{
    Axis, PHONE_SIDE, ParameterMap, SIDE, first_axes, parameters,
};
use crate::variation::tile::Picture;
use crate::work::message::Request;
use web_sys::{HtmlInputElement, HtmlSelectElement};

/// The controls of one axis: the parameter, and its range.
struct AxisControls {
    select: HtmlSelectElement,
    from: HtmlInputElement,
    to: HtmlInputElement,
}

impl AxisControls {
    fn find(name: &str) -> Option<Self> {
        Some(Self {
            select: element_as(&format!("map-{name}"))?,
            from: element_as(&format!("map-{name}-from"))?,
            to: element_as(&format!("map-{name}-to"))?,
        })
    }

    /// Offers the parameters, grouped by the panel's sections, choosing the one at `chosen`,
    /// spread around its value.
    fn offer(&self, kind: &str, parameters: &[(&'static Field, f64)], chosen: usize) {
        clear(&self.select);
        build(
            &self.select,
            &markup::field_options(parameters.iter().map(|(f, _)| *f)),
        );
        if let Some((field, _)) = parameters.get(chosen) {
            self.select.set_value(field.key);
        }
        self.spread(kind, parameters);
    }

    /// Sets the range to the default span around the chosen parameter's value.
    fn spread(&self, kind: &str, parameters: &[(&'static Field, f64)]) {
        let key = self.select.value();
        if let Some(axis) = parameters
            .iter()
            .find(|(f, _)| f.key == key)
            .and_then(|&(f, v)| Axis::around(kind, f, v, side()).ok())
        {
            self.from.set_value(&display(axis.values[0]));
            self.to
                .set_value(&display(axis.values[axis.values.len() - 1]));
        }
    }

    /// The axis the controls describe, `count` values of it, for a shell whose form is of
    /// `kind`.
    fn axis(&self, kind: &str, count: usize) -> Result<Axis, String> {
        let number = |input: &HtmlInputElement| {
            input
                .value()
                .trim()
                .parse::<f64>()
                .map_err(|_| format!("'{}' is not a number", input.value()))
        };
        Axis::new(
            kind,
            &self.select.value(),
            number(&self.from)?,
            number(&self.to)?,
            count,
        )
    }
}

/// The map over the view: its controls, its tiles, and the map being filled.
pub struct MapView {
    /// Whether the map is shown (over the shell, which waits meanwhile).
    open: bool,
    map: Option<ParameterMap>,
    grid: TileGrid,
    parameters: Vec<(&'static Field, f64)>,
    /// The kind of form of the shell mapped.
    kind: &'static str,
}

impl Default for MapView {
    fn default() -> Self {
        Self {
            open: false,
            map: None,
            grid: TileGrid::new("map-grid"),
            parameters: Vec::new(),
            kind: "",
        }
    }
}

/// Tiles along each side of the map: fewer on a phone, in the style sheet's narrow layout
/// (the same width as its `@media (max-width: 56rem)`).
fn side() -> usize {
    if super::page::matches("(max-width: 56rem)") {
        PHONE_SIDE
    } else {
        SIDE
    }
}

impl MapView {
    /// Whether the map is shown.
    pub fn is_open(&self) -> bool {
        self.open
    }

    /// Shows the map for `spec`, over the two numbers `axes` names (a story's step asks for
    /// them) or else its first two parameters, and starts filling it.
    pub fn open(
        &mut self,
        preset: &'static Preset,
        spec: &ShellSpec,
        axes: Option<&MapAxes>,
        workers: &mut Workers,
        pictures: &mut Pictures,
    ) {
        let (Some(section), Some(x), Some(y)) = (
            element("map"),
            AxisControls::find("x"),
            AxisControls::find("y"),
        ) else {
            return;
        };
        section.remove_attribute("hidden").ok();
        self.open = true;
        self.parameters = parameters(spec);
        self.kind = spec.form.kind();
        if self.parameters.len() < 2 {
            self.map = None;
            self.grid.clear();
            set_text(
                "map-status",
                "This shell has fewer than two parameters to map.",
            );
            signal("map", "none");
            return;
        }
        let at = |key: &str| self.parameters.iter().position(|(f, _)| f.key == key);
        let (across, down) = axes
            .and_then(|axes| at(&axes.across).zip(at(&axes.down)))
            .unwrap_or_else(|| first_axes(&self.parameters));
        x.offer(self.kind, &self.parameters, across);
        y.offer(self.kind, &self.parameters, down);
        self.draw(preset, spec, workers, pictures);
    }

    /// Hides the map and stops filling it.
    pub fn close(&mut self, workers: &mut Workers, pictures: &mut Pictures) {
        self.stop(workers, pictures);
        if let Some(section) = element("map") {
            attr(&section, "hidden", "");
        }
        self.open = false;
        self.map = None;
        signal("map", "");
    }

    /// The range of an axis whose parameter was chosen anew: the span around its value.
    pub fn chose(&mut self, name: &str) {
        if let Some(controls) = AxisControls::find(name) {
            controls.spread(self.kind, &self.parameters);
        }
    }

    /// Starts a map of `spec` over the axes the controls describe, as the core plans it, or
    /// says why it cannot.
    pub fn draw(
        &mut self,
        preset: &'static Preset,
        spec: &ShellSpec,
        workers: &mut Workers,
        pictures: &mut Pictures,
    ) {
        let (Some(x), Some(y)) = (AxisControls::find("x"), AxisControls::find("y")) else {
            return;
        };
        let axes = |count| {
            x.axis(self.kind, count)
                .and_then(|x| Ok((x, y.axis(self.kind, count)?)))
        };
        // A machine that drew the last shells slowly gets fewer of them.
        if let Some(pace) = debug::forced_pace() {
            pictures.assume_pace(pace);
        }
        let pace = pictures.pace(true);
        let planned = map_plan::plan(preset, spec, axes, side(), pace, pictures.draws());
        let MapPlan {
            mut map,
            labels,
            status,
        } = match planned {
            Ok(planned) => planned,
            Err(why) => return self.refuse(&why),
        };
        self.stop(workers, pictures);
        let shows = if map.shells() {
            Shows::Shell
        } else {
            Shows::Pattern
        };
        for (tile, label) in map.tiles().iter().zip(&labels) {
            (self.grid).add(|job| markup::map_tile(job, &tile.link, label, shows));
        }
        set_text("map-status", &status);
        for index in map.to_compute() {
            let job = self.grid.job(index);
            let tile = &map.tiles()[index];
            if map.shells() {
                if pictures.ask_tile(job, true, tile.preset, &tile.spec, workers) {
                    map.shown(index, Ok(()));
                }
            } else {
                workers.submit(Request::Tile {
                    job,
                    link: tile.link.clone(),
                    rows: map.rows as u32,
                });
            }
        }
        for (index, tile) in map.tiles().iter().enumerate() {
            if tile.failure.is_some() || tile.note.is_some() {
                self.grid.show(index, tile);
            }
        }
        signal_filled("map", map.finished());
        self.map = Some(map);
    }

    /// Moves the keyboard's focus `dx` tiles across and `dy` down (from the focused tile, or the
    /// one nearest the shell, or the first); Enter then opens that shell.
    pub fn step(&self, dx: i32, dy: i32) {
        if let Some(map) = &self.map {
            self.grid.step(dx, dy, map.x.values.len(), map.current);
        }
    }

    /// Drops the tiles of the map drawn so far that no worker has started.
    fn stop(&mut self, workers: &mut Workers, pictures: &mut Pictures) {
        workers.cancel(|r| matches!(r, Request::Tile { .. }));
        pictures.drop_tiles(workers);
        self.grid.clear();
    }

    fn refuse(&mut self, message: &str) {
        self.map = None;
        self.grid.clear();
        set_text("map-status", message);
        signal("map", "refused");
    }

    /// A worker computed the pattern of tile `job`: draws it, unless it belongs to an older
    /// map.
    pub fn take(&mut self, job: u32, result: Result<Picture, String>) {
        self.update(job, |map, index| map.place(index, result));
    }

    /// The shell of tile `job` was drawn as a picture, or could not be grown.
    pub fn shown(&mut self, job: u32, result: Result<(), String>) {
        self.update(job, |map, index| map.shown(index, result));
    }

    /// Applies `change` to tile `job` of the map shown, and shows the tile.
    fn update(&mut self, job: u32, change: impl FnOnce(&mut ParameterMap, usize)) {
        let (Some(map), Some(index)) = (&mut self.map, self.grid.index(job)) else {
            return;
        };
        change(map, index);
        self.grid.show(index, &map.tiles()[index]);
        signal_filled("map", map.finished());
    }
}
