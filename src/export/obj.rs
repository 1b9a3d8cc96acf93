//! Wavefront OBJ: welded positions, one normal per original vertex (creases stay sharp).

use super::weld::Welded;
use crate::mesh::Mesh;
use std::fmt::Write;

pub fn write(mesh: &Mesh) -> Vec<u8> {
    let welded = Welded::new(mesh);
    let mut out = String::from(
        "# seashells: a shell grown from the Fowler, Meinhardt & Prusinkiewicz model\n",
    );
    for [x, y, z] in &welded.positions {
        writeln!(out, "v {x} {y} {z}").expect("write to string");
    }
    for v in &mesh.vertices {
        let [x, y, z] = v.normal;
        writeln!(out, "vn {x} {y} {z}").expect("write to string");
    }
    for t in mesh.indices.chunks_exact(3) {
        let p = [0, 1, 2].map(|k| welded.index[t[k] as usize] + 1);
        if p[0] == p[1] || p[1] == p[2] || p[2] == p[0] {
            continue;
        }
        let n = [0, 1, 2].map(|k| t[k] + 1);
        writeln!(
            out,
            "f {}//{} {}//{} {}//{}",
            p[0], n[0], p[1], n[1], p[2], n[2]
        )
        .expect("write to string");
    }
    out.into_bytes()
}
