//! A pool of Web Workers simulated natively, as their owner (the page's thread, or the worker
//! that draws the view) has them: the core's [`Pool`] with its rules for its workers' events
//! ([`Pool::take_events`]), each worker the core's [`Host`] on a clock of its own, every
//! request and reply crossing as its bytes. A worker's replies reach the owner late, by up to
//! a given number of frames, each worker's in the order it sent them (as a worker's messages
//! do) and the workers' interleaved at random; a worker may throw, hang, send bytes nobody can
//! read, or have a reply delivered twice. Where the pool gives its workers up, one host works
//! on the owner's thread a frame's budget at a time. The simulator (`simulator.rs`) and the
//! tests of growth off the page's thread (`workers.rs`) both run on it.

use rand_core::Rng;
use rand_pcg::Pcg64;
use seashells_core::generator::Advance;
use seashells_core::view::draw_pacing::HEAVY_BYTES;
use seashells_core::work::host::{Budget, Host};
use seashells_core::work::message::{decode_reply, decode_request, encode_reply, encode_request};
use seashells_core::work::pool::{Polled, Pool, SESSIONS, WorkerEvent};
use seashells_core::work::replica::Replica;
use std::cell::Cell;
use std::collections::VecDeque;

/// A page's thread's budget for growth a frame where workers cannot run, milliseconds.
const LOCAL_BUDGET_MS: f64 = 8.0;

/// One simulated Web Worker.
struct Worker {
    host: Host,
    /// Its clock: a millisecond passes each time it is read, so that budgets run out after as
    /// many reads, the same way every run.
    clock: Cell<f64>,
    /// Spinning, or gone: it takes messages and answers none.
    silent: bool,
    garble_next: bool,
    twice_next: bool,
    /// What it sent and its owner has not heard yet, with the frame it arrives in.
    outbox: VecDeque<(u64, WorkerEvent)>,
    generation: u32,
}

impl Worker {
    fn new(generation: u32) -> Self {
        Self {
            host: Host::default(),
            clock: Cell::new(0.0),
            silent: false,
            garble_next: false,
            twice_next: false,
            outbox: VecDeque::new(),
            generation,
        }
    }
}

/// A clock that moves on by a millisecond each time it is read.
fn ticking(clock: &Cell<f64>) -> impl Fn() -> f64 + '_ {
    || {
        clock.set(clock.get() + 1.0);
        clock.get()
    }
}

/// The pool and its simulated workers.
pub struct Workers {
    pub pool: Pool,
    workers: Vec<Worker>,
    /// Where the workers were given up: one host on the owner's thread.
    local: Option<Host>,
    local_clock: Cell<f64>,
    /// Events heard and not yet taken in (a heavy reply waits a frame).
    inbox: Vec<WorkerEvent>,
}

impl Workers {
    pub fn new(size: usize) -> Self {
        Self {
            pool: Pool::new(size),
            workers: (0..size).map(|_| Worker::new(0)).collect(),
            local: None,
            local_clock: Cell::new(0.0),
            inbox: Vec::new(),
        }
    }

    /// The workers in the pool (0 once given up).
    pub fn count(&self) -> usize {
        self.workers.len()
    }

    /// Events heard and not yet taken in.
    pub fn unheard(&self) -> usize {
        self.inbox.len()
    }

    /// The owner's frame `frame` at `now`: what reached it is taken in by the pool's rules,
    /// the workers it replaced are started afresh, and where the workers were given up the
    /// owner's thread works a frame's budget.
    pub fn poll(&mut self, frame: u64, now: f64, rng: &mut Pcg64) -> Polled {
        self.hear(frame, rng);
        let mut polled = self.pool.take_events(&mut self.inbox, now);
        for (slot, generation, _) in &polled.start {
            self.workers[*slot] = Worker::new(*generation);
        }
        if polled.given_up.is_some() {
            self.workers.clear();
            self.local = Some(Host::default());
        }
        if let Some(host) = &mut self.local {
            let now_local = ticking(&self.local_clock);
            let until = self.local_clock.get() + LOCAL_BUDGET_MS;
            for (ticket, reply) in host.work(&now_local, Budget::Until(until)) {
                if let Some(request) = self.pool.answered(SESSIONS, ticket, now) {
                    polled.replies.push((request, reply));
                }
            }
        }
        polled
    }

    /// What reached the owner by `frame`, each worker's in the order it sent them, the
    /// workers' interleaved at random.
    fn hear(&mut self, frame: u64, rng: &mut Pcg64) {
        loop {
            let ready: Vec<usize> = (0..self.workers.len())
                .filter(|&w| {
                    self.workers[w]
                        .outbox
                        .front()
                        .is_some_and(|(at, _)| *at <= frame)
                })
                .collect();
            if ready.is_empty() {
                return;
            }
            let w = ready[(rng.next_u32() as usize) % ready.len()];
            if let Some((_, event)) = self.workers[w].outbox.pop_front() {
                self.inbox.push(event);
            }
        }
    }

