//! The pool's requests: which worker each goes to, which wait, which were sent and not yet
//! answered, and what to send again when a worker dies or hangs.

use crate::work::message::Request;
use std::collections::VecDeque;

/// Jobs a worker holds at once.
pub const JOBS_PER_WORKER: usize = 2;

/// The size of the pool a machine with `cores` logical processors gets: one worker per core
/// but the page's own, at least one and at most eight.
pub fn size_for(cores: usize) -> usize {
    cores.saturating_sub(1).clamp(1, 8)
}

/// A request sent and not yet answered.
#[derive(Clone, Debug, PartialEq)]
struct Sent {
    ticket: u32,
    request: Request,
    at: f64,
}

/// One worker's requests in flight.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Slot {
    sent: Vec<Sent>,
    /// When it last answered (or was given work while idle): a request's wait starts then.
    quiet_since: f64,
    /// Which worker holds the slot: each replacement is the next generation, and replies of
    /// an earlier one are dropped.
    pub(super) generation: u32,
}

impl Slot {
    fn jobs(&self) -> usize {
        self.sent.iter().filter(|s| !s.request.is_session()).count()
    }
}

/// A request to send now: to worker `slot`, with its ticket.
#[derive(Clone, Debug, PartialEq)]
pub struct Send {
    pub slot: usize,
    pub ticket: u32,
    pub request: Request,
}

/// The requests of the pool's workers.
#[derive(Clone, Debug)]
pub struct Pool {
    pub(super) slots: Vec<Slot>,
    /// Jobs waiting for a worker, with their tickets.
    waiting: VecDeque<(u32, Request)>,
    next_ticket: u32,
    /// The last session number given out (see [`Self::open_session`]).
    last_session: u32,
    /// Workers that died or hung so far.
    pub(super) deaths: usize,
    /// Whether any worker has answered yet: workers that all die before answering anything
    /// cannot run here (a browser without module workers, say).
    pub(super) answered_any: bool,
    /// The share of each request's allowance a worker is given before it is held to hang: 1
    /// in the product; less under the page tests' `hang-workers` switch, so that a hang is
    /// found out in seconds.
    patience: f64,
}

/// The worker that holds sessions.
pub const SESSIONS: usize = 0;

impl Pool {
    /// A pool of `size` workers (at least one).
    pub fn new(size: usize) -> Self {
        Self {
            slots: vec![Slot::default(); size.max(1)],
            waiting: VecDeque::new(),
            next_ticket: 1,
            last_session: 0,
            deaths: 0,
            answered_any: false,
            patience: 1.0,
        }
    }

    /// The same pool giving each request `patience` times its allowance (see
    /// [`Request::allowance_ms`]).
    pub fn with_patience(self, patience: f64) -> Self {
        Self { patience, ..self }
    }

    pub fn size(&self) -> usize {
        self.slots.len()
    }

    /// Workers that died or hung so far.
    pub fn deaths(&self) -> usize {
        self.deaths
    }

    /// A session number no owner of this pool was given before. The sessions' worker holds
    /// one shell and one preview, whoever asked for them: two viewers sharing the pool (the
    /// page's viewer and the one that takes its place when it cannot draw) must never both
    /// number a shell 1, or the replies of the one that left would be taken in by the other
    /// as its own. Numbers start at 1: 0 is a shell no worker holds.
    pub fn open_session(&mut self) -> u32 {
        self.last_session = self.last_session.wrapping_add(1);
        self.last_session
    }

    /// Takes a request: a session's is to be sent at once, a job when a worker is free (see
    /// [`Self::dispatch`]).
    pub fn submit(&mut self, request: Request) {
        let ticket = self.next_ticket;
        self.next_ticket = self.next_ticket.wrapping_add(1);
        self.waiting.push_back((ticket, request));
    }

