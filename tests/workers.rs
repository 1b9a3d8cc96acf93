//! The page's work shared among workers, simulated natively (`simulated_workers.rs`): hosts
//! (what each Web Worker runs) answer requests through the bytes that cross between threads,
//! the pool shares jobs out and takes its workers' events in by its own rules, and the
//! viewer's core state takes in what comes back in whatever order it comes. Whatever the
//! number of workers, whoever dies on the way, and however growth was cut into requests and
//! budgets, the shell, its pattern, the gallery's shells and the map's tiles are the same, bit
//! for bit, as one thread growing them alone.

use crate::simulated_workers::{Workers, within_copy};
use rand_core::SeedableRng;
use rand_pcg::Pcg64;
use seashells_core::export::MeshFormat;
use seashells_core::export::job::Export;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::Shell;
use seashells_core::generator::Generator;
use seashells_core::mesh::{Bounds, Surface, Vertex};
use seashells_core::presets::preset;
use seashells_core::share::link;
use seashells_core::spec::ShellSpec;
use seashells_core::variation::parameter_map::{Axis, ParameterMap, SIDE};
use seashells_core::work::growth_session::GrowthSession;
use seashells_core::work::host::{Budget, Host};
use seashells_core::work::message::{Delta, Progress, Reply, Request, decode_reply, encode_reply};
use seashells_core::work::replica::Replica;
use seashells_core::work::slotted_edge::{EdgeRun, EdgeWrites, Slot};
use seashells_core::work::viewer_command::{PresetSpec, ViewCommand};
use seashells_core::work::viewer_state::{ScreenChange, ViewerState};
use std::cell::Cell;

/// A clock that moves on by a millisecond each time it is read, so that budgets run out
/// after as many reads, the same way every run.
fn clock() -> impl Fn() -> f64 {
    let t = Cell::new(0.0);
    move || {
        t.set(t.get() + 1.0);
        t.get()
    }
}

/// A page growing shells on `size` simulated workers: the viewer's core state, its pool, and
/// the frames that pass.
struct Page {
    viewer: ViewerState,
    workers: Workers,
    /// Milliseconds each worker works between two frames.
    ms: f64,
    frame: u64,
    rng: Pcg64,
}

impl Page {
    /// A page of `size` workers, each working `ms` a frame (`None`: as long as it takes),
    /// their replies interleaved as `seed` draws.
    fn new(size: usize, ms: Option<f64>, seed: u64) -> Self {
        let mut viewer = ViewerState::new(false, true, 0.0);
        let mut workers = Workers::new(size);
        viewer.command(ViewCommand::Play(false), &mut workers.pool);
        Self {
            viewer,
            workers,
            ms: ms.unwrap_or(f64::INFINITY),
            frame: 0,
            rng: Pcg64::seed_from_u64(seed),
        }
    }

    fn command(&mut self, command: ViewCommand) {
        self.viewer.command(command, &mut self.workers.pool);
    }

    /// One frame: what reached the page is taken in, then what it asked is sent and worked
    /// on. Replies of jobs that are not the shell's are returned.
    fn frame(&mut self) -> Vec<Reply> {
        self.frame += 1;
        let now = self.frame as f64 * 16.0;
        let polled = self.workers.poll(self.frame, now, &mut self.rng);
        let (jobs, shell): (Vec<_>, Vec<_>) = polled
            .replies
            .into_iter()
            .partition(|(_, r)| matches!(r, Reply::Grown { .. } | Reply::Tiled { .. }));
        self.viewer
            .take_all(shell, polled.sessions_lost, &mut self.workers.pool)
            .expect("in step");
        self.workers.dispatch(now).expect("reads back");
        self.workers.work(self.frame, self.ms, 2, &mut self.rng);
        jobs.into_iter().map(|(_, reply)| reply).collect()
    }

    /// Frames until nothing is asked of the workers or on its way back; the replies of jobs
    /// that are not the shell's.
    fn settle(&mut self) -> Vec<Reply> {
        let mut jobs = Vec::new();
        loop {
            jobs.extend(self.frame());
            if self.workers.idle() {
                return jobs;
            }
        }
    }

    /// The page's copy of the shell shown.
    fn replica(&self) -> &Replica {
        self.viewer.shell().expect("a shell is shown").replica()
    }
}

