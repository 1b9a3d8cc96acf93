//! Files of a shell written where the viewer's copy of it is (`work::file_writer`), as the page
//! asks for them: the bytes are those the exporter writes of the same shell, a mesh of an
//! implicit shell still growing waits for it to be grown whole, and every file that cannot be
//! made is refused with its reason, never written half or from another shell.

use seashells_core::export::job::Export;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::Shell;
use seashells_core::export::{Download, MeshFormat};
use seashells_core::presets::Preset;
use seashells_core::share::link;
use seashells_core::spec::ShellSpec;
use seashells_core::work::file_writer::{Body, FileStage, FileWriter, Needs, Source};
use seashells_core::work::host::{Budget, Host};
use seashells_core::work::message::Reply;
use seashells_core::work::message::Request;
use seashells_core::work::replica::Replica;
use std::cell::Cell;

/// A clock that moves on by a millisecond each time it is read.
fn clock() -> impl Fn() -> f64 {
    let t = Cell::new(0.0);
    move || {
        t.set(t.get() + 1.0);
        t.get()
    }
}

/// The preset and spec of a link, and the copy of its shell in session `session`, grown by a
/// worker's host until `enough` says so.
fn grown(
    text: &str,
    session: u32,
    enough: impl Fn(&Replica) -> bool,
) -> (&'static Preset, ShellSpec, Replica) {
    let decoded = link::decode(text);
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    let mut host = Host::default();
    host.push(
        1,
        Request::Load {
            session,
            link: link::encode(decoded.preset, &decoded.spec),
        },
    );
    let mut replica = Replica::new(session);
    while !enough(&replica) {
        let mut replies = host.work(&clock(), Budget::Unbounded);
        if replies.is_empty() {
            host.push(
                2,
                Request::Grow {
                    session,
                    rows: 4,
                    budget_ms: 1e9,
                },
            );
            replies = host.work(&clock(), Budget::Unbounded);
        }
        for (_, reply) in replies {
            match reply {
                Reply::Loaded { shell, delta, .. } => {
                    replica.loaded(shell, delta).expect("in step");
                }
                Reply::Grew { delta, .. } => {
                    replica.apply(delta).expect("in step");
                }
                other => panic!("unexpected {other:?}"),
            }
        }
    }
    (decoded.preset, decoded.spec, replica)
}

fn source<'a>(preset: &'a Preset, spec: &'a ShellSpec, replica: &'a Replica) -> Source<'a> {
    Source {
        preset,
        spec,
        replica,
    }
}

/// Works on the file until it is written or refused.
fn finish_file(writer: &mut FileWriter, source: impl Fn() -> Source<'static>) -> FileStage {
    let now = clock();
    for _ in 0..100_000 {
        match writer
            .work(Some(source()), &now)
            .expect("a file is asked for")
        {
            FileStage::Writing { done, .. } => assert!((0.0..=1.0).contains(&done)),
            FileStage::Finishing => panic!("this shell is grown"),
            end => return end,
        }
    }
    panic!("the file was never written")
}

fn leak<T>(value: T) -> &'static T {
    Box::leak(Box::new(value))
}

#[test]
fn a_mesh_written_in_steps_is_the_exporters_file_of_the_same_shell() {
    let (preset, spec, replica) = grown("v=1&preset=stripes&growth.rows=60", 3, |r| {
        r.rows_done() >= 20
    });
    let (spec, replica) = (leak(spec), leak(replica));
    let size = PrintSize::new(120.0, "Height").unwrap();
    let mut writer = FileWriter::default();
    let finish = writer.start(
        Download::Mesh(MeshFormat::Glb),
        size,
        Some(source(preset, spec, replica)),
    );
    assert_eq!(
        finish,
        Needs::Nothing,
        "a swept shell is written as it stands"
    );
    assert!(writer.busy());
    let FileStage::Written(file) = finish_file(&mut writer, || source(preset, spec, replica))
    else {
        panic!("not written");
    };
    assert!(!writer.busy());
    assert_eq!(file.name, "stripes.glb");
    assert_eq!(file.what.mime(), MeshFormat::Glb.mime());
    let Body::Bytes(bytes) = file.body else {
        panic!("a mesh is bytes");
    };
    let shell = Shell::of(replica.for_export().unwrap(), spec, preset, size).unwrap();
    let mut export = Export::new(MeshFormat::Glb, shell).unwrap();
    let expected = export.work(|| true).unwrap().expect("written at once");
    assert_eq!(bytes, expected);
    assert!(
        writer
            .work(Some(source(preset, spec, replica)), &clock())
            .is_none()
    );
}

