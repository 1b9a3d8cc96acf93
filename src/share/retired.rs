//! Keys that links of earlier versions carried and this version reads another way. Such a link
//! still opens: its values are converted to today's keys before the spec is read, and a
//! [`Problem`] says what they were read as.
//!
//! `form.chamber.translation.{x,y,z}`: Kawaguchi's shift T, once applied beyond each chamber's
//! top base (in the top base's own scaled frame), so that chambers separated and a sheared
//! joint closed each gap. T is now the top base's position within its chamber, with T_z the
//! width H (`form.chamber.width`, `form.chamber.shift`). The old growth from one bottom base to
//! the next is one similarity, and so is the new chamber's: the link is read as the chamber
//! that gives the same similarity, so the same spiral, without the joints
//! ([`chamber_of_shift_beyond_top`]). A component the link leaves out is 0, as it was in every
//! preset but the horn.
//!
//! `form.stop`: rule 8 as a fraction of a branching form's first trunk's height, before the
//! rule counted pixels (`form.pixels`). Read as the picture whose pixel is that height, or the
//! nearest the field's range allows ([`pixels_of_stop`]).

use crate::forms::kawaguchi::chambers::chamber_stack::chamber_of_shift_beyond_top;
use crate::spec::fields;
use crate::spec::form::branching::reach_in_first_heights;
use crate::spec::form::chambers::ChamberSpec;
use crate::spec::problem::Problem;
use glam::DVec3;
use serde_json::Value;
use std::collections::BTreeMap;

/// The old shift's keys, x, y and z.
const SHIFT_BEYOND_TOP: [&str; 3] = [
    "form.chamber.translation.x",
    "form.chamber.translation.y",
    "form.chamber.translation.z",
];

/// Rule 8's old key: the stop height as a fraction of the first trunk's.
const STOP: &str = "form.stop";

/// What a link gave under retired keys.
#[derive(Default)]
pub(super) struct Retired {
    shift_beyond_top: Option<DVec3>,
    /// The old stop fraction, unless the link gives `form.pixels` too.
    stop: Option<f64>,
    problems: Vec<Problem>,
}

impl Retired {
    /// Takes the retired keys out of a link's `key → value` pairs.
    pub(super) fn take(pairs: &mut BTreeMap<String, String>) -> Self {
        let mut retired = Self::default();
        for (axis, key) in SHIFT_BEYOND_TOP.into_iter().enumerate() {
            let Some(text) = pairs.remove(key) else {
                continue;
            };
            let t = retired.shift_beyond_top.get_or_insert(DVec3::ZERO);
            match text.trim().parse::<f64>() {
                Ok(x) if x.is_finite() => t[axis] = x,
                _ => retired.problems.push(Problem::new(
                    key,
                    format!("'{text}' is not a finite number; read as 0"),
                )),
            }
        }
        if let Some(text) = pairs.remove(STOP) {
            match text.trim().parse::<f64>() {
                _ if pairs.contains_key("form.pixels") => retired.problems.push(Problem::read_as(
                    STOP,
                    "ignored: the link gives form.pixels",
                )),
                Ok(x) if x > 0.0 && x.is_finite() => retired.stop = Some(x),
                _ => retired.problems.push(Problem::new(
                    STOP,
                    format!("'{text}' is not a number above 0; ignored"),
                )),
            }
        }
        retired
    }

    /// Converts what was taken into today's values of the serialised spec `value`, and says
    /// so in `problems`.
    pub(super) fn apply(self, value: &mut Value, problems: &mut Vec<Problem>) {
        problems.extend(self.problems);
        if let Some(stop) = self.stop {
            problems.push(pixels_of_stop(value, stop));
        }
        let Some(beyond) = self.shift_beyond_top else {
            return;
        };
        const KEY: &str = "form.chamber.translation";
        let is_chambers = value.pointer("/form/kind").and_then(Value::as_str) == Some("chambers");
        let slot = value.pointer_mut("/form/chamber").filter(|_| is_chambers);
        let Some(chamber) = slot.and_then(|slot| {
            let old: ChamberSpec = serde_json::from_value(slot.clone()).ok()?;
            Some((slot, old))
        }) else {
            problems.push(Problem::new(KEY, "is not a key of this shell; ignored"));
            return;
        };
        let (slot, old) = chamber;
        let new = chamber_of_shift_beyond_top(&old, beyond);
        problems.push(Problem::read_as(
            KEY,
            format!(
                "links made before T became the top base's position shifted each chamber by T = ({}, {}, {}) beyond its top base; read as the same growth with no gaps: width H = {}, position (Tx, Ty) = ({}, {})",
                beyond.x, beyond.y, beyond.z, new.width, new.shift.x, new.shift.y
            ),
        ));
        *slot = serde_json::to_value(new).expect("a chamber always serialises");
    }
}

/// Sets `form.pixels` of the serialised branching spec `value` to the picture whose pixel is
/// `stop` times its first trunk's height: the first branch's reach in first heights over
/// `stop`, rounded into the field's range. Says what it read, as the problem returned.
fn pixels_of_stop(value: &mut Value, stop: f64) -> Problem {
    let is_branching = value.pointer("/form/kind").and_then(Value::as_str) == Some("branching");
    let knots = value.pointer("/form/knots").and_then(Value::as_u64);
    let taper = value.pointer("/form/trunk/taper").and_then(Value::as_f64);
    let (Some(knots), Some(taper), true) = (knots, taper, is_branching) else {
        return Problem::new(STOP, "is not a key of this shell; ignored");
    };
    let knots = u32::try_from(knots).unwrap_or(u32::MAX);
    let (min, max) = fields::range("branching", "form.pixels");
    let wanted = reach_in_first_heights(knots, taper) / stop;
    let pixels = wanted.round().clamp(min, max);
    value["form"]["pixels"] = Value::from(pixels as u32);
    let read = if pixels == wanted.round() {
        "whose pixel is that height"
    } else {
        "the nearest to a pixel that high the range allows"
    };
    Problem::read_as(
        STOP,
        format!(
            "links made before rule 8 counted pixels stopped a branch at {stop} times its first trunk's height; read as form.pixels = {pixels}, {read}"
        ),
    )
}
