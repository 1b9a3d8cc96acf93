//! The messages between the page and a viewer drawing in a worker (`work::viewer_message`): every
//! command and every kind of news reads back as it was written, a spec (sent as its link) bit
//! for bit; bytes that are cut short, have a stray byte after them, name an unknown preset,
//! carry a link with a problem or a size out of range are refused, never read as something
//! else.

use seashells_core::export::estimate::Counts;
use seashells_core::export::print_size::{Along, PrintSize};
use seashells_core::export::{Download, MeshFormat};
use seashells_core::presets;
use seashells_core::share::link;
use seashells_core::share::presentation::Layout;
use seashells_core::view::preview::PreviewState;
use seashells_core::view::recording::FrameAsk;
use seashells_core::work::file_writer::{Body, File, FileStage};
use seashells_core::work::planar_update::PlanarUpdate;
use seashells_core::work::viewer_command::{PointerChange, PresetSpec, ViewCommand};
use seashells_core::work::viewer_message::{
    PoolNews, ViewerNews, decode_command, decode_news, encode_command, encode_news,
};
use seashells_core::work::viewer_status::{Device, FrameReport, ShellStatus, ViewStatus};
use seashells_core::work::wire;

/// Every kind of command, with values that are not their defaults.
fn commands() -> Vec<ViewCommand> {
    let preset = presets::preset("murex-cabritii").expect("a preset");
    let edited = link::decode("#v=1&preset=oliva-porphyria&pattern.model.d_a=0.0123&seed=7");
    vec![
        ViewCommand::Load {
            shell: PresetSpec::new(preset, preset.spec.clone()),
            finish: true,
        },
        ViewCommand::Load {
            shell: PresetSpec::new(edited.preset, edited.spec.clone()),
            finish: false,
        },
        ViewCommand::Restyle(PresetSpec::new(
            preset,
            link::decode("#v=1&preset=murex-cabritii&material.gloss=0.9").spec,
        )),
        ViewCommand::Preview(link::encode(edited.preset, &edited.spec)),
        ViewCommand::EndPreview,
        ViewCommand::Grow(17),
        ViewCommand::Finish,
        ViewCommand::Play(false),
        ViewCommand::Hold(true),
        ViewCommand::Speed(2.5),
        ViewCommand::Layout(Layout::Four),
        ViewCommand::ResetCamera,
        ViewCommand::Pointer(PointerChange::Down {
            id: -3,
            x: 10.5,
            y: 20.25,
        }),
        ViewCommand::Pointer(PointerChange::Move {
            id: 7,
            x: -1.5,
            y: 2.0,
        }),
        ViewCommand::Pointer(PointerChange::Up { id: 7 }),
        ViewCommand::Wheel(-120.0),
        ViewCommand::Shown {
            width: 640,
            height: 480,
            pixel_ratio: 1.5,
        },
        ViewCommand::Background([1, 2, 250]),
        ViewCommand::RecordAt(Some((1280, 720))),
        ViewCommand::RecordAt(None),
        ViewCommand::AskFrame(FrameAsk {
            row: 312,
            dt: 1.0 / 30.0,
            turn: 0.07,
            timestamp_us: 1_033_333,
            duration_us: 33_333,
        }),
        ViewCommand::WriteFile {
            what: Download::Mesh(MeshFormat::ThreeMf),
            size: PrintSize::new(120.0, "size")
                .expect("in range")
                .along(Along::Z),
        },
        ViewCommand::WriteFile {
            what: Download::Picture,
            size: PrintSize::default(),
        },
    ]
}

#[test]
fn every_command_reads_back_as_written() {
    for command in commands() {
        let bytes = encode_command(&command);
        let back = decode_command(&bytes).expect("reads back");
        // Preset has no equality of its own: compare the debug forms (the spec's every field).
        assert_eq!(format!("{back:?}"), format!("{command:?}"));
        if let (ViewCommand::Load { shell, .. }, ViewCommand::Load { shell: back, .. }) =
            (&command, &back)
        {
            assert_eq!(back.preset.id, shell.preset.id);
            assert_eq!(back.spec, shell.spec, "the same spec");
        }
    }
}

