//! Colours in a spec: written as six hexadecimal digits ("c8a46e"), as links and preset files
//! carry them.

use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;
use std::str::FromStr;

/// An sRGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgb(pub [u8; 3]);

impl Rgb {
    /// The colour as linear-light fractions, for shading and for the colours an implicit
    /// shell's parts blend (with `libm`, so that native and wasm builds agree to the bit).
    pub fn linear(self) -> [f32; 3] {
        self.0.map(linear)
    }

    /// Linear interpolation in sRGB space, `x` in [0, 1], to the nearest step. Rounded by
    /// adding ½ and truncating (the channel is never negative): `f32::round` is a library call
    /// on both targets, and this runs for every cell of every row of a pattern.
    pub fn mix(self, other: Rgb, x: f32) -> Rgb {
        let x = x.clamp(0.0, 1.0);
        Rgb(std::array::from_fn(|i| {
            (f32::from(self.0[i]) * (1.0 - x) + f32::from(other.0[i]) * x + 0.5) as u8
        }))
    }
}

/// An sRGB byte in linear light (IEC 61966-2-1), with `libm` so that native and wasm agree.
pub fn linear(c: u8) -> f32 {
    let x = f32::from(c) / 255.0;
    if x <= 0.04045 {
        x / 12.92
    } else {
        libm::powf((x + 0.055) / 1.055, 2.4)
    }
}

impl fmt::Display for Rgb {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [r, g, b] = self.0;
        write!(f, "{r:02x}{g:02x}{b:02x}")
    }
}

impl FromStr for Rgb {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let digits = s.strip_prefix('#').unwrap_or(s);
        if digits.len() != 6 || !digits.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Err(format!(
                "'{s}' is not a colour: six hexadecimal digits, like c8a46e"
            ));
        }
        let byte = |i: usize| u8::from_str_radix(&digits[i..i + 2], 16).expect("checked hex");
        Ok(Rgb([byte(0), byte(2), byte(4)]))
    }
}

impl Serialize for Rgb {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        s.parse().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_round_trips() {
        let c: Rgb = "C8a46E".parse().unwrap();
        assert_eq!(c, Rgb([200, 164, 110]));
        assert_eq!(c.to_string(), "c8a46e");
        assert!("c8a46".parse::<Rgb>().is_err());
        assert!("zz0000".parse::<Rgb>().is_err());
    }
}
