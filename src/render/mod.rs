//! The one renderer: wgpu on WebGPU when the browser has an adapter, WebGL2 otherwise. It only
//! moves data: the mesh and pattern rows that the generator adds, the matrices of each pane of
//! the canvas (one view, or Kawaguchi's four), the material's strengths or the line drawing's
//! grid, and a quad on the ground under what has grown for the contact shadow.

mod canvas;
mod gpu;
mod in_flight;
mod pattern_texture;
mod pipeline;
mod shell_buffers;

use crate::generator::Advance;
use crate::mesh::{Bounds, Capacity, Mesh, Surface, Vertex};
use crate::pattern::texture_layout::TextureLayout;
use crate::shape::LineGrid;
use crate::spec::Colours;
use crate::spec::material::{Drawing, MaterialSpec};
use crate::view::camera::display_from_shell;
use crate::view::panes::{MAX_PANES, Pane};
use bytemuck::{Pod, Zeroable};
pub use canvas::Canvas;
use glam::DVec3;
use gpu::Gpu;
use in_flight::InFlight;
use pattern_texture::PatternTexture;
use pipeline::{DEPTH_FORMAT, Pipelines};
use shell_buffers::MeshBuffers;

/// The uniform block of shaders/shell.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Globals {
    view_proj: [[f32; 4]; 4],
    model: [[f32; 4]; 4],
    eye: [f32; 4],
    ground: [f32; 4],
    interior: [f32; 4],
    pattern: [f32; 4],
    options: [f32; 4],
    /// Gloss, anisotropy, translucency, occlusion.
    material: [f32; 4],
    /// x: strength of the ground shadow.
    shadow: [f32; 4],
    /// The clear colour in linear light (the ground is drawn in it).
    background: [f32; 4],
    /// x: 1 for a line drawing, y: lines across the edge, z: rows between rims.
    lines: [f32; 4],
    /// The pane's width and height in pixels.
    pixels: [f32; 4],
}

/// Bytes of one pane's uniform block.
const GLOBALS_SIZE: u64 = size_of::<Globals>() as u64;

/// What the shader needs to know about the shell being drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShellLook {
    pub ground: glam::Vec3,
    pub interior: glam::Vec3,
    /// Pattern rows per whorl, for the darkening inside the opening.
    pub rows_per_whorl: f32,
    /// Gloss, anisotropy, translucency, occlusion.
    pub material: [f32; 4],
    pub shadow: f32,
    /// Where the lines go, when the shell is drawn in lines.
    pub lines: Option<LineGrid>,
}

impl ShellLook {
    pub fn new(
        colours: &Colours,
        material: &MaterialSpec,
        rows_per_whorl: f64,
        line_grid: LineGrid,
    ) -> Self {
        let m = material;
        Self {
            ground: colours.ground.linear().into(),
            interior: colours.interior.linear().into(),
            rows_per_whorl: rows_per_whorl as f32,
            material: [m.gloss, m.anisotropy, m.translucency, m.occlusion].map(|x| x as f32),
            shadow: m.shadow as f32,
            lines: (m.drawing == Drawing::Lines).then_some(line_grid),
        }
    }

    /// Whether the ground's shadow is drawn: a line drawing is on plain paper.
    fn shadowed(&self) -> bool {
        self.shadow > 0.0 && self.lines.is_none()
    }
}

/// The ground under `grown` (shell space, whose −z is up on screen): a square a little wider
/// than the shell's footprint, just below its lowest point, facing up; its pattern coordinates
/// run from −1 to 1 across it, for the shadow's falloff.
fn ground_quad(grown: &Bounds) -> Mesh {
    let centre = grown.center();
    let half = (grown.max - grown.min).truncate().max_element() * 0.5 * 1.6 + 1e-6;
    let below = grown.max.z + 0.01 * grown.radius();
    let mut mesh = Mesh::default();
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        let p = DVec3::new(centre.x + x * half, centre.y + y * half, below);
        mesh.vertices
            .push(Vertex::new(p, DVec3::NEG_Z, [x, y], Surface::Ground));
    }
    mesh.quad([0, 1, 2, 3], true);
    mesh
}

/// A device the browser took away.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loss {
    /// Why, in words.
    pub reason: String,
    /// Whether the browser gave the canvas's WebGL context back, so that a device can be
    /// opened on the same canvas again.
    pub restored: bool,
}

/// The buffers of one shell.
struct Shell {
    mesh: MeshBuffers,
    edge: MeshBuffers,
    ground: MeshBuffers,
    pattern: Option<PatternTexture>,
    look: ShellLook,
    rows_grown: u32,
    bind_group: wgpu::BindGroup,
}

