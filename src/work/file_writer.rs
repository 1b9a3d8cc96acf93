//! A file of the shell written where the viewer's copy of it is: the mesh in any format, the
//! pattern as a PNG, or the picture as drawn. A file is written by the core in steps
//! ([`Export`]), a frame's budget at a time, so that nothing freezes. A mesh of an implicit
//! shell still growing is of the whole shell: the viewer first finishes it, its chunks shared by
//! the pool of workers as the Finish control shares them, then writes it. The page asks for a
//! file and is handed where it stands ([`FileStage`]) and, in the end, its bytes (the page
//! offers them); it reads nothing of the shell itself.

use super::replica::Replica;
use crate::export::Download;
use crate::export::job::Export;
use crate::export::print_size::PrintSize;
use crate::export::shell::Shell;
use crate::generator::within;
use crate::presets::Preset;
use crate::spec::ShellSpec;
use serde::{Deserialize, Serialize};

/// Milliseconds of a frame an export may take.
const EXPORT_BUDGET_MS: f64 = 8.0;

/// Where a file asked for stands.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum FileStage {
    /// The implicit shell is being finished before its mesh is written.
    Finishing,
    /// Being written: the file's name and the fraction done.
    Writing { name: String, done: f64 },
    /// Written whole.
    Written(File),
    /// It could not be made: why, in words.
    Refused(String),
}

/// A file written whole.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct File {
    pub what: Download,
    pub name: String,
    pub body: Body,
}

/// What a file holds: its bytes (of the type [`Download::mime`] names), or (the picture, as the browser reads it from the
/// canvas) the address of its data.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Body {
    Bytes(#[serde(with = "crate::pod_bytes")] Vec<u8>),
    Url(String),
}

/// A file being written in steps.
struct Job {
    export: Export,
    name: String,
    what: Download,
    /// The longest step lately (see [`within`]).
    longest: f64,
}

/// The file asked for, from the moment it is asked for until it is handed over.
enum Asked {
    /// Waiting for the shell of `session` to be grown whole.
    AfterFinish {
        what: Download,
        size: PrintSize,
        session: u32,
    },
    Job(Job),
    /// The picture, named so, being read from the canvas.
    Picture {
        name: String,
    },
    /// Made, or refused, and not yet handed over.
    Ready(FileStage),
}

/// What the viewer must do for a file it was just asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Needs {
    Nothing,
    /// Finish the shell (an implicit shell still growing, for its mesh).
    Finish,
    /// Draw the view and read it back, then hand it over ([`FileWriter::picture_taken`]).
    Picture,
}

/// The viewer's file under way, if any.
#[derive(Default)]
pub struct FileWriter {
    asked: Option<Asked>,
}

/// What a file is written from: the shell's copy, what it was grown from, and the picture.
pub struct Source<'a> {
    pub preset: &'a Preset,
    pub spec: &'a ShellSpec,
    pub replica: &'a Replica,
}

impl FileWriter {
    /// Whether a file is under way (another is not started meanwhile).
    pub fn busy(&self) -> bool {
        self.asked.is_some()
    }

    /// Starts the file `what` of `source` at `size` (GLB and 3MF), and says what the viewer
    /// must do for it.
    pub fn start(&mut self, what: Download, size: PrintSize, source: Option<Source>) -> Needs {
        let Some(source) = source else {
            self.asked = Some(Asked::Ready(FileStage::Refused("no shell is shown".into())));
            return Needs::Nothing;
        };
        let r = source.replica;
        let in_pieces = crate::forms::meshed_in_pieces(&source.spec.form);
        if matches!(what, Download::Mesh(_)) && in_pieces && r.shell().is_some() && !r.is_done() {
            self.asked = Some(Asked::AfterFinish {
                what,
                size,
                session: r.session(),
            });
            return Needs::Finish;
        }
        let name = what.file_name(source.preset.id);
        if matches!(what, Download::Picture) {
            self.asked = Some(Asked::Picture { name });
            return Needs::Picture;
        }
        self.asked = Some(match begin(what, name, size, &source) {
            Ok(job) => Asked::Job(job),
            Err(e) => Asked::Ready(FileStage::Refused(e)),
        });
        Needs::Nothing
    }

