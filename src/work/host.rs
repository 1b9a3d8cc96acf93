//! What a worker does with the page's requests: it holds at most one growing shell and one
//! previewed pattern (the sessions), does jobs (pieces of a shell's growth, whole shells for
//! the gallery, tiles of a parameter map) in the order they came, and answers each request
//! once. The same host runs in each Web Worker, and on the page's own thread where workers
//! cannot start, where it works a frame's budget at a time; natively, the tests run it.

use super::edge_slots::EdgeSlots;
use super::message::{Delta, Progress, Reply, Request, ShellInfo, WholeShell};
use crate::blobtree::polygonize::ChunkWork;
use crate::forms::{PieceMaker, piece_maker};
use crate::generator::{Advance, EdgeRuns, Generator, within};
use crate::generator::{RimLengths, pattern_alone};
use crate::mesh::{Bounds, Mesh};
use crate::share::link;
use crate::spec::ShellSpec;
use crate::variation::parameter_map::TileWork;
use crate::view::preview::{Preview, PreviewState};
use std::collections::VecDeque;

/// How long the host may work before it gives the thread back.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Budget {
    /// Until every request is answered (a worker, whose thread does nothing else).
    Unbounded,
    /// Until this time on the host's clock, in milliseconds (the page's own thread).
    Until(f64),
}

/// The shell a session grows.
struct Growth {
    session: u32,
    generator: Generator,
    /// Bounds of everything grown so far, edge included.
    grown: Bounds,
    /// The longest growth step lately (see [`within`]).
    longest: f64,
    /// The edge as the page holds it from this host's replies (none before the first, and on a
    /// host that regrew the shell: its first edge then crosses whole).
    sent_edge: EdgeSlots,
}

/// A job under way, kept between calls when the budget runs out.
enum Job {
    Pieces { job: u32, work: Box<ChunkWork> },
    Whole { job: u32, generator: Box<Generator> },
    Tile { job: u32, work: Box<TileWork> },
}

/// A worker's state: its sessions, the jobs waiting, and the pieces' maker of the last shell
/// it made pieces of.
#[derive(Default)]
pub struct Host {
    growth: Option<Growth>,
    preview: Option<(u32, Preview)>,
    maker: Option<(String, PieceMaker)>,
    queue: VecDeque<(u32, Request)>,
    current: Option<(u32, Job)>,
    /// The rim's lengths of the last form whose pattern was previewed or mapped.
    rims: RimLengths,
}

/// The spec a link gives.
fn spec_of(fragment: &str) -> ShellSpec {
    link::decode(fragment).spec
}

/// What the page needs to know of a shell growing in `generator`.
fn shell_info(generator: &Generator) -> ShellInfo {
    let (bounds, front) = generator.framing();
    ShellInfo {
        rows: generator.rows() as u32,
        cells: generator.pattern().map_or(0, |p| p.cells() as u32),
        capacity: generator.capacity(),
        bounds,
        front,
        line_grid: generator.line_grid(),
    }
}

fn progress(generator: &Generator) -> Progress {
    let done = generator.is_done();
    Progress {
        rows_done: generator.rows_done() as u32,
        steps_done: generator.steps_done() as u32,
        caught_up: generator.caught_up(),
        done,
        failure: generator.failure().map(str::to_string),
        pattern_hash: generator.pattern().map(|p| p.hash()),
        mesh_hash: done.then(|| generator.mesh_hash()),
    }
}

impl Growth {
    /// What `advance` added, as it crosses to the page.
    fn delta(&mut self, advance: &Advance) -> Delta {
        let generator = &self.generator;
        let mesh = generator.mesh();
        self.grown
            .include_vertices(&mesh.vertices[advance.vertices.clone()]);
        let edge = advance.edge.as_ref().map(|_| {
            let edge = generator.edge();
            self.grown.include_vertices(&edge.vertices);
            self.sent_edge.update(edge, &generator.edge_parts())
        });
        let (rgba, widths) = generator.pattern().map_or_else(Default::default, |p| {
            let row = p.cells() * 4;
            (
                p.rgba()[advance.rows.start * row..advance.rows.end * row].to_vec(),
                p.widths()[advance.rows.clone()].to_vec(),
            )
        });
        Delta {
            rows: advance.rows.start as u32..advance.rows.end as u32,
            rgba,
            widths,
            first_vertex: advance.vertices.start as u32,
            vertices: mesh.vertices[advance.vertices.clone()].to_vec(),
            first_index: advance.indices.start as u32,
            indices: mesh.indices[advance.indices.clone()].to_vec(),
            edge,
            grown: self.grown,
            progress: progress(generator),
        }
    }
}

impl Host {
    /// Takes a request with its ticket; it is answered by [`Self::work`].
    pub fn push(&mut self, ticket: u32, request: Request) {
        self.queue.push_back((ticket, request));
    }

