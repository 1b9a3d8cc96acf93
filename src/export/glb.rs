//! glTF 2.0 binary (GLB), the web's 3D format, in the shell's colours.
//!
//! Two primitives: the outer surface, whose `TEXCOORD_0` places the vertex's pattern
//! coordinates on the coloured planar pattern (embedded as a PNG `baseColorTexture`, filtered
//! by the viewer to the colours the page shows; the ground colour as a factor when there is no
//! pattern; where an implicit shell's parts blend their own colours into the pattern
//! (Galbraith et al. §3.4), which a texture cannot carry, the page's colour of every vertex as
//! `COLOR_0` instead), and the parts without a pattern (the inside of the wall, the lip and caps) in the
//! interior colour. Vertices are welded where every attribute agrees, so the surface is smooth
//! where the form made it smooth and split where the form split it (creases, the faceted look,
//! the seam where the pattern's x wraps). A triangle belongs to the part of its first corner,
//! whose surface the page's shader uses for the whole triangle.
//!
//! The mesh keeps the shell's own coordinates; the node turns it apex up (+y) to face the
//! viewer's front (+z) as the page first shows it, and scales it to its height in metres.
//! The JSON is written with `serde_json`, which the crate already uses: the document is a few
//! dozen fixed fields, and a typed glTF crate would add more code than it saves.

use super::error::ExportError;
use super::paint::Paint;
use super::placement::{fit, turn};
use super::png::{PngRows, rows_per_step};
use super::shell::Shell;
use super::steps::{Cursor, Writer, progress};
use crate::mesh::{Bounds, Vertex};
use glam::{DQuat, DVec3, Vec3};
use serde_json::{Value, json};
use std::collections::HashMap;

/// Triangles welded per step.
const TRIANGLES_PER_STEP: usize = 4096;
/// Vertices written per step.
const VERTICES_PER_STEP: usize = 8192;
/// Indices copied per step.
const INDICES_PER_STEP: usize = 65_536;
/// Bytes of the binary buffer copied into the file per step.
const BYTES_PER_STEP: usize = 1 << 20;
/// Shares of the work: welding, vertices, indices, texture, assembly, copying.
const WEIGHTS: [f64; 6] = [0.45, 0.2, 0.05, 0.2, 0.01, 0.09];

/// glTF's numbers for what the file uses.
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const LINEAR: u32 = 9729;
const LINEAR_MIPMAP_LINEAR: u32 = 9987;
const CLAMP_TO_EDGE: u32 = 33071;

/// Where a part's arrays lie in the binary buffer (byte offsets).
#[derive(Clone, Copy, Default)]
struct Layout {
    positions: usize,
    normals: usize,
    uvs: Option<usize>,
    colours: Option<usize>,
    indices: usize,
}

/// One primitive: the vertices welded into it, its triangles, and where they are written.
#[derive(Default)]
struct Part {
    /// Welded vertex of each distinct vertex (every bit of its data).
    keys: HashMap<[u32; 13], u32>,
    /// The mesh's vertex each welded vertex copies.
    sources: Vec<u32>,
    /// Area-weighted normals of the triangles around each welded vertex, for a vertex whose
    /// own normal is unusable.
    around: Vec<Vec3>,
    indices: Vec<u32>,
    layout: Layout,
    min: [f32; 3],
    max: [f32; 3],
}

impl Part {
    fn with_capacity(vertices: usize) -> Self {
        Self {
            keys: HashMap::with_capacity(vertices),
            ..Self::default()
        }
    }

    fn weld(&mut self, vertex: &Vertex, source: u32) -> u32 {
        let key: [u32; 13] = bytemuck::cast(*vertex);
        *self.keys.entry(key).or_insert_with(|| {
            self.sources.push(source);
            self.around.push(Vec3::ZERO);
            self.sources.len() as u32 - 1
        })
    }

