//! The parts' textures of the spec as the BlobTree's looks (Galbraith, Prusinkiewicz & Wyvill
//! §3.4): the pattern, a colour ramp in linear light along the part's own primitives, or an
//! image: another species' pattern ([`species_image`]).

use super::species_image::species_image;
use crate::blobtree::texture_blend::{Look, MapOn};
use crate::shape::ShapeError;
use crate::spec::form::textures::{PartTexture, SHADE_RANGE, TextureKind, TexturesSpec};

/// The look of a part textured by `texture`, mapped `on` it: a spine's or bump's ramp and
/// image start where it leaves the surface it stands on (`MapOn::Part`); the body's image runs
/// on its growth (`MapOn::Growth`), its ramp along each primitive from its start.
pub fn look(texture: &PartTexture, on: MapOn) -> Look {
    match texture.look {
        TextureKind::Pattern => Look::Pattern,
        TextureKind::Ramp => Look::Ramp {
            base: texture.base.linear().map(f64::from),
            tip: texture.tip.linear().map(f64::from),
            shade: texture.shade,
            start: match on {
                MapOn::Part { start } => start,
                MapOn::Growth { .. } => 0.0,
            },
        },
        TextureKind::Image => Look::Image {
            map: species_image(texture.image),
            on,
        },
    }
}

/// Refuses a ramp exponent out of its range, naming its key.
pub fn check_textures(textures: &TexturesSpec) -> Result<(), ShapeError> {
    let parts = [
        ("body", &textures.body),
        ("spines", &textures.spines),
        ("canal_spines", &textures.canal_spines),
        ("bumps", &textures.bumps),
    ];
    for (name, part) in parts {
        let [low, high] = SHADE_RANGE;
        if !(low..=high).contains(&part.shade) {
            return Err(ShapeError::new(
                format!("form.textures.{name}.shade"),
                format!(
                    "a ramp's exponent must lie between {low} and {high}, not {}",
                    part.shade
                ),
            ));
        }
    }
    Ok(())
}
