//! Merging vertices that share a position bit for bit (seams, lip and edge bands carry copies
//! with their own normals), so that exported solids are watertight by index as well as by
//! position.

use crate::mesh::Mesh;
use std::collections::HashMap;

/// The distinct positions of a mesh, and for each vertex the index of its position.
pub struct Welded {
    pub positions: Vec<[f32; 3]>,
    pub index: Vec<u32>,
}

impl Welded {
    pub fn new(mesh: &Mesh) -> Self {
        let mut positions = Vec::new();
        let mut seen: HashMap<[u32; 3], u32> = HashMap::new();
        let index = mesh
            .vertices
            .iter()
            .map(|v| {
                let key = v.position.map(f32::to_bits);
                *seen.entry(key).or_insert_with(|| {
                    positions.push(v.position);
                    positions.len() as u32 - 1
                })
            })
            .collect();
        Self { positions, index }
    }

    /// The mesh's triangles in welded indices, dropping those that collapse to a line.
    pub fn triangles<'a>(&'a self, mesh: &'a Mesh) -> impl Iterator<Item = [u32; 3]> + 'a {
        mesh.indices
            .chunks_exact(3)
            .map(|t| [0, 1, 2].map(|k| self.index[t[k] as usize]))
            .filter(|[a, b, c]| a != b && b != c && c != a)
    }
}
