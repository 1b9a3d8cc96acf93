//! What `seashells help` and `--help` print.

use crate::Failure;

/// One line per command, printed after a wrong command or option.
pub const USAGE: &str = "usage: seashells mesh (--preset ID | --link FRAGMENT) --out FILE.{glb,ply,3mf,obj,stl} [--resolution N] [--size MM] [--size-axis x|y|z] [--threads N] | \
seashells pattern (--preset ID | --link FRAGMENT) --out FILE.{png,csv} [--cells N] [--rows N] [--iterations N] | \
seashells info (LINK | --preset ID | --link FRAGMENT) [--threads N] | seashells presets | seashells bench | seashells help [COMMAND]";

/// The help on every command.
const HELP: &str = "seashells: the shells of the page's gallery and links, written as files by the same core

usage:
  seashells mesh (--preset ID | --link FRAGMENT) --out FILE.{glb,ply,3mf,obj,stl}
                 [--resolution N] [--size MM] [--size-axis x|y|z] [--threads N]
  seashells pattern (--preset ID | --link FRAGMENT) --out FILE.{png,csv}
                    [--cells N] [--rows N] [--iterations N]
  seashells info (LINK | --preset ID | --link FRAGMENT) [--threads N]
                          the shell's size and counts, and the files it would write
  seashells presets       lists every preset's ID and name
  seashells bench         times growth, patterns and meshing natively
  seashells help [COMMAND]

A FRAGMENT is the part of a page's link after '#', as in 'v=1&preset=turbinate&form.spiral.whorls=5';
the whole link may be given too. --out - writes the file to standard output (the report then goes to
standard error).

Exit status: 0 when the file is written (or the answer printed); 2 when refused (a wrong command,
option, preset, link or value, or a shell no file may hold), with one line on standard error saying
why and what to change; 1 when the file could not be written (a full disk, a missing folder).";

/// The help on `mesh`.
const HELP_MESH: &str = "seashells mesh (--preset ID | --link FRAGMENT) --out FILE [--resolution N] [--size MM] [--size-axis x|y|z] [--threads N]

Grows the shell to its end and writes its mesh in the format of FILE's extension: .glb (glTF
binary, with its pattern as a texture), .ply and .3mf (colour per vertex), .obj, .stl. Prints the
mesh's vertex and triangle counts and hash (as the page shows them) and the file's bytes.
  --format EXT       glb, ply, 3mf, obj or stl when FILE has no extension (--out - for stdout)
  --resolution N     the polygonization grid of an implicit shell (the Murex), N³ voxels; or
                     the picture a branching form is grown for, N pixels across (64 to 4096):
                     rule 8 stops a branch under one pixel, so more pixels grow finer tips
  --size MM          the largest side of a .glb or .3mf shell's box in millimetres, 5 to 500
                     (80 unless given): its height, or its length where it lies longer
  --size-axis x|y|z  make --size the box's side along x (across), y (front to back) or z (up,
                     the apex), as a printer's plate has them, instead of the largest
  --threads N        threads an implicit shell's last pieces are meshed on, 1 to 64 (unless
                     given, as many as the machine runs at once, at most 8); the file is the
                     same bit for bit on any number
A shell whose growth stopped, one whose values take it out of the range of numbers, one whose
whorls pass through one another, or a wall-less surface as .3mf is refused, and no file is written.";

/// The help on `pattern`.
const HELP_PATTERN: &str = "seashells pattern (--preset ID | --link FRAGMENT) --out FILE [--cells N] [--rows N] [--iterations N]

Computes the shell's pigmentation pattern on its growing edge and writes its planar
representation: .png (the colours, a row per time step) or .csv (the recorded value, the
activator's concentration, a line per row and a value per cell).
  --format EXT                         png or csv when FILE has no extension (--out - for stdout)
  --cells N, --rows N, --iterations N   override the spec's cells, rows and iterations per row";

/// The help on `info`.
const HELP_INFO: &str = "seashells info (LINK | --preset ID | --link FRAGMENT) [--threads N]

Grows the shell and prints what it is: its preset and form, the mesh's vertex and triangle counts
and hash, the pattern's cells and rows, the box it fills at the default size of 80 mm, and each
file `mesh` would write of it with its exact size in bytes, or why it would be refused.
  --threads N   as for `mesh`: the threads an implicit shell's last pieces are meshed on";

/// The help on `topic` (a command, or everything).
pub fn help(topic: Option<&str>) -> Result<String, Failure> {
    match topic {
        None | Some("presets" | "bench" | "help") => Ok(HELP.into()),
        Some("mesh") => Ok(HELP_MESH.into()),
        Some("pattern") => Ok(HELP_PATTERN.into()),
        Some("info") => Ok(HELP_INFO.into()),
        Some(other) => Err(Failure::usage(format!("there is no command '{other}'"))),
    }
}
