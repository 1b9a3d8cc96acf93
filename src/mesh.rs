//! The triangle mesh every form produces and every consumer reads: the GPU buffers, the
//! exporters and the tests. Vertices are laid out exactly as the vertex shader reads them.

use crate::fnv::Fnv;
use bytemuck::{Pod, Zeroable};
use glam::DVec3;
use serde::{Deserialize, Serialize};

/// Which part of the shell a vertex belongs to; the shader colours each differently.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// The outer surface, which carries the pigmentation pattern.
    Outer = 0,
    /// The inner surface of the wall (the porcelain inside of the opening).
    Inner = 1,
    /// The edges joining outer and inner surfaces: lip, apex and sides of an open curve.
    Edge = 2,
    /// The ground under the shell, which only the renderer draws (never exported).
    Ground = 3,
}

/// One mesh vertex, 52 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    /// Pattern coordinates: x is the position along the growing edge in [0, 1], y the growth
    /// time in pattern rows.
    pub pattern: [f32; 2],
    /// The [`Surface`] as a number.
    pub surface: f32,
    /// Colours blended by field on an implicit surface (Galbraith et al. §3.4): (r, g, b)
    /// in linear light, already weighted, and the pattern's share a; the outer surface's
    /// colour is a · pattern + (r, g, b). (0, 0, 0, 1) everywhere else: the pattern alone.
    pub tint: [f32; 4],
}

impl Vertex {
    pub fn new(position: DVec3, normal: DVec3, pattern: [f64; 2], surface: Surface) -> Self {
        Self {
            position: position.as_vec3().to_array(),
            normal: normal.as_vec3().to_array(),
            pattern: [pattern[0] as f32, pattern[1] as f32],
            surface: surface as u8 as f32,
            tint: [0.0, 0.0, 0.0, 1.0],
        }
    }

    /// The same vertex with the colours blended there ([`Vertex::tint`]).
    pub fn tinted(self, tint: [f64; 4]) -> Self {
        Self {
            tint: tint.map(|c| c as f32),
            ..self
        }
    }

    /// Whether the vertex is on the outer surface, which carries the pattern.
    pub fn is_outer(&self) -> bool {
        self.surface == Surface::Outer as u8 as f32
    }
}

/// An indexed triangle list.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Mesh {
    #[serde(with = "crate::pod_bytes")]
    pub vertices: Vec<Vertex>,
    #[serde(with = "crate::pod_bytes")]
    pub indices: Vec<u32>,
}

impl Mesh {
    /// Makes room for `capacity` in all, what the mesh holds included.
    pub fn reserve_total(&mut self, capacity: Capacity) {
        let (v, i) = (self.vertices.len(), self.indices.len());
        self.vertices.reserve(capacity.vertices.saturating_sub(v));
        self.indices.reserve(capacity.indices.saturating_sub(i));
    }

    /// Index the next pushed vertex will get.
    pub fn next_index(&self) -> u32 {
        self.vertices.len() as u32
    }

    pub fn clear(&mut self) {
        self.vertices.clear();
        self.indices.clear();
    }

