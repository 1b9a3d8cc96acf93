//! The ZIP container of a 3MF package: each part deflated straight into the package as it is
//! written (a step at a time), its local header filled in at its end, then the central
//! directory and its end record. Written here rather
//! than with the `zip` crate: a package of three parts in memory needs about sixty lines, and
//! the crate would bring its reader, its encryption and six more crates into the page; the
//! compressor (`flate2`) and the checksum (`crc32fast`) are the ones the PNG encoder already
//! uses. Dates are left at the format's earliest (1980-01-01), so the same shell gives the
//! same bytes.

use flate2::Compression;
use flate2::write::DeflateEncoder;
use std::io::Write;

/// A part already in the package: where its local header is, and what the directory repeats.
struct Entry {
    name: String,
    offset: usize,
    crc: u32,
    compressed: usize,
    size: usize,
}

impl Entry {
    /// The fields that local and central headers share: version needed (2.0), flags, method
    /// (deflate), time, date, checksum, sizes and the name's length.
    fn common(&self, out: &mut Vec<u8>) {
        for x in [20u16, 0, 8, 0, 0x21] {
            out.extend_from_slice(&x.to_le_bytes());
        }
        for x in [self.crc, self.compressed as u32, self.size as u32] {
            out.extend_from_slice(&x.to_le_bytes());
        }
        out.extend_from_slice(&(self.name.len() as u16).to_le_bytes());
    }

    /// The local header's length.
    fn header_len(&self) -> usize {
        30 + self.name.len()
    }
}

/// A package being written: parts one after the other, each deflated straight into it.
#[derive(Default)]
pub(crate) struct Package {
    out: Vec<u8>,
    entries: Vec<Entry>,
}

impl Package {
    /// A package with room for `bytes`, so that a large part is never moved as it grows.
    pub fn with_capacity(bytes: usize) -> Self {
        Self {
            out: Vec::with_capacity(bytes),
            entries: Vec::new(),
        }
    }
}

/// A part being deflated into its package, a piece at a time.
pub(crate) struct Deflating {
    encoder: DeflateEncoder<Vec<u8>>,
    entries: Vec<Entry>,
    entry: Entry,
    crc: crc32fast::Hasher,
}

impl Package {
    /// Adds a part whole.
    pub fn add(self, name: &str, bytes: &[u8]) -> Self {
        let mut part = self.begin(name);
        part.write(bytes);
        part.finish()
    }

    /// Starts a part: its local header, whose checksum and sizes are filled in at its end.
    pub fn begin(mut self, name: &str) -> Deflating {
        let entry = Entry {
            name: name.to_string(),
            offset: self.out.len(),
            crc: 0,
            compressed: 0,
            size: 0,
        };
        self.out.extend_from_slice(b"PK\x03\x04");
        entry.common(&mut self.out);
        self.out.extend_from_slice(&0u16.to_le_bytes());
        self.out.extend_from_slice(name.as_bytes());
        Deflating {
            encoder: DeflateEncoder::new(self.out, Compression::new(3)),
            entries: self.entries,
            entry,
            crc: crc32fast::Hasher::new(),
        }
    }

    /// The package: its parts, the central directory and its end record.
    pub fn finish(self) -> Vec<u8> {
        let mut out = self.out;
        let directory = out.len() as u32;
        for entry in &self.entries {
            out.extend_from_slice(b"PK\x01\x02");
            // Made by: version 2.0.
            out.extend_from_slice(&20u16.to_le_bytes());
            entry.common(&mut out);
            // Extra field, comment, disk, internal and external attributes.
            out.extend_from_slice(&[0; 12]);
            out.extend_from_slice(&(entry.offset as u32).to_le_bytes());
            out.extend_from_slice(entry.name.as_bytes());
        }
        let size = out.len() as u32 - directory;
        out.extend_from_slice(b"PK\x05\x06");
        out.extend_from_slice(&[0; 4]);
        for _ in 0..2 {
            out.extend_from_slice(&(self.entries.len() as u16).to_le_bytes());
        }
        out.extend_from_slice(&size.to_le_bytes());
        out.extend_from_slice(&directory.to_le_bytes());
        out.extend_from_slice(&0u16.to_le_bytes());
        out
    }
}

impl Deflating {
    pub fn write(&mut self, bytes: &[u8]) {
        self.crc.update(bytes);
        self.entry.size += bytes.len();
        self.encoder
            .write_all(bytes)
            .expect("writing to memory cannot fail");
    }

    /// Ends the part, filling in its local header.
    pub fn finish(self) -> Package {
        let mut out = self
            .encoder
            .finish()
            .expect("writing to memory cannot fail");
        let mut entry = self.entry;
        entry.crc = self.crc.finalize();
        entry.compressed = out.len() - entry.offset - entry.header_len();
        let mut header = Vec::with_capacity(entry.header_len());
        header.extend_from_slice(b"PK\x03\x04");
        entry.common(&mut header);
        out[entry.offset..entry.offset + header.len()].copy_from_slice(&header);
        let mut entries = self.entries;
        entries.push(entry);
        Package { out, entries }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use flate2::read::DeflateDecoder;
    use std::io::Read;

    #[test]
    fn parts_inflate_back_and_the_directory_finds_them() {
        let text = "<model>".repeat(1000);
        let mut model = Package::default()
            .add("a.txt", b"hello")
            .begin("3D/b.model");
        for piece in text.as_bytes().chunks(100) {
            model.write(piece);
        }
        let zip = model.finish().finish();
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