    /// Drops the jobs not yet sent that `drop` picks (work no longer wanted); replies to
    /// those already sent still come, and their owner ignores them.
    pub fn cancel(&mut self, mut drop: impl FnMut(&Request) -> bool) {
        self.waiting.retain(|(_, r)| r.is_session() || !drop(r));
    }

    /// What to send now, at time `now` (milliseconds): every session request, in order, to
    /// the sessions' worker; jobs, in order, to the workers with fewest in hand.
    pub fn dispatch(&mut self, now: f64) -> Vec<Send> {
        let mut out = Vec::new();
        let mut kept = VecDeque::new();
        while let Some((ticket, request)) = self.waiting.pop_front() {
            let slot = if request.is_session() {
                Some(SESSIONS)
            } else {
                (0..self.slots.len())
                    .filter(|&s| self.slots[s].jobs() < JOBS_PER_WORKER)
                    .min_by_key(|&s| (self.slots[s].sent.len(), s))
            };
            let Some(slot) = slot else {
                kept.push_back((ticket, request));
                continue;
            };
            let s = &mut self.slots[slot];
            if s.sent.is_empty() {
                s.quiet_since = now;
            }
            s.sent.push(Sent {
                ticket,
                request: request.clone(),
                at: now,
            });
            out.push(Send {
                slot,
                ticket,
                request,
            });
        }
        self.waiting = kept;
        out
    }

    /// Worker `slot` answered `ticket` at `now`: the request it answered, or `None` for a
    /// ticket it was not given (a reply from before it was replaced).
    pub fn answered(&mut self, slot: usize, ticket: u32, now: f64) -> Option<Request> {
        let s = self.slots.get_mut(slot)?;
        let at = s.sent.iter().position(|x| x.ticket == ticket)?;
        s.quiet_since = now;
        Some(s.sent.remove(at).request)
    }

    /// The first worker that has kept a request longer than its allowance, at `now`.
    pub fn overdue(&self, now: f64) -> Option<usize> {
        self.slots.iter().position(|s| {
            s.sent.first().is_some_and(|first| {
                now - s.quiet_since.max(first.at) > first.request.allowance_ms() * self.patience
            })
        })
    }

    /// Requests waiting to be sent.
    pub fn waiting(&self) -> usize {
        self.waiting.len()
    }

    /// Jobs sent and not yet answered, by slot.
    pub fn in_flight(&self) -> usize {
        self.slots.iter().map(|s| s.sent.len()).sum()
    }

    /// Whether jobs wait or are in flight.
    pub fn busy_with_jobs(&self) -> bool {
        self.slots.iter().any(|s| s.jobs() > 0) || self.waiting.iter().any(|(_, r)| !r.is_session())
    }

    /// A worker was held to hang: every request is given twice the time from now on. It may
    /// be this machine that is slow, not the worker that is stuck; without that, a job that
    /// takes longer than its allowance here would be cut off and sent again for ever.
    pub fn hung(&mut self) {
        self.patience *= 2.0;
    }

    /// Worker `slot` died or hung and is replaced by a fresh one: its jobs wait again, first
    /// in line, and the session requests it held are returned (its sessions are lost with it).
    pub fn failed(&mut self, slot: usize) -> Vec<Request> {
        self.deaths += 1;
        self.take_back(slot)
    }

    /// No worker can run here (each died before answering anything): the pool shrinks to the
    /// one worker the thread of its owner stands in for; every job waits again, in the order
    /// asked, and the session requests its workers held are returned.
    pub fn collapse(&mut self) -> Vec<Request> {
        let mut sessions = Vec::new();
        for slot in (0..self.slots.len()).rev() {
            sessions.splice(0..0, self.take_back(slot));
        }
        // Tickets follow the order the jobs were asked in.
        self.waiting
            .make_contiguous()
            .sort_by_key(|(ticket, _)| *ticket);
        self.slots = vec![Slot::default()];
        sessions
    }

