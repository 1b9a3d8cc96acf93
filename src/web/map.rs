//! The parameter map on the page: over the shell's view, a grid of the planar patterns of two
//! parameters of its pattern model spread over ranges the reader chooses (the core's
//! `ParameterMap`), its tiles computed by the pool of workers and drawn as they come; every tile
//! is a link that opens its shell.

use super::dom::{append, attr, clear, create, typed};
use super::page::{element, set_text, signal};
use super::panel::label;
use super::workers::Workers;
use crate::presets::Preset;
use crate::share::parameter_map::{
    Axis, ParameterMap, Picture, SIDE, Tile, first_axes, parameters,
};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, display};
use crate::work::message::Request;
use wasm_bindgen::{Clamped, JsCast};
use web_sys::{
    CanvasRenderingContext2d, Element, HtmlCanvasElement, HtmlInputElement, HtmlOptionElement,
    HtmlSelectElement, ImageData,
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

    /// Offers the parameters, choosing the one at `chosen`, spread around its value.
    fn offer(&self, parameters: &[(&'static Field, f64)], chosen: usize) {
        clear(&self.select);
        for (field, _) in parameters {
            let option: HtmlOptionElement = typed("option", "");
            option.set_value(field.key);
            option.set_text(&label(field));
            append(&self.select, &[&option]);
        }
        if let Some((field, _)) = parameters.get(chosen) {
            self.select.set_value(field.key);
        }
        self.spread(parameters);
    }

    /// Sets the range to the default span around the chosen parameter's value.
    fn spread(&self, parameters: &[(&'static Field, f64)]) {
        let key = self.select.value();
        if let Some(axis) = parameters
            .iter()
            .find(|(f, _)| f.key == key)
            .and_then(|&(f, v)| Axis::around(f, v, SIDE).ok())
        {
            self.from.set_value(&display(axis.values[0]));
            self.to.set_value(&display(axis.values[SIDE - 1]));
        }
    }

    /// The axis the controls describe.
    fn axis(&self) -> Result<Axis, String> {
        let number = |input: &HtmlInputElement| {
            input
                .value()
                .trim()
                .parse::<f64>()
                .map_err(|_| format!("'{}' is not a number", input.value()))
        };
        Axis::new(
            &self.select.value(),
            number(&self.from)?,
            number(&self.to)?,
            SIDE,
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
    /// The map drawn last: a tile's job number carries it, so that tiles of an older map
    /// are dropped.
    generation: u32,
}

/// Tiles of one map (the low bits of a tile's job number; `SIDE × SIDE` fit).
const TILES_PER_MAP: u32 = 256;

impl MapView {
    /// Whether the map is shown.
    pub fn is_open(&self) -> bool {
        self.open
    }

    /// Shows the map for `spec`, over its first two parameters, and starts filling it.
    pub fn open(&mut self, preset: &'static Preset, spec: &ShellSpec, workers: &mut Workers) {
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
        if self.parameters.len() < 2 {
            self.map = None;
            clear_grid();
            set_text(
                "map-status",
                "This shell's pattern has fewer than two parameters to map.",
            );
            signal("map", "none");
            return;
        }
        let (across, down) = first_axes(&self.parameters);
        x.offer(&self.parameters, across);
        y.offer(&self.parameters, down);
        self.draw(preset, spec, workers);
    }

    /// Hides the map and stops filling it.
    pub fn close(&mut self, workers: &mut Workers) {
        self.stop(workers);
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
            controls.spread(&self.parameters);
        }
    }

    /// Starts a map of `spec` over the axes the controls describe, or says why it cannot.
    pub fn draw(&mut self, preset: &'static Preset, spec: &ShellSpec, workers: &mut Workers) {
        let (Some(x), Some(y), Some(grid)) = (
            AxisControls::find("x"),
            AxisControls::find("y"),
            element("map-grid"),
        ) else {
            return;
        };
        let axes = x.axis().and_then(|x| Ok((x, y.axis()?)));
        let (x, y) = match axes {
            Ok((x, y)) if x.field.key == y.field.key => {
                return self.refuse("Choose two different parameters.");
            }
            Ok(axes) => axes,
            Err(e) => return self.refuse(&format!("{e}.")),
        };
        let map = ParameterMap::new(preset, spec, x, y);
        clear(&grid);
        self.tiles = map
            .tiles()
            .iter()
            .map(|tile| {
                let a = create("a", "tile", None);
                attr(&a, "href", &format!("#{}", tile.link));
                let (vx, vy) = tile.values;
                let label = format!(
                    "{} = {}, {} = {}",
                    symbol(map.x.field),
                    display(vx),
                    symbol(map.y.field),
                    display(vy)
                );
                attr(&a, "title", &label);
                attr(&a, "aria-label", &label);
                append(&a, &[&create("canvas", "", None)]);
                append(&grid, &[&a]);
                a.into()
            })
            .collect();
        set_text(
            "map-status",
            &format!(
                "{} across, {} down; {} rows each. Choose a tile to open that shell.",
                symbol(map.x.field),
                symbol(map.y.field),
                map.rows
            ),
        );
        self.stop(workers);
        for index in map.to_compute() {
            workers.submit(Request::Tile {
                job: self.generation * TILES_PER_MAP + index as u32,
                link: map.tiles()[index].link.clone(),
                rows: map.rows as u32,
            });
        }
        for (index, tile) in map.tiles().iter().enumerate() {
            if tile.failure.is_some() {
                show_tile(&self.tiles[index], tile);
            }
        }
        signal("map", if map.finished() { "whole" } else { "filling" });
        self.map = Some(map);
    }

    /// Drops the tiles of the map drawn so far that no worker has started.
    fn stop(&mut self, workers: &mut Workers) {
        workers.cancel(|r| matches!(r, Request::Tile { .. }));
        self.generation = (self.generation + 1) % (u32::MAX / TILES_PER_MAP);
    }

    fn refuse(&mut self, message: &str) {
        self.map = None;
        clear_grid();
        set_text("map-status", message);
        signal("map", "refused");
    }

    /// A worker computed tile `job`: draws it, unless it belongs to an older map.
    pub fn take(&mut self, job: u32, result: Result<Picture, String>) {
        let Some(map) = &mut self.map else { return };
        if job / TILES_PER_MAP != self.generation {
            return;
        }
        let index = (job % TILES_PER_MAP) as usize;
        if index >= map.tiles().len() {
            return;
        }
        map.place(index, result);
        show_tile(&self.tiles[index], &map.tiles()[index]);
        signal("map", if map.finished() { "whole" } else { "filling" });
    }
}

/// Draws a tile's picture, or hatches it and says why it has none.
fn show_tile(element: &Element, tile: &Tile) {
    match (&tile.picture, &tile.failure) {
        (Some(picture), _) => paint(element, picture),
        (None, failure) => {
            let _ = element.class_list().add_1("failed");
            let why = failure.as_deref().unwrap_or("no pattern");
            let title = element.get_attribute("title").unwrap_or_default();
            attr(element, "title", &format!("{title}: {why}"));
        }
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
