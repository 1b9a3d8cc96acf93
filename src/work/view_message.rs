//! The bytes the page and a viewer drawing in a worker send each other, in [`super::wire`]:
//! the page's [`ViewCommand`]s, and the viewer's [`ViewerNews`] (its renderer opened, each
//! frame's device and report, a shell refused, its pool of workers, a panic). What is not data
//! (a recording's `VideoFrame`, a fresh `OffscreenCanvas`) crosses beside the bytes,
//! transferred.

use super::file_writer::{Body, File, FileStage};
use super::planar_update::PlanarUpdate;
use super::view_command::{PointerChange, ViewCommand};
use super::view_status::{Device, FrameReport, ShellStatus, ViewStatus};
use super::wire::{Reader, WireError, Writer};
use crate::export::Download;
use crate::export::estimate::Counts;
use crate::export::print_size::{Along, PrintSize};
use crate::presets;
use crate::share::presentation::Layout;
use crate::spec::ShellSpec;
use crate::view::preview::PreviewState;
use crate::view::recording::FrameAsk;

/// What a viewer drawing in a worker tells the page.
#[derive(Clone, Debug, PartialEq)]
pub enum ViewerNews {
    /// Its renderer opened with this backend ("WebGPU" or "WebGL2"), or why none could be.
    Opened(Result<String, String>),
    /// A frame: the device's state and, when it was ready, the frame's report; and whether
    /// a recording's video frame was drawn (sent beside) or why not.
    Frame {
        device: Device,
        report: Option<Box<FrameReport>>,
        recorded: Option<Result<(), String>>,
    },
    /// The shell could not be built or grown: why, in words.
    Refused(String),
    /// What its pool of workers says of itself.
    Pool(PoolNews),
    /// Its renderer failed: the viewer draws no more (why, in words).
    Failed(String),
    /// It panicked: the message to show.
    Crashed(String),
}

/// What the drawing worker's pool of workers says of itself: how many, where the shells grow in
/// words, workers replaced so far and what the page should say of it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PoolNews {
    pub count: u32,
    pub status: String,
    pub deaths: u32,
    pub words: Option<String>,
}

fn bad(key: &'static str, at: usize) -> WireError {
    WireError { key, at }
}

fn write_spec(w: &mut Writer, spec: &ShellSpec) {
    w.str(&serde_json::to_string(spec).expect("a spec is always written as JSON"));
}

fn read_spec(r: &mut Reader) -> Result<ShellSpec, WireError> {
    let at = r.at();
    serde_json::from_str(&r.string("spec")?).map_err(|_| bad("spec", at))
}

fn write_download(w: &mut Writer, what: Download) {
    let i = Download::ALL.iter().position(|d| *d == what);
    w.u8(i.expect("every download is among ALL") as u8);
}

fn read_download(r: &mut Reader) -> Result<Download, WireError> {
    let at = r.at();
    let i = r.u8("download")?;
    Download::ALL
        .get(usize::from(i))
        .copied()
        .ok_or(bad("download", at))
}

/// The type of a file's bytes (the same for a download wherever it is written).
fn mime(what: Download) -> &'static str {
    match what {
        Download::Mesh(format) => format.mime(),
        Download::Picture | Download::Pattern => "image/png",
    }
}

const LOAD: u8 = 0;
const PREVIEW: u8 = 1;
const END_PREVIEW: u8 = 2;
const GROW: u8 = 3;
const FINISH: u8 = 4;
const PLAY: u8 = 5;
const HOLD: u8 = 6;
const SPEED: u8 = 7;
const LAYOUT: u8 = 8;
const RESET_CAMERA: u8 = 9;
const POINTER_DOWN: u8 = 10;
const POINTER_MOVE: u8 = 11;
const POINTER_UP: u8 = 12;
const WHEEL: u8 = 13;
const SHOWN: u8 = 14;
const BACKGROUND: u8 = 15;
const RECORD_AT: u8 = 16;
const ASK_FRAME: u8 = 17;
const WRITE_FILE: u8 = 18;
const RESTYLE: u8 = 19;