/// The link of `id` with `extra` values, as the page sends it.
fn link_of(id: &str, extra: &str) -> (String, ShellSpec) {
    let decoded = link::decode(&format!("v=1&preset={id}{extra}"));
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    (link::encode(decoded.preset, &decoded.spec), decoded.spec)
}

/// Loads `id` with `extra` values in `page`'s viewer, grows it in `grows` requests of `rows`
/// rows each (each once the last is answered), then finishes it, shared out among the pool;
/// the worker holding the session throws before the request `throw_after` is sent, and a
/// job's worker once while pieces are made, if asked.
fn grow_and_finish(
    page: &mut Page,
    id: &str,
    extra: &str,
    grows: usize,
    rows: usize,
    throw_after: Option<usize>,
    throw_a_job: bool,
) {
    let (link, _) = link_of(id, extra);
    let shell = PresetSpec::try_from(link).expect("a link");
    page.command(ViewCommand::Load {
        shell,
        finish: false,
    });
    page.settle();
    let room = page.replica().shell().expect("built").capacity;
    // The page's copy takes the room the shape expects at once: no frame of growth copies the
    // whole mesh into a larger one.
    assert!(page.replica().mesh().vertices.capacity() >= room.0.vertices);
    assert!(page.replica().mesh().indices.capacity() >= room.0.indices);
    assert!(page.replica().edge().mesh().vertices.capacity() >= room.1.vertices);
    for grow in 0..grows {
        if throw_after == Some(grow) {
            page.workers.throw(0, page.frame + 1);
            page.settle();
        }
        page.command(ViewCommand::Grow(rows));
        page.settle();
    }
    page.command(ViewCommand::Finish);
    if throw_a_job && page.workers.count() > 1 {
        while !page.workers.pool.busy_with_jobs() {
            page.frame();
        }
        page.frame();
        page.workers.throw(page.workers.count() - 1, page.frame + 1);
    }
    page.settle();
    let status = page.viewer.status((1, 1));
    let shell = status.shell.expect("built");
    assert!(shell.settled, "every request of the session is answered");
    assert!(shell.done, "the shell is grown");
}

/// The shell of `spec` grown alone: `grows` calls of `rows` rows, then finished.
fn alone(spec: &ShellSpec, grows: usize, rows: usize) -> Generator {
    let mut generator = Generator::new(spec).unwrap();
    for _ in 0..grows {
        generator.advance(rows);
    }
    generator.finish();
    generator
}

#[test]
fn a_murex_finished_by_one_two_or_four_workers_is_the_same_bit_for_bit() {
    let (_, spec) = link_of("murex-cabritii", "&form.resolution=40");
    let reference = alone(&spec, 0, 0);
    for size in [1, 2, 4] {
        for (grows, budget) in [(0, None), (5, Some(3.0))] {
            let mut page = Page::new(size, budget, (size * 7 + grows) as u64);
            grow_and_finish(
                &mut page,
                "murex-cabritii",
                "&form.resolution=40",
                grows,
                40,
                None,
                false,
            );
            let replica = page.replica();
            let what = format!("{size} workers, {grows} requests before Finish, budget {budget:?}");
            assert_eq!(replica.mesh(), reference.mesh(), "{what}");
            assert!(replica.edge().is_empty(), "{what}");
            assert_eq!(replica.mesh_hash(), Some(reference.mesh_hash()), "{what}");
            assert_eq!(
                replica.pattern_hash(),
                reference.pattern().map(|p| p.hash()),
                "{what}"
            );
            assert_eq!(
                replica.rgba(),
                reference.pattern().unwrap().rgba(),
                "{what}"
            );
        }
    }
}

/// Every mesh file of the shell `shell` gives, written as the page writes it.
fn files(shell: impl Fn() -> Shell) -> Vec<Vec<u8>> {
    MeshFormat::ALL
        .iter()
        .map(|&format| {
            let mut export = Export::new(format, shell()).unwrap();
            loop {
                if let Some(bytes) = export.work(|| true).unwrap() {
                    break bytes;
                }
            }
        })
        .collect()
}

