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

use crate::forms::kawaguchi::chambers::chamber_stack::chamber_of_shift_beyond_top;
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

/// What a link gave under retired keys.
#[derive(Default)]
pub(super) struct Retired {
    shift_beyond_top: Option<DVec3>,
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
        retired
    }

    /// Converts what was taken into today's values of the serialised spec `value`, and says
    /// so in `problems`.
    pub(super) fn apply(self, value: &mut Value, problems: &mut Vec<Problem>) {
        problems.extend(self.problems);
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
