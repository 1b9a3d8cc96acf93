//! A WebM muxer: encoded video frames (VP9, VP8 or AV1, as the browser's `VideoEncoder` makes
//! them) into one WebM file, a Matroska subset written as EBML. The file is assembled whole
//! when the recording ends, so it knows its sizes and duration, and carries a seek head and
//! cues (one per cluster, each cluster starting on a key frame) for players to seek by.
//!
//! Written here rather than taken from a library: the page's Content-Security-Policy serves
//! only its own files, the format needs a few dozen lines of EBML, and in the pure core it is
//! tested natively; a third-party reader checks the page's files in the page tests.

use std::fmt;

/// A video codec WebM carries, in the order the page prefers them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VideoCodec {
    Vp9,
    Vp8,
    Av1,
}

impl VideoCodec {
    /// The page's preference: the best compression a browser commonly encodes in software
    /// first, the oldest and fastest next, AV1 (slow to encode without hardware) last.
    pub const PREFERENCE: [VideoCodec; 3] = [VideoCodec::Vp9, VideoCodec::Vp8, VideoCodec::Av1];

    /// The WebCodecs codec string (profile 0, 8 bits; a level that holds 1080p at 60 fps).
    pub fn codec_string(self) -> &'static str {
        match self {
            VideoCodec::Vp9 => "vp09.00.41.08",
            VideoCodec::Vp8 => "vp8",
            VideoCodec::Av1 => "av01.0.09M.08",
        }
    }

    /// The Matroska codec id.
    pub fn matroska_id(self) -> &'static str {
        match self {
            VideoCodec::Vp9 => "V_VP9",
            VideoCodec::Vp8 => "V_VP8",
            VideoCodec::Av1 => "V_AV1",
        }
    }

    /// The name people know it by.
    pub fn name(self) -> &'static str {
        match self {
            VideoCodec::Vp9 => "VP9",
            VideoCodec::Vp8 => "VP8",
            VideoCodec::Av1 => "AV1",
        }
    }
}

/// A frame the muxer cannot take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MuxError {
    /// What was wrong: "timestamp".
    pub key: &'static str,
    pub message: String,
}

impl fmt::Display for MuxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for MuxError {}

/// Element ids (Matroska's specification, with their marker bits).
mod id {
    pub const EBML: u32 = 0x1A45_DFA3;
    pub const EBML_VERSION: u32 = 0x4286;
    pub const EBML_READ_VERSION: u32 = 0x42F7;
    pub const EBML_MAX_ID_LENGTH: u32 = 0x42F2;
    pub const EBML_MAX_SIZE_LENGTH: u32 = 0x42F3;
    pub const DOC_TYPE: u32 = 0x4282;
    pub const DOC_TYPE_VERSION: u32 = 0x4287;
    pub const DOC_TYPE_READ_VERSION: u32 = 0x4285;
    pub const SEGMENT: u32 = 0x1853_8067;
    pub const SEEK_HEAD: u32 = 0x114D_9B74;
    pub const SEEK: u32 = 0x4DBB;
    pub const SEEK_ID: u32 = 0x53AB;
    pub const SEEK_POSITION: u32 = 0x53AC;
    pub const INFO: u32 = 0x1549_A966;
    pub const TIMESTAMP_SCALE: u32 = 0x2A_D7B1;
    pub const DURATION: u32 = 0x4489;
    pub const MUXING_APP: u32 = 0x4D80;
    pub const WRITING_APP: u32 = 0x5741;
    pub const TRACKS: u32 = 0x1654_AE6B;
    pub const TRACK_ENTRY: u32 = 0xAE;
    pub const TRACK_NUMBER: u32 = 0xD7;
    pub const TRACK_UID: u32 = 0x73C5;
    pub const TRACK_TYPE: u32 = 0x83;
    pub const FLAG_LACING: u32 = 0x9C;
    pub const CODEC_ID: u32 = 0x86;
    pub const CODEC_PRIVATE: u32 = 0x63A2;
    pub const DEFAULT_DURATION: u32 = 0x23_E383;
    pub const VIDEO: u32 = 0xE0;
    pub const PIXEL_WIDTH: u32 = 0xB0;
    pub const PIXEL_HEIGHT: u32 = 0xBA;
    pub const CLUSTER: u32 = 0x1F43_B675;
    pub const TIMESTAMP: u32 = 0xE7;
    pub const SIMPLE_BLOCK: u32 = 0xA3;
    pub const CUES: u32 = 0x1C53_BB6B;
    pub const CUE_POINT: u32 = 0xBB;
    pub const CUE_TIME: u32 = 0xB3;
    pub const CUE_TRACK_POSITIONS: u32 = 0xB7;
    pub const CUE_TRACK: u32 = 0xF7;
    pub const CUE_CLUSTER_POSITION: u32 = 0xF1;
}

