//! The page's workers: a pool of Web Workers (`www/worker.js`, one per core but the page's own,
//! at most eight; `workers=N` in the address's query sets another number, for tests and
//! benchmarks), each running the core's host, with the core's [`Pool`] sharing requests out.
//! Requests and replies cross as bytes in transferred `ArrayBuffer`s. A worker that throws, or
//! keeps a request past its allowance, is terminated and replaced, and its jobs are sent again;
//! from the second time the page's status line says so ([`Replaced::words`]). A reply is read
//! (copied and decoded) in its `message` event as it comes; one of megabytes is taken in a
//! frame later, so that reading it and taking it in fall in different frames (see
//! [`crate::view::draw_pacing`]). Where workers cannot start (or with `workers=0`), one host
//! runs on the thread of the pool's owner (the page's, or the worker that draws the view) a
//! frame's budget at a time, and [`Workers::status`] says so.
//! Nothing here writes on the page: the page shows what these return.
//!
//! Test-only: `crash-workers=N` in the query makes the first N workers started throw on their
//! first request, and `hang-workers=N` the next N spin forever on theirs without answering (see
//! `www/worker.js`); with `hang-workers` a worker is held to hang after a fifth of each
//! request's allowance (3 s for a step or a job, 12 s for building or regrowing a shell), so
//! that a page test finds it out in seconds. `debug_crash_worker_on_fill` (`debug.rs`) makes
//! the worker holding the sessions throw when next asked for rows of a previewed pattern.

use super::clock::now;
use super::debug;
use super::scope;
use crate::view::draw_pacing::HEAVY_BYTES;
use crate::work::host::{Budget, Host};
use crate::work::message::{Reply, Request, decode_reply, encode_request};
use crate::work::pool::{Pool, SESSIONS, size_for};
use crate::work::wire::WireError;
use js_sys::{Array, Uint8Array};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{ErrorEvent, MessageEvent, Worker, WorkerOptions, WorkerType};

/// What a worker's events leave for the next frame: a reply, read from its bytes when it came
/// (in the message's own task, not in the frame), or its death.
enum Event {
    Reply {
        slot: usize,
        generation: u32,
        reply: Box<Result<(u32, Reply), WireError>>,
        /// Whether it was read from more than [`HEAVY_BYTES`] and waits a frame before it is
        /// taken in (see [`crate::view::draw_pacing`]).
        waits: bool,
    },
    Died(usize, u32, String),
}

type Inbox = Rc<RefCell<Vec<Event>>>;

/// One Web Worker with its listeners, and its generation (replies of a worker since replaced
/// are dropped).
struct Slot {
    worker: Worker,
    generation: u32,
    _on_message: Closure<dyn FnMut(MessageEvent)>,
    _on_error: Closure<dyn FnMut(ErrorEvent)>,
}

impl Drop for Slot {
    fn drop(&mut self) {
        self.worker.set_onmessage(None);
        self.worker.set_onerror(None);
        self.worker.terminate();
    }
}

/// Workers left to start that fail on their first request (test-only): first those that
/// throw, then those that hang.
#[derive(Clone, Copy, Default)]
struct Faults {
    throws: usize,
    hangs: usize,
}

impl Faults {
    /// The name of the next worker to start: one `www/worker.js` makes fail, or its own.
    fn next_name(&mut self) -> &'static str {
        if self.throws > 0 {
            self.throws -= 1;
            "seashells-throw"
        } else if self.hangs > 0 {
            self.hangs -= 1;
            "seashells-hang"
        } else {
            "seashells"
        }
    }
}

/// The share of each request's allowance a worker gets under the `hang-workers` switch.
const TEST_PATIENCE: f64 = 0.2;

/// Where requests are worked on.
enum Backend {
    Workers {
        slots: Vec<Slot>,
        inbox: Inbox,
        faults: Faults,
        /// Whether any worker has answered yet: workers that all die before answering
        /// anything cannot run here (a browser without module workers, say).
        answered: bool,
    },
    /// The page's own thread.
    Local(Box<Host>),
}

