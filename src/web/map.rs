//! The parameter map on the page: over the shell's view, a grid of shells that differ in two
//! parameters spread over ranges the reader chooses (the core's `ParameterMap`), its tiles
//! computed by the pool of workers and drawn as they come; every tile is a link that opens its
//! shell. Over two parameters of the pattern model a tile is the planar pattern; over one of the
//! form it is the whole shell, grown and drawn as a gallery card's picture is.

use super::dom::{append, attr, clear, create, typed};
use super::gallery::Pictures;
use super::page::{element, set_text, signal};
use super::panel::label;
use super::workers::Workers;
use crate::presets::Preset;
use crate::share::parameter_map::{
    Axis, PHONE_SIDE, ParameterMap, Picture, SIDE, Tile, first_axes, parameters,
};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Section, display};
use crate::work::message::Request;
use wasm_bindgen::{Clamped, JsCast};
use web_sys::{
    CanvasRenderingContext2d, Element, HtmlCanvasElement, HtmlImageElement, HtmlInputElement,
    HtmlOptionElement, HtmlSelectElement, ImageData,
};

/// The controls of one axis: the parameter, and its range.
struct AxisControls {
    select: HtmlSelectElement,
    from: HtmlInputElement,
    to: HtmlInputElement,
}

impl AxisControls {
    fn find(name: &str) -> Option<Self> {
        fn get<T: JsCast>(id: String) -> Option<T> {
            element(&id)?.dyn_into().ok()
        }
        Some(Self {
            select: get(format!("map-{name}"))?,
            from: get(format!("map-{name}-from"))?,
            to: get(format!("map-{name}-to"))?,
        })
    }

