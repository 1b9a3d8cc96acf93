//! The pictures the page asks of its pool and draws one a frame: the gallery's cards (asked
//! while the gallery is shown, waiting while it is not) and the tiles of a grid of shells (the
//! parameter map over a shape's parameters, breeding's offspring), each grown whole by a
//! worker as fine as its picture shows. A picture drawn just before the graphics device was
//! lost may be blank (the browser tells of a loss a little after the fact), so those drawn
//! within [`LOSS_NOTICE_MS`] of a loss are asked again. Decided here; `web/gallery.rs` draws
//! what this hands it and keeps the pictures' addresses.

use super::message::{Request, WholeShell};
use super::pool::Pool;
use crate::presets::{Preset, presets};
use crate::share::link;
use crate::spec::ShellSpec;
use crate::view::picture::{CARD_PIXELS, TILE_PIXELS, picture_spec};
use std::collections::{HashSet, VecDeque};

/// Milliseconds within which the browser is taken to report a lost device.
pub const LOSS_NOTICE_MS: f64 = 2000.0;

/// Where a picture goes: a gallery card's, or a tile of a grid of shells (the parameter map
/// over a shape's parameters, or breeding), by the tile's job number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Place {
    Card,
    /// A tile by its job number, `small` where the grid shows many (the map's 64) rather
    /// than a few large (breeding's nine).
    Tile {
        job: u32,
        small: bool,
    },
}

impl Place {
    /// Pixels across the picture as drawn.
    pub fn pixels(self) -> u32 {
        match self {
            Place::Card => CARD_PIXELS,
            Place::Tile { .. } => TILE_PIXELS,
        }
    }

    /// Whether the picture is drawn multisampled. A small tile is not: drawn at 128 pixels
    /// and shown at about 100 among 63 others, it is smoothed about as much by the browser's
    /// scaling, and one sample a pixel draws it in a third of the time on a software
    /// rasterizer. Breeding's tiles are shown larger than drawn, and multisampled.
    pub fn multisampled(self) -> bool {
        !matches!(self, Place::Tile { small: true, .. })
    }
}

/// A picture asked of the pool: where it goes, the shell and the link it is grown from, and
/// the job number it was asked with.
#[derive(Clone, Debug)]
pub struct Wanted {
    pub job: u32,
    pub place: Place,
    pub preset: &'static Preset,
    pub spec: ShellSpec,
    pub link: String,
}

/// The pictures asked, grown and drawn lately.
#[derive(Default)]
pub struct PictureQueue {
    /// The pictures not drawn yet.
    left: Vec<Wanted>,
    /// Whether the pool has been asked for the cards' since the gallery was last shown.
    asked: bool,
    /// The jobs sent to the pool (or waiting in it) and not answered yet: a card still there
    /// when the gallery is shown again is not asked twice.
    out: HashSet<u32>,
    /// Shells grown and not drawn yet.
    waiting: Vec<(Wanted, WholeShell)>,
    /// Pictures drawn within [`LOSS_NOTICE_MS`], and when.
    lately: VecDeque<(Wanted, f64)>,
    /// The job number of the next picture asked.
    next_job: u32,
    /// Since when tiles' pictures are being drawn, how many were asked, and whether they are
    /// small: the set being drawn, to time.
    tiles_since: Option<(f64, usize, bool)>,
    /// Seconds a tile's picture took, grown and drawn, over the last set of tiles drawn whole:
    /// large ones (breeding's, multisampled) first, then small ones (a map's).
    pace: [Option<f64>; 2],
}

/// The fewest tiles a set timed has: a smaller one (a generation cut short on a slow machine)
/// would share the pool's fixed costs among fewer shells, look slower still, and be cut
/// shorter the next time.
const TIMED_SET: usize = 9;

impl PictureQueue {
    /// A queue holding every preset's card.
    pub fn of_cards() -> Self {
        let mut queue = Self::default();
        for preset in presets() {
            queue.want(Place::Card, preset, &preset.spec);
        }
        queue
    }

