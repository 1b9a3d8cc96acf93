//! What crosses between the page and its workers: a [`Request`] the page sends, the one
//! [`Reply`] a worker sends back for it, each in an envelope with the request's ticket. Shells
//! are named by their links, which give the same spec bit for bit on every thread; meshes and
//! pattern rows cross as plain bytes ([`super::wire`]), and a growing shell sends only what
//! each request added.

use super::slotted_edge::{EdgeRun, EdgeWrites, Slot};
use super::wire::{Reader, WireError, Writer};
use crate::mesh::{Bounds, Capacity, Mesh, Vertex};
use crate::shape::{LineGrid, Pieces};
use crate::share::parameter_map::Picture;
use crate::view::preview::PreviewState;
use glam::DVec3;
use std::ops::Range;

/// What the page asks a worker. A session is one shell growing (or one pattern previewed) on
/// the worker that holds it; a job is a piece of work any worker may do.
#[derive(Clone, Debug, PartialEq)]
pub enum Request {
    /// Start growing the shell of `link` (a link's fragment), dropping any other.
    Load { session: u32, link: String },
    /// Grow the session's shell by up to `rows` pattern rows, stopping when `budget_ms` have
    /// passed (at least one row, or one step of the shape, is grown).
    Grow {
        session: u32,
        rows: u32,
        budget_ms: f64,
    },
    /// Grow the session's shell to its end at once, but for the pieces that can be made apart.
    Finish { session: u32 },
    /// Take over a session another worker held: grow the shell of `link` at once to `rows`
    /// rows and `steps` steps of its shape, where the page's copy of it stands.
    Resume {
        session: u32,
        link: String,
        rows: u32,
        steps: u32,
    },
    /// Start the whole pattern of `link` (a pattern slider being dragged), dropping any other.
    Preview { session: u32, link: String },
    /// Compute rows of the previewed pattern for `budget_ms`.
    Fill { session: u32, budget_ms: f64 },
    /// Make the pieces `ids` of the growth of `link` at growth step `step`.
    Pieces {
        job: u32,
        link: String,
        step: u32,
        ids: Vec<u32>,
    },
    /// Grow the shell of `link` whole (a gallery picture).
    Whole { job: u32, link: String },
    /// Compute `rows` rows of the pattern of `link`: a tile of a parameter map.
    Tile { job: u32, link: String, rows: u32 },
}

/// What a shell growing from a link is, known once it is built: what the page needs to show it.
#[derive(Clone, Debug, PartialEq)]
pub struct ShellInfo {
    /// Pattern rows from apex to opening.
    pub rows: u32,
    /// Cells of the pattern's row, 0 without a pattern.
    pub cells: u32,
    /// Sizes of the permanent mesh when grown, and of the edge at its largest.
    pub capacity: (Capacity, Capacity),
    /// Bounds of the grown shell and the direction it is best seen from.
    pub bounds: Bounds,
    pub front: DVec3,
    pub line_grid: LineGrid,
}

/// Where a growing shell stands after a request.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Progress {
    pub rows_done: u32,
    pub steps_done: u32,
    /// Whether the shape stands exactly at the rows (see `Generator::caught_up`).
    pub caught_up: bool,
    /// Whether growth has ended (grown, or stopped by a failure).
    pub done: bool,
    /// Why growth stopped early, in words.
    pub failure: Option<String>,
    /// The hash of the pattern so far, when there is one.
    pub pattern_hash: Option<u64>,
    /// The hash of the whole mesh, once growth has ended with nothing left apart.
    pub mesh_hash: Option<u64>,
}

/// What one request added to a growing shell.
#[derive(Clone, Debug, PartialEq)]
pub struct Delta {
    /// The pattern rows added, and their RGBA.
    pub rows: Range<u32>,
    pub rgba: Vec<u8>,
    /// The vertices added to the permanent mesh, the first being number `first_vertex`.
    pub first_vertex: u32,
    pub vertices: Vec<Vertex>,
    /// The indices added to the permanent mesh, the first at `first_index`.
    pub first_index: u32,
    pub indices: Vec<u32>,
    /// The new transient edge mesh, when it changed: the parts that differ from the edge sent
    /// before, written in their slots.
    pub edge: Option<EdgeWrites>,
    /// Bounds of everything grown so far, edge included.
    pub grown: Bounds,
    pub progress: Progress,
}

/// A shell grown whole: its mesh (edge included), its pattern, and what it is.
#[derive(Clone, Debug, PartialEq)]
pub struct WholeShell {
    pub shell: ShellInfo,
    pub mesh: Mesh,
    pub rgba: Vec<u8>,
}

