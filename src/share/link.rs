//! Links that reproduce a shell exactly: the URL fragment carries a version tag, the preset's
//! id, and only the values that differ from that preset, as readable `key=value` pairs
//! (`#v=1&preset=oliva-porphyria&pattern.model.d_a=0.02`). Keys are the dotted paths of the
//! serialised spec; lists are written compactly ("0.3,0,0;0.3,0.17,0").
//!
//! Decoding never fails: whatever is wrong with a link (an unknown key, a malformed or
//! out-of-range value, a truncated or hostile fragment, a newer version) becomes a
//! [`Problem`] that says which key, what was wrong and what was used instead, and the shell is
//! built from what could be read. Numbers are written in their shortest exact form, so
//! `decode(encode(spec))` gives back the very same spec.

use super::lineage::{self, Lineage};
use super::presentation::Presentation;
use super::repair::repair;
use super::retired::Retired;
use crate::presets::{self, DEFAULT_PRESET, Preset};
use crate::spec::ShellSpec;
use crate::spec::fields::{Field, Kind, field};
use crate::spec::problem::Problem;
use percent_encoding::{AsciiSet, NON_ALPHANUMERIC, percent_decode_str, utf8_percent_encode};
use serde_json::{Map, Number, Value};
use std::collections::BTreeMap;

/// The link format written by this version.
pub const VERSION: u32 = 1;
/// Longest fragment read; anything longer is refused as a whole.
pub const MAX_LINK: usize = 16 * 1024;
/// Longest single value read.
const MAX_VALUE: usize = 4096;

/// Characters written as they are in a value.
const KEEP: &AsciiSet = &NON_ALPHANUMERIC
    .remove(b'.')
    .remove(b'-')
    .remove(b'_')
    .remove(b',')
    .remove(b';')
    .remove(b'/')
    .remove(b'~');

/// What a link decodes to.
#[derive(Clone, Debug)]
pub struct Decoded {
    pub preset: &'static Preset,
    pub spec: ShellSpec,
    /// How the link asks the page to show the shell.
    pub presentation: Presentation,
    /// The shells bred from this one, when the link shows a lineage (`breed=`).
    pub lineage: Option<Lineage>,
    pub problems: Vec<Problem>,
}

/// Every leaf of `spec` by its dotted path, as a link writes it.
pub fn leaves(spec: &ShellSpec) -> BTreeMap<String, Value> {
    flatten(&to_value(spec))
}