#[test]
fn the_murexs_files_from_one_two_or_four_workers_are_the_command_lines_bit_for_bit() {
    let (_, spec) = link_of("murex-cabritii", "&form.resolution=40");
    let preset = preset("murex-cabritii").unwrap();
    let size = PrintSize::default;
    let reference = alone(&spec, 0, 0);
    let expected = files(|| Shell::new(&reference, &spec, preset, size()).unwrap());
    for workers in [1, 2, 4] {
        let mut page = Page::new(workers, Some(2.0), workers as u64);
        grow_and_finish(
            &mut page,
            "murex-cabritii",
            "&form.resolution=40",
            0,
            0,
            None,
            false,
        );
        let replica = page.replica();
        let made =
            files(|| Shell::of(replica.for_export().unwrap(), &spec, preset, size()).unwrap());
        assert!(made == expected, "the files made with {workers} workers");
    }
}

#[test]
fn grown_in_requests_the_shell_is_the_one_grown_alone() {
    for (id, extra) in [
        ("oliva-porphyria", ""),
        ("kawaguchi-coral", ""),
        ("implicit-whorl", "&form.resolution=48"),
    ] {
        let (_, spec) = link_of(id, extra);
        let mut page = Page::new(2, Some(2.0), 3);
        grow_and_finish(&mut page, id, extra, 30, 7, None, false);
        let replica = page.replica();
        let reference = alone(&spec, 30, 7);
        assert_eq!(
            replica.snapshot().content_hash(),
            reference.snapshot().content_hash(),
            "{id}"
        );
        assert_eq!(replica.mesh_hash(), Some(reference.mesh_hash()), "{id}");
        assert_eq!(
            replica.pattern_hash(),
            reference.pattern().map(|p| p.hash()),
            "{id}"
        );
    }
}

#[test]
fn a_worker_that_dies_is_replaced_and_its_work_done_again_to_the_same_bits() {
    let (_, spec) = link_of("murex-cabritii", "&form.resolution=40");
    let reference = alone(&spec, 0, 0);
    // The session's worker throws after a third of the growth; a job's worker while pieces
    // are made.
    let mut page = Page::new(3, Some(3.0), 5);
    grow_and_finish(
        &mut page,
        "murex-cabritii",
        "&form.resolution=40",
        12,
        20,
        Some(4),
        true,
    );
    assert_eq!(page.workers.pool.deaths(), 2);
    let replica = page.replica();
    assert_eq!(replica.mesh_hash(), Some(reference.mesh_hash()));
    assert_eq!(
        replica.snapshot().content_hash(),
        reference.snapshot().content_hash()
    );
    assert_eq!(
        replica.pattern_hash(),
        reference.pattern().map(|p| p.hash())
    );
}

#[test]
fn replies_sent_before_the_sessions_worker_died_are_taken_in_before_it_is_resumed() {
    let (link, spec) = link_of("kawaguchi-horn", "");
    let reference = alone(&spec, 0, 0);
    // The worker answers the Load, is sent a Grow and throws before answering it: the page
    // has the Load's reply in hand when it learns of the death, in the same frame.
    let mut page = Page::new(1, None, 0);
    page.command(ViewCommand::Load {
        shell: PresetSpec::try_from(link.clone()).expect("a link"),
        finish: false,
    });
    page.workers.dispatch(0.0).expect("reads back");
    page.workers
        .work(0, f64::INFINITY, 0, &mut Pcg64::seed_from_u64(0));
    page.command(ViewCommand::Grow(5));
    page.workers.dispatch(0.0).expect("reads back");
    page.workers.throw(0, 1);
    page.command(ViewCommand::Finish);
    page.settle();
    let replica = page.replica();
    assert!(replica.is_done());
    assert_eq!(replica.mesh_hash(), Some(reference.mesh_hash()));
    assert_eq!(
        replica.pattern_hash(),
        reference.pattern().map(|p| p.hash())
    );
    // Resumed before the Load's reply is in, the shell would be built twice, and the second
    // copy would not continue the first: the words Kawaguchi's horn stopped with, once in
    // three runs of the WebKit smoke suite, before the page took replies first.
    let mut host = Host::default();
    let mut sent = Vec::new();
    let mut growth = GrowthSession::load(1, link, &mut |r| sent.push(r));
    host.push(1, sent.remove(0));
    let (_, loaded) = host.work(&clock(), Budget::Unbounded).remove(0);
    let load = Request::Load {
        session: 1,
        link: growth.link().to_string(),
    };
    assert!(growth.grow(5, 4.0, &mut |_| {}), "lost with the worker");
    growth.resume(&[], &mut |r| sent.push(r));
    assert!(growth.finish(&mut |_| {}), "the page went on to finish it");
    let mut fresh = Host::default();
    fresh.push(2, sent.remove(0));
    let (_, again) = fresh.work(&clock(), Budget::Unbounded).remove(0);
    growth
        .take(&load, loaded, &mut |_| {})
        .expect("the first copy");
    assert_eq!(
        growth.take(&load, again, &mut |_| {}).err().as_deref(),
        Some("a worker's pattern rows start at 0 where the page holds 1")
    );
}