/// What a worker sends back.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// The session's shell is built: what it is, and its first step.
    Loaded {
        session: u32,
        shell: ShellInfo,
        delta: Delta,
    },
    /// The session's shell cannot be built, in words.
    Refused { session: u32, message: String },
    /// What a request added to the session's shell.
    Grew { session: u32, delta: Delta },
    /// The session's shell is grown but for `pieces`, to be made apart and joined; `hash` is
    /// the hash of the mesh without them.
    Apart {
        session: u32,
        delta: Delta,
        pieces: Pieces,
        hash: u64,
    },
    /// The session was taken over: the sizes of its permanent mesh, to check against the page's.
    Resumed {
        session: u32,
        vertices: u32,
        indices: u32,
    },
    /// Rows of the previewed pattern: `rgba` holds rows `first..` of `cells` cells (0 when the
    /// values give no pattern model); `failure` says in words why it stopped, or why there is
    /// no pattern.
    Previewed {
        session: u32,
        cells: u32,
        first: u32,
        rgba: Vec<u8>,
        state: PreviewState,
        failure: Option<String>,
    },
    /// The pieces of a job that hold part of the surface, by number, and the hash of them all.
    Made {
        job: u32,
        meshes: Vec<(u32, Mesh)>,
        hash: u64,
    },
    /// A shell grown whole, or why it cannot be.
    Grown {
        job: u32,
        result: Result<WholeShell, String>,
    },
    /// A tile's picture, or why it has none.
    Tiled {
        job: u32,
        result: Result<Picture, String>,
    },
}

impl Request {
    /// Whether the request belongs to a session, which only the worker holding it can serve.
    pub fn is_session(&self) -> bool {
        !matches!(
            self,
            Request::Pieces { .. } | Request::Whole { .. } | Request::Tile { .. }
        )
    }

    /// Milliseconds a worker may take to answer before it is held to hang: generous, for the
    /// slowest machine; growing a shell again from its apex may take far longer than a step.
    pub fn allowance_ms(&self) -> f64 {
        match self {
            Request::Resume { .. } | Request::Load { .. } | Request::Finish { .. } => 60_000.0,
            _ => 15_000.0,
        }
    }
}

// Tags of the variants in the bytes.
const LOAD: u8 = 1;
const GROW: u8 = 2;
const FINISH: u8 = 3;
const RESUME: u8 = 4;
const PREVIEW: u8 = 5;
const FILL: u8 = 6;
const PIECES: u8 = 7;
const WHOLE: u8 = 8;
const TILE: u8 = 9;

const LOADED: u8 = 101;
const REFUSED: u8 = 102;
const GREW: u8 = 103;
const APART: u8 = 104;
const RESUMED: u8 = 105;
const PREVIEWED: u8 = 106;
const MADE: u8 = 107;
const GROWN: u8 = 108;
const TILED: u8 = 109;

/// A request in its envelope, as bytes.
pub fn encode_request(ticket: u32, request: &Request) -> Vec<u8> {
    let mut w = Writer::default();
    w.u32(ticket);
    match request {
        Request::Load { session, link } => {
            w.u8(LOAD);
            w.u32(*session);
            w.str(link);
        }
        Request::Grow {
            session,
            rows,
            budget_ms,
        } => {
            w.u8(GROW);
            w.u32(*session);
            w.u32(*rows);
            w.f64(*budget_ms);
        }
        Request::Finish { session } => {
            w.u8(FINISH);
            w.u32(*session);
        }
        Request::Resume {
            session,
            link,
            rows,
            steps,
        } => {
            w.u8(RESUME);
            w.u32(*session);
            w.str(link);
            w.u32(*rows);
            w.u32(*steps);
        }
        Request::Preview { session, link } => {
            w.u8(PREVIEW);
            w.u32(*session);
            w.str(link);
        }
        Request::Fill { session, budget_ms } => {
            w.u8(FILL);
            w.u32(*session);
            w.f64(*budget_ms);
        }
        Request::Pieces {
            job,
            link,
            step,
            ids,
        } => {
            w.u8(PIECES);
            w.u32(*job);
            w.str(link);
            w.u32(*step);
            w.u32s(ids);
        }
        Request::Whole { job, link } => {
            w.u8(WHOLE);
            w.u32(*job);
            w.str(link);
        }
        Request::Tile { job, link, rows } => {
            w.u8(TILE);
            w.u32(*job);
            w.str(link);
            w.u32(*rows);
        }
    }
    w.into_bytes()
}

