//! Binary STL: an 80-byte header, the triangle count, then per triangle its facet normal and
//! three corners.

use super::weld::Welded;
use crate::mesh::Mesh;
use glam::Vec3;

pub fn write(mesh: &Mesh) -> Vec<u8> {
    let welded = Welded::new(mesh);
    let triangles: Vec<[u32; 3]> = welded.triangles(mesh).collect();
    let mut out = Vec::with_capacity(84 + 50 * triangles.len());
    let text = b"seashells: a shell grown from the Fowler, Meinhardt & Prusinkiewicz model";
    let mut header = [b' '; 80];
    header[..text.len()].copy_from_slice(text);
    out.extend_from_slice(&header);
    out.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
    for t in triangles {
        let [a, b, c] = t.map(|i| Vec3::from(welded.positions[i as usize]));
        let normal = (b - a).cross(c - a).normalize_or_zero();
        for v in [normal, a, b, c] {
            for x in v.to_array() {
                out.extend_from_slice(&x.to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    out
}
