//! The bytes a message between the page and its workers is written in: numbers little-endian,
//! lists and text prefixed by their length, vertices and indices as their own bytes (the layout
//! the GPU reads), so that a mesh crosses as one block of memory. Only the page and its own
//! workers read it, both built from this one crate.

use crate::mesh::{Bounds, Mesh, Vertex};
use glam::DVec3;
use std::fmt;

/// Why bytes could not be read as a message: what was being read, and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WireError {
    /// What was being read (a field of the message).
    pub key: &'static str,
    /// The byte it was read at.
    pub at: usize,
}

impl fmt::Display for WireError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} could not be read at byte {}", self.key, self.at)
    }
}

impl std::error::Error for WireError {}

/// A message being written.
#[derive(Default)]
pub struct Writer {
    bytes: Vec<u8>,
}

impl Writer {
    pub fn into_bytes(self) -> Vec<u8> {
        self.bytes
    }

    pub fn u8(&mut self, x: u8) {
        self.bytes.push(x);
    }

    pub fn bool(&mut self, x: bool) {
        self.u8(u8::from(x));
    }

    pub fn u32(&mut self, x: u32) {
        self.bytes.extend_from_slice(&x.to_le_bytes());
    }

    pub fn u64(&mut self, x: u64) {
        self.bytes.extend_from_slice(&x.to_le_bytes());
    }

    pub fn f64(&mut self, x: f64) {
        self.bytes.extend_from_slice(&x.to_le_bytes());
    }

    /// A count or size (this crate's sizes fit 32 bits: see `mesh::MAX_VERTICES`).
    pub fn len(&mut self, n: usize) {
        self.u32(u32::try_from(n).expect("sizes in messages fit 32 bits"));
    }

    pub fn bytes(&mut self, b: &[u8]) {
        self.len(b.len());
        self.bytes.extend_from_slice(b);
    }

    pub fn str(&mut self, s: &str) {
        self.bytes(s.as_bytes());
    }

    pub fn option_str(&mut self, s: Option<&str>) {
        self.bool(s.is_some());
        if let Some(s) = s {
            self.str(s);
        }
    }

    pub fn u32s(&mut self, xs: &[u32]) {
        self.bytes(bytemuck::cast_slice(xs));
    }

    pub fn vertices(&mut self, vs: &[Vertex]) {
        self.bytes(bytemuck::cast_slice(vs));
    }

    pub fn mesh(&mut self, m: &Mesh) {
        self.vertices(&m.vertices);
        self.u32s(&m.indices);
    }

    pub fn dvec3(&mut self, v: DVec3) {
        for x in v.to_array() {
            self.f64(x);
        }
    }

    pub fn bounds(&mut self, b: &Bounds) {
        self.dvec3(b.min);
        self.dvec3(b.max);
    }
}