    fn len(&self) -> usize {
        self.sources.len()
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    Weld,
    Vertices,
    Indices,
    Texture,
    Assemble,
    Copy,
}

/// A GLB being written.
pub(crate) struct Glb {
    shell: Shell,
    stage: Stage,
    cursor: Cursor,
    /// The outer surface, then the parts in the interior colour.
    parts: [Part; 2],
    turn: DQuat,
    /// Bounds of the turned shell.
    bounds: Bounds,
    /// The binary buffer's vertex and index arrays, laid out once the welding has counted them.
    bin: Vec<u8>,
    png: Option<PngRows>,
    image: Vec<u8>,
    /// Whether the outer surface carries colours per vertex rather than the texture.
    tinted: bool,
    /// The file.
    out: Vec<u8>,
}

impl Glb {
    pub fn new(shell: Shell) -> Self {
        let (triangles, vertices) = (shell.mesh.triangle_count(), shell.mesh.vertices.len());
        let outer = shell.mesh.vertices.iter().filter(|v| v.is_outer()).count();
        let tinted = Paint::tinted(&shell.mesh.vertices);
        Self {
            turn: turn(shell.facing, false),
            shell,
            stage: Stage::Weld,
            cursor: Cursor::new(triangles),
            parts: [
                Part::with_capacity(outer),
                Part::with_capacity(vertices - outer),
            ],
            bounds: Bounds::EMPTY,
            bin: Vec::new(),
            png: None,
            image: Vec::new(),
            tinted,
            out: Vec::new(),
        }
    }

    fn textured(&self) -> bool {
        self.shell.paint.texture().is_some() && !self.tinted
    }

    fn weld(&mut self) -> Result<(), ExportError> {
        let mesh = &self.shell.mesh;
        for t in self.cursor.next(TRIANGLES_PER_STEP) {
            if mesh.collapsed(t) {
                continue;
            }
            let corners = [0, 1, 2].map(|k| mesh.indices[3 * t + k]);
            let [a, b, c] = corners.map(|i| mesh.vertices[i as usize].position);
            let first = &mesh.vertices[corners[0] as usize];
            let part = &mut self.parts[usize::from(!first.is_outer())];
            let welded = corners.map(|i| part.weld(&mesh.vertices[i as usize], i));
            let [a, b, c] = [a, b, c].map(Vec3::from);
            let area = (b - a).cross(c - a);
            for i in welded {
                part.around[i as usize] += area;
            }
            part.indices.extend_from_slice(&welded);
        }
        if self.cursor.done() {
            if self.parts.iter().all(|p| p.indices.is_empty()) {
                return Err(ExportError::Empty);
            }
            self.lay_out();
            self.stage = Stage::Vertices;
            self.cursor = Cursor::new(self.parts[0].len() + self.parts[1].len());
        }
        Ok(())
    }

    /// Places every part's arrays in the binary buffer, each at a multiple of four bytes.
    fn lay_out(&mut self) {
        let (textured, tinted) = (self.textured(), self.tinted);
        let mut at = 0;
        let mut take = |bytes: usize| {
            let start = at;
            at += bytes.next_multiple_of(4);
            start
        };
        for (p, part) in self.parts.iter_mut().enumerate() {
            part.keys = HashMap::new();
            let n = part.len();
            part.layout = Layout {
                positions: take(12 * n),
                normals: take(12 * n),
                uvs: (p == 0 && textured).then(|| take(8 * n)),
                colours: (p == 0 && tinted).then(|| take(12 * n)),
                indices: take(4 * part.indices.len()),
            };
        }
        self.bin = vec![0; at];
    }

