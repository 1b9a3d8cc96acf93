//! The options of a command, given as `--name value`, and the shell they name.

use crate::Failure;
use seashells_core::presets::{self, Preset, presets};
use seashells_core::share::link;
use seashells_core::spec::Said;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::fields::{self, Kind};
use std::collections::BTreeMap;

/// The options of every command that writes a file: the shell, and where and how to write it.
pub const WRITES: &[&str] = &["preset", "link", "out", "format"];

/// Options given as `--name value`, and at most one word without a name (a link).
pub struct Options {
    named: BTreeMap<String, String>,
    word: Option<String>,
}

impl Options {
    /// Reads `args` as the options `allowed`; `word` says whether one plain word (a link)
    /// may stand among them.
    pub fn parse(args: &[String], allowed: &[&str], word: bool) -> Result<Self, Failure> {
        let mut named = BTreeMap::new();
        let mut plain = None;
        let mut it = args.iter();
        while let Some(arg) = it.next() {
            let Some(name) = arg.strip_prefix("--") else {
                if word && plain.is_none() {
                    plain = Some(arg.clone());
                    continue;
                }
                return Err(Failure::usage(format!("unexpected '{arg}'")));
            };
            if !allowed.contains(&name) {
                return Err(Failure::usage(format!("there is no option '{arg}' here")));
            }
            let value = it
                .next()
                .ok_or_else(|| Failure::usage(format!("--{name} needs a value")))?;
            if named.insert(name.to_string(), value.clone()).is_some() {
                return Err(format!("--{name} is given twice").into());
            }
        }
        Ok(Self { named, word: plain })
    }

    pub fn get(&self, name: &str) -> Option<&str> {
        self.named.get(name).map(String::as_str)
    }

    pub fn required(&self, name: &str) -> Result<&str, Failure> {
        self.get(name)
            .ok_or_else(|| Failure::usage(format!("--{name} is missing")))
    }

    /// The preset and the spec named by --preset, --link or a plain link (exactly one of
    /// them). A link's values read another way with the same meaning (keys of earlier
    /// versions) are said on stderr, as the page says them; any other problem refuses it.
    pub fn preset_and_spec(&self) -> Result<(&'static Preset, ShellSpec), Failure> {
        let fragment = match (self.get("preset"), self.get("link"), self.word.as_deref()) {
            (Some(id), None, None) => {
                return presets::preset(id)
                    .map(|p| (p, p.spec.clone()))
                    .ok_or_else(|| {
                        let ids: Vec<&str> = presets().iter().map(|p| p.id).collect();
                        format!("there is no preset '{id}' (presets: {})", ids.join(", ")).into()
                    });
            }
            (None, Some(fragment), None) | (None, None, Some(fragment)) => fragment,
            _ => {
                return Err(Failure::usage(
                    "give exactly one of --preset ID, --link FRAGMENT or a link",
                ));
            }
        };
        // A whole address is read from its fragment, as the page reads it. What was read
        // another way, or is shown but written to no file (which the writers then refuse), is
        // said as a note.
        let fragment = fragment.rsplit_once('#').map_or(fragment, |(_, f)| f);
        let decoded = link::decode(fragment);
        let (notes, problems): (Vec<_>, Vec<_>) = decoded
            .problems
            .iter()
            .partition(|p| p.said != Said::Changed);
        if !problems.is_empty() {
            let problems: Vec<String> = problems.iter().map(ToString::to_string).collect();
            return Err(
                format!("the link cannot be used as given: {}", problems.join("; ")).into(),
            );
        }
        for note in notes {
            eprintln!("seashells: note: {note}");
        }
        Ok((decoded.preset, decoded.spec))
    }

    /// A whole number option, within the range `spec` allows for its key.
    pub fn count(&self, name: &str, spec: &ShellSpec, key: &str) -> Result<Option<u32>, Failure> {
        let Some(text) = self.get(name) else {
            return Ok(None);
        };
        let n: u32 = text
            .parse()
            .map_err(|_| format!("--{name} takes a whole number, not '{text}'"))?;
        match fields::field(spec.form.kind(), key).map(|f| f.kind) {
            Some(Kind::Integer { min, max }) if !(min..=max).contains(&u64::from(n)) => {
                Err(format!("--{name} must be between {min} and {max}, not {n}").into())
            }
            _ => Ok(Some(n)),
        }
    }
}
