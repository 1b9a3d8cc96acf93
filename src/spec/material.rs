//! How the shell's surface meets the light: the "improved rendering" that Fowler, Meinhardt &
//! Prusinkiewicz (1992, §5) leave as an open problem — polished reflections, highlights
//! stretched along the growth lines, light through thin walls, the darkness deep inside the
//! opening — and a soft shadow on the ground beneath; or, instead of all of it, a drawing in
//! lines as Kawaguchi drew his shells on a vector display.

use serde::{Deserialize, Serialize};

/// How the shell is drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Drawing {
    /// A lit surface with its pattern and the effects below.
    #[default]
    Shaded,
    /// Lines on paper: the edges of the form's facets (for a sweep, its rims and a sparse set
    /// of lines along the growth direction) and its outline, hidden lines removed, as Kawaguchi
    /// drew GROWTH's shells on a vector display (*A morphological study of the form of
    /// nature*, where the research began as "a growth model of a shell by line drawing").
    Lines,
}

/// How the shell is drawn, and the strengths of each effect of a shaded drawing, each from 0
/// (none) to 1.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MaterialSpec {
    pub drawing: Drawing,
    /// Environment-like reflections of a polished surface (Oliva, Conus), rising at grazing
    /// angles (Fresnel).
    pub gloss: f64,
    /// Highlights stretched along the growth lines rather than round.
    pub anisotropy: f64,
    /// Light passing through the wall, seen where it is lit from behind.
    pub translucency: f64,
    /// Darkening with depth into the opening and on the inside of the wall.
    pub occlusion: f64,
    /// A soft contact shadow on the ground under the shell.
    pub shadow: f64,
}

impl Default for MaterialSpec {
    /// A porcelain-like shell: a little gloss along the growth lines, a deep opening, a shadow.
    fn default() -> Self {
        Self {
            drawing: Drawing::Shaded,
            gloss: 0.25,
            anisotropy: 0.35,
            translucency: 0.3,
            occlusion: 0.75,
            shadow: 0.6,
        }
    }
}
