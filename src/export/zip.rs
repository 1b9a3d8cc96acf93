//! The ZIP container of a 3MF package: each part deflated as it is written (a step at a
//! time), then local headers, the central directory and its end record. Written here rather
//! than with the `zip` crate: a package of three parts in memory needs about sixty lines, and
//! the crate would bring its reader, its encryption and six more crates into the page; the
//! compressor (`flate2`) and the checksum (`crc32fast`) are the ones the PNG encoder already
//! uses. Dates are left at the format's earliest (1980-01-01), so the same shell gives the
//! same bytes.

use flate2::Compression;
use flate2::write::DeflateEncoder;
use std::io::Write;

/// A part being deflated.
pub(crate) struct Deflating {
    name: String,
    encoder: DeflateEncoder<Vec<u8>>,
    crc: crc32fast::Hasher,
    size: usize,
}

/// A part of the package, deflated.
pub(crate) struct Part {
    name: String,
    data: Vec<u8>,
    crc: u32,
    size: usize,
}

impl Deflating {
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_string(),
            encoder: DeflateEncoder::new(Vec::new(), Compression::new(3)),
            crc: crc32fast::Hasher::new(),
            size: 0,
        }
    }

    pub fn write(&mut self, bytes: &[u8]) {
        self.crc.update(bytes);
        self.size += bytes.len();
        self.encoder
            .write_all(bytes)
            .expect("writing to memory cannot fail");
    }

    pub fn finish(self) -> Part {
        Part {
            name: self.name,
            data: self
                .encoder
                .finish()
                .expect("writing to memory cannot fail"),
            crc: self.crc.finalize(),
            size: self.size,
        }
    }
}

impl Part {
    /// A part deflated at once.
    pub fn whole(name: &str, bytes: &[u8]) -> Self {
        let mut part = Deflating::new(name);
        part.write(bytes);
        part.finish()
    }

    /// The fields that local and central headers share: version needed (2.0), flags, method
    /// (deflate), time, date, checksum, sizes and the name's length.
    fn common(&self, out: &mut Vec<u8>) {
        for x in [20u16, 0, 8, 0, 0x21] {
            out.extend_from_slice(&x.to_le_bytes());
        }
        for x in [self.crc, self.data.len() as u32, self.size as u32] {
            out.extend_from_slice(&x.to_le_bytes());
        }
        out.extend_from_slice(&(self.name.len() as u16).to_le_bytes());
    }
}

/// The package of `parts`, in order.
pub(crate) fn package(parts: &[Part]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut offsets = Vec::new();
    for part in parts {
        offsets.push(out.len() as u32);
        out.extend_from_slice(b"PK\x03\x04");
        part.common(&mut out);
        out.extend_from_slice(&0u16.to_le_bytes());
        out.extend_from_slice(part.name.as_bytes());
        out.extend_from_slice(&part.data);
    }
    let directory = out.len() as u32;
    for (part, offset) in parts.iter().zip(offsets) {
        out.extend_from_slice(b"PK\x01\x02");
        // Made by: version 2.0.
        out.extend_from_slice(&20u16.to_le_bytes());
        part.common(&mut out);
        // Extra field, comment, disk, internal and external attributes.
        out.extend_from_slice(&[0; 12]);
        out.extend_from_slice(&offset.to_le_bytes());
        out.extend_from_slice(part.name.as_bytes());
    }
    let size = out.len() as u32 - directory;
    out.extend_from_slice(b"PK\x05\x06");
    out.extend_from_slice(&[0; 4]);
    for _ in 0..2 {
        out.extend_from_slice(&(parts.len() as u16).to_le_bytes());
    }
    out.extend_from_slice(&size.to_le_bytes());
    out.extend_from_slice(&directory.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use flate2::read::DeflateDecoder;
    use std::io::Read;

    #[test]
    fn parts_inflate_back_and_the_directory_finds_them() {
        let text = "<model>".repeat(1000);
        let zip = package(&[
            Part::whole("a.txt", b"hello"),
            Part::whole("3D/b.model", text.as_bytes()),
        ]);
        // The end record points at the directory, which names both parts.
        let end = zip.len() - 22;
        assert_eq!(&zip[end..end + 4], b"PK\x05\x06");
        let directory = u32::from_le_bytes(zip[end + 16..end + 20].try_into().unwrap()) as usize;
        assert_eq!(&zip[directory..directory + 4], b"PK\x01\x02");
        // The second local header and its data.
        let second = u32::from_le_bytes(
            zip[directory + 46 + 5 + 42..directory + 46 + 5 + 46]
                .try_into()
                .unwrap(),
        ) as usize;
        assert_eq!(&zip[second..second + 4], b"PK\x03\x04");
        let compressed =
            u32::from_le_bytes(zip[second + 18..second + 22].try_into().unwrap()) as usize;
        let name = u16::from_le_bytes(zip[second + 26..second + 28].try_into().unwrap()) as usize;
        assert_eq!(&zip[second + 30..second + 30 + name], b"3D/b.model");
        let data = &zip[second + 30 + name..second + 30 + name + compressed];
        let mut inflated = String::new();
        DeflateDecoder::new(data)
            .read_to_string(&mut inflated)
            .unwrap();
        assert_eq!(inflated, text);
        assert!(compressed < text.len() / 20);
    }
}