/// Render targets that follow the canvas size.
struct Targets {
    depth: wgpu::TextureView,
    msaa: Option<wgpu::TextureView>,
}

/// The renderer of one canvas.
pub struct Renderer {
    gpu: Gpu,
    encode_srgb: bool,
    pipelines: Pipelines,
    layout: wgpu::BindGroupLayout,
    /// One uniform block per pane, `stride` bytes apart.
    uniforms: wgpu::Buffer,
    stride: u64,
    blank: PatternTexture,
    targets: Targets,
    /// Samples a pixel now takes: the device's MSAA samples, or 1 ([`Self::multisample`]).
    samples: u32,
    /// The pipelines of the other sample count, once built, by their samples.
    other: Option<(u32, Pipelines)>,
    shell: Option<Shell>,
    background: wgpu::Color,
    background_linear: [f32; 3],
    /// Frames handed to the GPU and not yet finished.
    in_flight: InFlight,
}

fn create_targets(
    device: &wgpu::Device,
    config: &wgpu::SurfaceConfiguration,
    samples: u32,
) -> Targets {
    let texture = |label, format, sample_count| {
        device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: config.width,
                    height: config.height,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&wgpu::TextureViewDescriptor::default())
    };
    Targets {
        depth: texture("depth", DEPTH_FORMAT, samples),
        msaa: (samples > 1).then(|| texture("msaa", config.format, samples)),
    }
}

impl Renderer {
    /// Sets up wgpu on the canvas: WebGPU if an adapter comes, WebGL2 otherwise.
    pub async fn new(canvas: &Canvas) -> Result<Self, String> {
        let gpu = Gpu::open(canvas).await?;
        let device = &gpu.device;
        let layout = pipeline::bind_group_layout(device, GLOBALS_SIZE);
        let pipelines = pipeline::pipelines(device, &layout, gpu.config.format, gpu.samples);
        let stride = GLOBALS_SIZE.next_multiple_of(u64::from(
            device.limits().min_uniform_buffer_offset_alignment,
        ));
        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("globals"),
            size: stride * MAX_PANES as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let blank = PatternTexture::new(device, TextureLayout::new(1, 1).expect("1×1 fits"));
        let targets = create_targets(device, &gpu.config, gpu.samples);
        let samples = gpu.samples;
        Ok(Self {
            encode_srgb: !gpu.config.format.is_srgb(),
            gpu,
            pipelines,
            layout,
            uniforms,
            stride,
            blank,
            targets,
            samples,
            other: None,
            shell: None,
            background: wgpu::Color::BLACK,
            background_linear: [0.0; 3],
            in_flight: InFlight::default(),
        })
    }

    /// Whether the GPU has finished enough of the frames handed to it for another to be drawn
    /// (see `in_flight.rs`): a frame drawn now would otherwise only wait in a queue behind them.
    pub fn ready(&self) -> bool {
        // Polling only looks at the GPU's fences; a failure to poll is a lost device, which the
        // watch reports.
        let _ = self.gpu.device.poll(wgpu::PollType::Poll);
        self.in_flight.has_room()
    }

    /// Frames the GPU has finished drawing since this renderer opened, and those handed to it
    /// and not finished yet: frames waiting while none finishes for long means nothing reaches
    /// the screen.
    pub fn frames(&self) -> (u64, u64) {
        // As in `ready`, a failure to poll is a lost device, which the watch reports.
        let _ = self.gpu.device.poll(wgpu::PollType::Poll);
        (self.in_flight.finished(), self.in_flight.unfinished())
    }

