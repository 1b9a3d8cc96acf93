//! Writing what the core grows to files: meshes as OBJ, binary PLY or binary STL, and patterns
//! as PNG or CSV, chosen by the file's extension.

pub mod csv;
pub mod obj;
pub mod ply;
pub mod png;
pub mod stl;
pub(crate) mod weld;

use crate::mesh::Mesh;

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    Obj,
    Ply,
    Stl,
}

impl MeshFormat {
    /// The format a file name's extension asks for.
    pub fn from_path(path: &str) -> Result<Self, String> {
        let ext = path.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase());
        match ext.as_deref() {
            Some("obj") => Ok(Self::Obj),
            Some("ply") => Ok(Self::Ply),
            Some("stl") => Ok(Self::Stl),
            _ => Err(format!("'{path}' should end in .obj, .ply or .stl")),
        }
    }

    /// The mesh in this format.
    pub fn write(self, mesh: &Mesh) -> Vec<u8> {
        match self {
            Self::Obj => obj::write(mesh),
            Self::Ply => ply::write(mesh),
            Self::Stl => stl::write(mesh),
        }
    }
}
