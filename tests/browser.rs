//! In-browser tests (wasm-bindgen-test in headless Chromium, WebGL2 through SwiftShader; see
//! tests/webdriver.json): the renderer comes up and draws a shell the core grew, in one view and
//! in Kawaguchi's four, and it paints the pattern in the colours the exporters give the same
//! points.
#![cfg(target_arch = "wasm32")]

use glam::{DVec3, Vec3};
use seashells_core::export::paint::{Paint, PatternImage};
use seashells_core::generator::{Advance, Generator};
use seashells_core::mesh::{Bounds, Capacity, Mesh, Surface, Vertex};
use seashells_core::pattern::texture_layout::TextureLayout;
use seashells_core::presets;
use seashells_core::render::{Canvas, Renderer, ShellLook};
use seashells_core::shape::LineGrid;
use seashells_core::share::presentation::Layout;
use seashells_core::view::camera::OrbitCamera;
use seashells_core::view::panes::panes;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;
use web_sys::{HtmlCanvasElement, OffscreenCanvas, OffscreenCanvasRenderingContext2d};

wasm_bindgen_test_configure!(run_in_browser);

/// A canvas off the page of `size` × `size` pixels, as the page's canvases draw (their
/// drawing handed to an `OffscreenCanvas`).
fn canvas(size: u32) -> OffscreenCanvas {
    OffscreenCanvas::new(size, size).unwrap()
}

/// A canvas element of `size` × `size` pixels, not in any page: what the page draws on from
/// its own thread where an offscreen canvas gives no WebGL2 (WebKit before Safari 17).
fn element(size: u32) -> HtmlCanvasElement {
    let canvas: HtmlCanvasElement = web_sys::window()
        .unwrap()
        .document()
        .unwrap()
        .create_element("canvas")
        .unwrap()
        .dyn_into()
        .unwrap();
    canvas.set_width(size);
    canvas.set_height(size);
    canvas
}

/// The RGBA pixels of a `size`-wide square of `canvas` from (`x`, `y`), read as drawn.
fn pixels(canvas: &Canvas, x: u32, y: u32, size: u32) -> Vec<u8> {
    let copy = self::canvas(canvas.size().0);
    let context: OffscreenCanvasRenderingContext2d =
        copy.get_context("2d").unwrap().unwrap().dyn_into().unwrap();
    match canvas {
        Canvas::Offscreen(c) => context.draw_image_with_offscreen_canvas(c, 0.0, 0.0),
        Canvas::Element(c) => context.draw_image_with_html_canvas_element(c, 0.0, 0.0),
    }
    .unwrap();
    let [x, y, size] = [x, y, size].map(f64::from);
    context
        .get_image_data(x, y, size, size)
        .unwrap()
        .data()
        .to_vec()
}

/// Share of pixels that are not the black background in the square of `size` at (x, y) of
/// the canvas, and the number of distinct grey levels among them (a lit surface has many).
fn coverage_in(canvas: &Canvas, x: u32, y: u32, size: u32) -> (f64, usize) {
    let data = pixels(canvas, x, y, size);
    let mut lit = 0;
    let mut shades = std::collections::BTreeSet::new();
    for px in data.chunks_exact(4) {
        let sum = u32::from(px[0]) + u32::from(px[1]) + u32::from(px[2]);
        if sum > 30 {
            lit += 1;
            shades.insert(sum / 3);
        }
    }
    (f64::from(lit) / f64::from(size * size), shades.len())
}