/// A message being read.
pub struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes, at: 0 }
    }

    /// The byte the next read starts at.
    pub fn at(&self) -> usize {
        self.at
    }

    /// Fails unless every byte was read: a message has nothing after its end.
    pub fn end(&self) -> Result<(), WireError> {
        if self.at == self.bytes.len() {
            Ok(())
        } else {
            Err(WireError {
                key: "the end of the message",
                at: self.at,
            })
        }
    }

    fn take(&mut self, n: usize, key: &'static str) -> Result<&'a [u8], WireError> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.bytes.len());
        let end = end.ok_or(WireError { key, at: self.at })?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }

    fn array<const N: usize>(&mut self, key: &'static str) -> Result<[u8; N], WireError> {
        let b = self.take(N, key)?;
        Ok(b.try_into().expect("took N bytes"))
    }

    pub fn u8(&mut self, key: &'static str) -> Result<u8, WireError> {
        Ok(self.array::<1>(key)?[0])
    }

    pub fn bool(&mut self, key: &'static str) -> Result<bool, WireError> {
        match self.u8(key)? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(WireError {
                key,
                at: self.at - 1,
            }),
        }
    }

    pub fn u32(&mut self, key: &'static str) -> Result<u32, WireError> {
        Ok(u32::from_le_bytes(self.array(key)?))
    }

    pub fn u64(&mut self, key: &'static str) -> Result<u64, WireError> {
        Ok(u64::from_le_bytes(self.array(key)?))
    }

    pub fn f64(&mut self, key: &'static str) -> Result<f64, WireError> {
        Ok(f64::from_le_bytes(self.array(key)?))
    }

    pub fn len(&mut self, key: &'static str) -> Result<usize, WireError> {
        Ok(self.u32(key)? as usize)
    }

    pub fn bytes(&mut self, key: &'static str) -> Result<&'a [u8], WireError> {
        let n = self.len(key)?;
        self.take(n, key)
    }

    pub fn string(&mut self, key: &'static str) -> Result<String, WireError> {
        let at = self.at;
        let b = self.bytes(key)?;
        String::from_utf8(b.to_vec()).map_err(|_| WireError { key, at })
    }

    pub fn option_string(&mut self, key: &'static str) -> Result<Option<String>, WireError> {
        if self.bool(key)? {
            self.string(key).map(Some)
        } else {
            Ok(None)
        }
    }

    /// Plain data of type `T` written by its bytes (copied out: the bytes need not be aligned).
    fn pods<T: bytemuck::Pod>(&mut self, key: &'static str) -> Result<Vec<T>, WireError> {
        let at = self.at;
        let b = self.bytes(key)?;
        if b.len() % size_of::<T>() != 0 {
            return Err(WireError { key, at });
        }
        Ok(bytemuck::pod_collect_to_vec(b))
    }

    pub fn u32s(&mut self, key: &'static str) -> Result<Vec<u32>, WireError> {
        self.pods(key)
    }

    pub fn vertices(&mut self, key: &'static str) -> Result<Vec<Vertex>, WireError> {
        self.pods(key)
    }

    /// A mesh whose indices all name its vertices.
    pub fn mesh(&mut self, key: &'static str) -> Result<Mesh, WireError> {
        let vertices = self.vertices(key)?;
        let at = self.at;
        let indices = self.u32s(key)?;
        if indices.iter().any(|&i| i as usize >= vertices.len()) {
            return Err(WireError { key, at });
        }
        Ok(Mesh { vertices, indices })
    }

    pub fn dvec3(&mut self, key: &'static str) -> Result<DVec3, WireError> {
        Ok(DVec3::new(self.f64(key)?, self.f64(key)?, self.f64(key)?))
    }

    pub fn bounds(&mut self, key: &'static str) -> Result<Bounds, WireError> {
        Ok(Bounds {
            min: self.dvec3(key)?,
            max: self.dvec3(key)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Surface;

    #[test]
    fn what_is_written_reads_back_and_short_or_long_bytes_are_refused() {
        let mut mesh = Mesh::default();
        for k in 0..3 {
            let p = DVec3::new(k as f64, 0.5, -1.0);
            mesh.vertices
                .push(Vertex::new(p, DVec3::Z, [0.25, 7.0], Surface::Outer));
        }
        mesh.triangle([0, 1, 2], false);
        let mut w = Writer::default();
        w.u32(7);
        w.str("preset=murex-cabritii");
        w.option_str(None);
        w.mesh(&mesh);
        w.f64(-0.0);
        let bytes = w.into_bytes();
        let mut r = Reader::new(&bytes);
        assert_eq!(r.u32("n"), Ok(7));
        assert_eq!(r.string("link").as_deref(), Ok("preset=murex-cabritii"));
        assert_eq!(r.option_string("why"), Ok(None));
        assert_eq!(r.mesh("mesh"), Ok(mesh));
        assert_eq!(r.f64("x").map(f64::to_bits), Ok((-0.0f64).to_bits()));
        assert_eq!(r.end(), Ok(()));
        let mut short = Reader::new(&bytes[..bytes.len() - 1]);
        short.u32("n").unwrap();
        short.string("link").unwrap();
        short.option_string("why").unwrap();
        short.mesh("mesh").unwrap();
        assert_eq!(short.f64("x").unwrap_err().key, "x");
        let mut long = bytes.clone();
        long.push(0);
        let mut r = Reader::new(&long);
        r.u32("n").unwrap();
        r.string("link").unwrap();
        r.option_string("why").unwrap();
        r.mesh("mesh").unwrap();
        r.f64("x").unwrap();
        assert_eq!(r.end().unwrap_err().key, "the end of the message");
    }

    #[test]
    fn a_mesh_whose_indices_leave_its_vertices_is_refused() {
        let mut w = Writer::default();
        w.vertices(&[Vertex::default()]);
        w.u32s(&[0, 0, 1]);
        let bytes = w.into_bytes();
        assert_eq!(Reader::new(&bytes).mesh("edge").unwrap_err().key, "edge");
    }
}
