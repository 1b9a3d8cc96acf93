//! What crosses between the page and its workers: a [`Request`] the page sends, the one
//! [`Reply`] a worker sends back for it, each in an envelope with the request's ticket. Shells
//! are named by their links, which give the same spec bit for bit on every thread; meshes and
//! pattern rows cross as blocks of bytes ([`super::wire`]), and a growing shell sends only what
//! each request added.

use super::slotted_edge::EdgeWrites;
use super::wire::{self, WireError};
use crate::mesh::{Bounds, Capacity, Mesh, Vertex};
use crate::shape::{LineGrid, Pieces};
use crate::variation::tile::Picture;
use crate::view::preview::PreviewState;
use glam::DVec3;
use serde::{Deserialize, Serialize};
use std::ops::Range;

/// What the page asks a worker. A session is one shell growing (or one pattern previewed) on
/// the worker that holds it; a job is a piece of work any worker may do.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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
    /// Grow the shell of `link` whole for a picture `pixels` wide (a gallery card, a tile of
    /// a grid of shells), its mesh no finer than the picture shows.
    Whole { job: u32, link: String, pixels: u32 },
    /// Compute `rows` rows of the pattern of `link`: a tile of a parameter map.
    Tile { job: u32, link: String, rows: u32 },
}

/// What a shell growing from a link is, known once it is built: what the page needs to show it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
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
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Delta {
    /// The pattern rows added, their RGBA, and the cells each has (see
    /// [`crate::pattern::run::PatternRun::widths`]).
    pub rows: Range<u32>,
    #[serde(with = "crate::pod_bytes")]
    pub rgba: Vec<u8>,
    pub widths: Vec<u32>,
    /// The vertices added to the permanent mesh, the first being number `first_vertex`.
    pub first_vertex: u32,
    #[serde(with = "crate::pod_bytes")]
    pub vertices: Vec<Vertex>,
    /// The indices added to the permanent mesh, the first at `first_index`.
    pub first_index: u32,
    #[serde(with = "crate::pod_bytes")]
    pub indices: Vec<u32>,
    /// The new transient edge mesh, when it changed: the parts that differ from the edge sent
    /// before, written in their slots.
    pub edge: Option<EdgeWrites>,
    /// Bounds of everything grown so far, edge included.
    pub grown: Bounds,
    pub progress: Progress,
}

/// A shell grown whole: its mesh (edge included), its pattern, and what it is.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct WholeShell {
    pub shell: ShellInfo,
    pub mesh: Mesh,
    #[serde(with = "crate::pod_bytes")]
    pub rgba: Vec<u8>,
    pub widths: Vec<u32>,
}

/// What a worker sends back.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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
    /// values give no pattern model), `widths` the cells each computed; `failure` says in
    /// words why it stopped, or why there is no pattern.
    Previewed {
        session: u32,
        cells: u32,
        first: u32,
        #[serde(with = "crate::pod_bytes")]
        rgba: Vec<u8>,
        widths: Vec<u32>,
        state: PreviewState,
        failure: Option<String>,
    },
    /// The mesh of a job's group of pieces (see [`Pieces`]), and its hash.
    Made { job: u32, mesh: Mesh, hash: u64 },
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

/// A request in its envelope, as bytes.
pub fn encode_request(ticket: u32, request: &Request) -> Vec<u8> {
    wire::write(&(ticket, request))
}

/// The ticket and request of an envelope's bytes.
pub fn decode_request(bytes: &[u8]) -> Result<(u32, Request), WireError> {
    wire::read(bytes, "request")
}

/// A reply in its envelope, as bytes.
pub fn encode_reply(ticket: u32, reply: &Reply) -> Vec<u8> {
    wire::write(&(ticket, reply))
}

/// The ticket and reply of an envelope's bytes, whose meshes and edge writes the page can
/// apply (`Reply::check`).
pub fn decode_reply(bytes: &[u8]) -> Result<(u32, Reply), WireError> {
    let (ticket, reply): (u32, Reply) = wire::read(bytes, "reply")?;
    reply.check()?;
    Ok((ticket, reply))
}

fn wrong(key: &'static str, why: impl Into<String>) -> WireError {
    WireError {
        key,
        why: why.into(),
    }
}

impl Reply {
    /// Fails unless every mesh's indices name its vertices, and every edge's writes lie within
    /// it (see [`check_edge`]): what the page copies into its buffers.
    fn check(&self) -> Result<(), WireError> {
        match self {
            Reply::Loaded { delta, .. }
            | Reply::Grew { delta, .. }
            | Reply::Apart { delta, .. } => delta.edge.as_ref().map_or(Ok(()), check_edge),
            Reply::Made { mesh, .. } => check_mesh(mesh, "piece"),
            Reply::Grown {
                result: Ok(whole), ..
            } => check_mesh(&whole.mesh, "mesh"),
            _ => Ok(()),
        }
    }
}

fn check_mesh(mesh: &Mesh, key: &'static str) -> Result<(), WireError> {
    match mesh
        .indices
        .iter()
        .find(|&&i| i as usize >= mesh.vertices.len())
    {
        Some(i) => Err(wrong(
            key,
            format!("index {i} of {} vertices", mesh.vertices.len()),
        )),
        None => Ok(()),
    }
}

/// Fails unless the slots (in the order of their numbers) and runs all lie within the edge's
/// counts, and its indices all name one of its vertices.
fn check_edge(e: &EdgeWrites) -> Result<(), WireError> {
    let within = |key, range: &Range<u32>, count: u32| {
        if range.start <= range.end && range.end <= count {
            Ok(())
        } else {
            Err(wrong(key, format!("{range:?} beyond {count}")))
        }
    };
    for (k, slot) in e.slots.iter().enumerate() {
        within("edge slot", &slot.vertices, e.vertex_count)?;
        within("edge slot", &slot.indices, e.index_count)?;
        if k > 0 && e.slots[k - 1].id >= slot.id {
            return Err(wrong(
                "edge slot",
                format!("slot {} after {}", slot.id, e.slots[k - 1].id),
            ));
        }
    }
    for run in &e.runs {
        let end = |first: u32, n: usize| first.saturating_add(n as u32);
        let vertices = run.first_vertex..end(run.first_vertex, run.vertices.len());
        within("edge run", &vertices, e.vertex_count)?;
        let indices = run.first_index..end(run.first_index, run.indices.len());
        within("edge run", &indices, e.index_count)?;
        if let Some(i) = run.indices.iter().find(|&&i| i >= e.vertex_count) {
            return Err(wrong(
                "edge indices",
                format!("index {i} of {} vertices", e.vertex_count),
            ));
        }
    }
    Ok(())
}