    /// Adds the picture of `spec` (a variant of `preset`) to those to draw, its mesh as fine as
    /// a picture shows.
    fn want(&mut self, place: Place, preset: &'static Preset, spec: &ShellSpec) {
        let spec = picture_spec(spec, place.pixels());
        let link = link::encode(preset, &spec);
        self.push(place, preset, spec, link)
    }

    fn push(&mut self, place: Place, preset: &'static Preset, spec: ShellSpec, link: String) {
        let wanted = Wanted {
            job: self.next_job,
            place,
            preset,
            link,
            spec,
        };
        self.next_job = self.next_job.wrapping_add(1);
        self.left.push(wanted);
    }

    /// Asks the pool for the last picture wanted.
    fn submit_last(&mut self, pool: &mut Pool) {
        let wanted = self.left.last().expect("a picture is wanted");
        Self::submit(&mut self.out, pool, wanted);
    }

    fn submit(out: &mut HashSet<u32>, pool: &mut Pool, wanted: &Wanted) {
        out.insert(wanted.job);
        pool.submit(Request::Whole {
            job: wanted.job,
            link: wanted.link.clone(),
            pixels: wanted.place.pixels(),
        });
    }

    /// Asks the pool for the cards' pictures not drawn yet and not still asked of it (once
    /// while the gallery is shown).
    pub fn ask_cards(&mut self, pool: &mut Pool) {
        if std::mem::replace(&mut self.asked, true) {
            return;
        }
        for wanted in self.left.iter().filter(|w| w.place == Place::Card) {
            if !self.out.contains(&wanted.job) {
                Self::submit(&mut self.out, pool, wanted);
            }
        }
    }

    /// A tile's picture of `spec` (a variant of `preset`): the spec as fine as a tile shows, and
    /// the link it is grown from (a picture drawn lately from the same link can be shown at
    /// once instead of asked).
    pub fn tile_picture(preset: &'static Preset, spec: &ShellSpec) -> (ShellSpec, String) {
        let spec = picture_spec(spec, TILE_PIXELS);
        let link = link::encode(preset, &spec);
        (spec, link)
    }

    /// Asks the pool at `now` for the picture of tile `job` (`small`: one of many,
    /// [`Place::Tile`]): `picture`, the [`Self::tile_picture`] of a shell of `preset`.
    pub fn ask_tile(
        &mut self,
        job: u32,
        small: bool,
        preset: &'static Preset,
        picture: (ShellSpec, String),
        pool: &mut Pool,
        now: f64,
    ) {
        let (since, asked, _) = self.tiles_since.unwrap_or((now, 0, small));
        self.tiles_since = Some((since, asked + 1, small));
        let (spec, link) = picture;
        self.push(Place::Tile { job, small }, preset, spec, link);
        self.submit_last(pool);
    }

    /// Asks the pool again for a picture that may have been drawn blank by a lost device (a
    /// card's waits for the gallery to be shown, as the others not drawn yet).
    pub fn ask_again(&mut self, wanted: &Wanted, pool: &mut Pool) {
        self.want(wanted.place, wanted.preset, &wanted.spec);
        if wanted.place != Place::Card || self.asked {
            self.submit_last(pool);
        }
    }

    /// Whether the pool's job `job` is a picture for `place`.
    fn job_for(&self, job: u32, place: impl Fn(Place) -> bool) -> bool {
        self.left.iter().any(|w| w.job == job && place(w.place))
    }

    /// The gallery was left: the cards' pictures not yet sent to a worker wait until it is
    /// shown again.
    pub fn pause(&mut self, pool: &mut Pool) {
        let mut cancelled = Vec::new();
        pool.cancel(|r| match r {
            Request::Whole { job, .. } if self.job_for(*job, |p| p == Place::Card) => {
                cancelled.push(*job);
                true
            }
            _ => false,
        });
        for job in cancelled {
            self.out.remove(&job);
        }
        self.asked = false;
    }

