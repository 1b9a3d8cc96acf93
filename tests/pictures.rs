//! Pictures of shells (the parameter map's and breeding's tiles, drawn as the gallery's cards
//! are) drawn by the core's [`PictureDrawer`] while the browser takes the graphics device away
//! at any moment (between two pictures, or while one is drawn; a WebGPU device, or a WebGL
//! context that comes back or not), on a simulated screen, with the shells grown whole by the
//! real pool and hosts (`simulated_workers.rs`): once the faults are over, every tile shows a
//! picture, and none shows or keeps one drawn blank.

use crate::simulated_workers::Workers;
use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use seashells_core::generator::Advance;
use seashells_core::presets::preset;
use seashells_core::share::presentation::Layout;
use seashells_core::view::recording::FrameAsk;
use seashells_core::work::device_survival::{Loss, RESTORE_WAIT_MS};
use seashells_core::work::message::{Reply, Request};
use seashells_core::work::picture_drawer::PictureDrawer;
use seashells_core::work::picture_queue::{LOSS_NOTICE_MS, PictureQueue, Place};
use seashells_core::work::screen::Screen;
use seashells_core::work::viewer_state::Growing;
use std::collections::{HashMap, HashSet};

/// The page's frame interval, milliseconds.
const FRAME_MS: f64 = 16.7;

/// A screen whose device the test takes away; each picture read is numbered, and those the
/// loss spoiled are remembered.
#[derive(Default)]
struct PictureScreen {
    frame: u64,
    lost: Option<Loss>,
    /// The frame an opening is answered in.
    opening: Option<u64>,
    /// The read that loses the device as it is drawn, if any.
    lose_at_read: Option<u32>,
    reads: u32,
    /// Pictures read this frame and the last: a device lost now may not have finished them.
    recent: Vec<u32>,
    blank: HashSet<u32>,
    size: (u32, u32),
    reopened: usize,
}

impl PictureScreen {
    /// The browser takes the device away: pictures not yet finished are blank.
    fn lose(&mut self, webgl: bool) {
        self.lost = Some(Loss {
            reason: "taken by the test".into(),
            restored: false,
            webgl,
        });
        self.blank.extend(self.recent.iter().copied());
    }
}

impl Screen for PictureScreen {
    type Video = ();
    type Canvas = ();
    type Picture = u32;

    fn backend(&self) -> Option<&'static str> {
        Some("simulated")
    }
    fn load(&mut self, _: &Growing) {}
    fn look(&mut self, _: &Growing) {}
    fn upload(&mut self, _: &Growing, _: &Advance) -> usize {
        0
    }
    fn grew(&mut self, _: &Growing) {}
    fn set_background(&mut self, _: [u8; 3]) {}
    fn failure(&mut self) -> Option<String> {
        None
    }
    fn lost(&self) -> Option<Loss> {
        self.lost.clone()
    }
    fn open_again(&mut self) {
        self.opening = Some(self.frame + 2);
    }
    fn open_on(&mut self, (): ()) {
        self.opening = Some(self.frame + 2);
    }
    fn opened(&mut self) -> Option<Result<(), String>> {
        self.opening.take_if(|at| *at <= self.frame)?;
        self.lost = None;
        self.reopened += 1;
        Some(Ok(()))
    }
    fn ready(&self) -> bool {
        true
    }
    fn flush(&mut self) {}
    fn size(&self) -> (u32, u32) {
        self.size
    }
    fn resize(&mut self, size: (u32, u32)) {
        self.size = size;
    }
    fn draw(&mut self, _: &Growing, _: Layout) -> Result<(), String> {
        Ok(())
    }
    fn video(&mut self, _: &FrameAsk) -> Result<(), String> {
        Ok(())
    }
    fn release(&mut self, (): ()) {}
    fn multisample(&mut self, _: bool) {}
    fn picture(&mut self) -> Result<u32, String> {
        let read = self.reads;
        self.reads += 1;
        if self.lose_at_read == Some(read) {
            self.lose(read.is_multiple_of(2));
        }
        if self.lost.is_some() {
            self.blank.insert(read);
        }
        self.recent.push(read);
        Ok(read)
    }
}