    fn vertices(&mut self) {
        let outer = self.parts[0].len();
        for i in self.cursor.next(VERTICES_PER_STEP) {
            let (p, i) = if i < outer { (0, i) } else { (1, i - outer) };
            let part = &mut self.parts[p];
            let v = &self.shell.mesh.vertices[part.sources[i] as usize];
            if i == 0 {
                (part.min, part.max) = (v.position, v.position);
            }
            for k in 0..3 {
                part.min[k] = part.min[k].min(v.position[k]);
                part.max[k] = part.max[k].max(v.position[k]);
            }
            let position = DVec3::from(v.position.map(f64::from));
            self.bounds.include(self.turn * position);
            let normal = unit(Vec3::from(v.normal))
                .or_else(|| unit(part.around[i]))
                .unwrap_or(Vec3::Z);
            let layout = part.layout;
            put(&mut self.bin, layout.positions + 12 * i, &v.position);
            put(&mut self.bin, layout.normals + 12 * i, &normal.to_array());
            if let Some(uvs) = layout.uvs {
                put(&mut self.bin, uvs + 8 * i, &self.shell.paint.uv(v.pattern));
            }
            if let Some(colours) = layout.colours {
                let paint = &self.shell.paint;
                put(
                    &mut self.bin,
                    colours + 12 * i,
                    &paint.linear(paint.colour(v)),
                );
            }
        }
        if self.cursor.done() {
            self.stage = Stage::Indices;
            self.cursor = Cursor::new(self.parts[0].indices.len() + self.parts[1].indices.len());
        }
    }

    fn indices(&mut self) {
        let outer = self.parts[0].indices.len();
        let range = self.cursor.next(INDICES_PER_STEP);
        for (p, part) in self.parts.iter().enumerate() {
            let base = if p == 0 { 0 } else { outer };
            let start = range.start.clamp(base, base + part.indices.len()) - base;
            let end = range.end.clamp(base, base + part.indices.len()) - base;
            let at = part.layout.indices + 4 * start;
            self.bin[at..at + 4 * (end - start)]
                .copy_from_slice(bytemuck::cast_slice(&part.indices[start..end]));
        }
        if self.cursor.done() {
            match self
                .shell
                .paint
                .texture()
                .filter(|_| self.parts[0].len() > 0 && !self.tinted)
            {
                Some(t) => {
                    self.png = Some(PngRows::new(t.width, t.height, png::ColorType::Rgb));
                    self.cursor = Cursor::new(t.height);
                    self.stage = Stage::Texture;
                }
                None => self.stage = Stage::Assemble,
            }
        }
    }

    fn texture(&mut self) {
        let t = self.shell.paint.texture().expect("a texture to encode");
        let row_bytes = t.width * 3;
        let rows = self.cursor.next(rows_per_step(row_bytes));
        let png = self.png.as_mut().expect("the texture's encoder");
        png.write(&t.rgb[rows.start * row_bytes..rows.end * row_bytes]);
        if self.cursor.done() {
            self.image = self.png.take().map(PngRows::finish).unwrap_or_default();
            self.stage = Stage::Assemble;
        }
    }

