//! The page's listeners: the window's address and theme, the shell's canvas (orbit, zoom,
//! reset; again on a fresh canvas that took its place), every control, a swipe across a
//! story's card, and the keyboard, whose rules are the core's (`work::shortcuts`). Each hands
//! what happened to the app.

use super::canvases::canvas;
use super::page;
use super::record;
use crate::export::Download;
use crate::view::gestures;
use crate::web::app::{App, Shared};
use crate::web::dom;
use crate::work::recording::Support;
use crate::work::session::Session;
use crate::work::shortcuts::{self, Press, Shortcut, Target};
use crate::work::viewer_command::{PointerChange, ViewCommand};
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_sys::{Event, EventTarget, HtmlInputElement, KeyboardEvent, PointerEvent, WheelEvent};

/// Adds an event listener that lives as long as the page.
fn on<E: JsCast + 'static>(
    target: &EventTarget,
    kind: &str,
    app: &Shared,
    handler: impl Fn(&mut App, E) + 'static,
) -> Result<(), JsValue> {
    let app = Rc::clone(app);
    let closure = Closure::<dyn FnMut(Event)>::new(move |event: Event| {
        // After a panic the app stays borrowed: events then do nothing, and the page shows
        // the panic's message.
        if let (Ok(event), Ok(mut app)) = (event.dyn_into::<E>(), app.try_borrow_mut()) {
            handler(&mut app, event);
        }
    });
    let options = web_sys::AddEventListenerOptions::new();
    options.set_passive(false);
    target.add_event_listener_with_callback_and_add_event_listener_options(
        kind,
        closure.as_ref().unchecked_ref(),
        &options,
    )?;
    closure.forget();
    Ok(())
}

/// A click on the element with this id.
fn on_click(id: &str, app: &Shared, handler: impl Fn(&mut App) + 'static) -> Result<(), JsValue> {
    match page::element(id) {
        Some(e) => on(&e.into(), "click", app, move |a, _: Event| handler(a)),
        None => Ok(()),
    }
}

/// Listens to the shell's canvas: orbit, zoom, reset (again on a fresh canvas that replaced it).
pub(super) fn listen_canvas(app: &Shared, canvas: &EventTarget) -> Result<(), JsValue> {
    on(canvas, "pointerdown", app, |a, e: PointerEvent| {
        // Capture keeps the drag alive outside the canvas; failing that, it ends at the edge.
        if let Some(canvas) = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
        {
            let _ = canvas.set_pointer_capture(e.pointer_id());
        }
        a.viewer()
            .command(ViewCommand::Pointer(PointerChange::Down {
                id: e.pointer_id(),
                x: e.client_x() as f32,
                y: e.client_y() as f32,
            }));
    })?;
    on(canvas, "pointermove", app, |a, e: PointerEvent| {
        a.viewer()
            .command(ViewCommand::Pointer(PointerChange::Move {
                id: e.pointer_id(),
                x: e.client_x() as f32,
                y: e.client_y() as f32,
            }));
    })?;
    for kind in ["pointerup", "pointercancel"] {
        on(canvas, kind, app, |a, e: PointerEvent| {
            a.viewer().command(ViewCommand::Pointer(PointerChange::Up {
                id: e.pointer_id(),
            }));
        })?;
    }
    on(canvas, "wheel", app, |a, e: WheelEvent| {
        // An embedded shell leaves the wheel to the page around it; a pinch (or the wheel with
        // Ctrl) still zooms.
        if a.embedded() && !e.ctrl_key() {
            return;
        }
        e.prevent_default();
        a.viewer().command(ViewCommand::Wheel(e.delta_y()));
    })?;
    on(canvas, "dblclick", app, |a, _: Event| a.reset_camera())?;
    Ok(())
}

