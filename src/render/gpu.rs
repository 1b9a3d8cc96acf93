//! The browser's graphics device on one canvas (an element or an offscreen canvas): WebGPU when an adapter comes, WebGL2
//! otherwise, the canvas configured in an 8-bit colour format, and a watch that records a lost
//! device (WebGPU's device-lost callback, WebGL's `webglcontextlost` and
//! `webglcontextrestored` events) apart from an uncaptured error, so that the page can open a
//! device again after the one and say the other in words.

use super::canvas::Canvas;
use std::sync::{Arc, Mutex};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::Closure;

/// MSAA samples when the format allows them.
const SAMPLES: u32 = 4;

/// A device and the canvas surface it draws on.
pub(super) struct Gpu {
    pub(super) surface: wgpu::Surface<'static>,
    pub(super) device: wgpu::Device,
    pub(super) queue: wgpu::Queue,
    pub(super) config: wgpu::SurfaceConfiguration,
    /// "WebGPU" or "WebGL2".
    pub(super) backend: &'static str,
    /// MSAA samples the surface's format allows, up to [`SAMPLES`].
    pub(super) samples: u32,
    /// What the watch saw: a lost device, an uncaptured error.
    pub(super) watch: Arc<Mutex<Watch>>,
    /// The canvas's WebGL context events, removed with the device.
    _context_events: Vec<CanvasListener>,
}

/// A lost device or an error, as the watch saw them.
#[derive(Clone, Debug, Default)]
pub(super) struct Watch {
    /// Why the device was lost, in words, once it is.
    pub(super) lost: Option<String>,
    /// Whether the browser gave a lost WebGL context back (`webglcontextrestored`).
    pub(super) restored: bool,
    /// The first uncaptured error, in words.
    pub(super) error: Option<String>,
}

impl Gpu {
    /// Opens a device on `canvas` and configures the canvas for it.
    pub(super) async fn open(canvas: &Canvas) -> Result<Self, String> {
        let (width, height) = canvas.size();
        let (width, height) = (width.max(1), height.max(1));
        let (surface, adapter, backend) = adapter(canvas).await?;
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("seashells"),
                required_features: wgpu::Features::empty(),
                required_limits: wgpu::Limits::downlevel_webgl2_defaults()
                    .using_resolution(adapter.limits()),
                ..Default::default()
            })
            .await
            .map_err(|e| format!("The {backend} device could not be opened ({e})."))?;
        let watch = watch(&device);
        let context_events = if backend == "WebGL2" {
            watch_context(canvas, &watch)
        } else {
            Vec::new()
        };
        let config = configuration(&surface, &adapter, width, height)?;
        surface.configure(&device, &config);
        let samples = if adapter
            .get_texture_format_features(config.format)
            .flags
            .sample_count_supported(SAMPLES)
        {
            SAMPLES
        } else {
            1
        };
        Ok(Self {
            surface,
            device,
            queue,
            config,
            backend,
            samples,
            watch,
            _context_events: context_events,
        })
    }
}

/// The canvas's surface and an adapter for it, with the backend's name.
async fn adapter(
    canvas: &Canvas,
) -> Result<(wgpu::Surface<'static>, wgpu::Adapter, &'static str), String> {
    let instance = wgpu::util::new_instance_with_webgpu_detection(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::BROWSER_WEBGPU | wgpu::Backends::GL,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    })
    .await;
    let surface = instance
        .create_surface(canvas.surface_target())
        .map_err(|e| {
            format!("This browser offers neither WebGPU nor WebGL2 on this page ({e}).")
        })?;
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: Some(&surface),
            apply_limit_buckets: false,
        })
        .await
        .map_err(|e| {
            format!("No graphics adapter is available: neither WebGPU nor WebGL2 works here ({e}).")
        })?;
    let backend = match adapter.get_info().backend {
        wgpu::Backend::BrowserWebGpu => "WebGPU",
        _ => "WebGL2",
    };
    Ok((surface, adapter, backend))
}

/// Where a lost device or an uncaptured error is written, in words, for the page.
fn watch(device: &wgpu::Device) -> Arc<Mutex<Watch>> {
    let watch = Arc::new(Mutex::new(Watch::default()));
    let lost = Arc::clone(&watch);
    device.set_device_lost_callback(move |reason, message| {
        if let Ok(mut w) = lost.lock() {
            w.lost = Some(format!("{reason:?}: {message}"));
        }
    });
    let errors = Arc::clone(&watch);
    device.on_uncaptured_error(Arc::new(move |error| {
        if let Ok(mut w) = errors.lock() {
            w.error
                .get_or_insert_with(|| format!("The graphics device reported an error: {error}"));
        }
    }));
    watch
}

/// An event listener on a canvas, removed when dropped (its closure goes with it).
pub(super) struct CanvasListener {
    canvas: web_sys::EventTarget,
    kind: &'static str,
    closure: Closure<dyn FnMut(web_sys::Event)>,
}

impl Drop for CanvasListener {
    fn drop(&mut self) {
        // Removing a listener that is there cannot fail.
        let _ = self
            .canvas
            .remove_event_listener_with_callback(self.kind, self.closure.as_ref().unchecked_ref());
    }
}

/// Watches a WebGL2 canvas for the browser taking its context away, and giving it back. The
/// loss is accepted (`preventDefault`), which asks the browser to restore the context later.
fn watch_context(canvas: &Canvas, watch: &Arc<Mutex<Watch>>) -> Vec<CanvasListener> {
    let canvas = canvas.events();
    let listen = |kind: &'static str, seen: fn(&mut Watch)| {
        let watch = Arc::clone(watch);
        let closure = Closure::<dyn FnMut(web_sys::Event)>::new(move |event: web_sys::Event| {
            event.prevent_default();
            if let Ok(mut w) = watch.lock() {
                seen(&mut w);
            }
        });
        // Adding a listener to a canvas cannot fail.
        let _ = canvas.add_event_listener_with_callback(kind, closure.as_ref().unchecked_ref());
        CanvasListener {
            canvas: canvas.clone(),
            kind,
            closure,
        }
    };
    vec![
        listen("webglcontextlost", |w| {
            w.lost = Some("the browser took the WebGL context away".into());
        }),
        listen("webglcontextrestored", |w| w.restored = true),
    ]
}

/// The canvas's configuration: an sRGB 8-bit format where it has one (else a linear one, and
/// the shader encodes), presented in step with the display.
fn configuration(
    surface: &wgpu::Surface,
    adapter: &wgpu::Adapter,
    width: u32,
    height: u32,
) -> Result<wgpu::SurfaceConfiguration, String> {
    let caps = surface.get_capabilities(adapter);
    let format = caps
        .formats
        .iter()
        .copied()
        .find(|f| {
            matches!(
                f,
                wgpu::TextureFormat::Rgba8UnormSrgb | wgpu::TextureFormat::Bgra8UnormSrgb
            )
        })
        .or_else(|| {
            caps.formats.iter().copied().find(|f| {
                matches!(
                    f,
                    wgpu::TextureFormat::Rgba8Unorm | wgpu::TextureFormat::Bgra8Unorm
                )
            })
        })
        .ok_or_else(|| {
            format!(
                "The canvas offers no 8-bit colour format ({:?}).",
                caps.formats
            )
        })?;
    Ok(wgpu::SurfaceConfiguration {
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        format,
        color_space: wgpu::SurfaceColorSpace::Auto,
        width,
        height,
        present_mode: wgpu::PresentMode::Fifo,
        desired_maximum_frame_latency: 2,
        alpha_mode: caps.alpha_modes[0],
        view_formats: vec![],
    })
}