#[test]
fn gallery_shells_and_map_tiles_from_workers_are_those_made_alone() {
    let mut page = Page::new(2, Some(5.0), 1);
    // The implicit shell at a coarse polygonization, to keep the test short.
    let ids = [
        ("stripes", ""),
        ("kawaguchi-horn", ""),
        ("implicit-canal-whorl", "&form.resolution=32"),
    ];
    for (job, (id, extra)) in ids.iter().enumerate() {
        let (link, _) = link_of(id, extra);
        page.workers.pool.submit(Request::Whole {
            job: job as u32,
            link,
            pixels: 128,
        });
    }
    let oliva = preset("oliva-porphyria").unwrap();
    let axis = |key: &str, from, to| Axis::new("sweep", key, from, to, SIDE).unwrap();
    let map = |page: Option<&mut Page>| {
        let mut map = ParameterMap::new(
            oliva,
            &oliva.spec,
            axis("pattern.model.d_a", 0.01, 0.03),
            axis("pattern.model.rho", 0.05, 0.15),
        );
        let Some(page) = page else {
            while !map.finished() {
                map.work(|| true);
            }
            return map;
        };
        for index in map.to_compute() {
            page.workers.pool.submit(Request::Tile {
                job: index as u32,
                link: map.tiles()[index].link.clone(),
                rows: map.rows as u32,
            });
        }
        map
    };
    let mut shared = map(Some(&mut page));
    let mut wholes = 0;
    for reply in page.settle() {
        match reply {
            Reply::Grown { job, result } => {
                let whole = result.expect("grows");
                let (id, extra) = ids[job as usize];
                let (_, spec) = link_of(id, extra);
                let mut alone = Generator::picture(&spec, 128).unwrap();
                alone.finish();
                assert_eq!(whole.mesh.content_hash(), alone.mesh_hash(), "{id}");
                assert_eq!(whole.shell.rows as usize, alone.rows());
                wholes += 1;
            }
            Reply::Tiled { job, result } => shared.place(job as usize, result),
            other => panic!("unexpected {other:?}"),
        }
    }
    assert_eq!(wholes, ids.len());
    assert!(shared.finished());
    let single = map(None);
    for (a, b) in shared.tiles().iter().zip(single.tiles()) {
        assert_eq!(
            (&a.picture, &a.failure),
            (&b.picture, &b.failure),
            "{}",
            a.link
        );
    }
}

#[test]
fn a_request_for_a_session_the_worker_does_not_hold_is_refused() {
    let mut host = Host::default();
    let (link, _) = link_of("stripes", "");
    host.push(1, Request::Load { session: 2, link });
    host.push(
        2,
        Request::Grow {
            session: 9,
            rows: 1,
            budget_ms: 1.0,
        },
    );
    host.push(3, Request::Finish { session: 9 });
    let replies = host.work(&clock(), Budget::Unbounded);
    assert!(matches!(replies[0], (1, Reply::Loaded { session: 2, .. })));
    assert!(matches!(replies[1], (2, Reply::Refused { session: 9, .. })));
    assert!(matches!(replies[2], (3, Reply::Refused { session: 9, .. })));
    assert!(!host.busy());
}

/// The bytes of a mesh's vertices and indices, to compare meshes bit for bit.
fn mesh_bytes(mesh: &seashells_core::mesh::Mesh) -> (Vec<u8>, Vec<u32>) {
    (
        bytemuck::cast_slice(&mesh.vertices).to_vec(),
        mesh.indices.clone(),
    )
}

