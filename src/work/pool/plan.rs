//! The pool a page starts with, read from its address's query: how many workers (one per
//! core but the page's own, at most eight; `workers=N` sets another number, for tests and
//! benchmarks, `workers=0` none), the least time a worker grows the shell per request
//! (`grow-budget=N`, for benchmarks), and, test-only, workers that fail: `crash-workers=N`
//! makes the first N started throw on their first request, and `hang-workers=N` the next N
//! spin forever on theirs without answering (see `www/worker.js`). With `hang-workers` a worker
//! is held to hang after a fifth of each request's allowance (3 s for a step or a job, 12 s for
//! building or regrowing a shell), so that a page test finds it out in seconds. The status
//! line's words for where the shells grow are here too.

use super::dispatch::size_for;

/// The most workers a pool has, whatever the query asks.
const MOST_WORKERS: usize = 8;
/// Least milliseconds a worker grows the shell per request: off the page's thread a request
/// may take longer than the page's own frame budget, for fewer round trips, while a change of
/// value still waits at most this long behind the growth under way (see "Who runs where" in
/// `docs/design/architecture.md` for the measurement).
const WORKER_GROWTH_MS: f64 = 24.0;
/// The share of each request's allowance a worker gets under the `hang-workers` switch.
const TEST_PATIENCE: f64 = 0.2;

/// Workers left to start that fail on their first request (test-only): first those that
/// throw, then those that hang.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Faults {
    throws: usize,
    hangs: usize,
}

impl Faults {
    /// The name of the next worker to start: one `www/worker.js` makes fail, or its own.
    pub fn next_name(&mut self) -> &'static str {
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

/// The pool to start.
#[derive(Clone, Debug, PartialEq)]
pub struct PoolPlan {
    /// Workers to start; none: the pool's owner's thread grows the shells.
    pub size: usize,
    pub faults: Faults,
    /// The share of each request's allowance a worker gets before it is held to hang.
    pub patience: f64,
    /// Least milliseconds a worker grows the shell per request.
    pub worker_growth_ms: f64,
}

impl PoolPlan {
    /// The plan for a machine of `cores` logical processors, as the query (read by `query`)
    /// changes it; a value that is not a count is ignored.
    pub fn from_query(query: impl Fn(&str) -> Option<String>, cores: usize) -> Self {
        let number = |key: &str| query(key).and_then(|v| v.parse::<usize>().ok());
        let faults = Faults {
            throws: number("crash-workers").unwrap_or(0),
            hangs: number("hang-workers").unwrap_or(0),
        };
        Self {
            size: number("workers")
                .unwrap_or_else(|| size_for(cores))
                .min(MOST_WORKERS),
            faults,
            patience: if faults.hangs > 0 { TEST_PATIENCE } else { 1.0 },
            worker_growth_ms: number("grow-budget").map_or(WORKER_GROWTH_MS, |ms| ms as f64),
        }
    }

    /// The status line where the plan's workers grow the shells.
    pub fn status(&self) -> String {
        format!(
            "Growing on {} worker{}.",
            self.size,
            if self.size == 1 { "" } else { "s" }
        )
    }
}

/// The status line where the thread `thread` (the page's, or the drawing worker's own) grows
/// the shells instead of workers, and why.
pub fn local_status(thread: &str, why: &str) -> String {
    format!("Growing on {thread}: {why}.")
}

/// The status line once the pool has given its workers up (each stopped before answering,
/// the last for `why`) and `thread` grows the shells.
pub fn given_up_status(thread: &str, why: &str) -> String {
    local_status(
        thread,
        &format!("workers could not run here (each stopped before answering: {why})"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(query: &[(&str, &str)], cores: usize) -> PoolPlan {
        PoolPlan::from_query(
            |key| {
                query
                    .iter()
                    .find(|(k, _)| *k == key)
                    .map(|(_, v)| v.to_string())
            },
            cores,
        )
    }

    #[test]
    fn a_worker_per_core_but_the_pages_and_at_most_eight_whatever_is_asked() {
        assert_eq!(plan(&[], 4).size, 3);
        assert_eq!(plan(&[], 1).size, 1);
        assert_eq!(plan(&[], 32).size, 8);
        assert_eq!(plan(&[("workers", "2")], 16).size, 2);
        assert_eq!(plan(&[("workers", "0")], 16).size, 0);
        assert_eq!(plan(&[("workers", "64")], 16).size, 8);
        assert_eq!(plan(&[("workers", "many")], 4).size, 3, "not a count");
        assert_eq!(plan(&[], 4).status(), "Growing on 3 workers.");
        assert_eq!(
            plan(&[("workers", "1")], 4).status(),
            "Growing on 1 worker."
        );
        assert_eq!(
            local_status("the page's thread", "workers are off"),
            "Growing on the page's thread: workers are off."
        );
        assert_eq!(
            given_up_status("the drawing worker's own thread", "it threw"),
            "Growing on the drawing worker's own thread: workers could not run here (each \
             stopped before answering: it threw)."
        );
    }

    #[test]
    fn failing_workers_throw_first_then_hang_and_hangs_are_found_out_sooner() {
        let mut p = plan(&[("crash-workers", "1"), ("hang-workers", "2")], 4);
        assert_eq!(p.patience, TEST_PATIENCE);
        let names: Vec<_> = (0..5).map(|_| p.faults.next_name()).collect();
        assert_eq!(
            names,
            [
                "seashells-throw",
                "seashells-hang",
                "seashells-hang",
                "seashells",
                "seashells"
            ]
        );
        let quiet = plan(&[("crash-workers", "3")], 4);
        assert_eq!(
            quiet.patience, 1.0,
            "a worker that throws is found out at once"
        );
        assert_eq!(quiet.worker_growth_ms, WORKER_GROWTH_MS);
        assert_eq!(plan(&[("grow-budget", "80")], 4).worker_growth_ms, 80.0);
    }
}