/// Nanoseconds per tick of the file's timestamps: milliseconds, Matroska's default.
const TIMESTAMP_SCALE_NS: u64 = 1_000_000;
/// The one track's number.
const TRACK: u8 = 1;

/// An element id: its bytes as written (the id carries its own length).
fn put_id(out: &mut Vec<u8>, id: u32) {
    let bytes = id.to_be_bytes();
    let skip = bytes.iter().take_while(|&&b| b == 0).count();
    out.extend_from_slice(&bytes[skip..]);
}

/// An element's data size as an EBML variable-length integer, in as few bytes as it needs
/// (all ones at any length is reserved for "unknown").
fn put_size(out: &mut Vec<u8>, size: u64) {
    let length = (1..=8u32)
        .find(|&l| size < (1u64 << (7 * l)) - 1)
        .expect("an element is smaller than 2^56 bytes");
    let marked = size | (1u64 << (7 * length));
    out.extend_from_slice(&marked.to_be_bytes()[8 - length as usize..]);
}

fn element(out: &mut Vec<u8>, id: u32, data: &[u8]) {
    put_id(out, id);
    put_size(out, data.len() as u64);
    out.extend_from_slice(data);
}

/// An unsigned integer element in as few bytes as it needs.
fn uint(out: &mut Vec<u8>, id: u32, value: u64) {
    let bytes = value.to_be_bytes();
    let skip = bytes.iter().take_while(|&&b| b == 0).count().min(7);
    element(out, id, &bytes[skip..]);
}

/// An unsigned integer element in eight bytes: positions in the seek head, whose size must not
/// depend on the positions it holds.
fn uint8(out: &mut Vec<u8>, id: u32, value: u64) {
    element(out, id, &value.to_be_bytes());
}

fn master(out: &mut Vec<u8>, id: u32, fill: impl FnOnce(&mut Vec<u8>)) {
    let mut data = Vec::new();
    fill(&mut data);
    element(out, id, &data);
}

/// A cluster: frames from one key frame to the next.
struct Cluster {
    /// Its first frame's time, in ticks.
    time: u64,
    /// Its SimpleBlocks, written.
    blocks: Vec<u8>,
}

/// One video track's frames, collected until [`WebmWriter::finish`] writes the file.
pub struct WebmWriter {
    codec: VideoCodec,
    width: u32,
    height: u32,
    /// Nanoseconds per frame.
    frame_ns: u64,
    codec_private: Option<Vec<u8>>,
    clusters: Vec<Cluster>,
    frames: usize,
    /// The last frame's time, in ticks.
    last: Option<u64>,
}

impl WebmWriter {
    /// A file of `width` × `height` frames at `fps` frames a second.
    pub fn new(codec: VideoCodec, width: u32, height: u32, fps: u32) -> Self {
        Self {
            codec,
            width,
            height,
            frame_ns: 1_000_000_000 / u64::from(fps.max(1)),
            codec_private: None,
            clusters: Vec::new(),
            frames: 0,
            last: None,
        }
    }

    /// The decoder's configuration bytes, when the encoder gives them (AV1's `av1C`).
    pub fn set_codec_private(&mut self, bytes: &[u8]) {
        self.codec_private = Some(bytes.to_vec());
    }

