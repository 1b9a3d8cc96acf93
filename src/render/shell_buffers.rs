//! GPU buffers sized once for the fully grown shell; each frame writes only what it adds (of a
//! rewritten edge, the parts that changed, in their slots). Where
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

    /// Takes `mesh` as the buffers' content, of which only the ranges `vertices` and
    /// `indices` differ from what they hold (the rest is as written before); when the mesh has
    /// outgrown them, new buffers take all of it. The bytes written.
    pub fn write(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &Mesh,
        vertices: &[Range<usize>],
        indices: &[Range<usize>],
    ) -> usize {
        let (vertex_count, index_count) = (mesh.vertices.len(), mesh.indices.len());
        if vertex_count > self.capacity.vertices || index_count > self.capacity.indices {
            let grown = Capacity {
                vertices: self.capacity.vertices.max(vertex_count * 3 / 2),
                indices: self.capacity.indices.max(index_count * 3 / 2),
            };
            *self = Self::new(device, grown, self.label);
            return self.replace(device, queue, mesh);
        }
        self.vertex_count = vertex_count;
        self.index_count = index_count as u32;
        let mut written = 0;
        for run in vertices.iter().filter(|r| !r.is_empty()) {
            let offset = (run.start * size_of::<Vertex>()) as u64;
            let bytes: &[u8] = bytemuck::cast_slice(&mesh.vertices[run.clone()]);
            queue.write_buffer(&self.vertices, offset, bytes);
            written += bytes.len();
        }
        for run in indices.iter().filter(|r| !r.is_empty()) {
            let offset = (run.start * size_of::<u32>()) as u64;
            let bytes: &[u8] = bytemuck::cast_slice(&mesh.indices[run.clone()]);
            queue.write_buffer(&self.indices, offset, bytes);
            written += bytes.len();
        }
        written
    }

    /// Replaces the whole content (for the ground's quad); the bytes written.
    pub fn replace(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, mesh: &Mesh) -> usize {
        let all = (0..mesh.vertices.len(), 0..mesh.indices.len());
        self.write(device, queue, mesh, &[all.0], &[all.1])
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
