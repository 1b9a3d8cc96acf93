//! The entry of the worker that draws the page's main view (`www/drawing-worker.js` loads this
//! same module): handed the page's canvas as an `OffscreenCanvas`, it runs the [`Viewer`] and a
//! pool of workers of its own for the sessions, and does what the page's commands ask. Each of
//! the page's animation frames ends with a tick, on which the worker keeps the device, takes in
//! its pool's replies, runs the viewer's frame and posts the news (`work::viewer_message`), a
//! recording's `VideoFrame` transferred beside it: the page's thread only reads the news, the
//! growing shell's bytes never reach it. (Driven by its own `requestAnimationFrame`, the worker
//! was seen to stop drawing after a lost context's canvas was replaced; the page's frames go
//! on.)
//!
//! What the page sends, as plain objects: `{init: {canvas, planar, background}}` once, with the
//! canvas transferred; `{command}` (a command's bytes); `{tick}` (a frame); `{canvas}` (a fresh
//! canvas a lost device asked for); `{debug, ms}` (the page tests' hooks, `debug.rs`).

use super::debug::{self, Loss};
use super::viewer::Viewer;
use super::workers::Workers;
use crate::generator::GROWTH_BUDGET_MS;
use crate::render::Canvas;
use crate::work::viewer_command::ViewCommand;
use crate::work::viewer_message::{PoolNews, ViewerNews, decode_command, encode_news};
use crate::work::viewer_status::Device;
use js_sys::{Array, Reflect, Uint8Array};
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{DedicatedWorkerGlobalScope, MessageEvent, OffscreenCanvas};

/// The viewer once its renderer is open, and its pool.
struct Running {
    viewer: Viewer,
    workers: Rc<RefCell<Workers>>,
    /// Its renderer failed: it draws no more.
    stopped: bool,
}

/// What the worker holds: the viewer (once open) and the commands that came before it was.
#[derive(Default)]
struct State {
    running: Option<Running>,
    early: Vec<ViewCommand>,
}

fn scope() -> DedicatedWorkerGlobalScope {
    js_sys::global().unchecked_into()
}

/// Posts `news` to the page, with `transfer` (a video frame) moved beside its bytes.
fn post(news: &ViewerNews, transfer: Option<&JsValue>) {
    let bytes = Uint8Array::from(&encode_news(news)[..]).buffer();
    let message = js_sys::Object::new();
    let _ = Reflect::set(&message, &"news".into(), &bytes);
    let moved = Array::of1(&bytes);
    if let Some(t) = transfer {
        let _ = Reflect::set(&message, &"frame".into(), t);
        moved.push(t);
    }
    // A page that is gone takes nothing; the worker ends with it.
    let _ = scope().post_message_with_transfer(&message, &moved);
}

fn get(object: &JsValue, key: &str) -> Option<JsValue> {
    Reflect::get(object, &key.into())
        .ok()
        .filter(|v| !v.is_undefined())
}

/// Starts the worker: from now on it takes the page's messages. Panics are posted to the page
/// as its crash message.
#[wasm_bindgen]
pub fn drawing_worker_start() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        post(
            &ViewerNews::Crashed(super::activity::crash_words(info)),
            None,
        );
    }));
    let state: Rc<RefCell<State>> = Rc::default();
    let on_message = Closure::<dyn FnMut(MessageEvent)>::new(move |e: MessageEvent| {
        take(&state, &e.data());
    });
    scope().set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    on_message.forget();
}

