//! Writing what the core grows to files: meshes as OBJ, binary PLY or binary STL, and patterns
//! as PNG or CSV, chosen by the file's extension; recorded growth as WebM.

pub mod csv;
pub mod obj;
pub mod ply;
pub mod png;
pub mod stl;
pub mod webm;
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

impl MeshFormat {
    /// The file name's extension for this format.
    pub fn extension(self) -> &'static str {
        match self {
            Self::Obj => "obj",
            Self::Ply => "ply",
            Self::Stl => "stl",
        }
    }
}

/// A file the page offers to download for the shell shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Download {
    /// The view as drawn, as PNG.
    Picture,
    /// The planar pattern, as PNG.
    Pattern,
    /// The mesh grown so far.
    Mesh(MeshFormat),
}

impl Download {
    /// Every download the page offers, in the order of its buttons.
    pub const ALL: [Download; 4] = [
        Download::Picture,
        Download::Pattern,
        Download::Mesh(MeshFormat::Obj),
        Download::Mesh(MeshFormat::Stl),
    ];

    /// Its name, which names its button on the page (`download-NAME`).
    pub fn name(self) -> &'static str {
        match self {
            Download::Picture => "picture",
            Download::Pattern => "pattern",
            Download::Mesh(format) => format.extension(),
        }
    }

    /// The file name it is offered under, for the preset `id`.
    pub fn file_name(self, id: &str) -> String {
        match self {
            Download::Picture => format!("{id}.png"),
            Download::Pattern => format!("{id}-pattern.png"),
            Download::Mesh(format) => format!("{id}.{}", format.extension()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_download_has_its_own_name_and_file() {
        let names: std::collections::BTreeSet<_> = Download::ALL.iter().map(|d| d.name()).collect();
        let files: std::collections::BTreeSet<_> =
            Download::ALL.iter().map(|d| d.file_name("oliva")).collect();
        assert_eq!(names.len(), Download::ALL.len());
        assert_eq!(files.len(), Download::ALL.len());
        for format in [MeshFormat::Obj, MeshFormat::Ply, MeshFormat::Stl] {
            let file = Download::Mesh(format).file_name("oliva");
            assert_eq!(MeshFormat::from_path(&file), Ok(format), "{file}");
        }
    }
}