    /// The glTF document of the parts laid out in the binary buffer, and the image after them.
    fn document(&self) -> Value {
        let mut views = Views::default();
        let (mut primitives, mut materials) = (Vec::new(), Vec::new());
        let paint = &self.shell.paint;
        let roughness = self.shell.roughness;
        let image =
            (!self.image.is_empty()).then(|| views.add(self.bin.len(), self.image.len(), None));
        for (p, part) in self.parts.iter().enumerate() {
            if part.indices.is_empty() {
                continue;
            }
            let (n, layout) = (part.len(), part.layout);
            let position = views.floats(layout.positions, n, "VEC3");
            views.accessors[position]["min"] = json!(part.min.map(f64::from));
            views.accessors[position]["max"] = json!(part.max.map(f64::from));
            let normal = views.floats(layout.normals, n, "VEC3");
            let mut attributes = json!({ "POSITION": position, "NORMAL": normal });
            let mut pbr = match (layout.uvs.filter(|_| image.is_some()), layout.colours) {
                (Some(uvs), _) => {
                    attributes["TEXCOORD_0"] = views.floats(uvs, n, "VEC2").into();
                    json!({ "baseColorTexture": { "index": 0 } })
                }
                (None, Some(colours)) => {
                    attributes["COLOR_0"] = views.floats(colours, n, "VEC3").into();
                    json!({ "baseColorFactor": [1.0, 1.0, 1.0, 1.0] })
                }
                (None, None) => {
                    let colour = if p == 0 {
                        paint.ground()
                    } else {
                        paint.interior()
                    };
                    let [r, g, b] = paint.linear(colour);
                    json!({ "baseColorFactor": [r, g, b, 1.0] })
                }
            };
            pbr["metallicFactor"] = 0.0.into();
            pbr["roughnessFactor"] = roughness.into();
            primitives.push(json!({
                "attributes": attributes,
                "indices": views.indices(layout.indices, part.indices.len()),
                "material": materials.len(),
                "mode": 4,
            }));
            materials.push(json!({
                "name": if p == 0 { "shell" } else { "interior" },
                "pbrMetallicRoughness": pbr,
                "doubleSided": true,
            }));
        }
        let (scale, translation) = fit(&self.bounds, self.shell.size, 1000.0, 1);
        let q = self.turn;
        let mut document = json!({
            "asset": { "version": "2.0", "generator": "seashells" },
            "scene": 0,
            "scenes": [{ "nodes": [0] }],
            "nodes": [{
                "name": self.shell.title,
                "mesh": 0,
                "rotation": [q.x, q.y, q.z, q.w],
                "scale": [scale, scale, scale],
                "translation": translation.to_array(),
            }],
            "meshes": [{ "name": self.shell.title, "primitives": primitives }],
            "materials": materials,
            "accessors": views.accessors,
            "bufferViews": views.views,
            "buffers": [{ "byteLength": (self.bin.len() + self.image.len()).next_multiple_of(4) }],
        });
        if let Some(view) = image {
            document["images"] = json!([{ "bufferView": view, "mimeType": "image/png" }]);
            document["samplers"] = json!([{
                "magFilter": LINEAR,
                "minFilter": LINEAR_MIPMAP_LINEAR,
                "wrapS": CLAMP_TO_EDGE,
                "wrapT": CLAMP_TO_EDGE,
            }]);
            document["textures"] = json!([{ "sampler": 0, "source": 0 }]);
        }
        document
    }

    /// Starts the GLB container: a 12-byte header, the JSON chunk (padded with spaces to a
    /// multiple of four bytes) and the binary chunk's header; its data (the arrays, then the
    /// image, padded with zeros) follows a megabyte a step.
    fn assemble(&mut self) {
        let json = self.document().to_string();
        let json_len = json.len().next_multiple_of(4);
        let bin_len = (self.bin.len() + self.image.len()).next_multiple_of(4);
        let total = 12 + 8 + json_len + 8 + bin_len;
        let out = &mut self.out;
        out.reserve_exact(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(json_len as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(json.as_bytes());
        out.resize(20 + json_len, b' ');
        out.extend_from_slice(&(bin_len as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        self.stage = Stage::Copy;
        self.cursor = Cursor::new(self.bin.len());
    }

    /// Copies the next megabyte of the arrays; the whole file once they and the image are in.
    fn copy(&mut self) -> Option<Vec<u8>> {
        let range = self.cursor.next(BYTES_PER_STEP);
        self.out.extend_from_slice(&self.bin[range]);
        if !self.cursor.done() {
            return None;
        }
        self.out.extend_from_slice(&self.image);
        let total = u32::from_le_bytes(self.out[8..12].try_into().expect("the header's length"));
        self.out.resize(total as usize, 0);
        Some(std::mem::take(&mut self.out))
    }
}

/// Writes floats at `at` in `bin`, little-endian.
fn put(bin: &mut [u8], at: usize, values: &[f32]) {
    for (k, x) in values.iter().enumerate() {
        bin[at + 4 * k..at + 4 * k + 4].copy_from_slice(&x.to_le_bytes());
    }
}

/// The normal scaled to unit length, if it has a direction.
fn unit(n: Vec3) -> Option<Vec3> {
    let n = n.try_normalize()?;
    n.is_finite().then_some(n)
}

/// The buffer views and accessors of the document.
#[derive(Default)]
struct Views {
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Views {
    /// A view of `length` bytes at `offset` of the buffer; returns its index.
    fn add(&mut self, offset: usize, length: usize, target: Option<u32>) -> usize {
        let mut view = json!({ "buffer": 0, "byteOffset": offset, "byteLength": length });
        if let Some(target) = target {
            view["target"] = target.into();
        }
        self.views.push(view);
        self.views.len() - 1
    }

    /// An accessor of `count` float vectors of `kind` ("VEC2", "VEC3") at `offset`; returns
    /// its index.
    fn floats(&mut self, offset: usize, count: usize, kind: &str) -> usize {
        let size = if kind == "VEC2" { 8 } else { 12 };
        let view = self.add(offset, size * count, Some(ARRAY_BUFFER));
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": FLOAT,
            "count": count,
            "type": kind,
        }));
        self.accessors.len() - 1
    }

    /// An accessor of `count` triangle indices at `offset`; returns its index.
    fn indices(&mut self, offset: usize, count: usize) -> usize {
        let view = self.add(offset, 4 * count, Some(ELEMENT_ARRAY_BUFFER));
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": UNSIGNED_INT,
            "count": count,
            "type": "SCALAR",
        }));
        self.accessors.len() - 1
    }
}

