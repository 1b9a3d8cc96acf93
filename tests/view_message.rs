//! The messages between the page and a viewer drawing in a worker (`work::view_message`): every
//! command and every kind of news reads back as it was written, a spec bit for bit; bytes that
//! are cut short, have a stray byte after them, name an unknown preset or carry a size out of
//! range are refused, never read as something else.
#![cfg(not(target_arch = "wasm32"))]

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
use seashells_core::work::view_command::{PointerChange, ViewCommand};
use seashells_core::work::view_message::{
    PoolNews, ViewerNews, decode_command, decode_news, encode_command, encode_news,
};
use seashells_core::work::view_status::{Device, FrameReport, ShellStatus, ViewStatus};

/// Every kind of command, with values that are not their defaults.
fn commands() -> Vec<ViewCommand> {
    let preset = presets::preset("murex-cabritii").expect("a preset");
    let edited = link::decode("#v=1&preset=oliva-porphyria&pattern.model.d_a=0.0123&seed=7");
    vec![
        ViewCommand::Load {
            preset,
            spec: Box::new(preset.spec.clone()),
            finish: true,
        },
        ViewCommand::Load {
            preset: edited.preset,
            spec: Box::new(edited.spec.clone()),
            finish: false,
        },
        ViewCommand::Restyle(Box::new(
            link::decode("#v=1&preset=murex-cabritii&material.gloss=0.9").spec,
        )),
        ViewCommand::Preview(Box::new(edited.spec)),
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
        if let (
            ViewCommand::Load { preset, spec, .. },
            ViewCommand::Load {
                preset: p, spec: s, ..
            },
        ) = (&command, &back)
        {
            assert_eq!(p.id, preset.id);
            assert_eq!(
                link::encode(p, s),
                link::encode(preset, spec),
                "the same link"
            );
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
        ViewerNews::Refused("the spec has no rows".into()),
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
        preset,
        spec: Box::new(preset.spec.clone()),
        finish: false,
    });
    let refused = |bytes: &[u8]| decode_command(bytes).expect_err("refused").key;
    assert_eq!(
        refused(&replaced(&load, b"turbinate", b"turbinaTe")),
        "command"
    );
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
