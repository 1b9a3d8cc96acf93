//! In-browser tests (wasm-bindgen-test in headless Chromium, WebGL2 through SwiftShader; see
//! tests/webdriver.json): the renderer comes up and draws a shell the core grew, in one view and
//! in Kawaguchi's four.
#![cfg(target_arch = "wasm32")]

use seashells_core::generator::Generator;
use seashells_core::mesh::Bounds;
use seashells_core::presets;
use seashells_core::render::{Renderer, ShellLook};
use seashells_core::share::presentation::Layout;
use seashells_core::view::camera::OrbitCamera;
use seashells_core::view::panes::panes;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

wasm_bindgen_test_configure!(run_in_browser);

fn canvas(size: u32) -> HtmlCanvasElement {
    let document = web_sys::window().unwrap().document().unwrap();
    let canvas: HtmlCanvasElement = document
        .create_element("canvas")
        .unwrap()
        .dyn_into()
        .unwrap();
    canvas.set_width(size);
    canvas.set_height(size);
    document.body().unwrap().append_child(&canvas).unwrap();
    canvas
}

/// Share of pixels that are not the black background in the square of `size` at (x, y) of
/// the canvas, and the number of distinct grey levels among them (a lit surface has many).
fn coverage_in(canvas: &HtmlCanvasElement, x: u32, y: u32, size: u32) -> (f64, usize) {
    let copy = self::canvas(canvas.width());
    let context: CanvasRenderingContext2d =
        copy.get_context("2d").unwrap().unwrap().dyn_into().unwrap();
    context
        .draw_image_with_html_canvas_element(canvas, 0.0, 0.0)
        .unwrap();
    let data = context
        .get_image_data(f64::from(x), f64::from(y), f64::from(size), f64::from(size))
        .unwrap()
        .data();
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

/// A renderer on a new square canvas of `size`, with `id`'s shell grown whole and loaded, a
/// camera framing it, and its bounds.
async fn grown(id: &str, size: u32) -> (HtmlCanvasElement, Renderer, OrbitCamera, Bounds) {
    let canvas = canvas(size);
    let mut renderer = Renderer::new(canvas.clone())
        .await
        .expect("a renderer on WebGL2");
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
    let (canvas, mut renderer, camera, bounds) = grown("turbinate", 256).await;
    renderer
        .draw(&panes(Layout::Single, &camera, &bounds, renderer.aspect()))
        .expect("a frame");
    let (share, shades) = coverage_in(&canvas, 0, 0, 256);
    assert!(share > 0.05, "the shell covers {share:.3} of the canvas");
    assert!(shades > 20, "only {shades} grey levels: not lit");
    assert_eq!(renderer.failure(), None);
}

#[wasm_bindgen_test]
async fn four_views_draw_the_shell_in_every_quarter() {
    let (canvas, mut renderer, camera, bounds) = grown("kawaguchi-horn", 256).await;
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
