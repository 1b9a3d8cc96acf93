//! The parts' textures of the spec as the BlobTree's looks (Galbraith, Prusinkiewicz & Wyvill
//! §3.4): the pattern, or a colour ramp in linear light along the part's own primitives.

use crate::blobtree::texture_blend::Look;
use crate::shape::ShapeError;
use crate::spec::form::textures::{PartTexture, SHADE_RANGE, TextureKind, TexturesSpec};

/// The look of a part textured by `texture`, its ramp starting `start` of the way along its
/// primitives (where the part leaves the surface it stands on).
pub fn look(texture: &PartTexture, start: f64) -> Look {
    match texture.look {
        TextureKind::Pattern => Look::Pattern,
        TextureKind::Ramp => Look::Ramp {
            base: texture.base.linear().map(f64::from),
            tip: texture.tip.linear().map(f64::from),
            shade: texture.shade,
            start,
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