/// A renderer on `canvas`, with `id`'s shell grown whole and loaded, a camera framing it,
/// and its bounds.
async fn grown(id: &str, canvas: Canvas) -> (Canvas, Renderer, OrbitCamera, Bounds) {
    let mut renderer = Renderer::new(&canvas).await.expect("a renderer on WebGL2");
    assert_eq!(renderer.backend(), "WebGL2");
    let preset = presets::preset(id).expect("preset");
    let mut generator = Generator::new(&preset.spec).expect("generator");
    generator.finish();
    renderer.set_background([0, 0, 0]);
    renderer.load_shell(
        generator.capacity(),
        None,
        ShellLook::new(
            &preset.spec.colours,
            &preset.spec.material,
            seashells_core::forms::rows_per_whorl(&preset.spec),
            generator.line_grid(),
        ),
    );
    renderer.upload(generator.mesh(), generator.edge(), &generator.grown(), &[]);
    let (bounds, front) = generator.framing();
    let camera = OrbitCamera::framing(&bounds, front, 0.0, 0.0);
    (canvas, renderer, camera, bounds)
}

#[wasm_bindgen_test]
async fn renderer_initialises_on_webgl2_and_draws_a_lit_shell() {
    let (canvas, mut renderer, camera, bounds) =
        grown("turbinate", Canvas::Offscreen(canvas(256))).await;
    renderer
        .draw(&panes(Layout::Single, &camera, &bounds, renderer.aspect()))
        .expect("a frame");
    let (share, shades) = coverage_in(&canvas, 0, 0, 256);
    assert!(share > 0.05, "the shell covers {share:.3} of the canvas");
    assert!(shades > 20, "only {shades} grey levels: not lit");
    assert_eq!(renderer.failure(), None);
}

/// Waits for the browser's next animation frame (a turn of its event loop, after which the GPU
/// may report work done).
async fn next_frame() {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        web_sys::window()
            .unwrap()
            .request_animation_frame(&resolve)
            .unwrap();
    });
    wasm_bindgen_futures::JsFuture::from(promise).await.unwrap();
}

#[wasm_bindgen_test]
async fn the_renderer_draws_on_a_canvas_element_and_counts_the_frames_the_gpu_finished() {
    let (canvas, mut renderer, camera, bounds) =
        grown("diskoid", Canvas::Element(element(192))).await;
    assert_eq!(renderer.frames(), (0, 0));
    let frame = panes(Layout::Single, &camera, &bounds, renderer.aspect());
    renderer.draw(&frame).expect("a frame");
    let (share, shades) = coverage_in(&canvas, 0, 0, 192);
    assert!(share > 0.05, "the shell covers {share:.3} of the element");
    assert!(shades > 20, "only {shades} grey levels: not lit");
    // Two frames may wait for the GPU, not three.
    renderer.draw(&frame).expect("a second frame");
    let mut waited = 0;
    while !renderer.ready() {
        assert!(
            waited < 600,
            "the GPU finished no frame in 600 animation frames"
        );
        next_frame().await;
        waited += 1;
    }
    let (finished, unfinished) = renderer.frames();
    assert!(
        finished >= 1 && finished + unfinished == 2,
        "{finished} and {unfinished} of 2"
    );
    assert_eq!(renderer.failure(), None);
}

#[wasm_bindgen_test]
async fn four_views_draw_the_shell_in_every_quarter() {
    let (canvas, mut renderer, camera, bounds) =
        grown("kawaguchi-horn", Canvas::Offscreen(canvas(256))).await;
    renderer
        .draw(&panes(Layout::Four, &camera, &bounds, renderer.aspect()))
        .expect("a frame");
    for (x, y) in [(0, 0), (128, 0), (0, 128), (128, 128)] {
        let (share, shades) = coverage_in(&canvas, x, y, 128);
        assert!(
            share > 0.03,
            "the quarter at ({x}, {y}) is {share:.3} shell"
        );
        assert!(
            shades > 10,
            "the quarter at ({x}, {y}) has {shades} grey levels"
        );
    }
    assert_eq!(renderer.failure(), None);
}

/// The colour at the centre of the canvas.
fn centre(canvas: &Canvas) -> [u8; 3] {
    let half = canvas.size().0 / 2;
    let data = pixels(canvas, half, half, 1);
    [data[0], data[1], data[2]]
}

