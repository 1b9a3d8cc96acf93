//! What the page does when a shell is asked for (a link followed, a value set in the panel)
//! while another is shown: nothing when it is the shell shown; the shown shell drawn again when
//! only its material changed ([`ShellSpec::grows_like`]); else the shell grown, from its apex,
//! or whole at once when an implicit shell grown whole had a value changed (its chunks are
//! meshed by the pool, which is quicker than growing it again whorl by whorl). Restarting the
//! shell shown, or recording it, grows it from its apex whatever it is: neither asks here.

use crate::forms::meshed_in_pieces;
use crate::presets::Preset;
use crate::spec::ShellSpec;

/// The shell the page shows.
#[derive(Clone, Copy, Debug)]
pub struct Shown<'a> {
    pub preset: &'a Preset,
    pub spec: &'a ShellSpec,
    /// Its growth has ended (as the viewer last said).
    pub grown_whole: bool,
}

/// What the page does with a shell asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShellChange {
    /// It is the shell shown: nothing changes.
    Same,
    /// The shell shown in another material: drawn again, its growth going on.
    Restyle,
    /// Another shell: grown from its apex, or whole at once (`finish`).
    Grow { finish: bool },
}

impl ShellChange {
    /// What asking for `spec` of `preset` does while `shown` is shown (or nothing is);
    /// `finish` asks for the shell whole at once whatever was shown (an embed for a reader
    /// who asked for less motion).
    pub fn of(shown: Option<Shown>, preset: &Preset, spec: &ShellSpec, finish: bool) -> Self {
        let Some(shown) = shown.filter(|s| s.preset.id == preset.id) else {
            return Self::Grow { finish };
        };
        if shown.spec == spec {
            Self::Same
        } else if shown.spec.grows_like(spec) {
            Self::Restyle
        } else {
            let remesh = meshed_in_pieces(&spec.form) && shown.grown_whole;
            Self::Grow {
                finish: finish || remesh,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::preset;

    fn shown<'a>(id: &str, spec: &'a ShellSpec, grown_whole: bool) -> Option<Shown<'a>> {
        Some(Shown {
            preset: preset(id).unwrap(),
            spec,
            grown_whole,
        })
    }

    fn spec(id: &str) -> ShellSpec {
        preset(id).unwrap().spec.clone()
    }

    #[test]
    fn the_shell_shown_asked_again_changes_nothing() {
        let oliva = spec("oliva-porphyria");
        let change = ShellChange::of(
            shown("oliva-porphyria", &oliva, false),
            preset("oliva-porphyria").unwrap(),
            &oliva,
            false,
        );
        assert_eq!(change, ShellChange::Same);
    }

    #[test]
    fn another_material_draws_the_shell_again_and_grows_nothing() {
        let oliva = spec("oliva-porphyria");
        let mut glossy = oliva.clone();
        glossy.material.gloss = if oliva.material.gloss > 0.5 { 0.1 } else { 0.9 };
        let p = preset("oliva-porphyria").unwrap();
        assert_eq!(
            ShellChange::of(shown("oliva-porphyria", &oliva, true), p, &glossy, false),
            ShellChange::Restyle
        );
        // The same values under another preset are another shell.
        assert_eq!(
            ShellChange::of(shown("turbinate", &oliva, true), p, &glossy, false),
            ShellChange::Grow { finish: false }
        );
    }

    #[test]
    fn an_implicit_shell_grown_whole_is_remeshed_whole_when_a_value_changes() {
        let murex = spec("murex-cabritii");
        let mut other = murex.clone();
        other.seed += 1;
        let p = preset("murex-cabritii").unwrap();
        assert_eq!(
            ShellChange::of(shown("murex-cabritii", &murex, true), p, &other, false),
            ShellChange::Grow { finish: true }
        );
        // Still growing, it grows again from its apex.
        assert_eq!(
            ShellChange::of(shown("murex-cabritii", &murex, false), p, &other, false),
            ShellChange::Grow { finish: false }
        );
        // A swept shell grown whole grows again from its apex.
        let oliva = spec("oliva-porphyria");
        let mut seeded = oliva.clone();
        seeded.seed += 1;
        assert_eq!(
            ShellChange::of(
                shown("oliva-porphyria", &oliva, true),
                preset("oliva-porphyria").unwrap(),
                &seeded,
                false
            ),
            ShellChange::Grow { finish: false }
        );
    }

    #[test]
    fn with_nothing_shown_the_shell_grows_and_finishes_only_when_asked() {
        let oliva = spec("oliva-porphyria");
        let p = preset("oliva-porphyria").unwrap();
        assert_eq!(
            ShellChange::of(None, p, &oliva, false),
            ShellChange::Grow { finish: false }
        );
        assert_eq!(
            ShellChange::of(None, p, &oliva, true),
            ShellChange::Grow { finish: true }
        );
    }
}
