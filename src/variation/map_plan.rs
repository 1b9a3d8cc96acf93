//! What the page shows of a parameter map before any tile is computed: the two axes checked
//! (two different parameters, each within its range), fewer tiles where the last map's shells
//! were drawn slowly, each tile's label (its two values, whorls apart, the presets nearest it,
//! the tile nearest the shell) and the status line; or, in a sentence, why no map can be
//! drawn. `web/map.rs` lays out what this returns.

use super::parameter_map::{Axis, ParameterMap, side_for};
use crate::presets::Preset;
use crate::spec::ShellSpec;
use crate::spec::fields::display;

/// A tile's label.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// What the tile shows, in words.
    pub text: String,
    /// Its whorls lie apart (open coiling).
    pub apart: bool,
    /// The tile nearest the shell shown.
    pub current: bool,
    /// The presets nearest it, by name ("" for none).
    pub landmarks: String,
    /// Where each of them falls in the tile, across and down as percentages of its side, and
    /// its name: a marker on the map.
    pub marks: Vec<(f64, f64, &'static str)>,
}

/// A map to draw.
pub struct MapPlan {
    pub map: ParameterMap,
    /// Each tile's label, in the map's order.
    pub labels: Vec<Label>,
    /// The status line under the map.
    pub status: String,
}

/// The map of `spec` (a variant of `preset`) over the axes `axes` gives for a side of so many
/// tiles (at most `widest`): fewer where the last map's shells took `pace` seconds each, and
/// refused where its tiles are whole shells and nothing is drawn in 3D here (`draws`).
pub fn plan(
    preset: &'static Preset,
    spec: &ShellSpec,
    axes: impl Fn(usize) -> Result<(Axis, Axis), String>,
    widest: usize,
    pace: Option<f64>,
    draws: bool,
) -> Result<MapPlan, String> {
    let (x, y) = match axes(widest) {
        Ok((x, y)) if x.field.key == y.field.key => {
            return Err("Choose two different parameters.".into());
        }
        Ok(axes) => axes,
        Err(e) => return Err(format!("{e}.")),
    };
    let count = side_for(pace, widest);
    let fewer = (x.shapes() || y.shapes()) && count < widest;
    let (x, y) = match fewer.then(|| axes(count)) {
        Some(Ok(axes)) => axes,
        _ => (x, y),
    };
    let map = ParameterMap::new(preset, spec, x, y);
    if map.shells() && !draws {
        return Err(
            "This browser draws no 3D here, so the map shows patterns only: choose two \
             parameters of the pattern model."
                .into(),
        );
    }
    let labels = (0..map.tiles().len())
        .map(|index| label(&map, index))
        .collect();
    let each = if map.shells() {
        "each the whole shell".to_string()
    } else {
        format!("{} rows each", map.rows)
    };
    let clamped: String = [&map.x.note, &map.y.note]
        .into_iter()
        .flatten()
        .map(|note| format!(" {note}."))
        .collect();
    let slow = match pace {
        Some(pace) if fewer => format!(
            " {count} × {count} tiles: this machine drew the last map's shells at {pace:.1} s \
             each."
        ),
        _ => String::new(),
    };
    let status = format!(
        "{} across, {} down; {each}. Choose a tile to open that shell.{clamped}{slow}",
        map.x.field.short_name(),
        map.y.field.short_name(),
    );
    Ok(MapPlan {
        map,
        labels,
        status,
    })
}

/// The label of tile `index` of `map`.
fn label(map: &ParameterMap, index: usize) -> Label {
    let tile = &map.tiles()[index];
    let (vx, vy) = map.values(index);
    let mut text = format!(
        "{} = {}, {} = {}",
        map.x.field.short_name(),
        display(vx),
        map.y.field.short_name(),
        display(vy)
    );
    if tile.apart {
        text.push_str(" (whorls apart: open coiling, rare among real shells)");
    }
    let here: Vec<_> = map.landmarks.iter().filter(|l| l.tile == index).collect();
    let marks = here
        .iter()
        .map(|l| {
            (
                l.within.0 * 100.0,
                l.within.1 * 100.0,
                l.preset.name.as_str(),
            )
        })
        .collect();
    let here: Vec<&str> = here.iter().map(|l| l.preset.name.as_str()).collect();
    let landmarks = here.join(", ");
    if !here.is_empty() {
        text.push_str(&format!(" (here: {landmarks})"));
    }
    let current = map.current == Some(index);
    if current {
        text.push_str(" (nearest this shell)");
    }
    Label {
        text,
        apart: tile.apart,
        current,
        landmarks,
        marks,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::preset;
    use crate::variation::parameter_map::SIDE;

    fn axes(
        x: (&'static str, f64, f64),
        y: (&'static str, f64, f64),
    ) -> impl Fn(usize) -> Result<(Axis, Axis), String> {
        move |count| {
            Ok((
                Axis::new("sweep", x.0, x.1, x.2, count)?,
                Axis::new("sweep", y.0, y.1, y.2, count)?,
            ))
        }
    }

    #[test]
    fn one_parameter_on_both_axes_is_refused_in_a_sentence() {
        let oliva = preset("oliva-porphyria").unwrap();
        let same = axes(
            ("pattern.model.rho", 0.05, 0.15),
            ("pattern.model.rho", 0.05, 0.1),
        );
        let refused = plan(oliva, &oliva.spec, same, SIDE, None, true).err();
        assert_eq!(refused.as_deref(), Some("Choose two different parameters."));
    }

    #[test]
    fn a_pattern_map_labels_each_tile_with_its_two_values() {
        let oliva = preset("oliva-porphyria").unwrap();
        let pattern = axes(
            ("pattern.model.d_a", 0.01, 0.03),
            ("pattern.model.rho", 0.05, 0.15),
        );
        let planned = plan(oliva, &oliva.spec, pattern, SIDE, Some(100.0), false).unwrap();
        assert_eq!(
            planned.labels.len(),
            SIDE * SIDE,
            "patterns are never fewer"
        );
        assert!(
            planned.labels[0].text.contains(" = "),
            "{:?}",
            planned.labels[0]
        );
        assert!(planned.status.contains("rows each"), "{}", planned.status);
    }

    #[test]
    fn a_map_of_shells_is_smaller_on_a_slow_machine_and_refused_without_3d() {
        let turbinate = preset("turbinate").unwrap();
        let shape = || axes(("raup.w", 1.5, 3.0), ("raup.t", 0.0, 4.0));
        let quick = plan(turbinate, &turbinate.spec, shape(), SIDE, None, true).unwrap();
        assert_eq!(quick.labels.len(), SIDE * SIDE);
        let slow = plan(turbinate, &turbinate.spec, shape(), SIDE, Some(1.0), true).unwrap();
        assert!(slow.labels.len() < SIDE * SIDE);
        assert!(slow.status.contains("this machine drew"), "{}", slow.status);
        let without = plan(turbinate, &turbinate.spec, shape(), SIDE, None, false);
        assert!(without.is_err_and(|why| why.contains("draws no 3D")));
    }
}
