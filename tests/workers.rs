//! The page's work shared among workers, simulated natively: hosts (what each Web Worker
//! runs) answer requests through the bytes that cross between threads, the pool shares jobs
//! out, and the page's copy of the shell takes in what comes back in whatever order it comes.
//! Whatever the number of workers, whoever dies on the way, and however growth was cut into
//! requests and budgets, the shell, its pattern, the gallery's shells and the map's tiles are
//! the same, bit for bit, as one thread growing them alone.

use seashells_core::export::MeshFormat;
use seashells_core::export::job::Export;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::Shell;
use seashells_core::generator::Generator;
use seashells_core::mesh::{Bounds, Surface, Vertex};
use seashells_core::presets::preset;
use seashells_core::share::link;
use seashells_core::share::parameter_map::{Axis, ParameterMap, SIDE};
use seashells_core::spec::ShellSpec;
use seashells_core::work::growth_session::{GrowthSession, Took};
use seashells_core::work::host::{Budget, Host};
use seashells_core::work::message::{
    Delta, Progress, Reply, Request, decode_reply, decode_request, encode_reply, encode_request,
};
use seashells_core::work::pool::Pool;
use seashells_core::work::replica::Replica;
use seashells_core::work::slotted_edge::{EdgeRun, EdgeWrites, Slot};
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

/// A page with `size` workers: the pool, the hosts, and the replies not yet taken in.
struct Page {
    pool: Pool,
    hosts: Vec<Host>,
    /// Replies waiting, as bytes, with the worker they came from.
    inbox: Vec<(usize, Vec<u8>)>,
    /// How the hosts spend their time: all at once, or a few milliseconds a call.
    budget: Option<f64>,
    now: Box<dyn Fn() -> f64>,
    /// Turns the order replies are taken in: a number that picks the next.
    shuffle: usize,
}

impl Page {
    fn new(size: usize, budget: Option<f64>, shuffle: usize) -> Self {
        Self {
            pool: Pool::new(size),
            hosts: (0..size).map(|_| Host::default()).collect(),
            inbox: Vec::new(),
            budget,
            now: Box::new(clock()),
            shuffle,
        }
    }

    /// Sends what the pool has to send, through the bytes, to the hosts.
    fn send(&mut self) {
        for send in self.pool.dispatch((self.now)()) {
            let (ticket, request) =
                decode_request(&encode_request(send.ticket, &send.request)).expect("reads back");
            assert_eq!(request, send.request);
            self.hosts[send.slot].push(ticket, request);
        }
    }

    /// Sends what the pool has to send and lets each host work once.
    fn run_hosts(&mut self) {
        self.send();
        for (slot, host) in self.hosts.iter_mut().enumerate() {
            let budget = match self.budget {
                None => Budget::Unbounded,
                Some(ms) => Budget::Until((self.now)() + ms),
            };
            for (ticket, reply) in host.work(&*self.now, budget) {
                self.inbox.push((slot, encode_reply(ticket, &reply)));
            }
        }
    }

    /// The next reply, with the request it answers: each worker's replies come in the order
    /// it sent them (as messages from a Web Worker do), and the shuffle picks which worker's
    /// comes next. A reply from a worker since replaced is dropped, as the page drops it.
    fn next_reply(&mut self) -> Option<(Request, Reply)> {
        loop {
            while self.inbox.is_empty() {
                self.run_hosts();
                if self.inbox.is_empty() && !self.hosts.iter().any(Host::busy) {
                    return None;
                }
            }
            let mut slots: Vec<usize> = self.inbox.iter().map(|(s, _)| *s).collect();
            slots.sort_unstable();
            slots.dedup();
            let slot = slots[self.shuffle % slots.len()];
            self.shuffle = self.shuffle.wrapping_mul(31).wrapping_add(7);
            let at = self.inbox.iter().position(|(s, _)| *s == slot)?;
            let (slot, bytes) = self.inbox.remove(at);
            let (ticket, reply) = decode_reply(&bytes).expect("reads back");
            if let Some(request) = self.pool.answered(slot, ticket, (self.now)()) {
                return Some((request, reply));
            }
        }
    }