/// `command` as bytes.
pub fn encode_command(command: &ViewCommand) -> Vec<u8> {
    let mut w = Writer::default();
    match command {
        ViewCommand::Load {
            preset,
            spec,
            finish,
        } => {
            w.u8(LOAD);
            w.str(preset.id);
            write_spec(&mut w, spec);
            w.bool(*finish);
        }
        ViewCommand::Restyle(spec) => {
            w.u8(RESTYLE);
            write_spec(&mut w, spec);
        }
        ViewCommand::Preview(spec) => {
            w.u8(PREVIEW);
            write_spec(&mut w, spec);
        }
        ViewCommand::EndPreview => w.u8(END_PREVIEW),
        ViewCommand::Grow(rows) => {
            w.u8(GROW);
            w.len(*rows);
        }
        ViewCommand::Finish => w.u8(FINISH),
        ViewCommand::Play(playing) => {
            w.u8(PLAY);
            w.bool(*playing);
        }
        ViewCommand::Hold(held) => {
            w.u8(HOLD);
            w.bool(*held);
        }
        ViewCommand::Speed(speed) => {
            w.u8(SPEED);
            w.f64(*speed);
        }
        ViewCommand::Layout(layout) => {
            w.u8(LAYOUT);
            w.str(layout.name());
        }
        ViewCommand::ResetCamera => w.u8(RESET_CAMERA),
        ViewCommand::Pointer(PointerChange::Down { id, x, y }) => {
            w.u8(POINTER_DOWN);
            w.u32(*id as u32);
            w.f64(f64::from(*x));
            w.f64(f64::from(*y));
        }
        ViewCommand::Pointer(PointerChange::Move { id, x, y }) => {
            w.u8(POINTER_MOVE);
            w.u32(*id as u32);
            w.f64(f64::from(*x));
            w.f64(f64::from(*y));
        }
        ViewCommand::Pointer(PointerChange::Up { id }) => {
            w.u8(POINTER_UP);
            w.u32(*id as u32);
        }
        ViewCommand::Wheel(delta) => {
            w.u8(WHEEL);
            w.f64(*delta);
        }
        ViewCommand::Shown {
            width,
            height,
            pixel_ratio,
        } => {
            w.u8(SHOWN);
            w.u32(*width);
            w.u32(*height);
            w.f64(*pixel_ratio);
        }
        ViewCommand::Background(srgb) => {
            w.u8(BACKGROUND);
            w.bytes(srgb);
        }
        ViewCommand::RecordAt(size) => {
            w.u8(RECORD_AT);
            w.bool(size.is_some());
            if let Some((width, height)) = size {
                w.u32(*width);
                w.u32(*height);
            }
        }
        ViewCommand::AskFrame(ask) => {
            w.u8(ASK_FRAME);
            w.len(ask.row);
            w.f64(f64::from(ask.dt));
            w.f64(f64::from(ask.turn));
            w.u64(ask.timestamp_us);
            w.u64(ask.duration_us);
        }
        ViewCommand::WriteFile { what, size } => {
            w.u8(WRITE_FILE);
            write_download(&mut w, *what);
            w.f64(size.mm());
            w.u8(Along::ALL
                .iter()
                .position(|&a| a == size.side())
                .unwrap_or(0) as u8);
        }
    }
    w.into_bytes()
}

