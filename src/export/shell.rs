//! What an export reads: the shell as it stands (its mesh, the growing edge's closure
//! included), how it is painted, its material, the way the page first sees it, its name, and
//! the size asked for. Taken in one go when the export starts, so that growth may go on (or
//! restart) while the file is written.

use super::error::ExportError;
use super::paint::{Paint, PatternImage};
use super::placement::{fit, turn};
use super::print_size::PrintSize;
use crate::forms;
use crate::generator::Generator;
use crate::mesh::{Bounds, Mesh};
use crate::presets::Preset;
use crate::spec::ShellSpec;
use crate::view::camera::facing;
use glam::DVec3;

/// A shell to export.
pub struct Shell {
    pub mesh: Mesh,
    pub paint: Paint,
    /// The material's roughness for glTF (see [`roughness`]).
    pub roughness: f32,
    /// The yaw (radians, about the vertical of the shell shown apex up) of the page's first
    /// view: files are turned so that a viewer's front view (from +z, y up) shows it.
    pub facing: f64,
    /// The preset's name.
    pub title: String,
    pub size: PrintSize,
}

/// What an export reads of a grown shell, wherever it grew (a generator here, or the page's
/// copy of a shell grown on a worker).
pub struct Grown<'a> {
    /// The shell as it stands, edge included.
    pub mesh: Mesh,
    /// Why growth stopped early, if it did.
    pub failure: Option<&'a str>,
    /// The direction the shell is best seen from.
    pub front: DVec3,
    pub pattern: Option<PatternImage<'a>>,
}

impl Shell {
    /// The shell `generator` has grown so far from `spec` (a variant of `preset`); refused
    /// when it has no surface yet, growth stopped on a failure, a coordinate is not finite, or
    /// the form passes through itself.
    pub fn new(
        generator: &Generator,
        spec: &ShellSpec,
        preset: &Preset,
        size: PrintSize,
    ) -> Result<Self, ExportError> {
        let grown = Grown {
            mesh: generator.snapshot(),
            failure: generator.failure(),
            front: generator.framing().1,
            pattern: generator.pattern().map(PatternImage::from),
        };
        Self::of(grown, spec, preset, size)
    }

    /// The shell `grown` from `spec` (a variant of `preset`), refused as [`Self::new`] says.
    pub fn of(
        grown: Grown,
        spec: &ShellSpec,
        preset: &Preset,
        size: PrintSize,
    ) -> Result<Self, ExportError> {
        if let Some(why) = grown.failure {
            return Err(ExportError::Failed(why.to_string()));
        }
        if grown.mesh.triangle_count() == 0 {
            return Err(ExportError::Empty);
        }
        if !grown.mesh.is_finite() {
            return Err(ExportError::NotFinite);
        }
        if let Some(problem) = forms::self_overlap(&spec.form) {
            return Err(ExportError::Overlap(problem));
        }
        Ok(Self {
            mesh: grown.mesh,
            paint: Paint::new(&spec.colours, grown.pattern),
            roughness: roughness(spec.material.gloss),
            facing: facing(grown.front) + f64::from(preset.view.yaw).to_radians(),
            title: preset.name.clone(),
            size,
        })
    }

    /// The sides (mm) of the box the shell fills in a 3MF file at its size: x across, y from
    /// front to back, z up (the apex), as a printer's plate has them.
    pub fn printed_sides(&self) -> DVec3 {
        let turn = turn(self.facing, true);
        let mut bounds = Bounds::EMPTY;
        for v in &self.mesh.vertices {
            bounds.include(turn * DVec3::from(v.position.map(f64::from)));
        }
        let (scale, _) = fit(&bounds, self.size, 1.0, 2);
        (bounds.max - bounds.min) * scale
    }
}

/// The roughness of a glTF metallic-roughness material for the spec's gloss (0 to 1): from
/// 0.9, a matte surface whose highlights spread wide, to 0.15 for the full polish the page
/// shows with sharp reflections of its studio (Oliva and Conus, 0.9, get 0.225).
pub fn roughness(gloss: f64) -> f32 {
    (0.9 - 0.75 * gloss.clamp(0.0, 1.0)) as f32
}