    /// Frames taken so far.
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// Adds an encoded frame shown at `timestamp_us` microseconds; a key frame starts a new
    /// cluster, and so does a frame too far (32 s) from its cluster's start. Frames must come
    /// in order of time.
    pub fn push(&mut self, frame: &[u8], timestamp_us: u64, key: bool) -> Result<(), MuxError> {
        let time = timestamp_us * 1000 / TIMESTAMP_SCALE_NS;
        if let Some(last) = self.last.filter(|&last| time <= last) {
            return Err(MuxError {
                key: "timestamp",
                message: format!(
                    "a frame at {time} ms comes after one at {last} ms; frames must come in order of time"
                ),
            });
        }
        let far = |c: &Cluster| time - c.time > i16::MAX as u64;
        if key || self.clusters.last().is_none_or(far) {
            self.clusters.push(Cluster {
                time,
                blocks: Vec::new(),
            });
        }
        let cluster = self.clusters.last_mut().expect("a cluster was just made");
        let relative = (time - cluster.time) as i16;
        let mut block = Vec::with_capacity(frame.len() + 4);
        block.push(0x80 | TRACK);
        block.extend_from_slice(&relative.to_be_bytes());
        block.push(if key { 0x80 } else { 0 });
        block.extend_from_slice(frame);
        element(&mut cluster.blocks, id::SIMPLE_BLOCK, &block);
        self.frames += 1;
        self.last = Some(time);
        Ok(())
    }

    /// The file's duration in ticks: to the end of the last frame.
    fn duration(&self) -> f64 {
        match self.last {
            Some(last) => last as f64 + self.frame_ns as f64 / TIMESTAMP_SCALE_NS as f64,
            None => 0.0,
        }
    }