/// The ticket and request of an envelope's bytes.
pub fn decode_request(bytes: &[u8]) -> Result<(u32, Request), WireError> {
    let mut r = Reader::new(bytes);
    let ticket = r.u32("ticket")?;
    let request = match r.u8("kind of request")? {
        LOAD => Request::Load {
            session: r.u32("session")?,
            link: r.string("link")?,
        },
        GROW => Request::Grow {
            session: r.u32("session")?,
            rows: r.u32("rows")?,
            budget_ms: r.f64("budget")?,
        },
        FINISH => Request::Finish {
            session: r.u32("session")?,
        },
        RESUME => Request::Resume {
            session: r.u32("session")?,
            link: r.string("link")?,
            rows: r.u32("rows")?,
            steps: r.u32("steps")?,
        },
        PREVIEW => Request::Preview {
            session: r.u32("session")?,
            link: r.string("link")?,
        },
        FILL => Request::Fill {
            session: r.u32("session")?,
            budget_ms: r.f64("budget")?,
        },
        PIECES => Request::Pieces {
            job: r.u32("job")?,
            link: r.string("link")?,
            step: r.u32("step")?,
            ids: r.u32s("pieces")?,
        },
        WHOLE => Request::Whole {
            job: r.u32("job")?,
            link: r.string("link")?,
        },
        TILE => Request::Tile {
            job: r.u32("job")?,
            link: r.string("link")?,
            rows: r.u32("rows")?,
        },
        _ => {
            return Err(WireError {
                key: "kind of request",
                at: 4,
            });
        }
    };
    r.end()?;
    Ok((ticket, request))
}

fn write_capacity(w: &mut Writer, c: Capacity) {
    w.len(c.vertices);
    w.len(c.indices);
}

fn read_capacity(r: &mut Reader) -> Result<Capacity, WireError> {
    Ok(Capacity {
        vertices: r.len("capacity")?,
        indices: r.len("capacity")?,
    })
}

fn write_shell(w: &mut Writer, s: &ShellInfo) {
    w.u32(s.rows);
    w.u32(s.cells);
    write_capacity(w, s.capacity.0);
    write_capacity(w, s.capacity.1);
    w.bounds(&s.bounds);
    w.dvec3(s.front);
    w.f64(s.line_grid.across);
    w.f64(s.line_grid.rows);
}

fn read_shell(r: &mut Reader) -> Result<ShellInfo, WireError> {
    Ok(ShellInfo {
        rows: r.u32("rows")?,
        cells: r.u32("cells")?,
        capacity: (read_capacity(r)?, read_capacity(r)?),
        bounds: r.bounds("bounds")?,
        front: r.dvec3("front")?,
        line_grid: LineGrid {
            across: r.f64("line grid")?,
            rows: r.f64("line grid")?,
        },
    })
}

fn write_option_u64(w: &mut Writer, x: Option<u64>) {
    w.bool(x.is_some());
    if let Some(x) = x {
        w.u64(x);
    }
}

fn read_option_u64(r: &mut Reader, key: &'static str) -> Result<Option<u64>, WireError> {
    if r.bool(key)? {
        r.u64(key).map(Some)
    } else {
        Ok(None)
    }
}

fn write_delta(w: &mut Writer, d: &Delta) {
    w.u32(d.rows.start);
    w.u32(d.rows.end);
    w.bytes(&d.rgba);
    w.u32(d.first_vertex);
    w.vertices(&d.vertices);
    w.u32(d.first_index);
    w.u32s(&d.indices);
    w.bool(d.edge.is_some());
    if let Some(edge) = &d.edge {
        write_edge_writes(w, edge);
    }
    w.bounds(&d.grown);
    let p = &d.progress;
    w.u32(p.rows_done);
    w.u32(p.steps_done);
    w.bool(p.caught_up);
    w.bool(p.done);
    w.option_str(p.failure.as_deref());
    write_option_u64(w, p.pattern_hash);
    write_option_u64(w, p.mesh_hash);
}

fn read_delta(r: &mut Reader) -> Result<Delta, WireError> {
    Ok(Delta {
        rows: r.u32("rows")?..r.u32("rows")?,
        rgba: r.bytes("pattern rows")?.to_vec(),
        first_vertex: r.u32("first vertex")?,
        vertices: r.vertices("vertices")?,
        first_index: r.u32("first index")?,
        indices: r.u32s("indices")?,
        edge: if r.bool("edge")? {
            Some(read_edge_writes(r)?)
        } else {
            None
        },
        grown: r.bounds("grown")?,
        progress: Progress {
            rows_done: r.u32("rows done")?,
            steps_done: r.u32("steps done")?,
            caught_up: r.bool("caught up")?,
            done: r.bool("done")?,
            failure: r.option_string("failure")?,
            pattern_hash: read_option_u64(r, "pattern hash")?,
            mesh_hash: read_option_u64(r, "mesh hash")?,
        },
    })
}