    /// Whether requests wait or a job is under way.
    pub fn busy(&self) -> bool {
        self.current.is_some() || !self.queue.is_empty()
    }

    /// Answers requests in the order they came, within `budget` on the clock `now`
    /// (milliseconds): at least one step of work is done if any waits. Returns the replies
    /// with their tickets.
    pub fn work(&mut self, now: &dyn Fn() -> f64, budget: Budget) -> Vec<(u32, Reply)> {
        let mut keep_going = || match budget {
            Budget::Unbounded => true,
            Budget::Until(deadline) => now() < deadline,
        };
        let mut replies = Vec::new();
        let mut first = true;
        while first || keep_going() {
            first = false;
            if self.current.is_none() {
                let Some((ticket, request)) = self.queue.pop_front() else {
                    break;
                };
                match self.start(request, now) {
                    Ok(reply) => {
                        replies.push((ticket, reply));
                        continue;
                    }
                    Err(job) => self.current = Some((ticket, job)),
                }
            }
            if let Some((ticket, job)) = self.current.take() {
                match self.resume(job, budget, &mut keep_going) {
                    Ok(reply) => replies.push((ticket, reply)),
                    Err(job) => self.current = Some((ticket, job)),
                }
            }
        }
        replies
    }

    /// Answers a request at once, or starts its job.
    fn start(&mut self, request: Request, now: &dyn Fn() -> f64) -> Result<Reply, Job> {
        let refused = |session| Reply::Refused {
            session,
            message: "this worker holds no such session".into(),
        };
        Ok(match request {
            Request::Load { session, link } => match Generator::new(&spec_of(&link)) {
                Ok(generator) => {
                    let mut growth = Growth {
                        session,
                        generator,
                        grown: Bounds::EMPTY,
                        longest: 0.0,
                        sent_edge: EdgeSlots::default(),
                    };
                    let delta = growth.delta(&growth.generator.grown());
                    let shell = shell_info(&growth.generator);
                    self.growth = Some(growth);
                    Reply::Loaded {
                        session,
                        shell,
                        delta,
                    }
                }
                Err(e) => {
                    self.growth = None;
                    Reply::Refused {
                        session,
                        message: format!("This shell cannot be built: {e}"),
                    }
                }
            },
            Request::Grow {
                session,
                rows,
                budget_ms,
            } => match &mut self.growth {
                Some(g) if g.session == session => {
                    let advance = g
                        .generator
                        .advance_while(rows as usize, within(now, budget_ms, &mut g.longest));
                    Reply::Grew {
                        session,
                        delta: g.delta(&advance),
                    }
                }
                _ => refused(session),
            },
            Request::Finish { session } => match &mut self.growth {
                Some(g) if g.session == session => {
                    let (v0, i0, r0) = (
                        g.generator.mesh().vertices.len(),
                        g.generator.mesh().indices.len(),
                        g.generator.rows_done(),
                    );
                    let pieces = g.generator.finish_apart();
                    let advance = Advance {
                        vertices: v0..g.generator.mesh().vertices.len(),
                        indices: i0..g.generator.mesh().indices.len(),
                        edge: Some(EdgeRuns::whole(g.generator.edge())),
                        rows: r0..g.generator.rows_done(),
                    };
                    let mut delta = g.delta(&advance);
                    match pieces {
                        None => Reply::Grew { session, delta },
                        Some(pieces) => {
                            // The mesh lacks the pieces: its hash is theirs to complete.
                            delta.progress.mesh_hash = None;
                            Reply::Apart {
                                session,
                                delta,
                                pieces,
                                hash: g.generator.mesh_hash(),
                            }
                        }
                    }
                }
                _ => refused(session),
            },
            Request::Resume {
                session,
                link,
                rows,
                steps,
            } => match Generator::new(&spec_of(&link)) {
                Ok(mut generator) => {
                    generator.catch_up(rows as usize, steps as usize);
                    let mut grown = Bounds::EMPTY;
                    grown.include_vertices(&generator.mesh().vertices);
                    grown.include_vertices(&generator.edge().vertices);
                    let reply = Reply::Resumed {
                        session,
                        vertices: generator.mesh().vertices.len() as u32,
                        indices: generator.mesh().indices.len() as u32,
                    };
                    self.growth = Some(Growth {
                        session,
                        generator,
                        grown,
                        longest: 0.0,
                        sent_edge: EdgeSlots::default(),
                    });
                    reply
                }
                Err(e) => Reply::Refused {
                    session,
                    message: format!("This shell cannot be built: {e}"),
                },
            },
            Request::Preview { session, link } => {
                let spec = spec_of(&link);
                let rows = spec.growth.rows as usize;
                match pattern_alone(&spec, &mut self.rims) {
                    Ok(Some(run)) => {
                        let reply = Reply::Previewed {
                            session,
                            cells: run.cells() as u32,
                            first: 0,
                            rgba: run.rgba().to_vec(),
                            widths: run.widths().to_vec(),
                            state: PreviewState::Filling,
                            failure: None,
                        };
                        self.preview = Some((session, Preview::new(run, rows)));
                        reply
                    }
                    none => {
                        // No pattern to preview: none in the spec (whole at once), or values
                        // that give none (stopped, with the reason).
                        self.preview = None;
                        let failure = none
                            .err()
                            .map(|e| format!("With these values there is no pattern: {e}."));
                        Reply::Previewed {
                            session,
                            cells: 0,
                            first: 0,
                            rgba: Vec::new(),
                            widths: Vec::new(),
                            state: if failure.is_some() {
                                PreviewState::Stopped
                            } else {
                                PreviewState::Whole
                            },
                            failure,
                        }
                    }
                }
            }
            Request::Fill { session, budget_ms } => match &mut self.preview {
                Some((s, preview)) if *s == session => {
                    let until = now() + budget_ms;
                    let (first, failure) = preview.fill(|| now() < until);
                    let run = preview.run();
                    let row = run.cells() * 4;
                    Reply::Previewed {
                        session,
                        cells: run.cells() as u32,
                        first: first as u32,
                        rgba: run.rgba()[first * row..].to_vec(),
                        widths: run.widths()[first..].to_vec(),
                        state: preview.state(),
                        failure: failure
                            .map(|e| format!("With these values the pattern stops {e}.")),
                    }
                }
                _ => refused(session),
            },
            Request::Pieces {
                job,
                link,
                step,
                ids,
            } => {
                if self.maker.as_ref().is_none_or(|(l, _)| *l != link) {
                    let spec = spec_of(&link);
                    let rows = spec.growth.rows_grown();
                    match piece_maker(&spec, rows) {
                        Ok(Some(maker)) => self.maker = Some((link, maker)),
                        Ok(None) | Err(_) => {
                            self.maker = None;
                            return Ok(Reply::Made {
                                job,
                                mesh: Mesh::default(),
                                hash: 0,
                            });
                        }
                    }
                }
                let (_, maker) = self.maker.as_ref().expect("made above");
                return Err(Job::Pieces {
                    job,
                    work: Box::new(maker.start(step, &ids)),
                });
            }
            Request::Whole { job, link, pixels } => {
                match Generator::picture(&spec_of(&link), pixels) {
                    Ok(generator) => {
                        return Err(Job::Whole {
                            job,
                            generator: Box::new(generator),
                        });
                    }
                    Err(e) => Reply::Grown {
                        job,
                        result: Err(format!("This shell cannot be built: {e}")),
                    },
                }
            }
            Request::Tile { job, link, rows } => {
                match TileWork::new(&spec_of(&link), rows as usize, &mut self.rims) {
                    Ok(work) => {
                        return Err(Job::Tile {
                            job,
                            work: Box::new(work),
                        });
                    }
                    Err(why) => Reply::Tiled {
                        job,
                        result: Err(why),
                    },
                }
            }
        })
    }