/// Every leaf of a serialised spec by its dotted path; lists are leaves.
pub fn flatten(value: &Value) -> BTreeMap<String, Value> {
    fn walk(value: &Value, prefix: &str, out: &mut BTreeMap<String, Value>) {
        match value {
            Value::Object(map) => {
                for (k, v) in map {
                    let key = if prefix.is_empty() {
                        k.clone()
                    } else {
                        format!("{prefix}.{k}")
                    };
                    walk(v, &key, out);
                }
            }
            leaf => {
                out.insert(prefix.to_string(), leaf.clone());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(value, "", &mut out);
    out
}

fn to_value(spec: &ShellSpec) -> Value {
    serde_json::to_value(spec).expect("a spec always serialises")
}

/// A leaf written as link text.
pub fn format_value(value: &Value) -> String {
    match value {
        Value::Array(items) => {
            let nested = items.iter().any(Value::is_array);
            let parts: Vec<String> = items.iter().map(format_value).collect();
            parts.join(if nested { ";" } else { "," })
        }
        Value::String(s) => s.clone(),
        Value::Null => String::new(),
        // Shortest exact form without a trailing ".0" ("5", "0.015").
        Value::Number(n) => match n.as_f64() {
            Some(x) if n.is_f64() => format!("{x}"),
            _ => n.to_string(),
        },
        other => other.to_string(),
    }
}

fn real(text: &str) -> Result<f64, String> {
    let x: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a number"))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("'{text}' is not a finite number"))
    }
}

fn whole(text: &str) -> Result<u64, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a whole number ≥ 0"))
}

fn float_value(x: f64) -> Value {
    Value::Number(Number::from_f64(x).expect("finite"))
}

/// A list written "a,b,c" (width 1) or "a,b;c,d" (tuples of `width`).
fn parse_list(text: &str, width: usize, integer: bool) -> Result<Value, String> {
    let number = |t: &str| -> Result<Value, String> {
        if integer {
            whole(t).map(Value::from)
        } else {
            real(t).map(float_value)
        }
    };
    if text.trim().is_empty() {
        return Ok(Value::Array(vec![]));
    }
    if width == 1 {
        return text
            .split(',')
            .map(number)
            .collect::<Result<_, _>>()
            .map(Value::Array);
    }
    text.split(';')
        .map(|tuple| {
            let items: Vec<Value> = tuple.split(',').map(number).collect::<Result<_, _>>()?;
            if items.len() == width {
                Ok(Value::Array(items))
            } else {
                Err(format!(
                    "'{tuple}' has {} numbers, not {width}",
                    items.len()
                ))
            }
        })
        .collect::<Result<_, _>>()
        .map(Value::Array)
}

/// Rows of whole numbers of any length: "0,1,1;0,0,1" (empty text: no rows).
fn parse_table(text: &str) -> Result<Value, String> {
    if text.trim().is_empty() {
        return Ok(Value::Array(vec![]));
    }
    text.split(';')
        .map(|row| parse_list(row, 1, true))
        .collect::<Result<_, _>>()
        .map(Value::Array)
}

/// Reads `text` as the value of `field`, shaped like `current`. Out-of-range numbers are
/// clamped; the second item says so.
fn parse_value(
    text: &str,
    field: Option<&Field>,
    current: &Value,
) -> Result<(Value, Option<String>), String> {
    if text.len() > MAX_VALUE {
        return Err(format!(
            "the value is {} characters long, more than {MAX_VALUE}",
            text.len()
        ));
    }
    let kind = field.map(|f| f.kind);
    match (kind, current) {
        (Some(Kind::Real { min, max, .. }), _) => {
            let x = real(text)?;
            let clamped = x.clamp(min, max);
            let note = (clamped != x)
                .then(|| format!("{text} is outside the range {min} to {max}; used {clamped}"));
            Ok((float_value(clamped), note))
        }
        (Some(Kind::Integer { min, max }), _) => {
            let x = whole(text)?;
            let clamped = x.clamp(min, max);
            let note = (clamped != x)
                .then(|| format!("{x} is outside the range {min} to {max}; used {clamped}"));
            Ok((Value::from(clamped), note))
        }
        (Some(Kind::Flag), _) | (None, Value::Bool(_)) => match text {
            "true" => Ok((Value::Bool(true), None)),
            "false" => Ok((Value::Bool(false), None)),
            _ => Err(format!("'{text}' is neither true nor false")),
        },
        (Some(Kind::Choice(options)), _) => {
            if options.contains(&text) {
                Ok((Value::String(text.to_string()), None))
            } else {
                Err(format!("'{text}' is not one of {}", options.join(", ")))
            }
        }
        (Some(Kind::Colour), _) => text
            .parse::<crate::spec::colour::Rgb>()
            .map(|c| (Value::String(c.to_string()), None)),
        (Some(Kind::List { width, integer }), _) => {
            parse_list(text, width, integer).map(|v| (v, None))
        }
        (Some(Kind::Table), _) => parse_table(text).map(|v| (v, None)),
        (Some(Kind::Text), _) | (None, Value::String(_)) => {
            Ok((Value::String(text.to_string()), None))
        }
        (None, Value::Number(n)) if n.is_f64() => real(text).map(|x| (float_value(x), None)),
        (None, Value::Number(_)) => whole(text).map(|x| (Value::from(x), None)),
        (None, _) => Err("this key cannot be set from a link".to_string()),
    }
}

fn slot<'a>(root: &'a mut Value, key: &str) -> Option<&'a mut Value> {
    key.split('.')
        .try_fold(root, |v, part| v.as_object_mut()?.get_mut(part))
        .filter(|v| !v.is_object())
}

/// The parameters of the first preset whose object at `parent` has `kind`: what switching
/// a form or model to that kind starts from.
fn variant_default(parent: &str, kind: &str) -> Option<Value> {
    presets::presets().iter().find_map(|p| {
        let value = to_value(&p.spec);
        let object = parent
            .split('.')
            .filter(|s| !s.is_empty())
            .try_fold(&value, |v, part| v.get(part))?;
        (object.get("kind")? == kind).then(|| object.clone())
    })
}

/// The kind of the form of a serialised spec ("" when it has none).
fn form_kind(value: &Value) -> &str {
    value
        .pointer("/form/kind")
        .and_then(Value::as_str)
        .unwrap_or_default()
}

fn parent_mut<'a>(root: &'a mut Value, parent: &str) -> Option<&'a mut Map<String, Value>> {
    parent
        .split('.')
        .filter(|s| !s.is_empty())
        .try_fold(root, |v, part| v.as_object_mut()?.get_mut(part))?
        .as_object_mut()
}