    /// Worker `slot` dies: what it was doing and what it had answered but not delivered are
    /// lost, a fresh host takes its place; returns the session requests it held.
    fn kill(&mut self, slot: usize) -> Vec<Request> {
        self.hosts[slot] = Host::default();
        self.inbox.retain(|(s, _)| *s != slot);
        self.pool.failed(slot)
    }
}

/// The link of `id` with `extra` values, as the page sends it.
fn link_of(id: &str, extra: &str) -> (String, ShellSpec) {
    let decoded = link::decode(&format!("v=1&preset={id}{extra}"));
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    (link::encode(decoded.preset, &decoded.spec), decoded.spec)
}

/// The page's copy of a shell grown in `grows` requests of `rows` rows each (with a budget
/// of a few milliseconds), then finished apart by the pool, by the viewer's own
/// [`GrowthSession`]; the worker holding the session dies after `kill_after` requests, and a
/// job's worker once while pieces are made, if asked.
fn grow_and_finish(
    page: &mut Page,
    link: &str,
    grows: usize,
    rows: u32,
    kill_after: Option<usize>,
    kill_a_job: bool,
) -> GrowthSession {
    let mut growth = GrowthSession::load(1, link.into(), &mut |r| page.pool.submit(r));
    let mut grown = 0;
    let mut finish_sent = false;
    let mut killed_job = false;
    loop {
        if grown < grows && page.pool.in_flight() == 0 && growth.replica().shell().is_some() {
            if kill_after == Some(grown) {
                let lost = page.kill(0);
                assert!(lost.is_empty(), "nothing was in flight");
                growth.resume(&lost, &mut |r| page.pool.submit(r));
            }
            assert!(growth.grow(rows, 4.0, &mut |r| page.pool.submit(r)));
            grown += 1;
        } else if grown == grows && !finish_sent && page.pool.in_flight() == 0 {
            assert!(growth.finish(&mut |r| page.pool.submit(r)));
            finish_sent = true;
        }
        if kill_a_job && !killed_job && page.pool.busy_with_jobs() && page.pool.size() > 1 {
            page.run_hosts();
            assert!(page.kill(page.pool.size() - 1).is_empty());
            killed_job = true;
        }
        let Some((request, reply)) = page.next_reply() else {
            break;
        };
        let took = growth.take(&request, reply, &mut |r| page.pool.submit(r));
        match took.expect("in step") {
            Took::Loaded(shell, _) => {
                // The page's copy takes the room the shape expects at once: no frame of
                // growth copies the whole mesh into a larger one.
                let (room, replica) = (shell.capacity, growth.replica());
                assert!(replica.mesh().vertices.capacity() >= room.0.vertices);
                assert!(replica.mesh().indices.capacity() >= room.0.indices);
                assert!(replica.edge().mesh().vertices.capacity() >= room.1.vertices);
            }
            Took::Previewed(reply) => panic!("unexpected {reply:?}"),
            Took::Advanced(_) | Took::Nothing => {}
        }
    }
    assert!(growth.settled(), "every request of the session is answered");
    assert!(growth.replica().is_done(), "the shell is grown");
    growth
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
    let (link, spec) = link_of("murex-cabritii", "&form.resolution=40");
    let reference = alone(&spec, 0, 0);
    for size in [1, 2, 4] {
        for (grows, budget) in [(0, None), (5, Some(3.0))] {
            let mut page = Page::new(size, budget, size * 7 + grows);
            let growth = grow_and_finish(&mut page, &link, grows, 40, None, false);
            let replica = growth.replica();
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
    let (link, spec) = link_of("murex-cabritii", "&form.resolution=40");
    let preset = preset("murex-cabritii").unwrap();
    let size = PrintSize::default;
    let reference = alone(&spec, 0, 0);
    let expected = files(|| Shell::new(&reference, &spec, preset, size()).unwrap());
    for workers in [1, 2, 4] {
        let mut page = Page::new(workers, Some(2.0), workers);
        let growth = grow_and_finish(&mut page, &link, 0, 0, None, false);
        let replica = growth.replica();
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
        let (link, spec) = link_of(id, extra);
        let mut page = Page::new(2, Some(2.0), 3);
        let growth = grow_and_finish(&mut page, &link, 30, 7, None, false);
        let replica = growth.replica();
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
    let (link, spec) = link_of("murex-cabritii", "&form.resolution=40");
    let reference = alone(&spec, 0, 0);
    // The session's worker dies after a third of the growth; a job's worker while pieces are
    // made.
    let mut page = Page::new(3, Some(3.0), 5);
    let growth = grow_and_finish(&mut page, &link, 12, 20, Some(4), true);
    let replica = growth.replica();
    assert_eq!(page.pool.deaths(), 2);
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

/// The shell of `link` as the page grows it when the sessions' worker answers Load, is sent a
/// Grow and dies before answering it: the page has the Load's reply in hand, and takes it in
/// before it resumes the lost session (`resume_first` false, as the page does) or after.
fn loaded_then_replaced(link: &str, resume_first: bool) -> Result<GrowthSession, String> {
    let mut page = Page::new(1, None, 0);
    let mut growth = GrowthSession::load(1, link.into(), &mut |r| page.pool.submit(r));
    let (load, loaded) = page.next_reply().expect("the shell is built");
    assert!(growth.grow(5, 4.0, &mut |r| page.pool.submit(r)));
    page.send();
    let lost = page.kill(0);
    assert!(matches!(lost[..], [Request::Grow { .. }]), "{lost:?}");
    if resume_first {
        growth.resume(&lost, &mut |r| page.pool.submit(r));
    }
    growth.take(&load, loaded, &mut |r| page.pool.submit(r))?;
    if !resume_first {
        growth.resume(&lost, &mut |r| page.pool.submit(r));
    }
    loop {
        if page.pool.in_flight() == 0 {
            growth.finish(&mut |r| page.pool.submit(r));
        }
        let Some((request, reply)) = page.next_reply() else {
            break;
        };
        growth.take(&request, reply, &mut |r| page.pool.submit(r))?;
    }
    Ok(growth)
}

#[test]
fn replies_sent_before_the_sessions_worker_died_are_taken_in_before_it_is_resumed() {
    let (link, spec) = link_of("kawaguchi-horn", "");
    let reference = alone(&spec, 0, 0);
    let growth = loaded_then_replaced(&link, false).expect("in step");
    let replica = growth.replica();
    assert!(replica.is_done() && growth.settled());
    assert_eq!(replica.mesh_hash(), Some(reference.mesh_hash()));
    assert_eq!(
        replica.pattern_hash(),
        reference.pattern().map(|p| p.hash())
    );
    // Resumed before the Load's reply is in, the shell is built twice, and the second copy
    // does not continue the first: the words Kawaguchi's horn stopped with, once in three
    // runs of the WebKit smoke suite, before the page took replies first.
    assert_eq!(
        loaded_then_replaced(&link, true).err().as_deref(),
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
        page.pool.submit(Request::Whole {
            job: job as u32,
            link,
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
            page.pool.submit(Request::Tile {
                job: index as u32,
                link: map.tiles()[index].link.clone(),
                rows: map.rows as u32,
            });
        }
        map
    };
    let mut shared = map(Some(&mut page));
    let mut wholes = 0;
    while let Some((_, reply)) = page.next_reply() {
        match reply {
            Reply::Grown { job, result } => {
                let whole = result.expect("grows");
                let (id, extra) = ids[job as usize];
                let (_, spec) = link_of(id, extra);
                let mut alone = Generator::new(&spec).unwrap();
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