    /// "WebGPU" or "WebGL2".
    pub fn backend(&self) -> &'static str {
        self.gpu.backend
    }

    /// An uncaptured error of the device, in words.
    pub fn failure(&self) -> Option<String> {
        self.gpu.watch.lock().ok().and_then(|w| w.error.clone())
    }

    /// Whether the browser took the device away, and why: then nothing more is drawn with
    /// this renderer, and another must be opened.
    pub fn lost(&self) -> Option<Loss> {
        let watch = self.gpu.watch.lock().ok()?;
        watch.lost.clone().map(|reason| Loss {
            reason,
            restored: watch.restored,
        })
    }

    /// Destroys the device as a driver reset would (`GPUDevice.destroy()` on WebGPU; nothing
    /// on WebGL2, whose context the `WEBGL_lose_context` extension takes away instead). For the
    /// page tests' test-only hook.
    pub fn destroy_device(&self) {
        self.gpu.device.destroy();
    }

    /// The clear colour, as sRGB bytes; written as is to a target that does not encode sRGB.
    pub fn set_background(&mut self, srgb: [u8; 3]) {
        let [r, g, b] = if self.encode_srgb {
            srgb.map(|c| f64::from(c) / 255.0)
        } else {
            crate::spec::colour::Rgb(srgb).linear().map(f64::from)
        };
        self.background = wgpu::Color { r, g, b, a: 1.0 };
        self.background_linear = crate::spec::colour::Rgb(srgb).linear();
    }

    /// Width over height of the canvas.
    pub fn aspect(&self) -> f32 {
        self.gpu.config.width as f32 / self.gpu.config.height as f32
    }

    /// Follows the canvas size in device pixels.
    pub fn resize(&mut self, width: u32, height: u32) {
        let (width, height) = (width.max(1), height.max(1));
        if (width, height) != (self.gpu.config.width, self.gpu.config.height) {
            self.gpu.config.width = width;
            self.gpu.config.height = height;
            self.gpu
                .surface
                .configure(&self.gpu.device, &self.gpu.config);
            self.targets = create_targets(&self.gpu.device, &self.gpu.config, self.samples);
        }
    }

    /// Draws with the device's MSAA samples, or with one sample a pixel: a picture shown
    /// smaller than drawn is smoothed as much by the browser's downscaling, at a third of the
    /// cost on a software rasterizer. A change builds the targets anew, and the pipelines the
    /// first time (their shaders take most of a second to compile on one).
    pub fn multisample(&mut self, on: bool) {
        let samples = if on { self.gpu.samples } else { 1 };
        if samples == self.samples {
            return;
        }
        let (device, format) = (&self.gpu.device, self.gpu.config.format);
        let pipelines = match self.other.take() {
            Some((built, pipelines)) if built == samples => pipelines,
            _ => pipeline::pipelines(device, &self.layout, format, samples),
        };
        let before = std::mem::replace(&mut self.pipelines, pipelines);
        self.other = Some((self.samples, before));
        self.samples = samples;
        self.targets = create_targets(device, &self.gpu.config, samples);
    }

    /// Allocates the buffers of a new shell at its final size; `pattern` is its texture layout
    /// when it has a pattern.
    pub fn load_shell(
        &mut self,
        capacity: (Capacity, Capacity),
        pattern: Option<TextureLayout>,
        look: ShellLook,
    ) {
        let pattern = pattern.map(|layout| PatternTexture::new(&self.gpu.device, layout));
        let view = &pattern.as_ref().unwrap_or(&self.blank).view;
        let bind_group = self
            .gpu
            .device
            .create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("shell"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                            buffer: &self.uniforms,
                            offset: 0,
                            size: wgpu::BufferSize::new(GLOBALS_SIZE),
                        }),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(view),
                    },
                ],
            });
        self.shell = Some(Shell {
            mesh: MeshBuffers::new(&self.gpu.device, capacity.0, "mesh"),
            edge: MeshBuffers::new(&self.gpu.device, capacity.1, "edge"),
            ground: MeshBuffers::new(
                &self.gpu.device,
                Capacity {
                    vertices: 4,
                    indices: 6,
                },
                "ground",
            ),
            pattern,
            look,
            rows_grown: 0,
            bind_group,
        });
    }

    /// Uploads what the generator just added: new mesh ranges, the ranges of the edge written
    /// anew, new pattern rows (`rgba` holds the rows of `advance.rows`). The bytes written,
    /// which reach the GPU at the next [`Self::draw`] or [`Self::flush`].
    pub fn upload(&mut self, mesh: &Mesh, edge: &Mesh, advance: &Advance, rgba: &[u8]) -> usize {
        let Some(shell) = self.shell.as_mut() else {
            return 0;
        };
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        let added = (advance.vertices.clone(), advance.indices.clone());
        let mut written = (shell.mesh).write(device, queue, mesh, &[added.0], &[added.1]);
        if let Some(runs) = &advance.edge {
            written += (shell.edge).write(device, queue, edge, &runs.vertices, &runs.indices);
        }
        if let Some(pattern) = shell.pattern.as_ref().filter(|_| !rgba.is_empty()) {
            pattern.write_rows(&self.gpu.queue, advance.rows.start as u32, rgba);
            written += rgba.len();
        }
        shell.rows_grown = advance.rows.end as u32;
        written
    }

    /// Draws the shell loaded with `look` from the next frame on (its buffers stay).
    pub fn set_look(&mut self, look: ShellLook) {
        if let Some(shell) = self.shell.as_mut() {
            shell.look = look;
        }
    }

    /// Hands the writes made since the last frame to the GPU without drawing.
    pub fn flush(&self) {
        self.gpu.queue.submit([]);
    }

    /// Lays the ground under `grown`, the part of the shell grown so far.
    pub fn set_ground(&mut self, grown: &Bounds) {
        if let Some(shell) = self.shell.as_mut()
            && grown.min.x <= grown.max.x
        {
            shell
                .ground
                .replace(&self.gpu.device, &self.gpu.queue, &ground_quad(grown));
        }
    }

    /// The uniform block of `pane` for `shell`.
    fn globals(&self, shell: &Shell, pane: &Pane) -> Globals {
        let [_, _, width, height] =
            pixels(pane.viewport, self.gpu.config.width, self.gpu.config.height);
        let (cells, block_rows, patterned) = match &shell.pattern {
            Some(p) => (p.layout.cells, p.layout.block_rows, 1.0),
            None => (1, 1, 0.0),
        };
        let lines = match shell.look.lines {
            Some(grid) => [1.0, grid.across as f32, grid.rows as f32, 0.0],
            None => [0.0; 4],
        };
        Globals {
            view_proj: pane.view_projection.to_cols_array_2d(),
            model: display_from_shell().to_cols_array_2d(),
            eye: pane.eye.to_array(),
            ground: shell.look.ground.extend(1.0).to_array(),
            interior: shell.look.interior.extend(1.0).to_array(),
            pattern: [
                cells as f32,
                shell.rows_grown as f32,
                block_rows as f32,
                patterned,
            ],
            options: [
                if self.encode_srgb { 1.0 } else { 0.0 },
                shell.look.rows_per_whorl,
                0.0,
                0.0,
            ],
            material: shell.look.material,
            shadow: [shell.look.shadow, 0.0, 0.0, 0.0],
            background: [
                self.background_linear[0],
                self.background_linear[1],
                self.background_linear[2],
                1.0,
            ],
            lines,
            pixels: [width as f32, height as f32, 0.0, 0.0],
        }
    }

    /// Draws one frame: the shell in each of `panes` (at most [`MAX_PANES`]).
    pub fn draw(&mut self, panes: &[Pane]) -> Result<(), String> {
        let frame = match self.gpu.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(frame)
            | wgpu::CurrentSurfaceTexture::Suboptimal(frame) => frame,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                return Ok(());
            }
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.gpu
                    .surface
                    .configure(&self.gpu.device, &self.gpu.config);
                return Ok(());
            }
            other => return Err(format!("The canvas could not be drawn on ({other:?}).")),
        };
        let view = frame
            .texture
            .create_view(&wgpu::TextureViewDescriptor::default());
        let panes = &panes[..panes.len().min(MAX_PANES)];
        if let Some(shell) = &self.shell {
            for (i, pane) in panes.iter().enumerate() {
                let globals = self.globals(shell, pane);
                self.gpu.queue.write_buffer(
                    &self.uniforms,
                    i as u64 * self.stride,
                    bytemuck::bytes_of(&globals),
                );
            }
        }
        let mut encoder = self
            .gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        {
            let (target, resolve) = match &self.targets.msaa {
                Some(msaa) => (msaa, Some(&view)),
                None => (&view, None),
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("shell"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: resolve,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(self.background),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &self.targets.depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            if let Some(shell) = &self.shell {
                let (width, height) = (self.gpu.config.width, self.gpu.config.height);
                for (i, pane) in panes.iter().enumerate() {
                    let [x, y, w, h] = pixels(pane.viewport, width, height);
                    if w == 0 || h == 0 {
                        continue;
                    }
                    pass.set_viewport(x as f32, y as f32, w as f32, h as f32, 0.0, 1.0);
                    pass.set_scissor_rect(x, y, w, h);
                    pass.set_bind_group(0, &shell.bind_group, &[(i as u64 * self.stride) as u32]);
                    if shell.look.lines.is_some() {
                        pass.set_pipeline(&self.pipelines.outline);
                        shell.mesh.draw(&mut pass);
                        shell.edge.draw(&mut pass);
                    }
                    pass.set_pipeline(&self.pipelines.shell);
                    shell.mesh.draw(&mut pass);
                    shell.edge.draw(&mut pass);
                    if shell.look.shadowed() {
                        shell.ground.draw(&mut pass);
                    }
                }
                // WebGL2 resolves the multisampled target with a blit that the scissor still
                // clips: open it to the whole canvas again, or only the last pane shows.
                pass.set_scissor_rect(0, 0, width, height);
            }
        }
        self.gpu.queue.submit([encoder.finish()]);
        self.in_flight.submitted(&self.gpu.queue);
        self.gpu.queue.present(frame);
        Ok(())
    }
}

/// A viewport given in fractions of the canvas, in whole pixels within it.
fn pixels([x, y, w, h]: [f32; 4], width: u32, height: u32) -> [u32; 4] {
    let at = |f: f32, size: u32| ((f * size as f32).round() as u32).min(size);
    let (left, top) = (at(x, width), at(y, height));
    [left, top, at(x + w, width) - left, at(y + h, height) - top]
}