fn news() -> Vec<ViewerNews> {
    let status = ViewStatus {
        shell: Some(ShellStatus {
            session: 4,
            rows_done: 312,
            rows: 577,
            done: false,
            settled: true,
            at_rest: false,
            failure: Some("the curve folds over itself at row 313".into()),
            pattern_hash: Some(0xdead_beef_0123_4567),
            mesh_hash: None,
            counts: Counts {
                vertices: 123_456,
                triangles: 234_567,
                pattern: Some((400, 2900)),
                picture: (1280, 960),
            },
        }),
        preview: Some(PreviewState::Whole),
    };
    let written = |body| {
        FileStage::Written(File {
            what: Download::Mesh(MeshFormat::Glb),
            name: "murex-cabritii.glb".into(),
            body,
        })
    };
    vec![
        ViewerNews::Opened(Ok("WebGPU".into())),
        ViewerNews::Opened(Err("no adapter".into())),
        ViewerNews::Frame {
            device: Device::Ready,
            report: Some(Box::new(FrameReport {
                loads: 3,
                file: Some(written(Body::Bytes((0..=255).collect()))),
                drawn: true,
                status: status.clone(),
                notice: Some("these values give no pattern".into()),
                planar: vec![
                    PlanarUpdate::Open(Some((400, 2900))),
                    PlanarUpdate::Rows {
                        first: 10,
                        rgba: vec![9; 400 * 4 * 2],
                    },
                    PlanarUpdate::Follow(12),
                    PlanarUpdate::Open(None),
                ],
            })),
            recorded: Some(Ok(())),
        },
        ViewerNews::Frame {
            device: Device::Ready,
            report: Some(Box::new(FrameReport {
                file: Some(FileStage::Written(File {
                    what: Download::Picture,
                    name: "murex-cabritii.png".into(),
                    body: Body::Url("blob:http://127.0.0.1/1234".into()),
                })),
                ..FrameReport::default()
            })),
            recorded: Some(Err("the canvas could not be read".into())),
        },
        ViewerNews::Frame {
            device: Device::Ready,
            report: Some(Box::new(FrameReport {
                file: Some(FileStage::Writing {
                    name: "murex-cabritii.3mf".into(),
                    done: 0.25,
                }),
                status: ViewStatus {
                    shell: None,
                    preview: Some(PreviewState::Filling),
                },
                ..FrameReport::default()
            })),
            recorded: None,
        },
        ViewerNews::Frame {
            device: Device::Ready,
            report: Some(Box::new(FrameReport {
                file: Some(FileStage::Finishing),
                ..FrameReport::default()
            })),
            recorded: None,
        },
        ViewerNews::Frame {
            device: Device::Ready,
            report: Some(Box::new(FrameReport {
                file: Some(FileStage::Refused("no shell is shown".into())),
                ..FrameReport::default()
            })),
            recorded: None,
        },
        ViewerNews::Frame {
            device: Device::Reopening("the context was lost".into()),
            report: None,
            recorded: None,
        },
        ViewerNews::Frame {
            device: Device::NeedsCanvas("WebGPU is gone".into()),
            report: None,
            recorded: None,
        },
        ViewerNews::Frame {
            device: Device::Reopened("WebGL2".into()),
            report: None,
            recorded: None,
        },
        ViewerNews::Frame {
            device: Device::Gone("no device".into()),
            report: None,
            recorded: None,
        },
        ViewerNews::Refused {
            loads: Some(7),
            why: "the spec has no rows".into(),
        },
        ViewerNews::Refused {
            loads: None,
            why: "a command was misread".into(),
        },
        ViewerNews::Pool(PoolNews {
            count: 3,
            status: "Growing on 3 workers.".into(),
            deaths: 2,
            words: Some("A worker was replaced twice".into()),
        }),
        ViewerNews::Crashed("Something went wrong while growing murex, row 4".into()),
        ViewerNews::Failed("the GPU refused the draw".into()),
    ]
}

#[test]
fn every_kind_of_news_reads_back_as_written() {
    for news in news() {
        let back = decode_news(&encode_news(&news)).expect("reads back");
        assert_eq!(back, news);
    }
}

#[test]
fn cut_or_padded_bytes_are_refused_never_misread() {
    for command in commands() {
        let bytes = encode_command(&command);
        for cut in 0..bytes.len() {
            assert!(
                decode_command(&bytes[..cut]).is_err(),
                "{command:?} cut to {cut} bytes of {} was read",
                bytes.len()
            );
        }
        let mut padded = bytes.clone();
        padded.push(0);
        let error = decode_command(&padded).expect_err("a stray byte is refused");
        assert_eq!(error.why, "1 bytes after its end");
    }
    for news in news() {
        let bytes = encode_news(&news);
        let mut padded = bytes.clone();
        padded.push(0);
        assert!(decode_news(&padded).is_err());
        for cut in (0..bytes.len()).step_by(97) {
            assert!(decode_news(&bytes[..cut]).is_err());
        }
    }
}