#[test]
fn an_edge_crossing_as_the_parts_that_changed_is_the_edge_grown_alone() {
    // An implicit shell re-meshes a few chunks a step: its edge crosses as the parts that
    // changed, each written in its slot, and the page's copy joined is the generator's edge at
    // every step.
    let (link, spec) = link_of("implicit-whorl", "&form.resolution=48");
    let mut host = Host::default();
    host.push(1, Request::Load { session: 1, link });
    let mut replica = Replica::new(1);
    let (mut changes, mut partial) = (0, 0);
    while !replica.is_done() {
        for (ticket, reply) in host.work(&clock(), Budget::Unbounded) {
            let (_, reply) = decode_reply(&encode_reply(ticket, &reply)).expect("reads back");
            let (delta, loaded) = match reply {
                Reply::Loaded { shell, delta, .. } => (delta, Some(shell)),
                Reply::Grew { delta, .. } => (delta, None),
                other => panic!("unexpected {other:?}"),
            };
            let written = (delta.edge.as_ref())
                .map(|e| e.runs.iter().map(|r| r.vertices.len()).sum::<usize>());
            let advance = match loaded {
                Some(shell) => replica.loaded(shell, delta),
                None => replica.apply(delta),
            }
            .expect("in step");
            if advance.edge.is_some() {
                changes += 1;
                let mut alone = Generator::new(&spec).unwrap();
                alone.catch_up(replica.rows_done(), replica.steps_done());
                let joined = replica.edge().joined();
                assert_eq!(
                    mesh_bytes(&joined),
                    mesh_bytes(alone.edge()),
                    "row {}",
                    replica.rows_done()
                );
                partial += usize::from(written < Some(joined.vertices.len()));
                // Nothing outside the parts' slots draws a triangle.
                let held = replica.edge().mesh();
                let mut in_slot = vec![false; held.indices.len()];
                for slot in replica.edge().slots() {
                    in_slot[slot.indices.start as usize..slot.indices.end as usize].fill(true);
                }
                assert!(
                    (held.indices.iter().zip(&in_slot)).all(|(&i, &inside)| inside || i == 0),
                    "row {}",
                    replica.rows_done()
                );
            }
        }
        host.push(
            2,
            Request::Grow {
                session: 1,
                rows: 9,
                budget_ms: 1e9,
            },
        );
    }
    assert!(changes >= 4, "{changes} edges");
    assert!(partial >= 1, "every edge crossed whole ({changes} edges)");
}

/// A delta that writes `edge` and adds nothing else.
fn edge_delta(edge: EdgeWrites) -> Delta {
    Delta {
        rows: 0..0,
        rgba: Vec::new(),
        widths: Vec::new(),
        first_vertex: 0,
        vertices: Vec::new(),
        first_index: 0,
        indices: Vec::new(),
        edge: Some(edge),
        grown: Bounds::EMPTY,
        progress: Progress::default(),
    }
}

#[test]
fn edge_writes_that_do_not_fit_their_edge_are_refused_by_their_key() {
    let vertex = Vertex::new(
        glam::DVec3::ZERO,
        glam::DVec3::Z,
        [0.0, 0.0],
        Surface::Outer,
    );
    let triangle = EdgeWrites {
        fresh: true,
        vertex_count: 3,
        index_count: 3,
        slots: vec![Slot {
            id: 7,
            vertices: 0..3,
            indices: 0..3,
        }],
        runs: vec![EdgeRun {
            first_vertex: 0,
            vertices: vec![vertex; 3],
            first_index: 0,
            indices: vec![0, 1, 2],
        }],
    };
    let refused = |edge: EdgeWrites| {
        let delta = edge_delta(edge);
        let bytes = encode_reply(1, &Reply::Grew { session: 1, delta });
        decode_reply(&bytes).unwrap_err().key
    };
    // Indices beyond the edge's vertices cannot be read.
    let mut beyond = triangle.clone();
    beyond.runs[0].indices = vec![0, 1, 4];
    assert_eq!(refused(beyond), "edge indices");
    // Nor a run beyond its counts,
    let mut long = triangle.clone();
    long.runs[0].first_vertex = 1;
    assert_eq!(refused(long), "edge run");
    // nor a slot beyond them, nor slots out of the order of their numbers.
    let mut outside = triangle.clone();
    outside.slots[0].indices = 0..6;
    assert_eq!(refused(outside), "edge slot");
    let mut twice = triangle.clone();
    twice.slots.push(twice.slots[0].clone());
    assert_eq!(refused(twice), "edge slot");
    // What fits is taken, and joins to the part.
    let mut replica = Replica::new(1);
    let bytes = encode_reply(
        1,
        &Reply::Grew {
            session: 1,
            delta: edge_delta(triangle),
        },
    );
    let Reply::Grew { delta, .. } = decode_reply(&bytes).unwrap().1 else {
        panic!("a delta reads back as one");
    };
    let advance = replica.apply(delta).expect("in step");
    assert_eq!(advance.edge.unwrap().indices, vec![0..3]);
    assert_eq!(replica.edge().joined().indices, vec![0, 1, 2]);
}

