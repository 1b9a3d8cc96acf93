//! How the parts of an implicit shell are coloured (Galbraith, Prusinkiewicz & Wyvill §3.4,
//! fig 12): the paper textures four parts separately (the main body whorl, the spines in the
//! varices, the axial spines on the canal, the bumps) and blends their colours by field where
//! the parts meet. Each part shows either the shell's pattern or a colour ramp along its own
//! parameterisation, with its own colours.

use crate::spec::colour::Rgb;
use serde::{Deserialize, Serialize};

/// The four parts' textures.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TexturesSpec {
    /// The main body whorl (its generating surfaces, the canal among them, and the ridges of
    /// the varices): by default the pattern, which runs on along the growing edge.
    pub body: PartTexture,
    /// The spines in the varices, from base to tip.
    pub spines: PartTexture,
    /// The axial spines on the canal, from base to tip.
    pub canal_spines: PartTexture,
    /// The bumps, from where they melt into the whorl to their tops.
    pub bumps: PartTexture,
}

impl Default for TexturesSpec {
    /// Close to *Murex cabritii*: the body patterned (pale with fine brown spiral lines, as the
    /// pattern and colours make it), spines and canal spines pale at the base and dark brown
    /// toward the tips, the bumps a little darker on their tops.
    fn default() -> Self {
        let spine = PartTexture {
            look: TextureKind::Ramp,
            base: Rgb([236, 222, 208]),
            tip: Rgb([92, 54, 38]),
            shade: 1.6,
        };
        Self {
            body: PartTexture::default(),
            spines: spine,
            canal_spines: spine,
            bumps: PartTexture {
                look: TextureKind::Ramp,
                base: Rgb([236, 222, 208]),
                tip: Rgb([176, 128, 100]),
                shade: 1.0,
            },
        }
    }
}

/// What a part shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TextureKind {
    /// The shell's pattern (whatever pattern model the spec chooses), in its own colours.
    Pattern,
    /// A ramp from `base` to `tip` along the part's own parameterisation.
    Ramp,
}

/// One part's texture.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PartTexture {
    pub look: TextureKind,
    /// The ramp's colour where the part leaves the surface it stands on.
    pub base: Rgb,
    /// The ramp's colour at the part's tip.
    pub tip: Rgb,
    /// How the ramp bends: the colour moves from base to tip as sᵉ of the way s along the
    /// part (1: evenly; above 1: it stays pale longer and darkens toward the tip).
    pub shade: f64,
}

impl Default for PartTexture {
    /// The pattern.
    fn default() -> Self {
        Self {
            look: TextureKind::Pattern,
            base: Rgb([236, 222, 208]),
            tip: Rgb([92, 54, 38]),
            shade: 1.0,
        }
    }
}

/// The smallest and largest ramp exponent.
pub const SHADE_RANGE: [f64; 2] = [0.2, 5.0];
