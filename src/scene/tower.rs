//! The 54-block wooden tower of the thesis's Jenga scenes (Fig. 4.6).

use super::ObjectDesc;
use glam::Vec3;

/// Levels of a tower.
pub const LEVELS: usize = 18;
/// Blocks per level.
pub const SLOTS: usize = 3;

/// A tower of 18 levels × 3 wooden blocks of 7.5 × 2.5 × 1.5 cm, alternate
/// levels turned 90°, standing on `base` (world, m).
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tower {
    /// The centre of its bottom face (m).
    pub base: Vec3,
}

/// The name of the block in `slot` (0..3) of `level` (0..18).
pub fn block_name(level: usize, slot: usize) -> String {
    format!("block{level}-{slot}")
}

impl Tower {
    /// The blocks, bottom level first, named by [`block_name`].
    pub fn blocks(&self) -> Vec<ObjectDesc> {
        let (long, wide, tall) = (0.075, 0.025, 0.015);
        let mass = 600.0 * long * wide * tall; // wood, 600 kg/m³
        let mut blocks = Vec::with_capacity(LEVELS * SLOTS);
        for level in 0..LEVELS {
            for slot in 0..SLOTS {
                let across = (slot as f32 - 1.0) * wide;
                let y = tall * (level as f32 + 0.5);
                let (offset, size) = if level % 2 == 0 {
                    (Vec3::new(across, y, 0.0), Vec3::new(wide, tall, long))
                } else {
                    (Vec3::new(0.0, y, across), Vec3::new(long, tall, wide))
                };
                let name = block_name(level, slot);
                blocks.push(ObjectDesc::cuboid(&name, size, mass, self.base + offset));
            }
        }
        blocks
    }

    /// The names of all its blocks, as [`Self::blocks`] gives them.
    pub fn block_names() -> impl Iterator<Item = String> {
        (0..LEVELS).flat_map(|l| (0..SLOTS).map(move |s| block_name(l, s)))
    }
}
