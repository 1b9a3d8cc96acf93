//! 3MF, the 3D Manufacturing Format, for colour printing: a ZIP package whose model part is
//! XML, in millimetres, the shell standing apex up at the height asked for (80 mm unless
//! chosen). One object per connected body of the welded mesh, each a closed surface (an open
//! one is refused: it cannot be printed); every vertex carries its colour from one colour
//! group of the Materials and Properties extension (`m:colorgroup`, the colours a triangle's
//! `p1`–`p3` interpolate), the page's colour there (see [`Paint::colour`]).
//!
//! [`Paint::colour`]: super::paint::Paint::colour

use super::bodies::{Edges, Pieces};
use super::error::ExportError;
use super::placement::{fit, turn};
use super::shell::Shell;
use super::steps::{Cursor, Writer, progress};
use super::weld::{Welded, Welder};
use super::zip::{Deflating, Package};
use crate::mesh::Bounds;
use glam::{DQuat, DVec3};
use std::collections::HashMap;
use std::fmt::Write;

/// Vertices or triangles welded, linked, coloured or sorted per step.
const PER_STEP: usize = 4096;
/// Vertices or triangles written per step (their XML is deflated in the same step).
const XML_PER_STEP: usize = 512;
/// Shares of the work: welding, linking, colouring, sorting, writing.
const WEIGHTS: [f64; 5] = [0.1, 0.15, 0.1, 0.05, 0.6];

/// The key an open surface is refused by: a swept shell's wall, whose thickness closes it.
const WALL: &str = "form.wall.thickness";

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>
"#;

const RELATIONSHIPS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>
"#;

/// The resource id of the colour group; objects follow it.
const COLOURS: usize = 1;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    Weld,
    Link,
    Colour,
    Sort,
    Write,
}

/// A 3MF being written.
pub(crate) struct ThreeMf {
    shell: Shell,
    stage: Stage,
    cursor: Cursor,
    welder: Option<Welder>,
    welded: Option<Welded>,
    /// The mesh's triangles in welded indices, collapsed ones left out.
    triangles: Vec<[u32; 3]>,
    pieces: Pieces,
    edges: Edges,
    turn: DQuat,
    bounds: Bounds,
    /// Whether a triangle uses each welded vertex.
    used: Vec<bool>,
    /// For each welded vertex: its colour in the group, its body and its index in the body.
    colour: Vec<u32>,
    body: Vec<u32>,
    local: Vec<u32>,
    palette: HashMap<[u8; 3], u32>,
    /// Each body's vertices and triangles.
    bodies: Vec<(Vec<u32>, Vec<u32>)>,
    /// Scale and translation into millimetres.
    fit: (f64, DVec3),
    /// Where the writing is: the body, and the place among its vertices then triangles.
    writing: (usize, Cursor),
    model: Option<Deflating>,
}

impl ThreeMf {
    pub fn new(shell: Shell) -> Self {
        Self {
            cursor: Cursor::new(shell.mesh.vertices.len()),
            welder: Some(Welder::new(&shell.mesh)),
            turn: turn(shell.facing, true),
            shell,
            stage: Stage::Weld,
            welded: None,
            triangles: Vec::new(),
            pieces: Pieces::new(0),
            edges: Edges::default(),
            bounds: Bounds::EMPTY,
            used: Vec::new(),
            colour: Vec::new(),
            body: Vec::new(),
            local: Vec::new(),
            palette: HashMap::new(),
            bodies: Vec::new(),
            fit: (1.0, DVec3::ZERO),
            writing: (0, Cursor::default()),
            model: None,
        }
    }

    fn welded(&self) -> &Welded {
        self.welded.as_ref().expect("welded")
    }

    /// Moves on to `stage`, over `len` items.
    fn begin(&mut self, stage: Stage, len: usize) {
        self.stage = stage;
        self.cursor = Cursor::new(len);
    }