/// What came back since the last frame.
#[derive(Default)]
pub struct Polled {
    /// Replies with the requests they answer, in the order they came.
    pub replies: Vec<(Request, Reply)>,
    /// Whether the worker holding the sessions was replaced: its shells are gone with it,
    /// and these of its requests were lost unanswered.
    pub sessions_lost: Option<Vec<Request>>,
    /// The last worker replaced since the last frame, if any.
    pub replaced: Option<Replaced>,
}

/// A worker that died or hung and was replaced.
pub struct Replaced {
    /// Workers replaced since the page opened.
    pub deaths: usize,
    /// Why this one was, in words.
    why: String,
    /// The status line, when the workers were given up for the owner's thread instead.
    given_up: Option<String>,
}

impl Replaced {
    /// The status line's words: none the first time (a worker's death is rare enough to
    /// redo its work silently once), the count and the cause from the second; where the
    /// shells grow now, once the workers are given up.
    pub fn words(&self) -> Option<String> {
        if let Some(status) = &self.given_up {
            return Some(status.clone());
        }
        (self.deaths >= 2).then(|| {
            format!(
                "A worker stopped ({}) for the {} time; it was replaced and its work done again.",
                self.why,
                ordinal(self.deaths)
            )
        })
    }
}

pub struct Workers {
    pool: Pool,
    backend: Backend,
    /// Milliseconds of a frame the page's own thread may work, without workers.
    budget_ms: f64,
    /// Least milliseconds a worker is given to grow the shell per request (`grow-budget=N` in
    /// the query sets another, for benchmarks).
    worker_growth_ms: f64,
    /// Where the shells grow, in words for the status line.
    status: String,
}

/// Least milliseconds a worker grows the shell per request: off the page's thread a request
/// may take longer than the page's own frame budget, for fewer round trips, while a change of
/// value still waits at most this long behind the growth under way (see "Who runs where" in
/// `docs/design/architecture.md` for the measurement).
const WORKER_GROWTH_MS: f64 = 24.0;

/// The page address's query parameter `key`, as a number.
fn query_number(key: &str) -> Option<usize> {
    scope::search()
        .trim_start_matches('?')
        .split('&')
        .find_map(|pair| pair.strip_prefix(key)?.strip_prefix('='))
        .and_then(|v| v.parse().ok())
}

/// Starts a worker named `name` for slot `slot` in generation `generation`, its events going
/// to `inbox`.
fn spawn(slot: usize, generation: u32, inbox: &Inbox, name: &str) -> Result<Slot, JsValue> {
    let options = WorkerOptions::new();
    options.set_type(WorkerType::Module);
    options.set_name(name);
    let worker = Worker::new_with_options("./worker.js", &options)?;
    let to = Rc::clone(inbox);
    let on_message = Closure::<dyn FnMut(MessageEvent)>::new(move |e: MessageEvent| {
        let bytes = Uint8Array::new(&e.data()).to_vec();
        to.borrow_mut().push(Event::Reply {
            slot,
            generation,
            reply: Box::new(decode_reply(&bytes)),
            waits: bytes.len() > HEAVY_BYTES,
        });
    });
    let to = Rc::clone(inbox);
    let on_error = Closure::<dyn FnMut(ErrorEvent)>::new(move |e: ErrorEvent| {
        e.prevent_default();
        to.borrow_mut()
            .push(Event::Died(slot, generation, e.message()));
    });
    worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
    Ok(Slot {
        worker,
        generation,
        _on_message: on_message,
        _on_error: on_error,
    })
}

