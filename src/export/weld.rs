//! Merging vertices that share a position bit for bit (seams, lip and edge bands carry copies
//! with their own normals), so that exported solids are watertight by index as well as by
//! position. The welding runs a slice of vertices at a time (see [`super::steps`]).

use crate::mesh::Mesh;
use std::collections::HashMap;
use std::ops::Range;

/// The distinct positions of a mesh, and for each vertex the index of its position.
pub struct Welded {
    pub positions: Vec<[f32; 3]>,
    pub index: Vec<u32>,
    /// For each position, the vertex whose colour it takes: the first on the outer surface
    /// (where the lip meets the outer surface, the pattern reaches the rim), else the first.
    pub source: Vec<u32>,
}

/// A welding under way.
pub struct Welder {
    seen: HashMap<[u32; 3], u32>,
    welded: Welded,
}

impl Welder {
    pub fn new(mesh: &Mesh) -> Self {
        Self {
            seen: HashMap::with_capacity(mesh.vertices.len()),
            welded: Welded {
                positions: Vec::new(),
                index: Vec::with_capacity(mesh.vertices.len()),
                source: Vec::new(),
            },
        }
    }

    /// Welds the vertices `range` of `mesh` (called over consecutive ranges from 0).
    pub fn weld(&mut self, mesh: &Mesh, range: Range<usize>) {
        let w = &mut self.welded;
        for (i, v) in mesh.vertices[range.clone()].iter().enumerate() {
            let i = (range.start + i) as u32;
            let key = v.position.map(f32::to_bits);
            let at = *self.seen.entry(key).or_insert_with(|| {
                w.positions.push(v.position);
                w.source.push(i);
                w.positions.len() as u32 - 1
            });
            let source = &mut w.source[at as usize];
            if v.is_outer() && !mesh.vertices[*source as usize].is_outer() {
                *source = i;
            }
            w.index.push(at);
        }
    }

    pub fn finish(self) -> Welded {
        self.welded
    }
}

impl Welded {
    /// Triangle `t` of the mesh in welded indices, or `None` when it collapses to a line.
    pub fn triangle(&self, mesh: &Mesh, t: usize) -> Option<[u32; 3]> {
        let c = [0, 1, 2].map(|k| self.index[mesh.indices[3 * t + k] as usize]);
        (c[0] != c[1] && c[1] != c[2] && c[2] != c[0]).then_some(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{Surface, Vertex};
    use glam::DVec3;

    #[test]
    fn copies_at_one_position_become_one_vertex_that_takes_the_outer_colour() {
        let mut mesh = Mesh::default();
        let at = |x: f64| DVec3::new(x, 0.0, 0.0);
        for (x, surface) in [
            (0.0, Surface::Edge),
            (1.0, Surface::Outer),
            (0.0, Surface::Outer),
            (2.0, Surface::Inner),
            (0.0, Surface::Outer),
        ] {
            mesh.vertices
                .push(Vertex::new(at(x), DVec3::Z, [0.0, 0.0], surface));
        }
        mesh.indices = vec![0, 1, 3, 2, 4, 1];
        let mut welder = Welder::new(&mesh);
        welder.weld(&mesh, 0..2);
        welder.weld(&mesh, 2..5);
        let welded = welder.finish();
        assert_eq!(welded.positions.len(), 3);
        assert_eq!(welded.index, [0, 1, 0, 2, 0]);
        assert_eq!(welded.source, [2, 1, 3]);
        assert_eq!(welded.triangle(&mesh, 0), Some([0, 1, 2]));
        assert_eq!(welded.triangle(&mesh, 1), None);
    }
}