#[test]
fn growth_taken_in_from_several_replies_hands_the_renderer_only_what_the_copy_holds() {
    // A Grow and the Finish after it answered in one frame: the Grow's edge was gone by the
    // time the renderer read it (the page panicked in `shell_buffers.rs` on the implicit whorl).
    let (link, _) = link_of("implicit-whorl", "");
    let mut page = Page::new(1, None, 4);
    page.command(ViewCommand::Load {
        shell: PresetSpec::try_from(link).expect("a link"),
        finish: false,
    });
    page.settle();
    page.viewer.take_screen();
    for rows in [3, 5, 8] {
        page.command(ViewCommand::Grow(rows));
    }
    page.command(ViewCommand::Finish);
    while !page.workers.idle() {
        page.frame();
        for change in page.viewer.take_screen() {
            if let ScreenChange::Rows(advance) = &change {
                assert!(within_copy(advance, page.replica()), "{advance:?}");
            }
        }
    }
    assert!(page.replica().is_done());
}

/// Where drawing holds the thread (WebGL on the page's thread of WebKit, a software
/// rasterizer), a frame's drawing takes most of the time between frames. Driven as the viewer
/// drives it (`ViewerState::frame` at each frame's start, `drawn` once the drawing ends), the
/// camera eases by the time from one frame's start to the next, the drawing included, and comes
/// to rest on the grown shell within a few frames. It once counted only the time after each
/// drawing (the clock moved when a frame was drawn, as `ViewerState::recorded` still moves it
/// for a recording's frames): 42 frames here, and a finished top shell waited 50 s on WebKit to
/// be said grown.
#[test]
fn a_drawing_that_holds_the_thread_does_not_slow_the_camera() {
    const FRAME_MS: f64 = 350.0;
    const DRAW_MS: f64 = 300.0;
    let (link, _) = link_of("turbinate", "&growth.speed=200");
    let mut page = Page::new(2, None, 5);
    page.command(ViewCommand::Load {
        shell: PresetSpec::try_from(link).expect("a link"),
        finish: false,
    });
    page.settle();
    page.command(ViewCommand::Play(true));
    let at_rest = |page: &Page| {
        let status = page.viewer.status((1, 1));
        status.shell.is_some_and(|s| s.done && s.at_rest)
    };
    let mut frames_after_done = 0;
    for k in 1..400u64 {
        let now = k as f64 * FRAME_MS;
        let polled = page.workers.poll(k, now, &mut page.rng);
        page.viewer
            .take_all(polled.replies, polled.sessions_lost, &mut page.workers.pool)
            .expect("in step");
        if page.viewer.frame(now, 8.0, 0.0, &mut page.workers.pool) {
            // The drawing ends DRAW_MS into the frame.
            page.viewer.drawn();
        }
        page.workers.dispatch(now + DRAW_MS).expect("reads back");
        page.workers.work(k, f64::INFINITY, 0, &mut page.rng);
        if page.replica().is_done() {
            frames_after_done += 1;
        }
        if at_rest(&page) {
            break;
        }
    }
    assert!(page.replica().is_done(), "the shell grew whole");
    assert!(at_rest(&page), "the camera came to rest");
    // At 350 ms a frame the easing (time constant 0.35 s) is within 1e-3 of its framing in
    // seven frames.
    assert!(
        frames_after_done <= 10,
        "the camera came to rest {frames_after_done} frames after the shell was whole"
    );
}