fn write_edge_writes(w: &mut Writer, e: &EdgeWrites) {
    w.bool(e.fresh);
    w.u32(e.vertex_count);
    w.u32(e.index_count);
    w.len(e.slots.len());
    for slot in &e.slots {
        w.u32(slot.id);
        w.u32(slot.vertices.start);
        w.u32(slot.vertices.end);
        w.u32(slot.indices.start);
        w.u32(slot.indices.end);
    }
    w.len(e.runs.len());
    for run in &e.runs {
        w.u32(run.first_vertex);
        w.vertices(&run.vertices);
        w.u32(run.first_index);
        w.u32s(&run.indices);
    }
}

/// An edge's writes, whose slots (in the order of their numbers) and runs all lie within its
/// counts, and whose indices all name one of its vertices.
fn read_edge_writes(r: &mut Reader) -> Result<EdgeWrites, WireError> {
    let fresh = r.bool("edge fresh")?;
    let vertex_count = r.u32("edge vertex count")?;
    let index_count = r.u32("edge index count")?;
    let within = |r: &Reader, key, range: &Range<u32>, count: u32| {
        if range.start <= range.end && range.end <= count {
            Ok(())
        } else {
            Err(WireError { key, at: r.at() })
        }
    };
    let mut slots: Vec<Slot> = Vec::new();
    for _ in 0..r.len("edge slots")? {
        let slot = Slot {
            id: r.u32("edge slot")?,
            vertices: r.u32("edge slot")?..r.u32("edge slot")?,
            indices: r.u32("edge slot")?..r.u32("edge slot")?,
        };
        within(r, "edge slot", &slot.vertices, vertex_count)?;
        within(r, "edge slot", &slot.indices, index_count)?;
        if slots.last().is_some_and(|last| last.id >= slot.id) {
            return Err(WireError {
                key: "edge slot",
                at: r.at(),
            });
        }
        slots.push(slot);
    }
    let mut runs = Vec::new();
    for _ in 0..r.len("edge runs")? {
        let first_vertex = r.u32("edge run")?;
        let vertices = r.vertices("edge vertices")?;
        let first_index = r.u32("edge run")?;
        let at = r.at();
        let indices = r.u32s("edge indices")?;
        let end = |first: u32, n: usize| first.saturating_add(n as u32);
        within(
            r,
            "edge run",
            &(first_vertex..end(first_vertex, vertices.len())),
            vertex_count,
        )?;
        within(
            r,
            "edge run",
            &(first_index..end(first_index, indices.len())),
            index_count,
        )?;
        if indices.iter().any(|&i| i >= vertex_count) {
            return Err(WireError {
                key: "edge indices",
                at,
            });
        }
        runs.push(EdgeRun {
            first_vertex,
            vertices,
            first_index,
            indices,
        });
    }
    Ok(EdgeWrites {
        fresh,
        vertex_count,
        index_count,
        slots,
        runs,
    })
}

fn write_result<T>(w: &mut Writer, result: &Result<T, String>, write: impl Fn(&mut Writer, &T)) {
    match result {
        Ok(x) => {
            w.bool(true);
            write(w, x);
        }
        Err(why) => {
            w.bool(false);
            w.str(why);
        }
    }
}

fn read_result<T>(
    r: &mut Reader,
    read: impl Fn(&mut Reader) -> Result<T, WireError>,
) -> Result<Result<T, String>, WireError> {
    Ok(if r.bool("result")? {
        Ok(read(r)?)
    } else {
        Err(r.string("why")?)
    })
}

fn preview_tag(state: PreviewState) -> u8 {
    match state {
        PreviewState::Filling => 0,
        PreviewState::Whole => 1,
        PreviewState::Stopped => 2,
    }
}