    /// Appends `other`, shifting its indices.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.next_index();
        self.vertices.extend_from_slice(&other.vertices);
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }

    /// Appends `other` as [`Mesh::append`] does, but once the mesh holds a million bytes or so,
    /// growing its room by an eighth at a time instead of doubling it: a large mesh joined
    /// piece by piece then holds at most an eighth more room than it fills, where doubling
    /// leaves up to as much again unused. Where a growing buffer is copied (WebAssembly's
    /// allocator; natively, large buffers move their pages instead) the copies add up to
    /// about eight times the mesh, against twice when doubling.
    pub fn append_sparingly(&mut self, other: &Mesh) {
        fn room_for<T>(v: &mut Vec<T>, more: usize) {
            if v.capacity() - v.len() < more {
                let step = if size_of_val(v.as_slice()) < 1 << 20 {
                    v.len()
                } else {
                    v.len() / 8
                };
                v.reserve_exact(more.max(step));
            }
        }
        room_for(&mut self.vertices, other.vertices.len());
        room_for(&mut self.indices, other.indices.len());
        self.append(other);
    }

    /// Pushes the two triangles of a quad a-b-c-d (in order around it); `flip` reverses them.
    pub fn quad(&mut self, [a, b, c, d]: [u32; 4], flip: bool) {
        if flip {
            self.indices.extend_from_slice(&[a, c, b, a, d, c]);
        } else {
            self.indices.extend_from_slice(&[a, b, c, a, c, d]);
        }
    }

    /// Pushes one triangle; `flip` reverses it.
    pub fn triangle(&mut self, [a, b, c]: [u32; 3], flip: bool) {
        if flip {
            self.indices.extend_from_slice(&[a, c, b]);
        } else {
            self.indices.extend_from_slice(&[a, b, c]);
        }
    }

    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Whether triangle `t` has two corners at one position, bit for bit: it has no area, and
    /// every file leaves it out.
    pub fn collapsed(&self, t: usize) -> bool {
        let [a, b, c] = [0, 1, 2].map(|k| {
            self.vertices[self.indices[3 * t + k] as usize]
                .position
                .map(f32::to_bits)
        });
        a == b || b == c || c == a
    }

    /// Whether every position and normal is a finite number.
    pub fn is_finite(&self) -> bool {
        self.vertices
            .iter()
            .all(|v| v.position.iter().chain(&v.normal).all(|x| x.is_finite()))
    }

    /// A hash of the triangles' vertex data (every bit of position, normal, pattern coordinates
    /// and surface) that does not depend on the order of the triangles: two meshes made of the
    /// same triangles in another order hash alike. Used to check that native and wasm builds,
    /// and growth step by step or all at once, give the same mesh.
    pub fn content_hash(&self) -> u64 {
        self.indices.chunks_exact(3).fold(0u64, |sum, t| {
            let mut h = Fnv::default();
            for &i in t {
                h.write(bytemuck::bytes_of(&self.vertices[i as usize]));
            }
            sum.wrapping_add(h.value())
        })
    }
}

/// The most a shell may grow from its apex to its opening, as a power of ten. A file written
/// in float32 (GLB, 3MF, STL) places the whole shell around the origin at its size, keeping
/// about 7 significant digits: a rim 10⁻⁴ of the whole, cut into as many as 512 segments,
/// keeps some 20 float32 steps along each, so its triangles stay distinct; at 10⁻⁵ the
/// property test found rims whose points fell together (tests/any_link.rs, docs/fuzzing.md),
/// and far beyond, the growth leaves the range of numbers. Every preset grows less than 10³.
pub const MAX_GROWTH_DECADES: f64 = 4.0;

/// Most vertices a shell's mesh may have (104 MB of vertex data): a spec whose form would
/// make more is repaired.
pub const MAX_VERTICES: u64 = 2_000_000;

/// Sizes a mesh reaches when fully grown, so buffers can be allocated once.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Capacity {
    pub vertices: usize,
    pub indices: usize,
}

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bounds {
    pub min: DVec3,
    pub max: DVec3,
}

impl Bounds {
    pub const EMPTY: Bounds = Bounds {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    pub fn include(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    /// Grows to hold the positions of `vertices`: what a mesh grown so far covers.
    pub fn include_vertices(&mut self, vertices: &[Vertex]) {
        for v in vertices {
            self.include(DVec3::from(v.position.map(f64::from)));
        }
    }

    pub fn center(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    /// Whether the box holds no point.
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// The smallest box holding both.
    pub fn union(&self, other: &Bounds) -> Bounds {
        Bounds {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The common part (empty when they are apart).
    pub fn intersection(&self, other: &Bounds) -> Bounds {
        Bounds {
            min: self.min.max(other.min),
            max: self.max.min(other.max),
        }
    }

    /// Whether the two boxes share a point.
    pub fn intersects(&self, other: &Bounds) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }

    /// Whether `p` lies in the box, faces included. Branch-free: the implicit modeller asks it
    /// at every node of a tree for every point it evaluates.
    pub fn contains(&self, p: DVec3) -> bool {
        (p.x >= self.min.x)
            & (p.x <= self.max.x)
            & (p.y >= self.min.y)
            & (p.y <= self.max.y)
            & (p.z >= self.min.z)
            & (p.z <= self.max.z)
    }

    /// The box grown by `margin` on every side.
    pub fn padded(&self, margin: f64) -> Bounds {
        Bounds {
            min: self.min - margin,
            max: self.max + margin,
        }
    }

    /// The eight corners.
    pub fn corners(&self) -> [DVec3; 8] {
        std::array::from_fn(|i| {
            DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            )
        })
    }

    /// Radius of the sphere around the centre that holds the box.
    pub fn radius(&self) -> f64 {
        (self.max - self.min).length() * 0.5
    }
}