/// The command written by [`encode_command`], or where its bytes could not be read.
pub fn decode_command(bytes: &[u8]) -> Result<ViewCommand, WireError> {
    let mut r = Reader::new(bytes);
    let at = r.at();
    let command = match r.u8("command")? {
        LOAD => {
            let at = r.at();
            let id = r.string("preset")?;
            let preset = presets::preset(&id).ok_or(bad("preset", at))?;
            ViewCommand::Load {
                preset,
                spec: Box::new(read_spec(&mut r)?),
                finish: r.bool("finish")?,
            }
        }
        RESTYLE => ViewCommand::Restyle(Box::new(read_spec(&mut r)?)),
        PREVIEW => ViewCommand::Preview(Box::new(read_spec(&mut r)?)),
        END_PREVIEW => ViewCommand::EndPreview,
        GROW => ViewCommand::Grow(r.len("rows")?),
        FINISH => ViewCommand::Finish,
        PLAY => ViewCommand::Play(r.bool("playing")?),
        HOLD => ViewCommand::Hold(r.bool("held")?),
        SPEED => ViewCommand::Speed(r.f64("speed")?),
        LAYOUT => {
            let at = r.at();
            let (layout, problem) = Layout::parse(&r.string("layout")?);
            if problem.is_some() {
                return Err(bad("layout", at));
            }
            ViewCommand::Layout(layout)
        }
        RESET_CAMERA => ViewCommand::ResetCamera,
        POINTER_DOWN => ViewCommand::Pointer(PointerChange::Down {
            id: r.u32("pointer")? as i32,
            x: r.f64("x")? as f32,
            y: r.f64("y")? as f32,
        }),
        POINTER_MOVE => ViewCommand::Pointer(PointerChange::Move {
            id: r.u32("pointer")? as i32,
            x: r.f64("x")? as f32,
            y: r.f64("y")? as f32,
        }),
        POINTER_UP => ViewCommand::Pointer(PointerChange::Up {
            id: r.u32("pointer")? as i32,
        }),
        WHEEL => ViewCommand::Wheel(r.f64("wheel")?),
        SHOWN => ViewCommand::Shown {
            width: r.u32("width")?,
            height: r.u32("height")?,
            pixel_ratio: r.f64("pixel ratio")?,
        },
        BACKGROUND => {
            let at = r.at();
            let srgb = r.bytes("background")?;
            ViewCommand::Background(srgb.try_into().map_err(|_| bad("background", at))?)
        }
        RECORD_AT => ViewCommand::RecordAt(if r.bool("recording")? {
            Some((r.u32("width")?, r.u32("height")?))
        } else {
            None
        }),
        ASK_FRAME => ViewCommand::AskFrame(FrameAsk {
            row: r.len("row")?,
            dt: r.f64("dt")? as f32,
            turn: r.f64("turn")? as f32,
            timestamp_us: r.u64("timestamp")?,
            duration_us: r.u64("duration")?,
        }),
        WRITE_FILE => {
            let what = read_download(&mut r)?;
            let at = r.at();
            let size = PrintSize::new(r.f64("size")?, "size").map_err(|_| bad("size", at))?;
            let at = r.at();
            let along = *Along::ALL
                .get(usize::from(r.u8("side")?))
                .ok_or_else(|| bad("side", at))?;
            let size = size.along(along);
            ViewCommand::WriteFile { what, size }
        }
        _ => return Err(bad("command", at)),
    };
    r.end()?;
    Ok(command)
}

fn write_device(w: &mut Writer, device: &Device) {
    let (tag, words) = match device {
        Device::Ready => (0, ""),
        Device::Reopening(why) => (1, why.as_str()),
        Device::NeedsCanvas(why) => (2, why.as_str()),
        Device::Reopened(backend) => (3, backend.as_str()),
        Device::Gone(why) => (4, why.as_str()),
    };
    w.u8(tag);
    w.str(words);
}

fn read_device(r: &mut Reader) -> Result<Device, WireError> {
    let at = r.at();
    let tag = r.u8("device")?;
    let words = r.string("device")?;
    Ok(match tag {
        0 => Device::Ready,
        1 => Device::Reopening(words),
        2 => Device::NeedsCanvas(words),
        3 => Device::Reopened(words),
        4 => Device::Gone(words),
        _ => return Err(bad("device", at)),
    })
}

fn write_file_stage(w: &mut Writer, stage: &FileStage) {
    match stage {
        FileStage::Finishing => w.u8(0),
        FileStage::Writing { name, done } => {
            w.u8(1);
            w.str(name);
            w.f64(*done);
        }
        FileStage::Written(File { what, name, body }) => {
            w.u8(2);
            write_download(w, *what);
            w.str(name);
            match body {
                Body::Bytes { bytes, .. } => {
                    w.bool(true);
                    w.bytes(bytes);
                }
                Body::Url(url) => {
                    w.bool(false);
                    w.str(url);
                }
            }
        }
        FileStage::Refused(why) => {
            w.u8(3);
            w.str(why);
        }
    }
}