impl Workers {
    /// The pool this browser gets, or the page's own thread where workers cannot start.
    pub fn start(budget_ms: f64) -> Self {
        let size = query_number("workers")
            .unwrap_or_else(|| size_for(scope::cores()))
            .min(8);
        let mut faults = Faults {
            throws: query_number("crash-workers").unwrap_or(0),
            hangs: query_number("hang-workers").unwrap_or(0),
        };
        let patience = if faults.hangs > 0 { TEST_PATIENCE } else { 1.0 };
        let local = |why: &str| Self {
            pool: Pool::new(1),
            backend: Backend::Local(Box::default()),
            budget_ms,
            worker_growth_ms: budget_ms,
            status: local_status(why),
        };
        if size == 0 {
            return local("workers are off (workers=0 in the address)");
        }
        let inbox: Inbox = Rc::default();
        let mut slots = Vec::new();
        for slot in 0..size {
            match spawn(slot, 0, &inbox, faults.next_name()) {
                Ok(s) => slots.push(s),
                Err(e) => {
                    let why = e
                        .as_string()
                        .or_else(|| e.dyn_ref::<js_sys::Error>().map(|e| e.message().into()))
                        .unwrap_or_else(|| "this browser cannot start workers".into());
                    return local(&format!("workers could not start ({why})"));
                }
            }
        }
        Self {
            status: format!(
                "Growing on {size} worker{}.",
                if size == 1 { "" } else { "s" }
            ),
            pool: Pool::new(size).with_patience(patience),
            backend: Backend::Workers {
                slots,
                inbox,
                faults,
                answered: false,
            },
            budget_ms,
            worker_growth_ms: query_number("grow-budget").map_or(WORKER_GROWTH_MS, |ms| ms as f64),
        }
    }

    /// The workers in the pool: 0 on the page's own thread.
    pub fn count(&self) -> usize {
        match &self.backend {
            Backend::Workers { slots, .. } => slots.len(),
            Backend::Local(_) => 0,
        }
    }

    /// Where the shells grow, in words for the status line.
    pub fn status(&self) -> &str {
        &self.status
    }

    /// Milliseconds to grow the shell for in one request, where the page's own thread would
    /// take `frame_ms`: as much on the page's thread, at least [`WORKER_GROWTH_MS`] on a worker.
    pub fn growth_budget(&self, frame_ms: f64) -> f64 {
        match self.backend {
            Backend::Local(_) => frame_ms,
            Backend::Workers { .. } => frame_ms.max(self.worker_growth_ms),
        }
    }

    /// Asks for `request` (sent in the next [`Self::poll`]).
    pub fn submit(&mut self, request: Request) {
        self.pool.submit(request);
    }

    /// Drops the jobs not yet sent that `drop` picks.
    pub fn cancel(&mut self, drop: impl FnMut(&Request) -> bool) {
        self.pool.cancel(drop);
    }

    /// Sends what waits: called at the end of each frame, so that a request asked in a frame
    /// is worked on while the page waits for the next, not a frame later.
    pub fn send(&mut self) {
        let sends = self.pool.dispatch(now());
        match &mut self.backend {
            Backend::Local(host) => {
                for send in sends {
                    host.push(send.ticket, send.request);
                }
            }
            Backend::Workers { slots, .. } => {
                for send in sends {
                    let fill = matches!(send.request, Request::Fill { .. });
                    let bytes = if fill && debug::crash_on_fill_asked() {
                        // Bytes no worker can read: it throws, as a worker that fails would.
                        Vec::new()
                    } else {
                        encode_request(send.ticket, &send.request)
                    };
                    let buffer = Uint8Array::from(&bytes[..]).buffer();
                    let transfer = Array::of1(&buffer);
                    // A worker that cannot take a message is found out by its silence.
                    let _ = slots[send.slot]
                        .worker
                        .post_message_with_transfer(&buffer, &transfer);
                }
            }
        }
    }

