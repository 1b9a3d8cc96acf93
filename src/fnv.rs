//! The one hash of the crate: FNV-1a, 64 bits. Small, with no state beyond a word, and the
//! same on every platform, so a pattern or a mesh hashed natively and in wasm compare bit for
//! bit.

/// FNV-1a, 64 bits, over the bytes written to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Fnv(u64);

impl Default for Fnv {
    fn default() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv {
    pub(crate) fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    pub(crate) fn value(self) -> u64 {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv_matches_the_reference_values() {
        let mut h = Fnv::default();
        assert_eq!(h.value(), 0xcbf29ce484222325);
        h.write(b"a");
        assert_eq!(h.value(), 0xaf63dc4c8601ec8c);
    }
}