    fn weld(&mut self) {
        let range = self.cursor.next(PER_STEP);
        let welder = self.welder.as_mut().expect("welding");
        welder.weld(&self.shell.mesh, range);
        if self.cursor.done() {
            let welded = self.welder.take().expect("welding").finish();
            self.pieces = Pieces::new(welded.positions.len());
            self.used = vec![false; welded.positions.len()];
            let triangles = self.shell.mesh.triangle_count();
            self.triangles.reserve(triangles);
            self.welded = Some(welded);
            self.begin(Stage::Link, triangles);
        }
    }

    fn link(&mut self) -> Result<(), ExportError> {
        let welded = self.welded.as_ref().expect("welded");
        for t in self.cursor.next(PER_STEP) {
            if let Some(t) = welded.triangle(&self.shell.mesh, t) {
                self.pieces.join(t[0], t[1]);
                self.pieces.join(t[1], t[2]);
                self.edges.add(t);
                self.triangles.push(t);
                for i in t {
                    self.used[i as usize] = true;
                }
            }
        }
        if self.cursor.done() {
            if self.triangles.is_empty() {
                return Err(ExportError::Empty);
            }
            if !self.edges.matched() {
                return Err(ExportError::Open { key: WALL });
            }
            let n = self.welded().positions.len();
            self.begin(Stage::Colour, n);
        }
        Ok(())
    }

    /// Colours the vertices that triangles use, numbers them within their bodies and measures
    /// the turned shell.
    fn colour(&mut self) {
        for i in self.cursor.next(PER_STEP) {
            if !self.used[i] {
                self.colour.push(u32::MAX);
                self.body.push(u32::MAX);
                self.local.push(u32::MAX);
                continue;
            }
            let welded = self.welded.as_ref().expect("welded");
            let source = &self.shell.mesh.vertices[welded.source[i] as usize];
            let next = self.palette.len() as u32;
            let colour = *self
                .palette
                .entry(self.shell.paint.colour(source))
                .or_insert(next);
            self.colour.push(colour);
            let position = DVec3::from(welded.positions[i].map(f64::from));
            self.bounds.include(self.turn * position);
            // A piece's representative is its first vertex (see `Pieces::join`), so a body is
            // numbered when its first vertex comes.
            let root = self.pieces.find(i as u32) as usize;
            let body = if root == i {
                self.bodies.push((Vec::new(), Vec::new()));
                self.bodies.len() as u32 - 1
            } else {
                self.body[root]
            };
            let vertices = &mut self.bodies[body as usize].0;
            self.local.push(vertices.len() as u32);
            vertices.push(i as u32);
            self.body.push(body);
        }
        if self.cursor.done() {
            self.fit = fit(&self.bounds, self.shell.size, 1.0, 2);
            self.begin(Stage::Sort, self.triangles.len());
        }
    }

    fn sort(&mut self) {
        for t in self.cursor.next(PER_STEP) {
            let body = self.body[self.triangles[t][0] as usize];
            self.bodies[body as usize].1.push(t as u32);
        }
        if self.cursor.done() {
            // Deflated, the model takes about 14 bytes a triangle (see `Download::estimate`).
            let mut model = Package::with_capacity(20 * self.triangles.len() + 4096)
                .add("[Content_Types].xml", CONTENT_TYPES.as_bytes())
                .add("_rels/.rels", RELATIONSHIPS.as_bytes())
                .begin("3D/3dmodel.model");
            model.write(self.head().as_bytes());
            self.model = Some(model);
            let first = self.bodies[0].0.len() + self.bodies[0].1.len();
            self.writing = (0, Cursor::new(first));
            let items = self.bodies.iter().map(|(v, t)| v.len() + t.len()).sum();
            self.begin(Stage::Write, items);
        }
    }