pub(super) fn listen(app: &Shared) -> Result<(), JsValue> {
    let window: EventTarget = web_sys::window().ok_or("no window")?.into();
    on(&window, "hashchange", app, |a, _: Event| a.route())?;
    if let Some(query) = page::media(page::DARK) {
        on(&query.into(), "change", app, |a, _: Event| {
            a.theme_changed()
        })?;
    }
    listen_canvas(app, &canvas("shell")?.into())?;
    on_click("play", app, |a| a.act(Session::toggle_playing))?;
    on_click("restart", app, |a| a.act(Session::restart))?;
    on_click("step", app, |a| a.act(Session::step))?;
    on_click("finish", app, |a| a.act(Session::finish))?;
    on_click("reset-camera", app, App::reset_camera)?;
    on_click("views", app, |a| a.act(Session::toggle_views))?;
    on_click("fullscreen", app, |a| a.toggle_fullscreen())?;
    on_click("copy-link", app, App::copy_link)?;
    on_click("copy-embed", app, App::copy_embed)?;
    if let Some(button) = page::element("record") {
        let shared = Rc::clone(app);
        let closure = Closure::<dyn FnMut()>::new(move || record_pressed(&shared));
        button.add_event_listener_with_callback("click", closure.as_ref().unchecked_ref())?;
        closure.forget();
    }
    on_click("record-cancel", app, |a| {
        a.stop_recording("you cancelled it")
    })?;
    for what in Download::ALL {
        on_click(&format!("download-{}", what.name()), app, move |a| {
            a.download(what)
        })?;
    }
    on_click("map-open", app, App::open_map)?;
    on_click("map-draw", app, App::draw_map)?;
    on_click("map-close", app, App::close_map)?;
    on_click("breed-open", app, App::open_breeding)?;
    on_click("breed-back", app, App::breed_back)?;
    on_click("breed-keep", app, App::breed_keep)?;
    if let Some(rate) = page::element("breed-rate") {
        on(&rate.clone().into(), "input", app, |_, e: Event| {
            if let Some(input) = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
            {
                page::set_text("breed-rate-value", &input.value());
            }
        })?;
        on(&rate.into(), "change", app, |a, e: Event| {
            let value = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                .and_then(|i| i.value().parse::<f64>().ok());
            if let Some(rate) = value {
                a.breed_rate(rate);
            }
        })?;
    }
    for name in ["x", "y"] {
        if let Some(select) = page::element(&format!("map-{name}")) {
            on(&select.into(), "change", app, move |a, _: Event| {
                a.map_chose(name)
            })?;
        }
    }
    on_click("panel-toggle", app, |_| {
        if let (Some(panel), Some(button)) = (page::element("panel"), page::element("panel-toggle"))
        {
            let open = panel.class_list().toggle("open").unwrap_or(false);
            dom::attr(
                &button,
                "aria-expanded",
                if open { "true" } else { "false" },
            );
        }
    })?;
    if let Some(speed) = page::element("speed") {
        on(&speed.into(), "change", app, |a, e: Event| {
            let value = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                .map(|i| i.value());
            if let Some(v) = value {
                a.set_speed(&v);
            }
        })?;
    }
    let document: EventTarget = page::document().into();
    on(&document, "visibilitychange", app, |a, _: Event| {
        if page::document().hidden() {
            a.stop_recording("the tab was hidden");
        }
    })?;
    // A swipe across the story's card turns its page, as the core reads the stroke.
    if let Some(card) = page::element("story") {
        let start = Rc::new(std::cell::Cell::new(None));
        let pressed = Rc::clone(&start);
        // A touch or a pen: a mouse dragged across the words selects them.
        on(
            &card.clone().into(),
            "pointerdown",
            app,
            move |_, e: PointerEvent| {
                let swipes = matches!(e.pointer_type().as_str(), "touch" | "pen");
                pressed.set(swipes.then(|| (e.client_x(), e.client_y(), e.time_stamp())));
            },
        )?;
        let cancelled = Rc::clone(&start);
        on(
            &card.clone().into(),
            "pointercancel",
            app,
            move |_, _: Event| {
                cancelled.set(None);
            },
        )?;
        on(&card.into(), "pointerup", app, move |a, e: PointerEvent| {
            let Some((x, y, t)) = start.take() else {
                return;
            };
            let (dx, dy) = ((e.client_x() - x) as f32, (e.client_y() - y) as f32);
            if let Some(forward) = gestures::swipe(dx, dy, e.time_stamp() - t) {
                a.story_step(forward);
            }
        })?;
    }
    on(&document, "keydown", app, |a, e: KeyboardEvent| {
        let target = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
            .map_or(Target::Page, |t| Target::of_tag(&t.tag_name()));
        let key = e.key();
        let press = Press {
            key: &key,
            modified: e.ctrl_key() || e.meta_key() || e.alt_key(),
            target,
            shell_shown: a.has_shell(),
            covered: a.covered(),
            in_story: a.in_story(),
        };
        let Some(shortcut) = shortcuts::shortcut(press) else {
            return;
        };
        match shortcut {
            Shortcut::Tiles(dx, dy) => a.step_tiles(dx, dy),
            Shortcut::Leave => a.escape(),
            Shortcut::PlayPause => a.act(Session::toggle_playing),
            Shortcut::Restart => a.act(Session::restart),
            Shortcut::Step => a.act(Session::step),
            Shortcut::Finish => a.act(Session::finish),
            Shortcut::ResetCamera => a.reset_camera(),
            Shortcut::ToggleViews => a.act(Session::toggle_views),
            Shortcut::Fullscreen => a.toggle_fullscreen(),
            Shortcut::Speed(change) => a.set_speed(&change.of(a.speed()).to_string()),
            Shortcut::StoryStep(forward) => a.story_step(forward),
        }
        e.prevent_default();
    })?;
    Ok(())
}

/// Record: records the growth; the first time, asks the browser what it can record video
/// with, shows the answer, and records once it has one.
/// (After a panic the app stays borrowed, and the click does nothing.)
fn record_pressed(app: &Shared) {
    let Ok(mut held) = app.try_borrow_mut() else {
        return;
    };
    let support = held.support();
    if *support.borrow() != Support::Unasked {
        held.record();
        return;
    }
    *support.borrow_mut() = Support::Checking;
    held.show_support();
    drop(held);
    let app = Rc::downgrade(app);
    wasm_bindgen_futures::spawn_local(async move {
        let found = record::probe().await;
        *support.borrow_mut() = found;
        if let Some(app) = app.upgrade()
            && let Ok(mut app) = app.try_borrow_mut()
        {
            app.show_support();
            app.record();
        }
    });
}