    /// Offers the parameters, grouped by the panel's sections, choosing the one at `chosen`,
    /// spread around its value.
    fn offer(&self, kind: &str, parameters: &[(&'static Field, f64)], chosen: usize) {
        clear(&self.select);
        let mut group: Option<(Section, Element)> = None;
        for (field, _) in parameters {
            if group.as_ref().is_none_or(|(s, _)| *s != field.section) {
                let optgroup = create("optgroup", "", None);
                attr(&optgroup, "label", field.section.title());
                append(&self.select, &[&optgroup]);
                group = Some((field.section, optgroup.into()));
            }
            let option: HtmlOptionElement = typed("option", "");
            option.set_value(field.key);
            option.set_text(&label(field));
            if let Some((_, g)) = &group {
                append(g, &[&option]);
            }
        }
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

    /// The axis the controls describe, for a shell whose form is of `kind`.
    fn axis(&self, kind: &str) -> Result<Axis, String> {
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
            side(),
        )
    }
}

/// The map over the view: its controls, its tiles, and the map being filled.
#[derive(Default)]
pub struct MapView {
    /// Whether the map is shown (over the shell, which waits meanwhile).
    open: bool,
    map: Option<ParameterMap>,
    tiles: Vec<Element>,
    parameters: Vec<(&'static Field, f64)>,
    /// The kind of form of the shell mapped.
    kind: &'static str,
    /// The map drawn last: a tile's job number carries it, so that tiles of an older map
    /// are dropped.
    generation: u32,
}

/// Tiles along each side of the map: fewer on a phone, in the style sheet's narrow layout
/// (the same width as its `@media (max-width: 56rem)`).
fn side() -> usize {
    let narrow = web_sys::window()
        .and_then(|w| w.match_media("(max-width: 56rem)").ok().flatten())
        .is_some_and(|m| m.matches());
    if narrow { PHONE_SIDE } else { SIDE }
}

/// Tiles of one map (the low bits of a tile's job number; `SIDE × SIDE` fit).
const TILES_PER_MAP: u32 = 256;

impl MapView {
    /// Whether the map is shown.
    pub fn is_open(&self) -> bool {
        self.open
    }

    /// Shows the map for `spec`, over its first two parameters, and starts filling it.
    pub fn open(
        &mut self,
        preset: &'static Preset,
        spec: &ShellSpec,
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
            clear_grid();
            set_text(
                "map-status",
                "This shell has fewer than two parameters to map.",
            );
            signal("map", "none");
            return;
        }
        let (across, down) = first_axes(&self.parameters);
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

    /// Starts a map of `spec` over the axes the controls describe, or says why it cannot.
    pub fn draw(
        &mut self,
        preset: &'static Preset,
        spec: &ShellSpec,
        workers: &mut Workers,
        pictures: &mut Pictures,
    ) {
        let (Some(x), Some(y), Some(grid)) = (
            AxisControls::find("x"),
            AxisControls::find("y"),
            element("map-grid"),
        ) else {
            return;
        };
        let axes = x.axis(self.kind).and_then(|x| Ok((x, y.axis(self.kind)?)));
        let (x, y) = match axes {
            Ok((x, y)) if x.field.key == y.field.key => {
                return self.refuse("Choose two different parameters.");
            }
            Ok(axes) => axes,
            Err(e) => return self.refuse(&format!("{e}.")),
        };
        let map = ParameterMap::new(preset, spec, x, y);
        if map.shells() && !pictures.draws() {
            return self.refuse(
                "This browser draws no 3D here, so the map shows patterns only: choose two \
                 parameters of the pattern model.",
            );
        }
        self.stop(workers, pictures);
        clear(&grid);
        self.tiles = map
            .tiles()
            .iter()
            .zip(0..)
            .map(|(tile, index)| {
                let a = create("a", "tile", None);
                attr(&a, "href", &format!("#{}", tile.link));
                attr(
                    &a,
                    "data-job",
                    &(self.generation * TILES_PER_MAP + index).to_string(),
                );
                let (vx, vy) = tile.values;
                let label = format!(
                    "{} = {}, {} = {}",
                    symbol(map.x.field),
                    display(vx),
                    symbol(map.y.field),
                    display(vy)
                );
                let label = if tile.apart {
                    let _ = a.class_list().add_1("apart");
                    format!("{label} (whorls apart: open coiling, rare among real shells)")
                } else {
                    label
                };
                let here: Vec<&str> = map
                    .landmarks
                    .iter()
                    .filter(|(at, _)| *at == index as usize)
                    .map(|(_, p)| p.name.as_str())
                    .collect();
                let label = if here.is_empty() {
                    label
                } else {
                    let names = here.join(", ");
                    append(&a, &[&create("span", "landmark", Some(&names))]);
                    format!("{label} (here: {names})")
                };
                let label = if map.current == Some(index as usize) {
                    let _ = a.class_list().add_1("current");
                    attr(&a, "aria-current", "true");
                    format!("{label} (nearest this shell)")
                } else {
                    label
                };
                attr(&a, "title", &label);
                attr(&a, "aria-label", &label);
                let picture: Element = if map.shells() {
                    let img: HtmlImageElement = typed("img", "");
                    img.set_alt("");
                    img.into()
                } else {
                    create("canvas", "", None).into()
                };
                let _ = a.prepend_with_node_1(&picture);
                append(&grid, &[&a]);
                a.into()
            })
            .collect();
        let each = if map.shells() {
            "each the whole shell".to_string()
        } else {
            format!("{} rows each", map.rows)
        };
        set_text(
            "map-status",
            &format!(
                "{} across, {} down; {each}. Choose a tile to open that shell.",
                symbol(map.x.field),
                symbol(map.y.field),
            ),
        );
        for index in map.to_compute() {
            let job = self.generation * TILES_PER_MAP + index as u32;
            let tile = &map.tiles()[index];
            if map.shells() {
                pictures.ask_tile(job, map.preset, &tile.spec, workers);
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
                show_tile(&self.tiles[index], tile);
            }
        }
        signal("map", if map.finished() { "whole" } else { "filling" });
        self.map = Some(map);
    }

    /// Moves the keyboard's focus `dx` tiles across and `dy` down (from the focused tile, or the
    /// one nearest the shell, or the first); Enter then opens that shell.
    pub fn step(&self, dx: i32, dy: i32) {
        let Some(map) = &self.map else { return };
        let side = map.x.values.len() as i32;
        let focused = super::page::document().active_element();
        let from = self
            .tiles
            .iter()
            .position(|t| Some(t) == focused.as_ref())
            .or(map.current);
        let to = match from {
            Some(at) => {
                let (i, j) = (at as i32 % side, at as i32 / side);
                let rows = self.tiles.len() as i32 / side;
                ((j + dy).clamp(0, rows - 1) * side + (i + dx).clamp(0, side - 1)) as usize
            }
            None => 0,
        };
        if let Some(tile) = self
            .tiles
            .get(to)
            .and_then(|t| t.dyn_ref::<web_sys::HtmlElement>())
        {
            let _ = tile.focus();
        }
    }

    /// Drops the tiles of the map drawn so far that no worker has started.
    fn stop(&mut self, workers: &mut Workers, pictures: &mut Pictures) {
        workers.cancel(|r| matches!(r, Request::Tile { .. }));
        pictures.drop_tiles(workers);
        self.generation = (self.generation + 1) % (u32::MAX / TILES_PER_MAP);
    }

    fn refuse(&mut self, message: &str) {
        self.map = None;
        clear_grid();
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
        let Some(map) = &mut self.map else { return };
        if job / TILES_PER_MAP != self.generation {
            return;
        }
        let index = (job % TILES_PER_MAP) as usize;
        if index >= map.tiles().len() {
            return;
        }
        change(map, index);
        show_tile(&self.tiles[index], &map.tiles()[index]);
        signal("map", if map.finished() { "whole" } else { "filling" });
    }
}

/// Draws a tile's picture, or hatches it and says why it has none; a tile whose link repaired
/// another value is marked, and says what.
fn show_tile(element: &Element, tile: &Tile) {
    let title = element.get_attribute("title").unwrap_or_default();
    match (&tile.picture, &tile.failure) {
        (_, Some(why)) => {
            let _ = element.class_list().add_1("failed");
            attr(element, "title", &format!("{title}: {why}"));
        }
        (Some(picture), None) => paint(element, picture),
        (None, None) => {}
    }
    if let (Some(note), None) = (&tile.note, &tile.failure)
        && !element.class_list().contains("repaired")
    {
        let _ = element.class_list().add_1("repaired");
        attr(element, "title", &format!("{title} (repaired: {note})"));
    }
}

fn symbol(field: &Field) -> &'static str {
    if field.symbol.is_empty() {
        field.name
    } else {
        field.symbol
    }
}

fn clear_grid() {
    if let Some(grid) = element("map-grid") {
        clear(&grid);
    }
}

/// Draws a tile's picture into its canvas.
fn paint(tile: &Element, picture: &Picture) {
    let Some(canvas) = tile
        .first_element_child()
        .and_then(|c| c.dyn_into::<HtmlCanvasElement>().ok())
    else {
        return;
    };
    canvas.set_width(picture.width as u32);
    canvas.set_height(picture.height as u32);
    let context = canvas
        .get_context("2d")
        .ok()
        .flatten()
        .and_then(|c| c.dyn_into::<CanvasRenderingContext2d>().ok());
    if let (Some(context), Ok(image)) = (
        context,
        ImageData::new_with_u8_clamped_array_and_sh(
            Clamped(&picture.rgba),
            picture.width as u32,
            picture.height as u32,
        ),
    ) {
        // Drawing into our own canvas cannot fail for in-range coordinates.
        let _ = context.put_image_data(&image, 0.0, 0.0);
    }
}