/// Whether `picture` was drawn blank.
fn screen_blank(drawer: &PictureDrawer<PictureScreen>, picture: &u32) -> bool {
    drawer.screen().blank.contains(picture)
}

/// Cheap shells of each kind of growth, each a tile.
const TILES: [&str; 6] = [
    "stripes",
    "ca-waves",
    "kawaguchi-horn",
    "kawaguchi-coral",
    "turbinate",
    "oliva-porphyria",
];

/// Draws the tiles with faults drawn from `seed` over the first `faulty` frames; returns the
/// renderers opened again. Fails with what a tile shows wrongly.
fn tiles(seed: u64, faulty: u64) -> Result<usize, String> {
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut workers = Workers::new(2);
    let mut drawer = PictureDrawer::new(PictureScreen::default(), 0.0);
    for (job, id) in TILES.iter().enumerate() {
        let p = preset(id).expect("a preset");
        let picture = PictureQueue::tile_picture(p, &p.spec);
        (drawer.queue_mut()).ask_tile(job as u32, false, p, picture, &mut workers.pool, 0.0);
    }
    // The picture each tile shows, and the pictures kept by link to be shown again at once
    // (as the page keeps them, `work::recent_pictures`).
    let mut shown: HashMap<u32, u32> = HashMap::new();
    let mut kept: HashMap<String, u32> = HashMap::new();
    let mut now = 0.0;
    for frame in 1..20_000u64 {
        now += FRAME_MS;
        let screen = drawer.screen_mut();
        screen.frame = frame;
        if frame.is_multiple_of(2) {
            screen.recent.clear();
        }
        if frame < faulty {
            match rng.next_u32() % 40 {
                0 => screen.lose(rng.next_u32().is_multiple_of(2)),
                1 => screen.lose_at_read = Some(screen.reads + rng.next_u32() % 3),
                2 => {
                    if let Some(lost) = &mut screen.lost {
                        lost.restored = true;
                    }
                }
                _ => {}
            }
        }
        for (request, reply) in workers.poll(frame, now, &mut rng).replies {
            if let (Request::Whole { job, .. }, Reply::Grown { result, .. }) = (request, reply) {
                drawer.queue_mut().take(job, result);
            }
        }
        let lost = drawer.screen().lost.is_some();
        let drew = drawer.work(now, &mut workers.pool, || Some(()));
        let job = |place| match place {
            Place::Tile { job, .. } => job,
            Place::Card => panic!("no card was asked for"),
        };
        for wanted in drew.forgotten {
            kept.remove(&wanted.link);
        }
        if let Some((wanted, picture)) = drew.drawn {
            shown.insert(job(wanted.place), picture);
            kept.insert(wanted.link, picture);
        }
        // A loss seen at the frame's start forgets every picture it may have spoiled.
        if lost && let Some((link, _)) = kept.iter().find(|(_, p)| screen_blank(&drawer, p)) {
            return Err(format!(
                "{link}, drawn blank, is still kept after the loss was seen"
            ));
        }
        workers.dispatch(now)?;
        workers.work(frame, f64::INFINITY, 0, &mut rng);
        let settled = now > (faulty as f64) * FRAME_MS + RESTORE_WAIT_MS + LOSS_NOTICE_MS;
        if settled && shown.len() == TILES.len() && drawer.screen().lost.is_none() {
            for (job, picture) in &shown {
                if drawer.screen().blank.contains(picture) {
                    return Err(format!(
                        "{}'s tile shows a picture drawn blank",
                        TILES[*job as usize]
                    ));
                }
            }
            return Ok(drawer.screen().reopened);
        }
    }
    Err(format!(
        "the tiles were not drawn within 20,000 frames: {} show a picture",
        shown.len()
    ))
}

#[test]
fn every_tile_shows_a_picture_drawn_whole_however_the_device_is_lost() {
    assert_eq!(
        tiles(0, 0),
        Ok(0),
        "without a loss, nothing is opened again"
    );
    let mut reopened = 0;
    for seed in 1..=6 {
        reopened += tiles(seed, 300).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    }
    assert!(reopened > 0, "the devices were lost and opened again");
}