/// A reply in its envelope, as bytes.
pub fn encode_reply(ticket: u32, reply: &Reply) -> Vec<u8> {
    let mut w = Writer::default();
    w.u32(ticket);
    match reply {
        Reply::Loaded {
            session,
            shell,
            delta,
        } => {
            w.u8(LOADED);
            w.u32(*session);
            write_shell(&mut w, shell);
            write_delta(&mut w, delta);
        }
        Reply::Refused { session, message } => {
            w.u8(REFUSED);
            w.u32(*session);
            w.str(message);
        }
        Reply::Grew { session, delta } => {
            w.u8(GREW);
            w.u32(*session);
            write_delta(&mut w, delta);
        }
        Reply::Apart {
            session,
            delta,
            pieces,
            hash,
        } => {
            w.u8(APART);
            w.u32(*session);
            write_delta(&mut w, delta);
            w.u32(pieces.step);
            w.len(pieces.groups.len());
            for group in &pieces.groups {
                w.u32s(group);
            }
            w.u64(*hash);
        }
        Reply::Resumed {
            session,
            vertices,
            indices,
        } => {
            w.u8(RESUMED);
            w.u32(*session);
            w.u32(*vertices);
            w.u32(*indices);
        }
        Reply::Previewed {
            session,
            cells,
            first,
            rgba,
            state,
            failure,
        } => {
            w.u8(PREVIEWED);
            w.u32(*session);
            w.u32(*cells);
            w.u32(*first);
            w.bytes(rgba);
            w.u8(preview_tag(*state));
            w.option_str(failure.as_deref());
        }
        Reply::Made { job, meshes, hash } => {
            w.u8(MADE);
            w.u32(*job);
            w.len(meshes.len());
            for (id, mesh) in meshes {
                w.u32(*id);
                w.mesh(mesh);
            }
            w.u64(*hash);
        }
        Reply::Grown { job, result } => {
            w.u8(GROWN);
            w.u32(*job);
            write_result(&mut w, result, |w, whole| {
                write_shell(w, &whole.shell);
                w.mesh(&whole.mesh);
                w.bytes(&whole.rgba);
            });
        }
        Reply::Tiled { job, result } => {
            w.u8(TILED);
            w.u32(*job);
            write_result(&mut w, result, |w, picture| {
                w.len(picture.width);
                w.len(picture.height);
                w.bytes(&picture.rgba);
            });
        }
    }
    w.into_bytes()
}

/// The ticket and reply of an envelope's bytes.
pub fn decode_reply(bytes: &[u8]) -> Result<(u32, Reply), WireError> {
    let mut r = Reader::new(bytes);
    let ticket = r.u32("ticket")?;
    let reply = match r.u8("kind of reply")? {
        LOADED => Reply::Loaded {
            session: r.u32("session")?,
            shell: read_shell(&mut r)?,
            delta: read_delta(&mut r)?,
        },
        REFUSED => Reply::Refused {
            session: r.u32("session")?,
            message: r.string("message")?,
        },
        GREW => Reply::Grew {
            session: r.u32("session")?,
            delta: read_delta(&mut r)?,
        },
        APART => Reply::Apart {
            session: r.u32("session")?,
            delta: read_delta(&mut r)?,
            pieces: Pieces {
                step: r.u32("step")?,
                groups: (0..r.len("groups")?)
                    .map(|_| r.u32s("group"))
                    .collect::<Result<_, _>>()?,
            },
            hash: r.u64("hash")?,
        },
        RESUMED => Reply::Resumed {
            session: r.u32("session")?,
            vertices: r.u32("vertices")?,
            indices: r.u32("indices")?,
        },
        PREVIEWED => Reply::Previewed {
            session: r.u32("session")?,
            cells: r.u32("cells")?,
            first: r.u32("first row")?,
            rgba: r.bytes("pattern rows")?.to_vec(),
            state: match r.u8("preview state")? {
                0 => PreviewState::Filling,
                1 => PreviewState::Whole,
                2 => PreviewState::Stopped,
                _ => {
                    return Err(WireError {
                        key: "preview state",
                        at: 0,
                    });
                }
            },
            failure: r.option_string("failure")?,
        },
        MADE => Reply::Made {
            job: r.u32("job")?,
            meshes: (0..r.len("pieces")?)
                .map(|_| Ok((r.u32("piece")?, r.mesh("piece")?)))
                .collect::<Result<_, WireError>>()?,
            hash: r.u64("hash")?,
        },
        GROWN => Reply::Grown {
            job: r.u32("job")?,
            result: read_result(&mut r, |r| {
                Ok(WholeShell {
                    shell: read_shell(r)?,
                    mesh: r.mesh("mesh")?,
                    rgba: r.bytes("pattern")?.to_vec(),
                })
            })?,
        },
        TILED => Reply::Tiled {
            job: r.u32("job")?,
            result: read_result(&mut r, |r| {
                Ok(Picture {
                    width: r.len("width")?,
                    height: r.len("height")?,
                    rgba: r.bytes("picture")?.to_vec(),
                })
            })?,
        },
        _ => {
            return Err(WireError {
                key: "kind of reply",
                at: 4,
            });
        }
    };
    r.end()?;
    Ok((ticket, reply))
}