    /// Takes back what worker `slot` held: its jobs wait again, first in line; its session
    /// requests are returned, and those of the sessions' worker not sent yet with them (the
    /// fresh worker holds none of the sessions they are for: their owner asks again).
    fn take_back(&mut self, slot: usize) -> Vec<Request> {
        let lost = std::mem::take(&mut self.slots[slot].sent);
        let mut sessions = Vec::new();
        for sent in lost.into_iter().rev() {
            if sent.request.is_session() {
                sessions.push(sent.request);
            } else {
                self.waiting.push_front((sent.ticket, sent.request));
            }
        }
        sessions.reverse();
        if slot == SESSIONS {
            let (unsent, jobs): (VecDeque<_>, VecDeque<_>) = std::mem::take(&mut self.waiting)
                .into_iter()
                .partition(|(_, r)| r.is_session());
            self.waiting = jobs;
            sessions.extend(unsent.into_iter().map(|(_, r)| r));
        }
        sessions
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_collapsed_pool_is_one_worker_with_every_job_waiting_and_the_sessions_returned() {
        let mut pool = Pool::new(3);
        let grow = Request::Grow {
            session: 1,
            rows: 4,
            budget_ms: 16.0,
        };
        pool.submit(grow.clone());
        for job in 0..5 {
            pool.submit(tile(job));
        }
        let sent = pool.dispatch(0.0);
        assert_eq!(sent.len(), 6, "the session and two jobs a worker");
        assert_eq!(pool.collapse(), vec![grow]);
        assert_eq!(pool.size(), 1);
        assert_eq!(pool.in_flight(), 0);
        assert_eq!(pool.deaths(), 0, "no worker died: none could run");
        let again: Vec<Request> = pool.dispatch(1.0).into_iter().map(|s| s.request).collect();
        assert_eq!(
            again,
            vec![tile(0), tile(1)],
            "jobs wait again in their order"
        );
        for _ in 0..2 {
            let ticket = pool.slots[0].sent[0].ticket;
            pool.answered(SESSIONS, ticket, 2.0);
        }
        let rest: Vec<Request> = pool.dispatch(3.0).into_iter().map(|s| s.request).collect();
        assert_eq!(rest, vec![tile(2), tile(3)]);
    }

    fn tile(job: u32) -> Request {
        Request::Tile {
            job,
            link: "v=1&preset=stripes".into(),
            rows: 10,
        }
    }

    #[test]
    fn session_numbers_are_never_given_twice_even_after_the_pool_collapses() {
        let mut pool = Pool::new(2);
        let first = [pool.open_session(), pool.open_session()];
        pool.collapse();
        let after = pool.open_session();
        assert_eq!((first, after), ([1, 2], 3));
    }

    #[test]
    fn the_pool_is_one_worker_per_core_but_one_within_one_and_eight() {
        assert_eq!(
            [0, 1, 2, 3, 4, 9, 16, 64].map(size_for),
            [1, 1, 1, 2, 3, 8, 8, 8]
        );
    }

    #[test]
    fn jobs_go_two_per_worker_to_the_least_busy_and_the_rest_wait() {
        let mut pool = Pool::new(2);
        pool.submit(Request::Grow {
            session: 1,
            rows: 1,
            budget_ms: 12.0,
        });
        for job in 0..6 {
            pool.submit(tile(job));
        }
        let sent = pool.dispatch(0.0);
        let slots: Vec<usize> = sent.iter().map(|s| s.slot).collect();
        assert_eq!(
            slots,
            [0, 1, 0, 1, 0],
            "growth at 0, then jobs to the least busy"
        );
        assert_eq!(pool.dispatch(0.0), [], "two jobs a worker");
        let first_job = sent[1].ticket;
        assert_eq!(pool.answered(1, first_job, 5.0), Some(tile(0)));
        let next = pool.dispatch(5.0);
        assert_eq!(next.len(), 1);
        assert_eq!((next[0].slot, &next[0].request), (1, &tile(4)));
        pool.cancel(|r| matches!(r, Request::Tile { job: 5, .. }));
        pool.answered(0, sent[2].ticket, 6.0);
        assert_eq!(pool.dispatch(6.0), [], "job 5 was cancelled");
        assert_eq!(pool.answered(0, 999, 6.0), None, "a ticket never given");
    }

    #[test]
    fn a_dead_workers_jobs_are_sent_again_and_its_sessions_returned() {
        let mut pool = Pool::new(2);
        pool.submit(Request::Finish { session: 3 });
        pool.submit(tile(0));
        pool.submit(tile(1));
        let sent = pool.dispatch(0.0);
        assert_eq!(sent.iter().map(|s| s.slot).collect::<Vec<_>>(), [0, 1, 0]);
        assert_eq!(pool.overdue(14_000.0), None);
        assert_eq!(
            pool.overdue(16_000.0),
            Some(1),
            "a tile is overdue before Finish"
        );
        assert!(pool.failed(1).is_empty());
        let again = pool.dispatch(16_000.0);
        assert_eq!(
            again
                .iter()
                .map(|s| (s.slot, s.request.clone()))
                .collect::<Vec<_>>(),
            [(1, tile(0))],
            "to the fresh worker"
        );
        assert_eq!(pool.failed(0), [Request::Finish { session: 3 }]);
        assert_eq!(pool.deaths(), 2);
        assert_eq!(pool.dispatch(16_000.0)[0].request, tile(1));
        assert_eq!(pool.answered(0, sent[0].ticket, 1.0), None);
    }

    #[test]
    fn session_requests_not_sent_yet_are_lost_with_the_sessions_worker() {
        let mut pool = Pool::new(2);
        pool.submit(Request::Finish { session: 3 });
        pool.dispatch(0.0);
        pool.submit(tile(0));
        pool.submit(Request::Grow {
            session: 3,
            rows: 2,
            budget_ms: 8.0,
        });
        let lost = pool.failed(SESSIONS);
        assert_eq!(
            lost,
            [
                Request::Finish { session: 3 },
                Request::Grow {
                    session: 3,
                    rows: 2,
                    budget_ms: 8.0
                }
            ],
            "sent first, then waiting"
        );
        let again: Vec<Request> = pool.dispatch(1.0).into_iter().map(|s| s.request).collect();
        assert_eq!(
            again,
            [tile(0)],
            "the job still waits; the session's do not"
        );
    }

    #[test]
    fn a_wait_counts_from_the_last_answer() {
        let mut pool = Pool::new(1);
        for job in 0..2 {
            pool.submit(tile(job));
        }
        let sent = pool.dispatch(0.0);
        pool.answered(0, sent[0].ticket, 10_000.0);
        assert_eq!(pool.overdue(20_000.0), None, "the second started at 10 s");
        assert_eq!(pool.overdue(25_001.0), Some(0));
    }

    #[test]
    fn each_hang_doubles_the_time_every_request_is_given() {
        let mut pool = Pool::new(1);
        pool.submit(tile(0));
        pool.dispatch(0.0);
        assert_eq!(pool.overdue(15_001.0), Some(0));
        pool.hung();
        assert!(pool.failed(0).is_empty());
        pool.dispatch(15_001.0);
        assert_eq!(
            pool.overdue(45_000.0),
            None,
            "30 s from when it was sent again"
        );
        assert_eq!(pool.overdue(45_002.0), Some(0));
    }

    #[test]
    fn less_patience_holds_a_worker_to_hang_sooner() {
        let mut pool = Pool::new(1).with_patience(0.2);
        pool.submit(Request::Load {
            session: 1,
            link: "v=1&preset=stripes".into(),
        });
        pool.submit(tile(0));
        pool.dispatch(0.0);
        assert_eq!(
            pool.overdue(11_999.0),
            None,
            "a fifth of the minute to build"
        );
        assert_eq!(pool.overdue(12_001.0), Some(0));
    }
}
