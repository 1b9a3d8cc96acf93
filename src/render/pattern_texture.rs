//! The pigmentation pattern on the GPU: a texture whose rows are time and whose columns are
//! cells of the growing edge, folded by [`TextureLayout`]. Colours are stored as sRGB bytes
//! (`Rgba8UnormSrgb`), which every backend can filter and read.

use crate::pattern::texture_layout::TextureLayout;

/// The pattern texture and its layout.
pub struct PatternTexture {
    texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub layout: TextureLayout,
}

impl PatternTexture {
    pub fn new(device: &wgpu::Device, layout: TextureLayout) -> Self {
        let (width, height) = layout.size();
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("pattern"),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8UnormSrgb,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        Self {
            texture,
            view,
            layout,
        }
    }

    /// Writes rows `first..` from `rgba`, which holds `cells × 4` bytes a row.
    pub fn write_rows(&self, queue: &wgpu::Queue, first: u32, rgba: &[u8]) {
        let row_bytes = self.layout.cells as usize * 4;
        let end = first + (rgba.len() / row_bytes) as u32;
        for (row, count) in self.layout.runs(first, end) {
            let (x, y) = self.layout.origin(row);
            let start = (row - first) as usize * row_bytes;
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &self.texture,
                    mip_level: 0,
                    origin: wgpu::Origin3d { x, y, z: 0 },
                    aspect: wgpu::TextureAspect::All,
                },
                &rgba[start..start + count as usize * row_bytes],
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(row_bytes as u32),
                    rows_per_image: Some(count),
                },
                wgpu::Extent3d {
                    width: self.layout.cells,
                    height: count,
                    depth_or_array_layers: 1,
                },
            );
        }
    }
}