    /// The picture asked for, as read from the canvas: the address of its data, or why it could
    /// not be read.
    pub fn picture_taken(&mut self, read: Result<String, String>) {
        let Some(Asked::Picture { name }) = self.asked.take() else {
            return;
        };
        self.asked = Some(Asked::Ready(match read {
            Ok(url) => FileStage::Written(File {
                what: Download::Picture,
                name,
                body: Body::Url(url),
            }),
            Err(e) => FileStage::Refused(e),
        }));
    }

    /// Works on the file under way for this frame's budget: where it stands, or `None` when no
    /// file is asked for. A file waiting for its shell to be finished starts once it is (and
    /// is refused when another shell took its place).
    pub fn work(&mut self, source: Option<Source>, now: &dyn Fn() -> f64) -> Option<FileStage> {
        let writing = match self.asked.take()? {
            Asked::AfterFinish {
                what,
                size,
                session,
            } => match source {
                Some(s) if s.replica.session() == session && !s.replica.is_done() => {
                    self.asked = Some(Asked::AfterFinish {
                        what,
                        size,
                        session,
                    });
                    return Some(FileStage::Finishing);
                }
                Some(s) if s.replica.session() == session => {
                    let name = what.file_name(s.preset.id);
                    match begin(what, name.clone(), size, &s) {
                        Ok(job) => {
                            self.asked = Some(Asked::Job(job));
                            FileStage::Writing { name, done: 0.0 }
                        }
                        Err(e) => FileStage::Refused(e),
                    }
                }
                _ => FileStage::Refused(
                    "the shell was changed before it was grown whole".to_string(),
                ),
            },
            Asked::Picture { name } => {
                let stage = FileStage::Writing {
                    name: name.clone(),
                    done: 0.0,
                };
                self.asked = Some(Asked::Picture { name });
                return Some(stage);
            }
            Asked::Ready(done) => done,
            Asked::Job(mut job) => {
                match job
                    .export
                    .work(within(now, EXPORT_BUDGET_MS, &mut job.longest))
                {
                    Ok(None) => {
                        let writing = FileStage::Writing {
                            name: job.name.clone(),
                            done: job.export.progress(),
                        };
                        self.asked = Some(Asked::Job(job));
                        return Some(writing);
                    }
                    Ok(Some(bytes)) => FileStage::Written(File {
                        what: job.what,
                        name: job.name,
                        body: Body::Bytes(bytes),
                    }),
                    Err(e) => FileStage::Refused(e.to_string()),
                }
            }
        };
        Some(writing)
    }
}

/// The job that writes `what` (the pattern or a mesh) of `source` as `name`.
fn begin(what: Download, name: String, size: PrintSize, source: &Source) -> Result<Job, String> {
    let r = source.replica;
    let export = match what {
        Download::Picture => return Err("the picture is not written in steps".into()),
        Download::Pattern => {
            if r.cells() == 0 {
                return Err("this shell has no pattern".into());
            }
            let rows = r.rgba().len() / (r.cells() * 4);
            Export::pattern(r.cells(), rows, r.planar(0..rows))
        }
        Download::Mesh(format) => {
            let size = if format.sized() {
                size
            } else {
                PrintSize::default()
            };
            let grown = r.for_export().ok_or("the shell is not built yet")?;
            let shell =
                Shell::of(grown, source.spec, source.preset, size).map_err(|e| e.to_string())?;
            Export::new(format, shell).map_err(|e| e.to_string())?
        }
    };
    Ok(Job {
        export,
        name,
        what,
        longest: 0.0,
    })
}
