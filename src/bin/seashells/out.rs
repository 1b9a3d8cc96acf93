//! Where a command writes its file: a path, or standard output for `-`.

use crate::Failure;
use std::io::Write;

/// The file named by `--out`.
pub struct Out<'a>(&'a str);

impl<'a> Out<'a> {
    pub fn new(path: &'a str) -> Self {
        Self(path)
    }

    /// The name to choose the format by (standard output has none: `-.stl` is not a path).
    pub fn name(&self) -> &str {
        self.0
    }

    fn is_stdout(&self) -> bool {
        self.0 == "-"
    }

    /// Writes `bytes`; a failure to write is exit status 1.
    pub fn write(&self, bytes: &[u8]) -> Result<(), Failure> {
        let written = if self.is_stdout() {
            let mut stdout = std::io::stdout().lock();
            stdout.write_all(bytes).and_then(|()| stdout.flush())
        } else {
            std::fs::write(self.0, bytes)
        };
        written.map_err(|e| Failure::Failed(format!("cannot write '{}': {e}", self.0)))
    }

    /// Says what was written: on standard output, or on standard error when the file went
    /// there.
    pub fn report(&self, line: &str) {
        if self.is_stdout() {
            eprintln!("{line}");
        } else {
            println!("{line}");
        }
    }
}
