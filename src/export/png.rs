//! PNG images: a pattern's planar representation (rows are time, columns are cells) as RGBA,
//! and the GLB's texture as RGB, encoded a few rows at a time so that a large image is made
//! over several steps (see [`super::steps`]).

use super::error::ExportError;
use super::steps::{Cursor, Writer};
use std::cell::RefCell;
use std::io::Write;
use std::rc::Rc;

/// Encodes `rgba` (width × height × 4 bytes) as PNG, at once.
pub fn encode(width: usize, height: usize, rgba: &[u8]) -> Vec<u8> {
    let mut png = PngRows::new(width, height, png::ColorType::Rgba);
    png.write(rgba);
    png.finish()
}

/// The bytes the encoder writes, kept where they can be taken back once it is dropped (the
/// encoder owns its output and drops it when it finishes).
#[derive(Clone, Default)]
struct Sink(Rc<RefCell<Vec<u8>>>);

impl Write for Sink {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(bytes);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// A PNG being encoded row by row.
pub(crate) struct PngRows {
    stream: png::StreamWriter<'static, Sink>,
    sink: Sink,
}

impl PngRows {
    /// A `width × height` image of 8-bit channels of `color` (RGB or RGBA).
    pub fn new(width: usize, height: usize, color: png::ColorType) -> Self {
        let sink = Sink::default();
        let mut encoder = png::Encoder::new(sink.clone(), width as u32, height as u32);
        encoder.set_color(color);
        encoder.set_depth(png::BitDepth::Eight);
        let stream = encoder
            .write_header()
            .and_then(png::Writer::into_stream_writer)
            .expect("writing to memory cannot fail");
        Self { stream, sink }
    }

    /// Appends whole rows of pixels.
    pub fn write(&mut self, rows: &[u8]) {
        self.stream
            .write_all(rows)
            .expect("writing to memory cannot fail");
    }

    /// The PNG file, once every row is written.
    pub fn finish(self) -> Vec<u8> {
        self.stream
            .finish()
            .expect("every row of the image was written");
        self.sink.0.take()
    }
}

/// Rows of an image a step encodes: about 64 kB.
pub(crate) fn rows_per_step(row_bytes: usize) -> usize {
    (65_536 / row_bytes.max(1)).max(1)
}

/// The pattern's planar representation as a PNG file, a few rows a step.
pub(crate) struct PatternPng {
    rgba: Vec<u8>,
    row_bytes: usize,
    rows: Cursor,
    png: Option<PngRows>,
}

impl PatternPng {
    /// The image of `cells × rows` RGBA texels.
    pub fn new(cells: usize, rows: usize, rgba: Vec<u8>) -> Self {
        Self {
            rgba,
            row_bytes: cells * 4,
            rows: Cursor::new(rows),
            png: Some(PngRows::new(cells, rows, png::ColorType::Rgba)),
        }
    }
}

impl Writer for PatternPng {
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError> {
        let rows = self.rows.next(rows_per_step(self.row_bytes));
        let png = self.png.as_mut().expect("not finished");
        png.write(&self.rgba[rows.start * self.row_bytes..rows.end * self.row_bytes]);
        Ok(if self.rows.done() {
            self.png.take().map(PngRows::finish)
        } else {
            None
        })
    }

    fn progress(&self) -> f64 {
        self.rows.fraction()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(bytes: Vec<u8>) -> (u32, u32, Vec<u8>) {
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        buf.truncate(info.buffer_size());
        (info.width, info.height, buf)
    }

    #[test]
    fn decodes_back_to_the_same_pixels() {
        let rgba: Vec<u8> = (0..3 * 2 * 4).map(|i| i as u8 * 10).collect();
        assert_eq!(decode(encode(3, 2, &rgba)), (3, 2, rgba));
    }

    #[test]
    fn a_pattern_written_in_steps_is_the_pattern_encoded_at_once() {
        let (cells, rows) = (300, 500);
        let rgba: Vec<u8> = (0..cells * rows * 4).map(|i| (i * 7 % 251) as u8).collect();
        let mut writer = PatternPng::new(cells, rows, rgba.clone());
        let mut steps = 0;
        let bytes = loop {
            steps += 1;
            if let Some(bytes) = writer.step().unwrap() {
                break bytes;
            }
            assert!(writer.progress() < 1.0);
        };
        assert!(steps > 5, "{steps} steps");
        assert_eq!(bytes, encode(cells, rows, &rgba));
    }
}
