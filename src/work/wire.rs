//! The bytes a message between the page and its workers is written in: postcard, serde's
//! compact binary format (numbers as variable-length integers, lists and text prefixed by
//! their length), with vertices, indices and pixels as blocks of their own bytes
//! ([`crate::pod_bytes`]) so that a mesh crosses as copies of memory. Only the page and its own
//! workers read it, both built from this one crate: the types themselves are the protocol.
//! Why postcard: docs/design/wire.md.

use serde::Serialize;
use serde::de::DeserializeOwned;
use std::fmt;

/// Why bytes could not be read as a message: what was being read, and why not.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WireError {
    /// What was being read (the message, or the part of it found wrong).
    pub key: &'static str,
    pub why: String,
}

impl fmt::Display for WireError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} could not be read: {}", self.key, self.why)
    }
}

impl std::error::Error for WireError {}

/// `message` as bytes.
pub fn write<T: Serialize>(message: &T) -> Vec<u8> {
    postcard::to_allocvec(message).expect("every message is plain data postcard writes")
}

/// The message `bytes` hold, `key` naming what it is: refused when they end early, hold
/// anything after it, or are not one.
pub fn read<T: DeserializeOwned>(bytes: &[u8], key: &'static str) -> Result<T, WireError> {
    let (message, rest) = postcard::take_from_bytes(bytes).map_err(|e| WireError {
        key,
        why: e.to_string(),
    })?;
    if rest.is_empty() {
        Ok(message)
    } else {
        Err(WireError {
            key,
            why: format!("{} bytes after its end", rest.len()),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{Mesh, Surface, Vertex};
    use glam::DVec3;

    type Message = (u32, String, Option<String>, Mesh, f64);

    #[test]
    fn what_is_written_reads_back_and_short_or_long_bytes_are_refused() {
        let mut mesh = Mesh::default();
        for k in 0..3 {
            let p = DVec3::new(k as f64, 0.5, -1.0);
            mesh.vertices
                .push(Vertex::new(p, DVec3::Z, [0.25, 7.0], Surface::Outer));
        }
        mesh.triangle([0, 1, 2], false);
        let message: Message = (7, "preset=murex-cabritii".into(), None, mesh, -0.0);
        let bytes = write(&message);
        let back: Message = read(&bytes, "test").unwrap();
        assert_eq!(back.4.to_bits(), (-0.0f64).to_bits());
        assert_eq!(back, message);
        let short = read::<Message>(&bytes[..bytes.len() - 1], "test");
        assert_eq!(short.unwrap_err().key, "test");
        let mut long = bytes.clone();
        long.push(0);
        let error = read::<Message>(&long, "test").unwrap_err();
        assert_eq!(error.why, "1 bytes after its end");
    }

    #[test]
    fn a_block_of_vertices_that_is_not_whole_vertices_is_refused() {
        let mesh = Mesh {
            vertices: vec![Vertex::default(); 2],
            indices: vec![0, 1, 1],
        };
        let mut bytes = write(&mesh);
        // The block's length leads it (one byte, under 128): one byte less, and one dropped.
        let block = 2 * size_of::<Vertex>();
        assert_eq!(usize::from(bytes[0]), block);
        bytes[0] -= 1;
        bytes.remove(1);
        assert_eq!(read::<Mesh>(&bytes, "mesh").unwrap_err().key, "mesh");
        bytes[0] = u8::try_from(size_of::<Vertex>()).unwrap();
        assert!(
            read::<Mesh>(&bytes, "mesh").is_err(),
            "one vertex read from a block of two"
        );
    }
}