#[test]
fn an_implicit_shell_still_growing_is_finished_before_its_mesh_is_written() {
    let text = "v=1&preset=implicit-whorl&form.resolution=32";
    let (preset, spec, growing) = grown(text, 5, |r| r.shell().is_some() && r.rows_done() > 0);
    assert!(!growing.is_done());
    let mut writer = FileWriter::default();
    let what = Download::Mesh(MeshFormat::Stl);
    assert_eq!(
        writer.start(
            what,
            PrintSize::default(),
            Some(source(preset, &spec, &growing))
        ),
        Needs::Finish,
        "the caller is told to finish it"
    );
    let now = clock();
    for _ in 0..3 {
        assert!(matches!(
            writer.work(Some(source(preset, &spec, &growing)), &now),
            Some(FileStage::Finishing)
        ));
    }
    let (_, _, whole) = grown(text, 5, Replica::is_done);
    let (spec, whole) = (leak(spec), leak(whole));
    assert!(matches!(
        writer.work(Some(source(preset, spec, whole)), &now),
        Some(FileStage::Writing { .. })
    ));
    let FileStage::Written(file) = finish_file(&mut writer, || source(preset, spec, whole)) else {
        panic!("not written");
    };
    let Body::Bytes(bytes) = file.body else {
        panic!("a mesh is bytes");
    };
    let triangles = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(
        triangles,
        whole.snapshot().triangle_count(),
        "the whole shell"
    );
}

#[test]
fn a_mesh_waiting_for_a_shell_that_was_replaced_is_refused() {
    let text = "v=1&preset=implicit-whorl&form.resolution=32";
    let (preset, spec, growing) = grown(text, 5, |r| r.shell().is_some());
    let mut writer = FileWriter::default();
    let what = Download::Mesh(MeshFormat::Obj);
    assert_eq!(
        writer.start(
            what,
            PrintSize::default(),
            Some(source(preset, &spec, &growing))
        ),
        Needs::Finish
    );
    let other = Replica::new(6);
    let stage = writer.work(Some(source(preset, &spec, &other)), &clock());
    let Some(FileStage::Refused(why)) = stage else {
        panic!("not refused");
    };
    assert!(why.contains("changed before it was grown whole"), "{why}");
    assert!(!writer.busy());
}

#[test]
fn what_cannot_be_made_is_refused_with_its_reason() {
    let now = clock();
    let refused = |writer: &mut FileWriter, source: Option<Source>| {
        let Some(FileStage::Refused(why)) = writer.work(source, &now) else {
            panic!("not refused");
        };
        why
    };
    let mut writer = FileWriter::default();
    writer.start(Download::Pattern, PrintSize::default(), None);
    assert_eq!(refused(&mut writer, None), "no shell is shown");

    let (preset, spec, plain) = grown("v=1&preset=turbinate&form.spiral.whorls=2", 1, |r| {
        r.shell().is_some()
    });
    writer.start(
        Download::Pattern,
        PrintSize::default(),
        Some(source(preset, &spec, &plain)),
    );
    assert_eq!(
        refused(&mut writer, Some(source(preset, &spec, &plain))),
        "this shell has no pattern"
    );

    let unbuilt = Replica::new(2);
    writer.start(
        Download::Mesh(MeshFormat::Ply),
        PrintSize::default(),
        Some(source(preset, &spec, &unbuilt)),
    );
    assert_eq!(
        refused(&mut writer, Some(source(preset, &spec, &unbuilt))),
        "the shell is not built yet"
    );

    let needs = writer.start(
        Download::Picture,
        PrintSize::default(),
        Some(source(preset, &spec, &plain)),
    );
    assert_eq!(needs, Needs::Picture);
    writer.picture_taken(Err("the graphics device was lost (test)".into()));
    assert_eq!(
        refused(&mut writer, Some(source(preset, &spec, &plain))),
        "the graphics device was lost (test)"
    );
}

#[test]
fn the_picture_is_what_the_view_gives_named_for_the_preset() {
    let (preset, spec, replica) = grown("v=1&preset=turbinate", 1, |r| r.shell().is_some());
    let mut writer = FileWriter::default();
    let needs = writer.start(
        Download::Picture,
        PrintSize::default(),
        Some(source(preset, &spec, &replica)),
    );
    assert_eq!(
        needs,
        Needs::Picture,
        "the viewer is asked to read its canvas"
    );
    let now = clock();
    for _ in 0..3 {
        assert!(
            matches!(
                writer.work(Some(source(preset, &spec, &replica)), &now),
                Some(FileStage::Writing { .. })
            ),
            "waits for the picture"
        );
    }
    writer.picture_taken(Ok("blob:picture".into()));
    let Some(FileStage::Written(file)) = writer.work(Some(source(preset, &spec, &replica)), &now)
    else {
        panic!("not written");
    };
    assert_eq!(file.name, "turbinate.png");
    assert!(matches!(file.body, Body::Url(url) if url == "blob:picture"));
    assert!(!writer.busy());
}