/// Does what one message of the page asks.
fn take(state: &Rc<RefCell<State>>, data: &JsValue) {
    if get(data, "tick").is_some() {
        if let Some(run) = &mut state.borrow_mut().running
            && !run.stopped
        {
            run.stopped = !frame(run);
        }
    } else if let Some(init) = get(data, "init") {
        let state = Rc::clone(state);
        wasm_bindgen_futures::spawn_local(async move { open(state, init).await });
    } else if let Some(bytes) = get(data, "command") {
        match decode_command(&Uint8Array::new(&bytes).to_vec()) {
            Ok(command) => {
                let mut s = state.borrow_mut();
                match &mut s.running {
                    Some(run) => run.viewer.command(command),
                    None => s.early.push(command),
                }
            }
            Err(e) => post(
                &ViewerNews::Refused {
                    loads: None,
                    why: format!("a command was misread: {e}"),
                },
                None,
            ),
        }
    } else if let Some(canvas) = get(data, "canvas") {
        if let (Some(run), Ok(canvas)) = (
            &mut state.borrow_mut().running,
            canvas.dyn_into::<OffscreenCanvas>(),
        ) {
            run.viewer.give_canvas(Canvas::Offscreen(canvas));
        }
    } else if let Some(ask) = get(data, "debug").and_then(|d| d.as_string()) {
        let ms = get(data, "ms").and_then(|m| m.as_f64()).map(|m| m as i32);
        let s = state.borrow();
        let done = match (ask.as_str(), &s.running) {
            ("panic", _) => {
                debug::debug_panic_while_growing();
                Ok(())
            }
            ("no-webgpu", _) => debug::debug_take_webgpu_away().map_err(|e| format!("{e:?}")),
            ("crash-on-fill", _) => {
                debug::debug_crash_worker_on_fill();
                Ok(())
            }
            ("destroy", Some(run)) => run.viewer.take_device(Loss::Destroy),
            ("lose", Some(run)) => run.viewer.take_device(Loss::Context {
                restore_after_ms: ms,
            }),
            _ => Err(format!("the drawing worker cannot do {ask} now")),
        };
        if let Err(e) = done {
            web_sys::console::error_1(&e.into());
        }
    }
}

/// Opens the viewer on the canvas the page handed over, and says so (or why it could not).
async fn open(state: Rc<RefCell<State>>, init: JsValue) {
    let canvas = get(&init, "canvas").and_then(|c| c.dyn_into::<OffscreenCanvas>().ok());
    let planar = get(&init, "planar").is_some_and(|p| p.is_truthy());
    let background = get(&init, "background")
        .map(|b| Uint8Array::new(&b).to_vec())
        .and_then(|b| <[u8; 3]>::try_from(b).ok())
        .unwrap_or([255, 255, 255]);
    let Some(canvas) = canvas else {
        post(
            &ViewerNews::Opened(Err("no canvas was handed over".into())),
            None,
        );
        return;
    };
    let workers = Workers::start(GROWTH_BUDGET_MS);
    post(&pool_news(&workers, 0, None), None);
    let workers = Rc::new(RefCell::new(workers));
    let viewer = Viewer::new(
        Canvas::Offscreen(canvas),
        planar,
        background,
        true,
        Rc::clone(&workers),
    )
    .await;
    let mut viewer = match viewer {
        Ok(viewer) => viewer,
        Err(e) => {
            post(&ViewerNews::Opened(Err(e)), None);
            return;
        }
    };
    let backend = viewer
        .backend()
        .map(str::to_string)
        .ok_or_else(|| "the drawing worker's viewer draws nothing".to_string());
    post(&ViewerNews::Opened(backend), None);
    {
        let mut s = state.borrow_mut();
        for command in s.early.drain(..) {
            viewer.command(command);
        }
        s.running = Some(Running {
            viewer,
            workers,
            stopped: false,
        });
    }
}

fn pool_news(workers: &Workers, deaths: usize, words: Option<String>) -> ViewerNews {
    ViewerNews::Pool(PoolNews {
        count: workers.count() as u32,
        status: workers.status().to_string(),
        deaths: deaths as u32,
        words,
    })
}

/// One frame of the worker ([`Viewer::tick`]): posts the news of its device, its pool, a
/// shell refused and the frame. Returns whether the loop goes on.
fn frame(run: &mut Running) -> bool {
    let tick = run.viewer.tick();
    if let Some(replaced) = &tick.replaced {
        post(
            &pool_news(&run.workers.borrow(), replaced.deaths, replaced.words()),
            None,
        );
    }
    if let Some(why) = tick.refused {
        let loads = Some(run.viewer.loads());
        post(&ViewerNews::Refused { loads, why }, None);
    }
    let (report, recorded, video) = match tick.frame {
        None => (None, None, None),
        Some(Err(failure)) => {
            post(&ViewerNews::Failed(failure), None);
            return false;
        }
        Some(Ok(frame)) => {
            let (recorded, video) = match frame.recorded {
                Some(Ok(video)) => (Some(Ok(())), Some(JsValue::from(video))),
                Some(Err(e)) => (Some(Err(e)), None),
                None => (None, None),
            };
            (Some(Box::new(frame.report)), recorded, video)
        }
    };
    let gone = matches!(tick.device, Device::Gone(_));
    post(
        &ViewerNews::Frame {
            device: tick.device,
            report,
            recorded,
        },
        video.as_ref(),
    );
    !gone
}
