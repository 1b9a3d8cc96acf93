//! Plain data (vertices, indices, pixels) serialised as one block of its own bytes, for
//! `#[serde(with = "crate::pod_bytes")]` on a `Vec` of it: a mesh crosses between threads as
//! copies of memory in the layout the GPU reads, not number by number. The bytes read back
//! need not be aligned; a block whose length is not a whole number of items is refused.

use bytemuck::Pod;
use serde::de::{Error, Visitor};
use serde::{Deserializer, Serializer};
use std::fmt;
use std::marker::PhantomData;

pub(crate) fn serialize<T: Pod, S: Serializer>(items: &[T], s: S) -> Result<S::Ok, S::Error> {
    s.serialize_bytes(bytemuck::cast_slice(items))
}

pub(crate) fn deserialize<'de, T: Pod, D: Deserializer<'de>>(d: D) -> Result<Vec<T>, D::Error> {
    d.deserialize_bytes(Items(PhantomData))
}

struct Items<T>(PhantomData<T>);

impl<T: Pod> Visitor<'_> for Items<T> {
    type Value = Vec<T>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "bytes of items {} bytes long", size_of::<T>())
    }

    fn visit_bytes<E: Error>(self, bytes: &[u8]) -> Result<Vec<T>, E> {
        if bytes.len().is_multiple_of(size_of::<T>()) {
            Ok(bytemuck::pod_collect_to_vec(bytes))
        } else {
            Err(E::invalid_length(bytes.len(), &self))
        }
    }
}