    /// The grid of shells was closed or drawn anew: its tiles' pictures are drawn no more.
    pub fn drop_tiles(&mut self, pool: &mut Pool) {
        let tile = |p: Place| matches!(p, Place::Tile { .. });
        pool.cancel(|r| matches!(r, Request::Whole { job, .. } if self.job_for(*job, tile)));
        for wanted in self.left.iter().filter(|w| tile(w.place)) {
            self.out.remove(&wanted.job);
        }
        self.left.retain(|w| !tile(w.place));
        self.waiting.retain(|(w, _)| !tile(w.place));
        self.lately.retain(|(w, _)| !tile(w.place));
        self.tiles_since = None;
    }

    /// Seconds a tile's picture took, grown by the pool and drawn, over the last set of at
    /// least [`TIMED_SET`] tiles of this size (`small`: a map's; else a generation of
    /// offspring) drawn whole: how slow this machine is.
    pub fn pace(&self, small: bool) -> Option<f64> {
        self.pace[usize::from(small)]
    }

    /// Takes `seconds` as the pace a tile's picture of either size takes (a test's slow
    /// machine).
    pub fn assume_pace(&mut self, seconds: f64) {
        self.pace = [Some(seconds); 2];
    }

    /// A worker grew the shell of picture `job`: it waits to be drawn. A tile whose shell could
    /// not be grown is returned with the reason; a job no longer wanted changes nothing.
    pub fn take(&mut self, job: u32, result: Result<WholeShell, String>) -> Option<(u32, String)> {
        self.out.remove(&job);
        let at = self.left.iter().position(|w| w.job == job)?;
        let wanted = self.left.remove(at);
        match (result, wanted.place) {
            (Ok(whole), _) => {
                self.waiting.push((wanted, whole));
                None
            }
            (Err(why), Place::Tile { job, .. }) => Some((job, why)),
            (Err(_), Place::Card) => None,
        }
    }

    /// The pictures' device is not ready (lost, or being opened again): what was drawn just
    /// before may be blank, and is asked again. Returns those asked again.
    pub fn device_lost(&mut self, pool: &mut Pool) -> Vec<Wanted> {
        let lost: Vec<Wanted> = self.lately.drain(..).map(|(w, _)| w).collect();
        for wanted in &lost {
            self.ask_again(wanted, pool);
        }
        lost
    }

    /// The next shell to draw at `now`, one a frame (reading a picture back waits for the GPU,
    /// and the page answers the user between two); pictures drawn longer ago than a loss is
    /// noticed are no longer watched.
    pub fn next(&mut self, now: f64) -> Option<(Wanted, WholeShell)> {
        let noticed = now - LOSS_NOTICE_MS;
        while self.lately.front().is_some_and(|(_, at)| *at < noticed) {
            self.lately.pop_front();
        }
        self.waiting.pop()
    }

    /// `wanted` was drawn at `now`; the last tile of a set drawn times the set.
    pub fn drawn(&mut self, wanted: Wanted, now: f64) {
        let tile = |w: &Wanted| matches!(w.place, Place::Tile { .. });
        let was_tile = tile(&wanted);
        self.lately.push_back((wanted, now));
        let more = self.left.iter().any(tile) || self.waiting.iter().any(|(w, _)| tile(w));
        if was_tile
            && !more
            && let Some((since, asked, small)) = self.tiles_since.take()
            && asked >= TIMED_SET
        {
            self.pace[usize::from(small)] = Some((now - since) / 1000.0 / asked as f64);
        }
    }

    /// Whether every card's picture is drawn, and the last of them long enough ago that a
    /// lost device would have been reported.
    pub fn finished(&self) -> bool {
        let card = |w: &Wanted| w.place == Place::Card;
        !self.left.iter().any(card)
            && !self.waiting.iter().any(|(w, _)| card(w))
            && !self.lately.iter().any(|(w, _)| card(w))
    }

