//! Writing what the core grows to files: meshes as GLB (glTF 2.0 binary, the pattern as a
//! texture), PLY (vertex colours), 3MF (colour printing), OBJ or STL, and patterns as PNG or
//! CSV, chosen by the file's extension; recorded growth as WebM. Every mesh and pattern file is
//! written in resumable steps ([`job::Export`]), so the page spreads a large export over frames.

use serde::{Deserialize, Serialize};

mod bodies;
pub mod csv;
pub mod error;
pub mod estimate;
mod glb;
pub mod job;
pub mod obj;
pub mod paint;
mod placement;
mod ply;
pub mod png;
pub mod print_size;
pub mod shell;
pub mod steps;
pub mod stl;
mod three_mf;
pub mod webm;
pub(crate) mod weld;
mod zip;

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum MeshFormat {
    Glb,
    Ply,
    ThreeMf,
    Obj,
    Stl,
}

impl MeshFormat {
    /// Every format, in the order the page offers them.
    pub const ALL: [MeshFormat; 5] = [
        MeshFormat::Glb,
        MeshFormat::Ply,
        MeshFormat::ThreeMf,
        MeshFormat::Obj,
        MeshFormat::Stl,
    ];

    /// The format a file name's extension asks for.
    pub fn from_path(path: &str) -> Result<Self, String> {
        let ext = path.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase());
        Self::ALL
            .into_iter()
            .find(|f| ext.as_deref() == Some(f.extension()))
            .ok_or_else(|| format!("'{path}' should end in .glb, .ply, .3mf, .obj or .stl"))
    }

    /// The file name's extension for this format.
    pub fn extension(self) -> &'static str {
        match self {
            Self::Glb => "glb",
            Self::Ply => "ply",
            Self::ThreeMf => "3mf",
            Self::Obj => "obj",
            Self::Stl => "stl",
        }
    }

    /// The file's media type.
    pub fn mime(self) -> &'static str {
        match self {
            Self::Glb => "model/gltf-binary",
            Self::Ply => "application/x-ply",
            Self::ThreeMf => "model/3mf",
            Self::Obj => "model/obj",
            Self::Stl => "model/stl",
        }
    }

    /// Whether the file carries the shell's size (3MF in millimetres, GLB in metres).
    pub fn sized(self) -> bool {
        matches!(self, Self::Glb | Self::ThreeMf)
    }
}

/// A file the page offers to download for the shell shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Download {
    /// The mesh grown so far.
    Mesh(MeshFormat),
    /// The view as drawn, as PNG.
    Picture,
    /// The planar pattern, as PNG.
    Pattern,
}

impl Download {
    /// Every download the page offers, in the order of its buttons.
    pub const ALL: [Download; 7] = [
        Download::Mesh(MeshFormat::Glb),
        Download::Mesh(MeshFormat::Ply),
        Download::Mesh(MeshFormat::ThreeMf),
        Download::Mesh(MeshFormat::Obj),
        Download::Mesh(MeshFormat::Stl),
        Download::Picture,
        Download::Pattern,
    ];

    /// Its name, which names its button on the page (`download-NAME`).
    pub fn name(self) -> &'static str {
        match self {
            Download::Picture => "picture",
            Download::Pattern => "pattern",
            Download::Mesh(format) => format.extension(),
        }
    }

    /// The media type of its file.
    pub fn mime(self) -> &'static str {
        match self {
            Download::Mesh(format) => format.mime(),
            Download::Picture | Download::Pattern => "image/png",
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
        for format in MeshFormat::ALL {
            let file = Download::Mesh(format).file_name("oliva");
            assert_eq!(MeshFormat::from_path(&file), Ok(format), "{file}");
        }
        assert_eq!(Download::ALL[0], Download::Mesh(MeshFormat::Glb));
        assert!(MeshFormat::from_path("shell.gltf").is_err());
    }
}