impl Writer for Glb {
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError> {
        match self.stage {
            Stage::Weld => self.weld()?,
            Stage::Vertices => self.vertices(),
            Stage::Indices => self.indices(),
            Stage::Texture => self.texture(),
            Stage::Assemble => self.assemble(),
            Stage::Copy => return Ok(self.copy()),
        }
        Ok(None)
    }

    fn progress(&self) -> f64 {
        // Stages are numbered in their order.
        let stage = self.stage as usize;
        progress(&WEIGHTS, stage, self.cursor.fraction())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::print_size::PrintSize;
    use crate::export::steps::run;
    use crate::generator::Generator;
    use crate::presets::preset;

    fn glb(id: &str) -> (Vec<u8>, Value, usize) {
        let preset = preset(id).unwrap();
        let mut g = Generator::new(&preset.spec).unwrap();
        g.finish();
        let shell = Shell::new(&g, &preset.spec, preset, PrintSize::default()).unwrap();
        let triangles = shell.mesh.triangle_count();
        let bytes = run(&mut Glb::new(shell)).unwrap();
        let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
        let json = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
        (bytes, json, triangles)
    }

    #[test]
    fn a_patterned_shell_has_a_textured_outer_part_and_an_interior_part() {
        let (bytes, doc, triangles) = glb("oliva-porphyria");
        assert_eq!(&bytes[..4], b"glTF");
        assert_eq!(
            u32::from_le_bytes(bytes[8..12].try_into().unwrap()) as usize,
            bytes.len()
        );
        let primitives = doc["meshes"][0]["primitives"].as_array().unwrap();
        assert_eq!(primitives.len(), 2);
        assert!(primitives[0]["attributes"]["TEXCOORD_0"].is_u64());
        assert!(primitives[1]["attributes"]["TEXCOORD_0"].is_null());
        let written: u64 = primitives
            .iter()
            .map(|p| {
                doc["accessors"][p["indices"].as_u64().unwrap() as usize]["count"]
                    .as_u64()
                    .unwrap()
                    / 3
            })
            .sum();
        assert!(written as usize <= triangles && written as usize > triangles * 99 / 100);
        assert_eq!(doc["images"][0]["mimeType"], "image/png");
        let roughness = doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"]
            .as_f64()
            .unwrap();
        assert!((roughness - 0.225).abs() < 1e-6, "{roughness}");
        assert!(doc["materials"][1]["pbrMetallicRoughness"]["baseColorFactor"].is_array());
    }

    #[test]
    fn a_shell_without_a_pattern_has_its_ground_colour_and_no_texture() {
        let (_, doc, _) = glb("kawaguchi-shell");
        assert!(doc["images"].is_null());
        let outer = &doc["materials"][0]["pbrMetallicRoughness"];
        assert!(outer["baseColorTexture"].is_null());
        assert_eq!(outer["baseColorFactor"].as_array().unwrap().len(), 4);
    }
}