    /// Goes on with a job while `keep_going` allows (at least a step): its reply once done,
    /// or the job to go on with later.
    fn resume(
        &mut self,
        job: Job,
        budget: Budget,
        keep_going: &mut dyn FnMut() -> bool,
    ) -> Result<Reply, Job> {
        match job {
            Job::Pieces { job, mut work } => {
                let Some((_, maker)) = &self.maker else {
                    unreachable!("a job of pieces is started with its maker");
                };
                if !maker.work(&mut work, keep_going) {
                    return Err(Job::Pieces { job, work });
                }
                let mesh = maker.finished(*work);
                let hash = mesh.content_hash();
                Ok(Reply::Made { job, mesh, hash })
            }
            Job::Whole { job, mut generator } => {
                if budget == Budget::Unbounded {
                    generator.finish();
                } else {
                    generator.advance_while(usize::MAX, &mut *keep_going);
                }
                if !generator.is_done() {
                    return Err(Job::Whole { job, generator });
                }
                let (rgba, widths) = generator.pattern().map_or_else(Default::default, |p| {
                    (p.rgba().to_vec(), p.widths().to_vec())
                });
                Ok(Reply::Grown {
                    job,
                    result: Ok(WholeShell {
                        shell: shell_info(&generator),
                        mesh: generator.snapshot(),
                        rgba,
                        widths,
                    }),
                })
            }
            Job::Tile { job, mut work } => match work.work(&mut *keep_going) {
                Some(result) => Ok(Reply::Tiled { job, result }),
                None => Err(Job::Tile { job, work }),
            },
        }
    }
}
