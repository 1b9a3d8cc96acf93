//! How the parts of an implicit shell are coloured (Galbraith, Prusinkiewicz & Wyvill §3.4,
//! fig 12): the paper textures four parts separately (the main body whorl, the spines in the
//! varices, the axial spines on the canal, the bumps) and blends their colours by field where
//! the parts meet. Each part shows the shell's pattern, a colour ramp along its own
//! parameterisation with its own colours, or an image: the paper's 2D texture map (its node m),
//! here the pattern another species' model computes, mapped onto the part's own
//! parameterisation (onto the body, onto its growth's).

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
            shade: 1.6,
            ..PartTexture::default()
        };
        Self {
            body: PartTexture::default(),
            spines: spine,
            canal_spines: spine,
            bumps: PartTexture {
                look: TextureKind::Ramp,
                tip: Rgb([176, 128, 100]),
                ..PartTexture::default()
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
    /// The pattern of the species `image`, computed by its own model: across the image around
    /// the part, its growth from the part's base to its tip.
    Image,
}

/// The species whose pattern a part may show as its image: of each pattern model, those whose
/// pattern an image of a part still shows (each a preset with a pattern whose image is not
/// flat, `tests/textures.rs` checks; Amoria's fine lines average out, for one).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ImageOf {
    Stripes,
    VolutoconusBednalli,
    OlivaPorphyria,
    ConusMarmoreus,
    CaConusPrinceps,
    CaSolitons,
    CaWaves,
}

impl ImageOf {
    /// The presets' ids, as the field table offers them.
    pub const IDS: &[&str] = &[
        "stripes",
        "volutoconus-bednalli",
        "oliva-porphyria",
        "conus-marmoreus",
        "ca-conus-princeps",
        "ca-solitons",
        "ca-waves",
    ];

    /// The preset whose pattern this is.
    pub fn id(self) -> &'static str {
        Self::IDS[self as usize]
    }
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
    /// The species whose pattern an image shows.
    pub image: ImageOf,
}

impl Default for PartTexture {
    /// The pattern.
    fn default() -> Self {
        Self {
            look: TextureKind::Pattern,
            base: Rgb([236, 222, 208]),
            tip: Rgb([92, 54, 38]),
            shade: 1.0,
            image: ImageOf::ConusMarmoreus,
        }
    }
}

/// The smallest and largest ramp exponent.
pub const SHADE_RANGE: [f64; 2] = [0.2, 5.0];