    /// Sends what the pool has to send at `now`, through the bytes.
    pub fn dispatch(&mut self, now: f64) -> Result<(), String> {
        for send in self.pool.dispatch(now) {
            let bytes = encode_request(send.ticket, &send.request);
            let (ticket, request) = decode_request(&bytes).map_err(|e| e.to_string())?;
            if let Some(host) = &mut self.local {
                host.push(ticket, request);
            } else {
                self.workers[send.slot].host.push(ticket, request);
            }
        }
        Ok(())
    }

    /// Lets each worker work `ms` of its own clock after the owner's frame `frame` (infinite:
    /// whatever it holds, to its end, as a Web Worker does, `web/worker_host.rs`); its
    /// replies reach the owner from the next frame, up to `lag` frames later.
    pub fn work(&mut self, frame: u64, ms: f64, lag: u8, rng: &mut Pcg64) {
        for (slot, worker) in self.workers.iter_mut().enumerate() {
            if worker.silent {
                continue;
            }
            let now = ticking(&worker.clock);
            let budget = if ms.is_finite() {
                Budget::Until(worker.clock.get() + ms)
            } else {
                Budget::Unbounded
            };
            for (ticket, reply) in worker.host.work(&now, budget) {
                let bytes = if std::mem::take(&mut worker.garble_next) {
                    Vec::new()
                } else {
                    encode_reply(ticket, &reply)
                };
                let last = worker.outbox.back().map_or(0, |(at, _)| *at);
                let at = (frame + 1 + u64::from(rng.next_u32()) % (u64::from(lag) + 1)).max(last);
                let copies = if std::mem::take(&mut worker.twice_next) {
                    2
                } else {
                    1
                };
                for _ in 0..copies {
                    worker.outbox.push_back((
                        at,
                        WorkerEvent::Reply {
                            slot,
                            generation: worker.generation,
                            reply: Box::new(decode_reply(&bytes)),
                            heavy: bytes.len() > HEAVY_BYTES,
                        },
                    ));
                }
            }
        }
    }

    /// Whether nothing is asked of the workers, nor on its way back.
    pub fn idle(&self) -> bool {
        self.pool.in_flight() == 0
            && self.pool.waiting() == 0
            && self.inbox.is_empty()
            && self.workers.iter().all(|w| w.outbox.is_empty())
    }

    /// The worker in `slot` (counted round the pool) throws, after the replies it has sent,
    /// heard from `frame` on.
    pub fn throw(&mut self, slot: usize, frame: u64) {
        let slot = slot % self.workers.len().max(1);
        if let Some(worker) = self.workers.get_mut(slot) {
            worker.silent = true;
            let last = worker.outbox.back().map_or(0, |(at, _)| *at);
            worker.outbox.push_back((
                last.max(frame),
                WorkerEvent::Died {
                    slot,
                    generation: worker.generation,
                    why: "it threw".into(),
                },
            ));
        }
    }

    /// The worker in `slot` spins for ever on what it holds.
    pub fn hang(&mut self, slot: usize) {
        let slot = slot % self.workers.len().max(1);
        if let Some(worker) = self.workers.get_mut(slot) {
            worker.silent = true;
        }
    }

    /// The next reply of the worker in `slot` arrives as bytes nobody can read.
    pub fn garble(&mut self, slot: usize) {
        let slot = slot % self.workers.len().max(1);
        if let Some(worker) = self.workers.get_mut(slot) {
            worker.garble_next = true;
        }
    }

    /// The next reply of the worker in `slot` reaches the owner twice.
    pub fn twice(&mut self, slot: usize) {
        let slot = slot % self.workers.len().max(1);
        if let Some(worker) = self.workers.get_mut(slot) {
            worker.twice_next = true;
        }
    }
}

/// Whether every range `advance` asks the renderer to read is in `replica` as it stands: what
/// the simulator and the tests of growth off the page's thread check of every upload.
pub fn within_copy(advance: &Advance, replica: &Replica) -> bool {
    let (mesh, edge) = (replica.mesh(), replica.edge().mesh());
    let edge_runs = advance.edge.iter().flat_map(|e| {
        let vertices = e.vertices.iter().map(|r| (r.end, edge.vertices.len()));
        vertices.chain(e.indices.iter().map(|r| (r.end, edge.indices.len())))
    });
    [
        (advance.vertices.end, mesh.vertices.len()),
        (advance.indices.end, mesh.indices.len()),
        (advance.rows.end * replica.cells() * 4, replica.rgba().len()),
    ]
    .into_iter()
    .chain(edge_runs)
    .all(|(end, len)| end <= len)
}
