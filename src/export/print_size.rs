//! How large an exported shell is: the length in millimetres of its bounding box's largest
//! side (a tusk lies long, a shell stands tall: either fits a build volume of that size), or of
//! one chosen side. 3MF files are written in millimetres at that size (for printing) and GLB
//! files in metres (a viewer in augmented reality shows the shell at that size).

use super::error::ExportError;
use serde::{Deserialize, Serialize};

/// Which side of the exported shell's bounding box a [`PrintSize`] sets. The sides are those
/// of a printer's build plate, the shell standing apex up and facing the way the page first
/// shows it: x across, y from front to back, z up.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Along {
    /// The largest side, whichever it is.
    Largest,
    X,
    Y,
    Z,
}

impl Along {
    /// Every reading, in the order of their codes.
    pub const ALL: [Along; 4] = [Along::Largest, Along::X, Along::Y, Along::Z];

    /// The side named `x`, `y` or `z`.
    pub fn axis(name: &str) -> Option<Self> {
        match name {
            "x" => Some(Along::X),
            "y" => Some(Along::Y),
            "z" => Some(Along::Z),
            _ => None,
        }
    }

    /// The file axis (0, 1, 2) of this side in a file whose up axis is `up` (1 for glTF's y,
    /// 2 for 3MF's z); None for the largest side. The side x is every file's x; the depth y
    /// is the axis that is neither x nor up.
    pub(crate) fn file_axis(self, up: usize) -> Option<usize> {
        match self {
            Along::Largest => None,
            Along::X => Some(0),
            Along::Y => Some(3 - up),
            Along::Z => Some(up),
        }
    }
}

/// The size of an exported shell. Read back from its parts (between threads) only within the
/// sizes [`PrintSize::new`] allows.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(into = "(f64, Along)", try_from = "(f64, Along)")]
pub struct PrintSize {
    mm: f64,
    along: Along,
}

impl PrintSize {
    /// The size unless one is chosen: a shell that fills a hand.
    pub const DEFAULT_MM: f64 = 80.0;
    /// The smallest height a printer can give a shell's detail.
    pub const MIN_MM: f64 = 5.0;
    /// The largest size, beyond the build volume of large printers.
    pub const MAX_MM: f64 = 500.0;

    /// A largest side of `mm` millimetres, refused outside [`Self::MIN_MM`]–[`Self::MAX_MM`]
    /// with a message naming `key` (the option or field it came from).
    pub fn new(mm: f64, key: &'static str) -> Result<Self, ExportError> {
        if (Self::MIN_MM..=Self::MAX_MM).contains(&mm) {
            Ok(Self {
                mm,
                along: Along::Largest,
            })
        } else {
            Err(ExportError::Size {
                key,
                mm,
                min: Self::MIN_MM,
                max: Self::MAX_MM,
            })
        }
    }

    /// The same length set along the side `along` instead.
    pub fn along(self, along: Along) -> Self {
        Self { along, ..self }
    }

    /// The length in millimetres.
    pub fn mm(self) -> f64 {
        self.mm
    }

    /// The side the length is of.
    pub fn side(self) -> Along {
        self.along
    }
}

impl From<PrintSize> for (f64, Along) {
    fn from(size: PrintSize) -> Self {
        (size.mm, size.along)
    }
}

impl TryFrom<(f64, Along)> for PrintSize {
    type Error = ExportError;

    fn try_from((mm, along): (f64, Along)) -> Result<Self, ExportError> {
        Ok(Self::new(mm, "size")?.along(along))
    }
}

impl Default for PrintSize {
    fn default() -> Self {
        Self {
            mm: Self::DEFAULT_MM,
            along: Along::Largest,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_outside_sensible_bounds_are_refused_by_name() {
        assert_eq!(PrintSize::new(80.0, "size").unwrap().mm(), 80.0);
        assert_eq!(PrintSize::default().mm(), 80.0);
        for mm in [0.0, -3.0, 4.9, 501.0, f64::NAN, f64::INFINITY] {
            let e = PrintSize::new(mm, "--size").unwrap_err();
            assert!(e.to_string().starts_with("--size: "), "{e}");
        }
    }
}
