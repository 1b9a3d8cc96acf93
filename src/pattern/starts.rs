//! Starting cells of excitable models: blocks of cells set to a level, placed by the seed.

use super::noise::Noise;

/// Sets `count` blocks of `width` cells (in unrefined cells, scaled by `refinement`) of `v` to
/// `level`, at positions drawn from `seed`.
pub fn place(v: &mut [f32], count: u32, width: u32, level: f64, refinement: u32, seed: u64) {
    let width = (width.max(1) * refinement.max(1)) as usize;
    let mut noise = Noise::new(seed, 2);
    for _ in 0..count {
        let first = noise.below(v.len());
        for cell in v.iter_mut().skip(first).take(width) {
            *cell = level as f32;
        }
    }
}