    /// The whole file.
    pub fn finish(self) -> Vec<u8> {
        let mut header = Vec::new();
        master(&mut header, id::EBML, |e| {
            uint(e, id::EBML_VERSION, 1);
            uint(e, id::EBML_READ_VERSION, 1);
            uint(e, id::EBML_MAX_ID_LENGTH, 4);
            uint(e, id::EBML_MAX_SIZE_LENGTH, 8);
            element(e, id::DOC_TYPE, b"webm");
            uint(e, id::DOC_TYPE_VERSION, 4);
            uint(e, id::DOC_TYPE_READ_VERSION, 2);
        });
        let mut info = Vec::new();
        master(&mut info, id::INFO, |e| {
            uint(e, id::TIMESTAMP_SCALE, TIMESTAMP_SCALE_NS);
            element(e, id::DURATION, &self.duration().to_be_bytes());
            element(e, id::MUXING_APP, b"seashells");
            element(e, id::WRITING_APP, b"seashells");
        });
        let mut tracks = Vec::new();
        master(&mut tracks, id::TRACKS, |e| {
            master(e, id::TRACK_ENTRY, |t| {
                uint(t, id::TRACK_NUMBER, u64::from(TRACK));
                uint(t, id::TRACK_UID, 1);
                uint(t, id::TRACK_TYPE, 1);
                uint(t, id::FLAG_LACING, 0);
                element(t, id::CODEC_ID, self.codec.matroska_id().as_bytes());
                if let Some(private) = &self.codec_private {
                    element(t, id::CODEC_PRIVATE, private);
                }
                uint(t, id::DEFAULT_DURATION, self.frame_ns);
                master(t, id::VIDEO, |v| {
                    uint(v, id::PIXEL_WIDTH, u64::from(self.width));
                    uint(v, id::PIXEL_HEIGHT, u64::from(self.height));
                });
            });
        });
        let seek_head = |positions: [(u32, u64); 3]| {
            let mut out = Vec::new();
            master(&mut out, id::SEEK_HEAD, |e| {
                for (target, position) in positions {
                    master(e, id::SEEK, |s| {
                        let mut target_id = Vec::new();
                        put_id(&mut target_id, target);
                        element(s, id::SEEK_ID, &target_id);
                        uint8(s, id::SEEK_POSITION, position);
                    });
                }
            });
            out
        };
        // Positions count from the start of the segment's data; the seek head's size does not
        // depend on them, so a first pass with zeros measures it.
        let head_size = seek_head([(id::INFO, 0), (id::TRACKS, 0), (id::CUES, 0)]).len() as u64;
        let info_at = head_size;
        let tracks_at = info_at + info.len() as u64;
        let mut clusters = Vec::new();
        let mut cue_points = Vec::new();
        let clusters_at = tracks_at + tracks.len() as u64;
        for c in &self.clusters {
            let at = clusters_at + clusters.len() as u64;
            master(&mut cue_points, id::CUE_POINT, |p| {
                uint(p, id::CUE_TIME, c.time);
                master(p, id::CUE_TRACK_POSITIONS, |t| {
                    uint(t, id::CUE_TRACK, u64::from(TRACK));
                    uint(t, id::CUE_CLUSTER_POSITION, at);
                });
            });
            master(&mut clusters, id::CLUSTER, |e| {
                uint(e, id::TIMESTAMP, c.time);
                e.extend_from_slice(&c.blocks);
            });
        }
        let cues_at = clusters_at + clusters.len() as u64;
        let mut cues = Vec::new();
        element(&mut cues, id::CUES, &cue_points);
        let head = seek_head([
            (id::INFO, info_at),
            (id::TRACKS, tracks_at),
            (id::CUES, cues_at),
        ]);
        let mut segment = head;
        for part in [info, tracks, clusters, cues] {
            segment.extend_from_slice(&part);
        }
        let mut out = header;
        element(&mut out, id::SEGMENT, &segment);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reads an element at `at`: (id, data range).
    fn read(bytes: &[u8], at: usize) -> (u32, std::ops::Range<usize>) {
        let id_len = bytes[at].leading_zeros() as usize + 1;
        let id = bytes[at..at + id_len]
            .iter()
            .fold(0u32, |a, &b| a << 8 | u32::from(b));
        let size_at = at + id_len;
        let size_len = bytes[size_at].leading_zeros() as usize + 1;
        let mut size = u64::from(bytes[size_at] & (0xFF >> size_len));
        for &b in &bytes[size_at + 1..size_at + size_len] {
            size = size << 8 | u64::from(b);
        }
        let start = size_at + size_len;
        (id, start..start + size as usize)
    }

    /// The children of the element whose data is `range`.
    fn children(bytes: &[u8], range: std::ops::Range<usize>) -> Vec<(u32, std::ops::Range<usize>)> {
        let mut out = Vec::new();
        let mut at = range.start;
        while at < range.end {
            let (id, data) = read(bytes, at);
            at = data.end;
            out.push((id, data));
        }
        assert_eq!(at, range.end, "children fill their parent exactly");
        out
    }

    fn number(bytes: &[u8]) -> u64 {
        bytes.iter().fold(0, |a, &b| a << 8 | u64::from(b))
    }

    #[test]
    fn sizes_take_the_fewest_bytes_and_avoid_the_reserved_value() {
        let size = |n| {
            let mut v = Vec::new();
            put_size(&mut v, n);
            v
        };
        assert_eq!(size(0), [0x80]);
        assert_eq!(size(126), [0xFE]);
        assert_eq!(size(127), [0x40, 0x7F], "0xFF alone means unknown");
        assert_eq!(size(16_382), [0x7F, 0xFE]);
        assert_eq!(size(16_383), [0x20, 0x3F, 0xFF]);
    }

    #[test]
    fn a_stream_reads_back_frame_for_frame_with_its_clusters_cues_and_duration() {
        let mut w = WebmWriter::new(VideoCodec::Vp9, 1280, 720, 30);
        let frames = 75;
        for i in 0..frames {
            let data = vec![i as u8; 10 + i * 7];
            w.push(&data, i as u64 * 1_000_000 / 30, i % 60 == 0)
                .unwrap();
        }
        assert_eq!(w.frames(), frames);
        let file = w.finish();
        let top = children(&file, 0..file.len());
        assert_eq!(top.len(), 2);
        assert_eq!(top[0].0, id::EBML);
        let header = children(&file, top[0].1.clone());
        let doc_type = header.iter().find(|(i, _)| *i == id::DOC_TYPE).unwrap();
        assert_eq!(&file[doc_type.1.clone()], b"webm");
        assert_eq!(top[1].0, id::SEGMENT);
        let segment_start = top[1].1.start;
        let parts = children(&file, top[1].1.clone());
        let ids: Vec<u32> = parts.iter().map(|p| p.0).collect();
        assert_eq!(
            ids,
            [
                id::SEEK_HEAD,
                id::INFO,
                id::TRACKS,
                id::CLUSTER,
                id::CLUSTER,
                id::CUES
            ]
        );
        // The seek head points at the elements it names.
        for (_, seek) in children(&file, parts[0].1.clone()) {
            let fields = children(&file, seek.clone());
            let target = number(&file[fields[0].1.clone()]) as u32;
            let position = number(&file[fields[1].1.clone()]) as usize;
            assert_eq!(read(&file, segment_start + position).0, target);
        }
        let info = children(&file, parts[1].1.clone());
        let duration = info.iter().find(|(i, _)| *i == id::DURATION).unwrap();
        let duration = f64::from_be_bytes(file[duration.1.clone()].try_into().unwrap());
        assert!(
            (duration - 2500.0).abs() < 1.0,
            "75 frames at 30 fps: {duration} ms"
        );
        let track = children(&file, parts[2].1.clone());
        let entry = children(&file, track[0].1.clone());
        let codec = entry.iter().find(|(i, _)| *i == id::CODEC_ID).unwrap();
        assert_eq!(&file[codec.1.clone()], b"V_VP9");
        let video = entry.iter().find(|(i, _)| *i == id::VIDEO).unwrap();
        let dims: Vec<u64> = children(&file, video.1.clone())
            .iter()
            .map(|(_, r)| number(&file[r.clone()]))
            .collect();
        assert_eq!(dims, [1280, 720]);
        // Every frame is there, in order, with its time and key flag.
        let mut seen = 0;
        for cluster in &parts[3..5] {
            let items = children(&file, cluster.1.clone());
            let base = number(&file[items[0].1.clone()]);
            for (n, (kind, block)) in items[1..].iter().enumerate() {
                assert_eq!(*kind, id::SIMPLE_BLOCK);
                let b = &file[block.clone()];
                assert_eq!(b[0], 0x81);
                let time = base as i64 + i64::from(i16::from_be_bytes([b[1], b[2]]));
                assert_eq!(time, (seen as i64 * 1000) / 30);
                assert_eq!(b[3] == 0x80, seen % 60 == 0, "frame {seen}");
                assert_eq!(n == 0, seen % 60 == 0, "a cluster starts on a key frame");
                assert_eq!(&b[4..], vec![seen as u8; 10 + seen * 7]);
                seen += 1;
            }
        }
        assert_eq!(seen, frames);
        // One cue per cluster, pointing at it.
        let cues = children(&file, parts[5].1.clone());
        assert_eq!(cues.len(), 2);
        for (cue, cluster) in cues.iter().zip(&parts[3..5]) {
            let fields = children(&file, cue.1.clone());
            let positions = children(&file, fields[1].1.clone());
            let at = number(&file[positions[1].1.clone()]) as usize;
            assert_eq!(read(&file, segment_start + at), *cluster);
        }
    }

    #[test]
    fn frames_out_of_order_are_refused_by_key() {
        let mut w = WebmWriter::new(VideoCodec::Vp8, 64, 64, 60);
        w.push(&[1], 100_000, true).unwrap();
        let e = w.push(&[2], 50_000, false).unwrap_err();
        assert_eq!(e.key, "timestamp");
        assert_eq!(w.frames(), 1);
    }
}