    /// The model's start: its unit, names, and the colour group.
    fn head(&self) -> String {
        let mut colours = vec![[0u8; 3]; self.palette.len()];
        for (&c, &i) in &self.palette {
            colours[i as usize] = c;
        }
        let mut xml = format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
             <model unit=\"millimeter\" xml:lang=\"en-US\" \
             xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\" \
             xmlns:m=\"http://schemas.microsoft.com/3dmanufacturing/material/2015/02\">\n\
             <metadata name=\"Title\">{}</metadata>\n\
             <metadata name=\"Application\">seashells</metadata>\n\
             <resources>\n<m:colorgroup id=\"{COLOURS}\">\n",
            escape(&self.shell.title)
        );
        for [r, g, b] in colours {
            writeln!(xml, "<m:color color=\"#{r:02X}{g:02X}{b:02X}\"/>").expect("to string");
        }
        xml.push_str("</m:colorgroup>\n");
        xml
    }

    /// Writes the next items of the body under way: its vertices, then its triangles.
    fn write(&mut self) {
        let mut xml = String::new();
        let (body, cursor) = &mut self.writing;
        let (vertices, triangles) = &self.bodies[*body];
        let id = COLOURS + 1 + *body;
        let range = cursor.next(XML_PER_STEP);
        for item in range.clone() {
            if item == 0 {
                writeln!(
                    xml,
                    "<object id=\"{id}\" type=\"model\" pid=\"{COLOURS}\" pindex=\"0\">\
                     <mesh>\n<vertices>"
                )
                .expect("to string");
            }
            if item < vertices.len() {
                let p = self.welded.as_ref().expect("welded").positions[vertices[item] as usize];
                let (scale, translation) = self.fit;
                let mm = translation + self.turn * DVec3::from(p.map(f64::from)) * scale;
                let [x, y, z] = mm.as_vec3().to_array();
                writeln!(xml, "<vertex x=\"{x}\" y=\"{y}\" z=\"{z}\"/>").expect("to string");
                continue;
            }
            let item = item - vertices.len();
            if item == 0 {
                xml.push_str("</vertices>\n<triangles>\n");
            }
            let t = self.triangles[triangles[item] as usize];
            let [a, b, c] = t.map(|i| self.local[i as usize]);
            let [pa, pb, pc] = t.map(|i| self.colour[i as usize]);
            write!(
                xml,
                "<triangle v1=\"{a}\" v2=\"{b}\" v3=\"{c}\" p1=\"{pa}\""
            )
            .expect("to string");
            if pa != pb || pa != pc {
                write!(xml, " p2=\"{pb}\" p3=\"{pc}\"").expect("to string");
            }
            xml.push_str("/>\n");
        }
        if cursor.done() {
            xml.push_str("</triangles>\n</mesh></object>\n");
            *body += 1;
            if let Some((v, t)) = self.bodies.get(*body) {
                *cursor = Cursor::new(v.len() + t.len());
            }
        }
        self.cursor.next(range.len());
        let model = self.model.as_mut().expect("the model under way");
        model.write(xml.as_bytes());
    }

    /// The model's end (the build: every body, as it is) and the package.
    fn package(&mut self) -> Vec<u8> {
        let mut xml = String::from("</resources>\n<build>\n");
        for body in 0..self.bodies.len() {
            writeln!(xml, "<item objectid=\"{}\"/>", COLOURS + 1 + body).expect("to string");
        }
        xml.push_str("</build>\n</model>\n");
        let mut model = self.model.take().expect("the model under way");
        model.write(xml.as_bytes());
        model.finish().finish()
    }
}

/// Text as XML character data.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

impl Writer for ThreeMf {
    fn step(&mut self) -> Result<Option<Vec<u8>>, ExportError> {
        match self.stage {
            Stage::Weld => self.weld(),
            Stage::Link => self.link()?,
            Stage::Colour => self.colour(),
            Stage::Sort => self.sort(),
            Stage::Write => {
                self.write();
                if self.writing.0 == self.bodies.len() {
                    return Ok(Some(self.package()));
                }
            }
        }
        Ok(None)
    }

    fn progress(&self) -> f64 {
        progress(&WEIGHTS, self.stage as usize, self.cursor.fraction())
    }
}
