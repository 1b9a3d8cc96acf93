//! A shell grown on a worker, as the page holds it: its copy ([`Replica`]), the link the worker
//! grows it from, the requests of its session not yet answered and whether growth to the end
//! was asked. It takes the workers' replies in whatever order they come and says what changed;
//! what must be asked of the workers in turn (the pieces of a shell that splits, the session
//! again on a fresh worker) it hands to `send`. The viewer runs one on the page, and
//! `tests/workers.rs` runs the same one against workers simulated natively.

use super::message::{Reply, Request, ShellInfo};
use super::replica::Replica;
use crate::generator::Advance;

/// What a reply changed.
pub enum Took {
    /// Nothing of this shell: a reply of another session, another link's pieces, pieces still
    /// waiting for the rest, or a worker saying its shell stands where the page's copy does.
    Nothing,
    /// The worker built the shell: what it is, and its first step.
    Loaded(ShellInfo, Advance),
    /// Growth moved on by this.
    Advanced(Advance),
    /// A pattern preview's rows, for the viewer's preview.
    Previewed(Box<Reply>),
}

/// A shell grown on a worker under one session number.
pub struct GrowthSession {
    /// The link its worker grows it from (in the material it was loaded with: a restyle does
    /// not change what the worker grows); empty for a shell grown whole elsewhere.
    link: String,
    replica: Replica,
    /// Requests of this session sent and not yet answered.
    pending: usize,
    /// Whether growth to the end was asked for.
    finishing: bool,
}

impl GrowthSession {
    /// Asks a worker to build the shell of `link` under `session`.
    pub fn load(session: u32, link: String, send: &mut dyn FnMut(Request)) -> Self {
        send(Request::Load {
            session,
            link: link.clone(),
        });
        Self {
            link,
            replica: Replica::new(session),
            pending: 1,
            finishing: false,
        }
    }

    /// A shell already grown whole (a gallery picture): nothing is asked of a worker.
    pub fn whole(replica: Replica) -> Self {
        Self {
            link: String::new(),
            replica,
            pending: 0,
            finishing: false,
        }
    }

    /// The page's copy of the shell.
    pub fn replica(&self) -> &Replica {
        &self.replica
    }

    /// The link its worker grows it from.
    pub fn link(&self) -> &str {
        &self.link
    }

    /// Whether the shell stands where its worker left it, nothing asked of it unanswered.
    pub fn settled(&self) -> bool {
        self.pending == 0 && self.replica.shell().is_some()
    }

    /// Whether more growth may be asked for: not finishing, not done.
    pub fn grows_on(&self) -> bool {
        !self.finishing && !self.replica.is_done()
    }

    /// Asks the worker to grow up to `rows` rows, stopping early when `budget_ms` has passed;
    /// false (and nothing sent) when growth is finishing or done.
    pub fn grow(&mut self, rows: u32, budget_ms: f64, send: &mut dyn FnMut(Request)) -> bool {
        if !self.grows_on() {
            return false;
        }
        send(Request::Grow {
            session: self.replica.session(),
            rows,
            budget_ms,
        });
        self.pending += 1;
        true
    }

    /// Asks the worker to grow the rest at once (what splits is shared among the pool when it
    /// answers); false (and nothing sent) when that was asked already or growth is done.
    pub fn finish(&mut self, send: &mut dyn FnMut(Request)) -> bool {
        if !self.grows_on() {
            return false;
        }
        send(Request::Finish {
            session: self.replica.session(),
        });
        self.pending += 1;
        self.finishing = true;
        true
    }

    /// Takes in a worker's `reply` to `request`. A shell that splits has its pieces asked of
    /// the pool through `send`. Fails with the words to show when the shell cannot be built
    /// or grown, or a worker's copy no longer agrees with the page's.
    pub fn take(
        &mut self,
        request: &Request,
        reply: Reply,
        send: &mut dyn FnMut(Request),
    ) -> Result<Took, String> {
        let session = self.replica.session();
        let ours = |s: u32| s == session;
        let advance = match reply {
            Reply::Loaded {
                session,
                shell,
                delta,
            } if ours(session) => {
                self.answered()?;
                let advance = self
                    .replica
                    .loaded(shell.clone(), delta)
                    .map_err(|e| e.to_string())?;
                return Ok(Took::Loaded(shell, advance));
            }
            Reply::Refused { session, message } if ours(session) => return Err(message),
            Reply::Grew { session, delta } if ours(session) => {
                self.answered()?;
                self.replica.apply(delta).map_err(|e| e.to_string())?
            }
            Reply::Apart {
                session,
                delta,
                pieces,
                hash,
            } if ours(session) => {
                self.answered()?;
                for (group, ids) in pieces.groups.iter().enumerate() {
                    send(Request::Pieces {
                        job: group as u32,
                        link: self.link.clone(),
                        step: pieces.step,
                        ids: ids.clone(),
                    });
                }
                self.replica
                    .apart(delta, pieces, hash)
                    .map_err(|e| e.to_string())?
            }
            Reply::Resumed {
                session,
                vertices,
                indices,
            } if ours(session) => {
                self.answered()?;
                let mesh = self.replica.mesh();
                if (vertices as usize, indices as usize)
                    != (mesh.vertices.len(), mesh.indices.len())
                {
                    return Err("a worker grew the shell again to another mesh".into());
                }
                return Ok(Took::Nothing);
            }
            reply @ Reply::Previewed { .. } => return Ok(Took::Previewed(Box::new(reply))),
            Reply::Made { job, mesh, hash } => {
                let Request::Pieces { link, .. } = request else {
                    return Ok(Took::Nothing);
                };
                if *link != self.link {
                    return Ok(Took::Nothing);
                }
                match self.replica.made(job as usize, mesh, hash) {
                    Some(advance) => advance,
                    None => return Ok(Took::Nothing),
                }
            }
            _ => return Ok(Took::Nothing),
        };
        Ok(Took::Advanced(advance))
    }

    /// One request of the session answered. An answer to nothing asked is refused in words:
    /// counted, it would leave the shell owing answers for ever (the count wraps in a release
    /// build), and so never settled, never grown on.
    fn answered(&mut self) -> Result<(), String> {
        self.pending = self
            .pending
            .checked_sub(1)
            .ok_or("a worker answered more than the page asked of it")?;
        Ok(())
    }

    /// The worker holding the shell was replaced, losing `lost` unanswered (its requests and
    /// those of shells left before it): through `send`, the shell is built again on the fresh
    /// one, or grown again to where the page's copy stands, and finished if that was asked of
    /// it. A shell whose growth is done or whose pieces
    /// are being made (the pool asks those again itself) needs nothing. Called once every
    /// reply the lost worker sent before it died is taken in: the copy must stand where the
    /// worker last said it did.
    pub fn resume(&mut self, lost: &[Request], send: &mut dyn FnMut(Request)) {
        let session = self.replica.session();
        self.pending = 0;
        if self.replica.shell().is_none() {
            send(Request::Load {
                session,
                link: self.link.clone(),
            });
        } else if self.replica.pieces().is_none() && !self.replica.is_done() {
            send(Request::Resume {
                session,
                link: self.link.clone(),
                rows: self.replica.rows_done() as u32,
                steps: self.replica.steps_done() as u32,
            });
        } else {
            return;
        }
        self.pending = 1;
        let finish_lost = lost
            .iter()
            .any(|r| matches!(r, Request::Finish { session: s } if *s == session));
        if self.finishing || finish_lost {
            send(Request::Finish { session });
            self.pending += 1;
            // No growth is asked after a Finish: its worker would grow a shell it holds whole.
            self.finishing = true;
        }
    }
}
