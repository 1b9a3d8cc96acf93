//! Binary little-endian PLY: welded vertices with averaged normals, triangle faces.

use super::weld::Welded;
use crate::mesh::Mesh;
use glam::Vec3;

pub fn write(mesh: &Mesh) -> Vec<u8> {
    let welded = Welded::new(mesh);
    let mut normals = vec![Vec3::ZERO; welded.positions.len()];
    for (v, &i) in mesh.vertices.iter().zip(&welded.index) {
        normals[i as usize] += Vec3::from(v.normal);
    }
    let triangles: Vec<[u32; 3]> = welded.triangles(mesh).collect();
    let header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment seashells\nelement vertex {}\n\
         property float x\nproperty float y\nproperty float z\n\
         property float nx\nproperty float ny\nproperty float nz\n\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        welded.positions.len(),
        triangles.len()
    );
    let mut out = header.into_bytes();
    for (p, n) in welded.positions.iter().zip(&normals) {
        let n = n.normalize_or(Vec3::Z);
        for x in p.iter().chain(n.to_array().iter()) {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    for t in triangles {
        out.push(3);
        for i in t {
            out.extend_from_slice(&i.to_le_bytes());
        }
    }
    out
}