    /// The page's signal of the gallery's pictures (`data-pictures`): none where nothing is
    /// drawn in 3D (`draws` false), done once [`Self::finished`], else drawing.
    pub fn signal(&self, draws: bool) -> &'static str {
        if !draws {
            "none"
        } else if self.finished() {
            "done"
        } else {
            "drawing"
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::work::host::{Budget, Host};
    use crate::work::message::Reply;

    /// The whole shell of the request `job` of the pool, grown by a host.
    fn grown(pool: &mut Pool) -> Vec<(u32, Result<WholeShell, String>)> {
        let mut host = Host::default();
        for send in pool.dispatch(0.0) {
            host.push(send.ticket, send.request);
        }
        host.work(&|| 0.0, Budget::Unbounded)
            .into_iter()
            .filter_map(|(_, reply)| match reply {
                Reply::Grown { job, result } => Some((job, result)),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn cards_are_asked_once_while_the_gallery_shows_and_wait_while_it_does_not() {
        let mut queue = PictureQueue::of_cards();
        let mut pool = Pool::new(1);
        queue.ask_cards(&mut pool);
        queue.ask_cards(&mut pool);
        let asked = pool.waiting();
        assert_eq!(asked, presets().len(), "each card once");
        queue.pause(&mut pool);
        assert_eq!(pool.waiting(), 0, "cancelled while the gallery is left");
        queue.ask_cards(&mut pool);
        assert_eq!(pool.waiting(), asked, "asked again when it is shown");
        assert!(!queue.finished());
        assert_eq!(queue.signal(true), "drawing");
        assert_eq!(queue.signal(false), "none", "nothing is drawn without 3D");
        assert_eq!(PictureQueue::default().signal(true), "done");
    }

    #[test]
    fn a_card_a_worker_still_holds_when_the_gallery_is_shown_again_is_not_asked_twice() {
        let mut queue = PictureQueue::of_cards();
        let mut pool = Pool::new(1);
        queue.ask_cards(&mut pool);
        let sent = pool.dispatch(0.0);
        assert!(!sent.is_empty());
        queue.pause(&mut pool);
        queue.ask_cards(&mut pool);
        assert_eq!(pool.in_flight() + pool.waiting(), presets().len());
        // A card drawn blank by a device lost while the gallery is left waits for it (here one
        // still asked, so it is asked twice: once as it was, once again as a new picture).
        let card = queue.left[0].clone();
        queue.pause(&mut pool);
        let waiting = pool.waiting();
        queue.ask_again(&card, &mut pool);
        assert_eq!(
            pool.waiting(),
            waiting,
            "not asked while the gallery is left"
        );
        queue.ask_cards(&mut pool);
        assert_eq!(pool.in_flight() + pool.waiting(), presets().len() + 1);
        // Its answer, come while the gallery was left, is drawn.
        let mut host = Host::default();
        host.push(sent[0].ticket, sent[0].request.clone());
        let Reply::Grown { job, result } = host.work(&|| 0.0, Budget::Unbounded).remove(0).1 else {
            panic!("a card's shell is grown");
        };
        assert_eq!(queue.take(job, result), None);
        assert!(queue.next(0.0).is_some());
    }

    #[test]
    fn a_picture_drawn_just_before_a_loss_is_asked_again_and_one_drawn_long_before_is_not() {
        let mut queue = PictureQueue::default();
        let mut pool = Pool::new(1);
        let stripes = crate::presets::preset("stripes").unwrap();
        let picture = || PictureQueue::tile_picture(stripes, &stripes.spec);
        queue.ask_tile(3, true, stripes, picture(), &mut pool, 0.0);
        queue.ask_tile(4, true, stripes, picture(), &mut pool, 0.0);
        for (job, result) in grown(&mut pool) {
            assert_eq!(queue.take(job, result), None);
        }
        let (first, _) = queue.next(0.0).expect("grown");
        queue.drawn(first, 0.0);
        let (second, _) = queue.next(LOSS_NOTICE_MS + 1.0).expect("grown");
        queue.drawn(second.clone(), LOSS_NOTICE_MS + 1.0);
        // The first was drawn long enough ago to be watched no more.
        let again = queue.device_lost(&mut pool);
        assert_eq!(again.len(), 1);
        assert_eq!(again[0].place, second.place);
        assert_eq!(pool.waiting(), 1, "asked again of the pool");
        queue.drop_tiles(&mut pool);
        assert_eq!(pool.waiting(), 0, "a grid closed draws no more");
        assert!(queue.next(0.0).is_none());
    }

    #[test]
    fn a_set_of_tiles_drawn_whole_times_this_machine_and_a_small_or_dropped_one_does_not() {
        let mut queue = PictureQueue::default();
        // A worker for each picture: every one is grown at once.
        let mut pool = Pool::new(32);
        let shells: Vec<_> = presets()
            .iter()
            .filter(|p| p.group == crate::presets::Group::Shapes)
            .take(TIMED_SET)
            .collect();
        assert_eq!(shells.len(), TIMED_SET);
        let ask = |queue: &mut PictureQueue, pool: &mut Pool, from: u32, small, n, now| {
            for (i, p) in shells.iter().take(n).enumerate() {
                let picture = PictureQueue::tile_picture(p, &p.spec);
                queue.ask_tile(from + i as u32, small, p, picture, pool, now);
            }
        };
        let draw_all = |queue: &mut PictureQueue, pool: &mut Pool, from: f64| {
            for (job, result) in grown(pool) {
                assert_eq!(queue.take(job, result), None);
            }
            let mut at = from;
            while let Some((wanted, _)) = queue.next(at) {
                queue.drawn(wanted, at);
                at += 1000.0;
            }
        };
        ask(&mut queue, &mut pool, 0, true, TIMED_SET, 0.0);
        draw_all(&mut queue, &mut pool, 1000.0);
        assert_eq!(queue.pace(true), Some(1.0), "9 small pictures in 9 s");
        assert_eq!(queue.pace(false), None, "the large ones are timed apart");
        // A generation cut short (three offspring) is not timed: it would look slower.
        ask(&mut queue, &mut pool, 100, false, 3, 20_000.0);
        draw_all(&mut queue, &mut pool, 50_000.0);
        assert_eq!(queue.pace(false), None);
        // A set dropped before it is whole is not timed with the next.
        ask(&mut queue, &mut pool, 200, false, TIMED_SET, 60_000.0);
        queue.drop_tiles(&mut pool);
        ask(&mut queue, &mut pool, 300, false, TIMED_SET, 100_000.0);
        draw_all(&mut queue, &mut pool, 101_000.0);
        assert_eq!(
            queue.pace(false),
            Some(1.0),
            "the last drawn 9 s after its ask"
        );
        queue.assume_pace(5.0);
        assert_eq!(
            (queue.pace(true), queue.pace(false)),
            (Some(5.0), Some(5.0))
        );
    }

    #[test]
    fn a_tile_that_cannot_grow_says_why_and_a_job_no_longer_wanted_changes_nothing() {
        let mut queue = PictureQueue::default();
        let mut pool = Pool::new(1);
        let stripes = crate::presets::preset("stripes").unwrap();
        let picture = PictureQueue::tile_picture(stripes, &stripes.spec);
        queue.ask_tile(7, false, stripes, picture, &mut pool, 0.0);
        assert_eq!(queue.take(0, Err("no".into())), Some((7, "no".to_string())));
        assert_eq!(queue.take(0, Err("again".into())), None, "taken once");
        assert_eq!(queue.take(99, Err("never asked".into())), None);
    }
}
