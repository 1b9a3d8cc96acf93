//! The recorded values of a pattern as CSV: one line per row, one value per cell, each number
//! in its shortest exact decimal form.

use std::fmt::Write;

/// Appends one row.
pub fn write_row(out: &mut String, values: &[f32]) {
    for (i, v) in values.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        write!(out, "{v}").expect("write to string");
    }
    out.push('\n');
}