fn read_file_stage(r: &mut Reader) -> Result<FileStage, WireError> {
    let at = r.at();
    Ok(match r.u8("file")? {
        0 => FileStage::Finishing,
        1 => FileStage::Writing {
            name: r.string("file name")?,
            done: r.f64("done")?,
        },
        2 => {
            let what = read_download(r)?;
            let name = r.string("file name")?;
            let body = if r.bool("body")? {
                Body::Bytes {
                    mime: mime(what),
                    bytes: r.bytes("file")?.to_vec(),
                }
            } else {
                Body::Url(r.string("file address")?)
            };
            FileStage::Written(File { what, name, body })
        }
        3 => FileStage::Refused(r.string("why")?),
        _ => return Err(bad("file", at)),
    })
}

fn write_option_u64(w: &mut Writer, x: Option<u64>) {
    w.bool(x.is_some());
    if let Some(x) = x {
        w.u64(x);
    }
}

fn read_option_u64(r: &mut Reader, key: &'static str) -> Result<Option<u64>, WireError> {
    Ok(if r.bool(key)? {
        Some(r.u64(key)?)
    } else {
        None
    })
}

fn write_status(w: &mut Writer, status: &ViewStatus) {
    w.bool(status.shell.is_some());
    if let Some(s) = &status.shell {
        w.u32(s.session);
        w.len(s.rows_done);
        w.len(s.rows);
        w.bool(s.done);
        w.bool(s.settled);
        w.bool(s.at_rest);
        w.option_str(s.failure.as_deref());
        write_option_u64(w, s.pattern_hash);
        write_option_u64(w, s.mesh_hash);
        let c = &s.counts;
        w.len(c.vertices);
        w.len(c.triangles);
        w.bool(c.pattern.is_some());
        if let Some((cells, rows)) = c.pattern {
            w.len(cells);
            w.len(rows);
        }
        w.len(c.picture.0);
        w.len(c.picture.1);
    }
    w.u8(match status.preview {
        None => 0,
        Some(PreviewState::Filling) => 1,
        Some(PreviewState::Whole) => 2,
        Some(PreviewState::Stopped) => 3,
    });
}

fn read_status(r: &mut Reader) -> Result<ViewStatus, WireError> {
    let shell = if r.bool("shell")? {
        Some(ShellStatus {
            session: r.u32("session")?,
            rows_done: r.len("rows done")?,
            rows: r.len("rows")?,
            done: r.bool("done")?,
            settled: r.bool("settled")?,
            at_rest: r.bool("at rest")?,
            failure: r.option_string("failure")?,
            pattern_hash: read_option_u64(r, "pattern hash")?,
            mesh_hash: read_option_u64(r, "mesh hash")?,
            counts: Counts {
                vertices: r.len("vertices")?,
                triangles: r.len("triangles")?,
                pattern: if r.bool("pattern")? {
                    Some((r.len("cells")?, r.len("pattern rows")?))
                } else {
                    None
                },
                picture: (r.len("picture width")?, r.len("picture height")?),
            },
        })
    } else {
        None
    };
    let at = r.at();
    let preview = match r.u8("preview")? {
        0 => None,
        1 => Some(PreviewState::Filling),
        2 => Some(PreviewState::Whole),
        3 => Some(PreviewState::Stopped),
        _ => return Err(bad("preview", at)),
    };
    Ok(ViewStatus { shell, preview })
}

fn write_planar(w: &mut Writer, update: &PlanarUpdate) {
    match update {
        PlanarUpdate::Open(size) => {
            w.u8(0);
            w.bool(size.is_some());
            if let Some((cells, rows)) = size {
                w.u32(*cells);
                w.u32(*rows);
            }
        }
        PlanarUpdate::Rows { first, rgba } => {
            w.u8(1);
            w.u32(*first);
            w.bytes(rgba);
        }
        PlanarUpdate::Follow(row) => {
            w.u8(2);
            w.u32(*row);
        }
    }
}

