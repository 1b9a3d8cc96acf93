//! What the pool makes of its workers' events, once a frame: the replies of a worker since
//! replaced are dropped (each worker has a generation, and a fresh one the next); a reply too
//! big to take in with the frame that read it waits, with everything after it, for the next
//! (see [`crate::view::draw_pacing`]); a worker that threw, sent bytes nobody can read, or
//! kept a request past its allowance is replaced (what it sent after is dropped), its jobs
//! sent again and the sessions it held handed back; and when workers keep dying before any of them has answered, they cannot
//! run here, and the pool gives them up for its owner's thread. The web runner only moves the
//! messages and starts the workers this says to start.

use super::dispatch::{Pool, SESSIONS};
use crate::work::message::{Reply, Request};
use crate::work::wire::WireError;

/// Workers beyond the pool's size that may die before any has answered before the pool takes
/// workers for unable to run here (the page tests make the first two fail on purpose).
pub const NEVER_ANSWERED_SPARE: usize = 2;

/// Something one of the pool's workers did, as its owner heard of it.
#[derive(Debug)]
pub enum WorkerEvent {
    /// A reply of worker `slot` in `generation`, read from its bytes when it came (or why it
    /// could not be read); `heavy` when it was read from more than
    /// [`crate::view::draw_pacing::HEAVY_BYTES`] and is to be taken in a frame later.
    Reply {
        slot: usize,
        generation: u32,
        reply: Box<Result<(u32, Reply), WireError>>,
        heavy: bool,
    },
    /// Worker `slot` of `generation` threw, for this reason.
    Died {
        slot: usize,
        generation: u32,
        why: String,
    },
}

/// A worker that died or hung and was replaced.
#[derive(Clone, Debug, PartialEq)]
pub struct Replaced {
    /// Workers replaced since the pool began.
    pub deaths: usize,
    /// Why this one was, in words.
    pub why: String,
    /// The status line, when the workers were given up for the owner's thread instead.
    pub given_up: Option<String>,
}

impl Replaced {
    /// The status line's words: none the first time (a worker's death is rare enough to redo
    /// its work silently once), the count and the cause from the second; where the shells
    /// grow now, once the workers are given up.
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

/// "second", "third", … for the status line.
fn ordinal(n: usize) -> String {
    match n {
        2 => "second".into(),
        3 => "third".into(),
        n => format!("{n}th"),
    }
}

/// What came of the events taken in a frame.
#[derive(Debug, Default)]
pub struct Polled {
    /// Replies with the requests they answer, in the order they came.
    pub replies: Vec<(Request, Reply)>,
    /// Whether the worker holding the sessions was replaced: its shells are gone with it, and
    /// these of its requests were lost unanswered. Its replies that came before it died are
    /// among [`Self::replies`], and must be taken in first (see
    /// [`crate::work::viewer_state::ViewerState::take_all`]).
    pub sessions_lost: Option<Vec<Request>>,
    /// The last worker replaced in this frame, if any.
    pub replaced: Option<Replaced>,
    /// Workers to start afresh: their slot, their generation, and why the one before was
    /// replaced.
    pub start: Vec<(usize, u32, String)>,
    /// Why the workers were given up (each died before any answered): the pool is one worker
    /// now, which its owner's thread stands in for.
    pub given_up: Option<String>,
}

impl Pool {
    /// The generation of worker `slot` (each replacement is the next).
    pub fn generation(&self, slot: usize) -> u32 {
        self.slots.get(slot).map_or(0, |s| s.generation)
    }