/// `bytes` with the first run of `old` replaced by `new`.
fn replaced(bytes: &[u8], old: &[u8], new: &[u8]) -> Vec<u8> {
    let at = bytes
        .windows(old.len())
        .position(|w| w == old)
        .expect("the bytes hold it");
    [&bytes[..at], new, &bytes[at + old.len()..]].concat()
}

#[test]
fn unknown_presets_sides_commands_and_sizes_out_of_range_are_refused() {
    let preset = presets::preset("turbinate").expect("a preset");
    let load = encode_command(&ViewCommand::Load {
        shell: PresetSpec::new(preset, preset.spec.clone()),
        finish: false,
    });
    let refused = |bytes: &[u8]| decode_command(bytes).expect_err("refused").key;
    assert_eq!(
        refused(&replaced(&load, b"turbinate", b"turbinaTe")),
        "command"
    );
    // A load is the first command: its number, its shell's link, whether to finish it.
    assert_eq!(load, wire::write(&(0u32, "v=1&preset=turbinate", false)));
    let bad = wire::write(&(0u32, "v=1&preset=turbinate&growth.rows=-5", false));
    assert_eq!(refused(&bad), "command");
    let file = encode_command(&ViewCommand::WriteFile {
        what: Download::Mesh(MeshFormat::Stl),
        size: PrintSize::default(),
    });
    let mm = PrintSize::DEFAULT_MM.to_le_bytes();
    assert_eq!(
        refused(&replaced(&file, &mm, &1e6f64.to_le_bytes())),
        "command"
    );
    assert_eq!(
        refused(&replaced(&file, &mm, &f64::NAN.to_le_bytes())),
        "command"
    );
    // The side is the last byte, the number of a variant of four.
    let mut sideways = file.clone();
    *sideways.last_mut().unwrap() = 4;
    assert_eq!(refused(&sideways), "command");
    // The command is the first byte, the number of a variant.
    let mut unknown = file.clone();
    unknown[0] = 100;
    assert_eq!(refused(&unknown), "command");
}

/// Links the page repairs, warns of or converts (the page tests' bad links): the shell the page
/// then shows crosses to the viewer as it is, whorls that overlap included.
#[test]
fn every_shell_the_page_shows_of_a_bad_link_crosses_as_it_is() {
    for fragment in [
        "#v=1&preset=turbinate&form.spiral.whorls=1e9",
        "#v=1&preset=oliva-porphyria&pattern.model.d_a=0.9",
        "#v=1&preset=oliva-porphyria&pattern.cells=2048&growth.rows=20000",
        "#v=1&preset=turbinate&form.spiral.whorls=30&form.spiral.subdivisions=16&form.curve.segments=512",
        "#v=1&preset=kawaguchi-shell&form.mouth.protuberances=0,-1.5",
        "#v=1&preset=kawaguchi-shell&form.mouth.apexes=256&form.chambers=2000&form.septa=true&form.chamber.ratio=1.001",
        "#v=1&preset=kawaguchi-shell&form.chambers=2000",
        "#v=1&preset=kawaguchi-ammonite&form.chamber.ratio=1",
        "#v=1&preset=implicit-whorl&form.spiral.lambda=1.01",
        "#v=1&preset=kawaguchi-shell&form.chamber.translation.x=0.1&form.chamber.translation.y=0.2&form.chamber.translation.z=0.15",
    ] {
        let shown = link::decode(fragment);
        assert!(
            !shown.problems.is_empty(),
            "{fragment} has something to say"
        );
        let command = ViewCommand::Load {
            shell: PresetSpec::new(shown.preset, shown.spec.clone()),
            finish: false,
        };
        let Ok(ViewCommand::Load { shell, .. }) = decode_command(&encode_command(&command)) else {
            panic!("{fragment} does not cross");
        };
        assert_eq!(
            (shell.preset.id, *shell.spec),
            (shown.preset.id, shown.spec),
            "{fragment}"
        );
    }
}
