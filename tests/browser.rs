//! In-browser tests (wasm-bindgen-test in headless Chromium, WebGL2 through SwiftShader; see
//! tests/webdriver.json): the renderer comes up and draws a shell the core grew.
#![cfg(target_arch = "wasm32")]

use seashells_core::generator::Generator;
use seashells_core::presets;
use seashells_core::render::{Renderer, ShellLook};
use seashells_core::view::camera::OrbitCamera;
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

/// Share of pixels that are not the black background, and the number of distinct grey levels
/// among them (a lit surface has many).
fn coverage(canvas: &HtmlCanvasElement) -> (f64, usize) {
    let size = canvas.width();
    let copy = self::canvas(size);
    let context: CanvasRenderingContext2d =
        copy.get_context("2d").unwrap().unwrap().dyn_into().unwrap();
    context
        .draw_image_with_html_canvas_element(canvas, 0.0, 0.0)
        .unwrap();
    let data = context
        .get_image_data(0.0, 0.0, f64::from(size), f64::from(size))
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

#[wasm_bindgen_test]
async fn renderer_initialises_on_webgl2_and_draws_a_lit_shell() {
    let canvas = canvas(256);
    let mut renderer = Renderer::new(canvas.clone())
        .await
        .expect("a renderer on WebGL2");
    assert_eq!(renderer.backend(), "WebGL2");
    let preset = presets::preset("turbinate").expect("preset");
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
        ),
    );
    renderer.upload(generator.mesh(), generator.edge(), &generator.grown(), &[]);
    let (bounds, front) = generator.framing();
    renderer
        .draw(&OrbitCamera::framing(&bounds, front, 0.0, 0.0))
        .expect("a frame");
    let (share, shades) = coverage(&canvas);
    assert!(share > 0.05, "the shell covers {share:.3} of the canvas");
    assert!(shades > 20, "only {shades} grey levels: not lit");
    assert_eq!(renderer.failure(), None);
}