#[wasm_bindgen_test]
async fn the_renderer_paints_the_pattern_in_the_colours_the_exporters_give() {
    // Four cells by three rows of strongly different colours.
    let texels: [[u8; 3]; 12] = [
        [230, 20, 20],
        [20, 200, 40],
        [30, 40, 220],
        [250, 250, 250],
        [10, 10, 10],
        [240, 200, 30],
        [200, 30, 200],
        [40, 210, 210],
        [120, 60, 20],
        [250, 150, 150],
        [60, 60, 160],
        [180, 180, 90],
    ];
    let rgba: Vec<u8> = texels
        .iter()
        .flat_map(|c| [c[0], c[1], c[2], 255])
        .collect();
    let (cells, rows) = (4, 3);
    let preset = presets::preset("oliva-porphyria").expect("preset");
    let paint = Paint::new(
        &preset.spec.colours,
        Some(PatternImage {
            cells,
            rows,
            rgba: &rgba,
        }),
    );
    let canvas = Canvas::Offscreen(canvas(64));
    let mut renderer = Renderer::new(&canvas).await.expect("a renderer");
    renderer.set_background([0, 0, 0]);
    // A square facing the camera, every corner at the same pattern coordinates, so the
    // pattern paints it in one colour.
    let square = |at: [f64; 2]| {
        let mut mesh = Mesh::default();
        for (x, z) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            mesh.vertices.push(Vertex::new(
                DVec3::new(x, 0.0, z),
                DVec3::Y,
                at,
                Surface::Outer,
            ));
        }
        mesh.quad([0, 1, 2, 3], true);
        mesh
    };
    let bounds = Bounds {
        min: DVec3::new(-1.0, -0.1, -1.0),
        max: DVec3::new(1.0, 0.1, 1.0),
    };
    let camera = OrbitCamera::framing(&bounds, DVec3::Y, 0.0, -0.2);
    let look = ShellLook::new(
        &preset.spec.colours,
        &preset.spec.material,
        100.0,
        // Unused: the Oliva is shaded, not drawn in lines.
        LineGrid {
            across: 1.0,
            rows: 1.0,
        },
    );
    let capacity = (
        Capacity {
            vertices: 4,
            indices: 6,
        },
        Capacity::default(),
    );
    let advance = Advance {
        vertices: 0..4,
        indices: 0..6,
        edge: None,
        rows: 0..rows,
    };
    // Drawn with the pattern, or with no pattern and the exporters' colour as its ground.
    let mut draw = |mesh: &Mesh, plain: Option<[u8; 3]>| {
        let (layout, look, rgba) = match plain {
            None => (
                TextureLayout::new(cells as u32, rows as u32),
                look,
                &rgba[..],
            ),
            Some(colour) => {
                let ground = Vec3::from(paint.linear(colour));
                (None, ShellLook { ground, ..look }, &[][..])
            }
        };
        renderer.load_shell(capacity, layout, look);
        renderer.upload(mesh, &Mesh::default(), &advance, rgba);
        renderer
            .draw(&panes(Layout::Single, &camera, &bounds, renderer.aspect()))
            .expect("a frame");
        centre(&canvas)
    };
    let mut seen = Vec::new();
    for at in [
        [0.0, 0.0],
        [1.0 / 3.0, 1.0],
        [1.0, 2.0],
        [0.5, 0.5],
        [1.0 / 6.0, 1.25],
        [0.9, 1.8],
    ] {
        let mesh = square(at);
        let colour = paint.colour(&mesh.vertices[0]);
        let drawn = draw(&mesh, None);
        let expected = draw(&mesh, Some(colour));
        let off = (0..3)
            .map(|k| drawn[k].abs_diff(expected[k]))
            .max()
            .unwrap();
        assert!(
            off <= 2,
            "at {at:?} the page draws {drawn:?}, the exporters' colour {colour:?} draws {expected:?}"
        );
        seen.push(drawn);
    }
    seen.sort();
    seen.dedup();
    assert_eq!(
        seen.len(),
        6,
        "the points are drawn in different colours: {seen:?}"
    );
    assert_eq!(renderer.failure(), None);
}
