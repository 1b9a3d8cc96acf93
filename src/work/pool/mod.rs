//! How the page shares requests out among its workers: the requests of a session go to the
//! worker that holds sessions (the first), jobs to whichever worker has fewest waiting (at most
//! [`JOBS_PER_WORKER`] each, so every worker has its next job at hand when it finishes one,
//! and a job can still be cancelled before it is sent). Every request sent is remembered until
//! its reply comes, so that when a worker dies or hangs (no reply within the request's
//! allowance) its jobs are sent again, and the session's owner learns what it lost.
//! What the pool makes of its workers' events (replies, deaths, hangs, giving them up) is
//! [`Pool::take_events`] (`events.rs`); which requests go where, `dispatch.rs`.

mod dispatch;
mod events;
mod plan;

pub use dispatch::{JOBS_PER_WORKER, Pool, SESSIONS, Send, size_for};
pub use events::{Polled, Replaced, WorkerEvent};
pub use plan::{Faults, PoolPlan, given_up_status, local_status};