    /// Takes in `events` in the order they came, at `now`: the replies of current workers,
    /// the deaths, and the workers that kept a request too long. A heavy reply not yet waited
    /// for stays in `events`, with all that came after it, for the next frame.
    pub fn take_events(&mut self, events: &mut Vec<WorkerEvent>, now: f64) -> Polled {
        let mut polled = Polled::default();
        let mut dead: Vec<(usize, String)> = Vec::new();
        let mut rest = std::mem::take(events).into_iter();
        while let Some(mut event) = rest.next() {
            if let WorkerEvent::Reply { heavy, .. } = &mut event
                && std::mem::take(heavy)
            {
                // Read in this frame's time: taken in, with all that came after it, in the
                // next.
                *events = std::iter::once(event).chain(rest).collect();
                break;
            }
            match event {
                WorkerEvent::Reply {
                    slot,
                    generation,
                    reply,
                    ..
                } => {
                    // A worker being replaced says nothing more: what it answered after a
                    // reply that could not be read would continue a copy that never took
                    // that reply in.
                    let replacing = dead.iter().any(|(s, _)| *s == slot);
                    if self.generation(slot) != generation || replacing {
                        continue;
                    }
                    match *reply {
                        Err(_) => dead.push((slot, "its reply could not be read".into())),
                        Ok((ticket, reply)) => {
                            self.answered_any = true;
                            if let Some(request) = self.answered(slot, ticket, now) {
                                polled.replies.push((request, reply));
                            }
                        }
                    }
                }
                WorkerEvent::Died {
                    slot,
                    generation,
                    why,
                } => {
                    if self.generation(slot) == generation {
                        dead.push((slot, why));
                    }
                }
            }
        }
        if let Some(slot) = self.overdue(now) {
            self.hung();
            dead.push((slot, "it did not answer in time".into()));
        }
        let mut replaced_slots = Vec::new();
        for (slot, why) in dead {
            if replaced_slots.contains(&slot) {
                continue;
            }
            replaced_slots.push(slot);
            let lost = self.failed(slot);
            if slot == SESSIONS {
                polled.sessions_lost = Some(lost);
            }
            self.slots[slot].generation += 1;
            polled
                .start
                .push((slot, self.slots[slot].generation, why.clone()));
            polled.replaced = Some(Replaced {
                deaths: self.deaths,
                why,
                given_up: None,
            });
        }
        if !self.answered_any && self.deaths > self.slots.len() + NEVER_ANSWERED_SPARE {
            let mut lost = self.collapse();
            if let Some(earlier) = polled.sessions_lost.take() {
                lost.splice(0..0, earlier);
            }
            polled.sessions_lost = Some(lost);
            polled.start.clear();
            polled.given_up = Some(polled.replaced.take().map_or_else(String::new, |r| r.why));
            events.clear();
        }
        polled
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn load() -> Request {
        Request::Load {
            session: 1,
            link: "v=1&preset=stripes".into(),
        }
    }

    fn reply(slot: usize, generation: u32, ticket: u32, heavy: bool) -> WorkerEvent {
        WorkerEvent::Reply {
            slot,
            generation,
            reply: Box::new(Ok((
                ticket,
                Reply::Refused {
                    session: 1,
                    message: format!("ticket {ticket}"),
                },
            ))),
            heavy,
        }
    }

    fn died(slot: usize, generation: u32) -> WorkerEvent {
        WorkerEvent::Died {
            slot,
            generation,
            why: "it threw".into(),
        }
    }

    #[test]
    fn a_dead_sessions_worker_is_started_afresh_after_its_replies_are_in() {
        let mut pool = Pool::new(1);
        pool.submit(load());
        pool.submit(load());
        let sent = pool.dispatch(0.0);
        let mut events = vec![reply(0, 0, sent[0].ticket, false), died(0, 0)];
        let polled = pool.take_events(&mut events, 1.0);
        assert_eq!(polled.replies.len(), 1, "the reply before its death is in");
        assert_eq!(polled.sessions_lost, Some(vec![load()]));
        assert_eq!(polled.start, vec![(0, 1, "it threw".to_string())]);
        assert_eq!(polled.replaced.map(|r| r.deaths), Some(1));
        assert!(events.is_empty());
        // A late reply of the worker replaced changes nothing.
        let mut late = vec![reply(0, 0, sent[1].ticket, false), died(0, 0)];
        let polled = pool.take_events(&mut late, 2.0);
        assert!(polled.replies.is_empty() && polled.start.is_empty());
        assert_eq!(pool.deaths(), 1);
    }

    #[test]
    fn what_a_worker_sends_after_bytes_nobody_can_read_is_dropped_with_it() {
        let mut pool = Pool::new(1);
        pool.submit(load());
        pool.submit(load());
        let sent = pool.dispatch(0.0);
        let garbled = WorkerEvent::Reply {
            slot: 0,
            generation: 0,
            reply: Box::new(crate::work::message::decode_reply(&[])),
            heavy: false,
        };
        let mut events = vec![garbled, reply(0, 0, sent[1].ticket, false)];
        let polled = pool.take_events(&mut events, 1.0);
        assert!(polled.replies.is_empty());
        assert_eq!(polled.sessions_lost, Some(vec![load(), load()]));
        assert_eq!(polled.start.len(), 1);
    }

    #[test]
    fn a_heavy_reply_and_what_follows_it_wait_a_frame() {
        let mut pool = Pool::new(1);
        for _ in 0..3 {
            pool.submit(load());
        }
        let sent = pool.dispatch(0.0);
        let mut events: Vec<WorkerEvent> = sent
            .iter()
            .enumerate()
            .map(|(i, s)| reply(0, 0, s.ticket, i == 1))
            .collect();
        assert_eq!(pool.take_events(&mut events, 1.0).replies.len(), 1);
        assert_eq!(events.len(), 2, "the heavy one and the one after it wait");
        assert_eq!(pool.take_events(&mut events, 2.0).replies.len(), 2);
        assert!(events.is_empty());
    }

    #[test]
    fn a_worker_that_keeps_a_request_too_long_is_replaced_once() {
        let mut pool = Pool::new(2);
        pool.submit(load());
        pool.dispatch(0.0);
        let mut events = vec![died(0, 0)];
        let polled = pool.take_events(&mut events, 1e9);
        assert_eq!(polled.start.len(), 1, "dead and overdue, replaced once");
        assert_eq!(pool.deaths(), 1);
        assert_eq!(pool.generation(0), 1);
    }

    #[test]
    fn workers_that_all_die_before_answering_are_given_up_for_the_owners_thread() {
        let mut pool = Pool::new(2);
        pool.submit(load());
        pool.dispatch(0.0);
        let mut given_up = None;
        for round in 0..3 {
            let mut events = vec![died(0, round), died(1, round)];
            let polled = pool.take_events(&mut events, 1.0);
            if polled.given_up.is_some() {
                assert_eq!(polled.sessions_lost, Some(vec![]));
                assert!(polled.start.is_empty(), "no worker is started again");
                given_up = Some(round);
                break;
            }
        }
        assert_eq!(given_up, Some(2), "after the pool's size and two more");
        assert_eq!(pool.size(), 1);
    }

    #[test]
    fn a_pool_that_answered_once_never_gives_its_workers_up() {
        let mut pool = Pool::new(1);
        pool.submit(load());
        let sent = pool.dispatch(0.0);
        let mut events = vec![reply(0, 0, sent[0].ticket, false)];
        pool.take_events(&mut events, 1.0);
        for generation in 0..10 {
            let mut events = vec![died(0, generation)];
            assert!(pool.take_events(&mut events, 2.0).given_up.is_none());
        }
        assert_eq!(pool.deaths(), 10);
    }

    #[test]
    fn the_status_line_says_a_death_from_the_second() {
        let replaced = |deaths| Replaced {
            deaths,
            why: "it threw".into(),
            given_up: None,
        };
        assert_eq!(replaced(1).words(), None);
        assert_eq!(
            replaced(3).words().as_deref(),
            Some(
                "A worker stopped (it threw) for the third time; it was replaced and its work done again."
            )
        );
    }
}
