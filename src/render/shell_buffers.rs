//! GPU buffers sized once for the fully grown shell; each frame writes only what it adds (of a
//! rewritten edge, what follows the start it kept). Where
//! a shape could only estimate its final size (an implicit surface), the buffers are
//! reallocated, half as large again as needed, the first time a mesh outgrows them. A draw
//! binds only the part written so far: wgpu fills every part of a buffer that a draw binds and
//! nothing has written with zeros first, which for a whole buffer sized for the grown shell
//! (tens of megabytes for the Murex) took one frame 26–54 ms of the page's thread on WebGL2.

use crate::mesh::{Capacity, Mesh, Vertex};
use std::ops::Range;

/// A vertex buffer and an index buffer allocated for a mesh's final size.
pub struct MeshBuffers {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    capacity: Capacity,
    label: &'static str,
    /// Vertices and indices written from the start of the buffers: what a draw binds.
    vertex_count: usize,
    index_count: u32,
}

fn bytes(count: usize, size: usize) -> u64 {
    // Never zero: an empty buffer cannot be bound.
    (count.max(4) * size) as u64
}

impl MeshBuffers {
    pub fn new(device: &wgpu::Device, capacity: Capacity, label: &'static str) -> Self {
        let vertices = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: bytes(capacity.vertices, size_of::<Vertex>()),
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let indices = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: bytes(capacity.indices, size_of::<u32>()),
            usage: wgpu::BufferUsages::INDEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Self {
            vertices,
            indices,
            capacity,
            label,
            vertex_count: 0,
            index_count: 0,
        }
    }

    /// Writes the given ranges of `mesh` at the same places in the buffers; when the mesh has
    /// outgrown them, new buffers take all of it.
    pub fn write(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &Mesh,
        mut vertices: Range<usize>,
        mut indices: Range<usize>,
    ) {
        if vertices.end > self.capacity.vertices || indices.end > self.capacity.indices {
            let grown = Capacity {
                vertices: self.capacity.vertices.max(vertices.end * 3 / 2),
                indices: self.capacity.indices.max(indices.end * 3 / 2),
            };
            *self = Self::new(device, grown, self.label);
            vertices = 0..vertices.end;
            indices = 0..indices.end;
        }
        self.vertex_count = vertices.end;
        self.index_count = indices.end as u32;
        if !vertices.is_empty() {
            let offset = (vertices.start * size_of::<Vertex>()) as u64;
            queue.write_buffer(
                &self.vertices,
                offset,
                bytemuck::cast_slice(&mesh.vertices[vertices]),
            );
        }
        if !indices.is_empty() {
            let offset = (indices.start * size_of::<u32>()) as u64;
            queue.write_buffer(
                &self.indices,
                offset,
                bytemuck::cast_slice(&mesh.indices[indices]),
            );
        }
    }

    /// Replaces the whole content (for the ground's quad).
    pub fn replace(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, mesh: &Mesh) {
        self.rewrite_from(device, queue, mesh, (0, 0));
    }

    /// Takes `mesh` as the whole content, the first `kept` (vertices, indices) being as the
    /// buffers hold them already: only the rest is written (for the transient edge mesh).
    pub fn rewrite_from(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &Mesh,
        kept: (usize, usize),
    ) {
        self.write(
            device,
            queue,
            mesh,
            kept.0..mesh.vertices.len(),
            kept.1..mesh.indices.len(),
        );
    }

    pub fn draw<'a>(&'a self, pass: &mut wgpu::RenderPass<'a>) {
        if self.index_count == 0 || self.vertex_count == 0 {
            return;
        }
        let vertex_bytes = (self.vertex_count * size_of::<Vertex>()) as u64;
        let index_bytes = u64::from(self.index_count) * size_of::<u32>() as u64;
        pass.set_vertex_buffer(0, self.vertices.slice(..vertex_bytes));
        pass.set_index_buffer(self.indices.slice(..index_bytes), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, 0..1);
    }
}