    /// Sends what waits, replaces workers that died or hang, and returns what came back: a
    /// reply of more than [`HEAVY_BYTES`], and what came after it, a frame after it was read.
    pub fn poll(&mut self) -> Polled {
        let mut polled = Polled::default();
        self.send();
        let Self {
            pool,
            backend,
            budget_ms,
            ..
        } = self;
        match backend {
            Backend::Local(host) => {
                for (ticket, reply) in host.work(&now, Budget::Until(now() + *budget_ms)) {
                    if let Some(request) = pool.answered(SESSIONS, ticket, now()) {
                        polled.replies.push((request, reply));
                    }
                }
            }
            Backend::Workers {
                slots,
                inbox,
                faults,
                answered,
            } => {
                let mut events = std::mem::take(&mut *inbox.borrow_mut()).into_iter();
                let mut dead = Vec::new();
                while let Some(mut event) = events.next() {
                    if let Event::Reply { waits, .. } = &mut event
                        && std::mem::take(waits)
                    {
                        // Read in this frame's time: taken in, with all that came after it,
                        // in the next.
                        let mut inbox = inbox.borrow_mut();
                        let later: Vec<Event> = std::iter::once(event)
                            .chain(events.by_ref())
                            .chain(inbox.drain(..))
                            .collect();
                        *inbox = later;
                        break;
                    }
                    match event {
                        Event::Reply {
                            slot,
                            generation,
                            reply,
                            ..
                        } => {
                            if slots[slot].generation != generation {
                                continue;
                            }
                            let Ok((ticket, reply)) = *reply else {
                                dead.push((slot, "its reply could not be read".to_string()));
                                continue;
                            };
                            *answered = true;
                            if let Some(request) = pool.answered(slot, ticket, now()) {
                                polled.replies.push((request, reply));
                            }
                        }
                        Event::Died(slot, generation, why) => {
                            if slots[slot].generation == generation {
                                dead.push((slot, why));
                            }
                        }
                    }
                }
                if let Some(slot) = pool.overdue(now()) {
                    pool.hung();
                    dead.push((slot, "it did not answer in time".into()));
                }
                dead.dedup_by_key(|(slot, _)| *slot);
                for (slot, why) in dead {
                    let lost = pool.failed(slot);
                    if slot == SESSIONS {
                        polled.sessions_lost = Some(lost);
                    }
                    let generation = slots[slot].generation + 1;
                    match spawn(slot, generation, inbox, faults.next_name()) {
                        Ok(fresh) => slots[slot] = fresh,
                        Err(_) => continue,
                    }
                    polled.replaced = Some(Replaced {
                        deaths: pool.deaths(),
                        why,
                        given_up: None,
                    });
                }
                if !*answered && pool.deaths() > slots.len() + NEVER_ANSWERED_SPARE {
                    let why = polled.replaced.take().map_or_else(String::new, |r| r.why);
                    self.run_here(&mut polled, why);
                }
            }
        }
        polled
    }

    /// Workers cannot run here: the pool's owner's thread takes their work (a frame's budget
    /// at a time), and the shells they held are grown again there.
    fn run_here(&mut self, polled: &mut Polled, why: String) {
        let mut lost = self.pool.collapse();
        if let Some(earlier) = polled.sessions_lost.take() {
            lost.splice(0..0, earlier);
        }
        polled.sessions_lost = Some(lost);
        self.backend = Backend::Local(Box::default());
        self.worker_growth_ms = self.budget_ms;
        self.status = local_status(&format!(
            "workers could not run here (each stopped before answering: {why})"
        ));
        polled.replaced = Some(Replaced {
            deaths: self.pool.deaths(),
            why,
            given_up: Some(self.status.clone()),
        });
    }
}

/// Workers beyond the pool's size that may die before any has answered before the pool takes
/// workers for unable to run here (the page tests make the first two fail on purpose).
const NEVER_ANSWERED_SPARE: usize = 2;

/// The status line where the pool's owner's thread grows the shells: why.
fn local_status(why: &str) -> String {
    format!("Growing on {}: {why}.", scope::thread_name())
}

/// "second", "third", … for the status line.
fn ordinal(n: usize) -> String {
    match n {
        2 => "second".into(),
        3 => "third".into(),
        n => format!("{n}th"),
    }
}