/// Writes the link fragment (without '#') for `spec`, relative to `preset`.
pub fn encode(preset: &Preset, spec: &ShellSpec) -> String {
    let base = leaves(&preset.spec);
    let current = leaves(spec);
    let changed: Vec<(&String, String)> = current
        .iter()
        .map(|(k, v)| (k, format_value(v)))
        .filter(|(k, text)| base.get(*k).map(format_value).as_ref() != Some(text))
        .collect();
    let (kinds, rest): (Vec<_>, Vec<_>) =
        changed.into_iter().partition(|(k, _)| k.ends_with(".kind"));
    let mut out = format!(
        "v={VERSION}&preset={}",
        utf8_percent_encode(preset.id, KEEP)
    );
    for (key, text) in kinds.into_iter().chain(rest) {
        out.push('&');
        out.push_str(key);
        out.push('=');
        out.push_str(&utf8_percent_encode(&text, KEEP).to_string());
    }
    out
}

fn default_preset() -> &'static Preset {
    presets::preset(DEFAULT_PRESET).expect("the default preset exists")
}

fn plain(preset: &'static Preset, problems: Vec<Problem>) -> Decoded {
    Decoded {
        preset,
        spec: preset.spec.clone(),
        presentation: Presentation::default(),
        lineage: None,
        problems,
    }
}

/// The `key=value` pairs of a fragment (without its '#'), percent-decoded, in order, and the
/// parts that are not of that form: what every link of the page is read from.
pub(crate) fn pairs(fragment: &str) -> (Vec<(String, String)>, Vec<String>) {
    let text = |s: &str| percent_decode_str(s).decode_utf8_lossy().into_owned();
    let mut pairs = Vec::new();
    let mut bare = Vec::new();
    for part in fragment.split('&').filter(|p| !p.is_empty()) {
        match part.split_once('=') {
            Some((k, v)) => pairs.push((text(k), text(v))),
            None => bare.push(text(part)),
        }
    }
    (pairs, bare)
}

/// Reads a link fragment (with or without its '#').
pub fn decode(fragment: &str) -> Decoded {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    if fragment.len() > MAX_LINK {
        let message = format!(
            "the link is {} characters long, more than the {MAX_LINK} this page reads; showing the {DEFAULT_PRESET} preset",
            fragment.len()
        );
        return plain(default_preset(), vec![Problem::new("link", message)]);
    }
    let text = |s: &str| percent_decode_str(s).decode_utf8_lossy().into_owned();
    if fragment.is_empty() {
        return plain(default_preset(), vec![]);
    }
    if !fragment.contains('=') {
        // Version 0: the fragment is a preset's id alone.
        let id = text(fragment);
        return match presets::preset(&id) {
            Some(p) => plain(p, vec![]),
            None => plain(
                default_preset(),
                vec![Problem::new(
                    "preset",
                    format!("there is no preset '{id}'; showing {DEFAULT_PRESET}"),
                )],
            ),
        };
    }
    let (mut pairs, bare) = pairs(fragment);
    let mut problems: Vec<Problem> = bare
        .into_iter()
        .map(|part| Problem::new(part, "is not of the form key=value; ignored"))
        .collect();
    let take = |pairs: &mut Vec<(String, String)>, key: &str| {
        let i = pairs.iter().rposition(|(k, _)| k == key)?;
        let found = pairs.remove(i).1;
        pairs.retain(|(k, _)| k != key);
        Some(found)
    };
    match take(&mut pairs, "v").map(|v| v.parse::<u32>()) {
        None => problems.push(Problem::new(
            "v",
            format!("the link has no version tag; read it as version {VERSION}"),
        )),
        Some(Ok(v)) if v > VERSION => {
            let preset = take(&mut pairs, "preset")
                .and_then(|id| presets::preset(&id))
                .unwrap_or_else(default_preset);
            let message = format!(
                "the link was made by a newer version of this page (link format {v}; this page reads up to {VERSION}); showing the {} preset without the link's changes",
                preset.id
            );
            problems.push(Problem::new("v", message));
            return plain(preset, problems);
        }
        Some(Ok(_)) => {}
        Some(Err(_)) => problems.push(Problem::new(
            "v",
            format!("is not a version number; read the link as version {VERSION}"),
        )),
    }
    let preset = match take(&mut pairs, "preset") {
        Some(id) => presets::preset(&id).unwrap_or_else(|| {
            problems.push(Problem::new(
                "preset",
                format!("there is no preset '{id}'; used {DEFAULT_PRESET}"),
            ));
            default_preset()
        }),
        None => {
            problems.push(Problem::new(
                "preset",
                format!("the link names no preset; used {DEFAULT_PRESET}"),
            ));
            default_preset()
        }
    };
    let mut presentation = Presentation::default();
    pairs.retain(|(key, value)| !presentation.read(key, value, &mut problems));
    let mut lineage = None;
    pairs.retain(|(key, value)| {
        if key != lineage::KEY {
            return true;
        }
        let (read, said) = Lineage::parse(value);
        problems.extend(said);
        lineage = Some(read);
        false
    });
    let mut seen = std::collections::BTreeSet::new();
    for (key, _) in &pairs {
        if !seen.insert(key.clone()) {
            problems.push(Problem::new(
                key.clone(),
                "is given more than once; used the last",
            ));
        }
    }
    Decoded {
        presentation,
        lineage,
        ..apply(preset, &preset.spec, pairs, problems)
    }
}

