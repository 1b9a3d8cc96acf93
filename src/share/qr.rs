//! The link as a QR code, drawn as SVG (by the `qrcode` crate) for the share panel: dark
//! modules on white whatever the page's theme, with the four-module quiet zone readers need.

use qrcode::render::svg;
use qrcode::{EcLevel, QrCode};
use std::fmt;

/// The most bytes a QR code holds (version 40, low error correction, byte mode).
pub const CAPACITY: usize = 2953;

/// Why a link has no QR code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QrError {
    /// What was too long: always the link.
    pub key: &'static str,
    /// The link's length in bytes.
    pub length: usize,
}

impl fmt::Display for QrError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the {} is {} bytes long, more than the {CAPACITY} a QR code holds",
            self.key, self.length
        )
    }
}

impl std::error::Error for QrError {}

/// The QR code of `text` as an SVG document at least `size` pixels square: medium error
/// correction (15 % of the code may be damaged), or low for a link too long for medium.
pub fn svg(text: &str, size: u32) -> Result<String, QrError> {
    let code = QrCode::with_error_correction_level(text, EcLevel::M)
        .or_else(|_| QrCode::with_error_correction_level(text, EcLevel::L))
        .map_err(|_| QrError {
            key: "link",
            length: text.len(),
        })?;
    Ok(code
        .render::<svg::Color>()
        .min_dimensions(size, size)
        .dark_color(svg::Color("#000000"))
        .light_color(svg::Color("#ffffff"))
        .quiet_zone(true)
        .build())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_gives_a_square_svg_with_a_quiet_zone() {
        let link = "https://example.org/#v=1&preset=murex-cabritii&pattern.model.d_a=0.02";
        let svg = svg(link, 240).expect("a short link fits");
        assert!(svg.contains("<svg"), "{svg}");
        let code = QrCode::with_error_correction_level(link, EcLevel::M).unwrap();
        let modules = code.width() as u32 + 8;
        // The side is a whole number of modules, at least the size asked for.
        let side = 240u32.div_ceil(modules) * modules;
        assert!(
            svg.contains(&format!("viewBox=\"0 0 {side} {side}\"")),
            "{side}: {svg}"
        );
        assert!(svg.contains("#000000") && svg.contains("#ffffff"));
    }

    #[test]
    fn a_link_longer_than_a_code_holds_is_refused_with_its_length() {
        let long = "x".repeat(CAPACITY + 1);
        let e = svg(&long, 100).unwrap_err();
        assert_eq!(e.length, CAPACITY + 1);
        assert_eq!(e.key, "link");
        assert!(e.to_string().contains("2954 bytes"), "{e}");
        assert!(
            svg(&"x".repeat(CAPACITY), 100).is_ok(),
            "the longest link that fits"
        );
    }
}
