//! How large an exported shell is: its height in millimetres, apex up. 3MF files are written
//! in millimetres at that height (for printing) and GLB files in metres (a viewer in augmented
//! reality shows the shell at that size).

use super::error::ExportError;

/// The height of an exported shell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrintSize {
    mm: f64,
}

impl PrintSize {
    /// The height unless one is chosen: a shell that fills a hand.
    pub const DEFAULT_MM: f64 = 80.0;
    /// The smallest height a printer can give a shell's detail.
    pub const MIN_MM: f64 = 5.0;
    /// The largest height, beyond the build volume of large printers.
    pub const MAX_MM: f64 = 500.0;

    /// A height of `mm` millimetres, refused outside [`Self::MIN_MM`]–[`Self::MAX_MM`] with a
    /// message naming `key` (the option or field it came from).
    pub fn new(mm: f64, key: &'static str) -> Result<Self, ExportError> {
        if (Self::MIN_MM..=Self::MAX_MM).contains(&mm) {
            Ok(Self { mm })
        } else {
            Err(ExportError::Size {
                key,
                mm,
                min: Self::MIN_MM,
                max: Self::MAX_MM,
            })
        }
    }

    /// The height in millimetres.
    pub fn mm(self) -> f64 {
        self.mm
    }
}

impl Default for PrintSize {
    fn default() -> Self {
        Self {
            mm: Self::DEFAULT_MM,
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