/// `spec` (a variant of `preset`) with one more `key=value`, read exactly as a link's would be:
/// what the editing panel uses.
pub fn with(preset: &'static Preset, spec: &ShellSpec, key: &str, value: &str) -> Decoded {
    with_all(preset, spec, vec![(key.to_string(), value.to_string())])
}

/// `spec` (a variant of `preset`) with several more `key=value`s at once, read exactly as a
/// link's would be (repaired once, with all of them).
pub fn with_all(
    preset: &'static Preset,
    spec: &ShellSpec,
    pairs: Vec<(String, String)>,
) -> Decoded {
    apply(preset, spec, pairs, Vec::new())
}

/// Applies `key=value` pairs (the last of a repeated key wins) to `spec`, then repairs it
/// against the preset.
fn apply(
    preset: &'static Preset,
    spec: &ShellSpec,
    pairs: Vec<(String, String)>,
    mut problems: Vec<Problem>,
) -> Decoded {
    let mut value = to_value(spec);
    let mut last: BTreeMap<String, String> = BTreeMap::new();
    let mut order = Vec::new();
    for (k, v) in pairs {
        if last.insert(k.clone(), v).is_none() {
            order.push(k);
        }
    }
    let retired = Retired::take(&mut last);
    order.retain(|k| last.contains_key(k));
    // Switch forms and models first: their parameters start from that kind's first preset.
    order.sort_by_key(|k| (!k.ends_with(".kind"), k.matches('.').count()));
    for key in order {
        let given = &last[&key];
        let kind = form_kind(&value).to_string();
        let field = field(&kind, &key);
        if let Some(parent) = key.strip_suffix(".kind") {
            let current = parent_mut(&mut value, parent).and_then(|m| m.get("kind").cloned());
            match (current, parse_value(given, field, &Value::Null)) {
                (None, _) => {
                    problems.push(Problem::new(key, "is not a key of this shell; ignored"))
                }
                (Some(now), Ok((kind, _))) if now == kind => {}
                (Some(_), Ok((kind, _))) => {
                    match variant_default(parent, kind.as_str().unwrap_or_default()) {
                        Some(default) => {
                            if let Some(map) = parent_mut(&mut value, parent) {
                                *map = default.as_object().cloned().unwrap_or_default();
                            }
                        }
                        None => problems.push(Problem::new(
                            key,
                            format!("no preset uses '{given}' to start from; ignored"),
                        )),
                    }
                }
                (Some(_), Err(e)) => problems.push(Problem::new(key, format!("{e}; ignored"))),
            }
            continue;
        }
        let Some(current) = slot(&mut value, &key) else {
            problems.push(Problem::new(key, "is not a key of this shell; ignored"));
            continue;
        };
        match parse_value(given, field, current) {
            Ok((parsed, note)) => {
                *current = parsed;
                if let Some(note) = note {
                    problems.push(Problem::new(key, note));
                }
            }
            Err(e) => problems.push(Problem::new(
                key,
                format!("{e}; kept {}", format_value(current)),
            )),
        }
    }
    retired.apply(&mut value, &mut problems);
    let mut spec: ShellSpec = match serde_json::from_value(value) {
        Ok(spec) => spec,
        Err(e) => {
            problems.push(Problem::new(
                "link",
                format!(
                    "its values do not make a shell ({e}); showing {}",
                    preset.id
                ),
            ));
            return plain(preset, problems);
        }
    };
    problems.extend(repair(&mut spec, &preset.spec));
    Decoded {
        preset,
        spec,
        presentation: Presentation::default(),
        lineage: None,
        problems: merged(problems),
    }
}

/// One problem per key, its messages in the order they arose ("…; used 0.5, then …").
fn merged(problems: Vec<Problem>) -> Vec<Problem> {
    let mut out: Vec<Problem> = Vec::with_capacity(problems.len());
    for p in problems {
        match out.iter_mut().find(|q| q.key == p.key) {
            Some(q) => {
                q.message.push_str(", then ");
                q.message.push_str(&p.message);
                q.said = q.said.max(p.said);
            }
            None => out.push(p),
        }
    }
    out
}