fn read_planar(r: &mut Reader) -> Result<PlanarUpdate, WireError> {
    let at = r.at();
    Ok(match r.u8("planar")? {
        0 => PlanarUpdate::Open(if r.bool("pattern")? {
            Some((r.u32("cells")?, r.u32("rows")?))
        } else {
            None
        }),
        1 => PlanarUpdate::Rows {
            first: r.u32("first row")?,
            rgba: r.bytes("rows")?.to_vec(),
        },
        2 => PlanarUpdate::Follow(r.u32("row")?),
        _ => return Err(bad("planar", at)),
    })
}

fn write_report(w: &mut Writer, report: &FrameReport) {
    w.bool(report.file.is_some());
    if let Some(stage) = &report.file {
        write_file_stage(w, stage);
    }
    w.bool(report.drawn);
    write_status(w, &report.status);
    w.option_str(report.notice.as_deref());
    w.len(report.planar.len());
    for update in &report.planar {
        write_planar(w, update);
    }
}

fn read_report(r: &mut Reader) -> Result<FrameReport, WireError> {
    let file = if r.bool("file")? {
        Some(read_file_stage(r)?)
    } else {
        None
    };
    let drawn = r.bool("drawn")?;
    let status = read_status(r)?;
    let notice = r.option_string("notice")?;
    let n = r.len("planar updates")?;
    let planar = (0..n).map(|_| read_planar(r)).collect::<Result<_, _>>()?;
    Ok(FrameReport {
        file,
        drawn,
        status,
        notice,
        planar,
    })
}

fn write_result(w: &mut Writer, result: &Result<impl AsRef<str>, String>) {
    w.bool(result.is_ok());
    match result {
        Ok(words) => w.str(words.as_ref()),
        Err(why) => w.str(why),
    }
}

/// `news` as bytes.
pub fn encode_news(news: &ViewerNews) -> Vec<u8> {
    let mut w = Writer::default();
    match news {
        ViewerNews::Opened(result) => {
            w.u8(0);
            write_result(&mut w, result);
        }
        ViewerNews::Frame {
            device,
            report,
            recorded,
        } => {
            w.u8(1);
            write_device(&mut w, device);
            w.bool(report.is_some());
            if let Some(report) = report {
                write_report(&mut w, report);
            }
            w.bool(recorded.is_some());
            if let Some(recorded) = recorded {
                write_result(
                    &mut w,
                    &recorded.as_ref().map(|()| "").map_err(Clone::clone),
                );
            }
        }
        ViewerNews::Refused(why) => {
            w.u8(2);
            w.str(why);
        }
        ViewerNews::Pool(pool) => {
            w.u8(3);
            w.u32(pool.count);
            w.str(&pool.status);
            w.u32(pool.deaths);
            w.option_str(pool.words.as_deref());
        }
        ViewerNews::Crashed(message) => {
            w.u8(4);
            w.str(message);
        }
        ViewerNews::Failed(why) => {
            w.u8(5);
            w.str(why);
        }
    }
    w.into_bytes()
}

/// The news written by [`encode_news`], or where its bytes could not be read.
pub fn decode_news(bytes: &[u8]) -> Result<ViewerNews, WireError> {
    let mut r = Reader::new(bytes);
    let at = r.at();
    let news = match r.u8("news")? {
        0 => {
            let ok = r.bool("opened")?;
            let words = r.string("backend")?;
            ViewerNews::Opened(if ok { Ok(words) } else { Err(words) })
        }
        1 => {
            let device = read_device(&mut r)?;
            let report = if r.bool("report")? {
                Some(Box::new(read_report(&mut r)?))
            } else {
                None
            };
            let recorded = if r.bool("recorded")? {
                let ok = r.bool("recorded")?;
                let why = r.string("recorded")?;
                Some(if ok { Ok(()) } else { Err(why) })
            } else {
                None
            };
            ViewerNews::Frame {
                device,
                report,
                recorded,
            }
        }
        2 => ViewerNews::Refused(r.string("why")?),
        3 => ViewerNews::Pool(PoolNews {
            count: r.u32("workers")?,
            status: r.string("status")?,
            deaths: r.u32("deaths")?,
            words: r.option_string("words")?,
        }),
        4 => ViewerNews::Crashed(r.string("message")?),
        5 => ViewerNews::Failed(r.string("why")?),
        _ => return Err(bad("news", at)),
    };
    r.end()?;
    Ok(news)
}
