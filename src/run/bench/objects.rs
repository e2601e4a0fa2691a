//! The cluttered scenes of `bench --objects`: the reference scene's two
//! hands and 16 held boxes among boxes of mixed sizes resting on a table
//! below the hands, a shelf behind them and rows of shelving units around
//! the room, up to thousands of objects in all.
//!
//! The clutter rests on its boards (placed 0.1 mm above them) and falls
//! asleep in the first simulated second, as objects on real shelves are at
//! rest; the held boxes stay awake under the hands. The question is how
//! the interaction layer's cost grows with the scene when the hands touch
//! the same few objects.

use super::scene::held_boxes_scene;
use crate::hand::BONES_PER_HAND;
use crate::pipeline::{InteractionConfig, InteractionWorld, WorldError};
use crate::scene::{ObjectDesc, ShapeDesc, StaticDesc};
use glam::{Quat, Vec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The held boxes of every cluttered scene (two bones each, 32 in all).
pub const HELD: usize = BONES_PER_HAND;
/// The most objects a cluttered scene holds: 16 held boxes and 3,984
/// resting on 56 boards.
pub const MAX_OBJECTS: usize = 4000;
/// The default object counts of `bench --objects`: the reference scene's
/// 70, then up to 2,000.
pub const DEFAULT_OBJECTS: [usize; 5] = [70, 250, 500, 1000, 2000];

/// Distance between the centres of neighbouring resting boxes (m).
const CELL: f32 = 0.1;
/// The smallest and largest side of a resting box (m).
const SIDES: (f32, f32) = (0.02, 0.07);
/// The resting boxes' density (kg/m³): a cardboard box of groceries.
const DENSITY: f32 = 400.0;
/// Thickness of tables and boards (m).
const BOARD: f32 = 0.02;
/// The seed of the boxes' sizes: every run has the same scene.
const SEED: u64 = 0x00b1_ec75;

/// A flat surface boxes rest on: its top's centre and half its width (x)
/// and depth (z), m.
#[derive(Debug, Clone, Copy)]
struct Surface {
    top: Vec3,
    half: (f32, f32),
}

impl Surface {
    /// The centres of its cells, row by row.
    fn cells(self) -> impl Iterator<Item = Vec3> {
        let columns = (2.0 * self.half.0 / CELL) as usize;
        let rows = (2.0 * self.half.1 / CELL) as usize;
        let corner = self.top - Vec3::new(self.half.0 - CELL / 2.0, 0.0, self.half.1 - CELL / 2.0);
        (0..rows).flat_map(move |r| {
            (0..columns).map(move |c| corner + Vec3::new(c as f32 * CELL, 0.0, r as f32 * CELL))
        })
    }

    fn board(self, name: String) -> StaticDesc {
        StaticDesc {
            name,
            shape: ShapeDesc::Box {
                half_extents: Vec3::new(self.half.0, BOARD / 2.0, self.half.1),
            },
            position: self.top - Vec3::Y * (BOARD / 2.0),
            rotation: Quat::IDENTITY,
            friction: 0.5,
        }
    }
}

/// The surfaces, nearest the hands first: a table under the held boxes
/// (which hang from 0.285 m up, at 0.2 to 0.44 m in x), a shelf of three
/// boards behind them, then 13 shelving units of 4 boards, in rows around
/// the room (each board 2 m by 0.4 m: 80 cells).
fn surfaces() -> Vec<Surface> {
    let mut all = vec![Surface { top: Vec3::new(0.32, 0.15, 0.0), half: (0.5, 0.3) }];
    for y in [0.28, 0.44, 0.60] {
        all.push(Surface { top: Vec3::new(0.32, y, 0.3), half: (0.5, 0.15) });
    }
    let units = (0..4)
        .flat_map(|row| (0..4).map(move |col| (row, col)))
        .filter(|&(row, col)| !(row == 0 && (col == 1 || col == 2)))
        .take(13);
    for (row, col) in units {
        let centre = Vec3::new(-3.3 + 2.2 * col as f32, 0.0, 1.2 + 0.9 * row as f32);
        let centre = if row == 0 { centre - Vec3::Z * 2.6 } else { centre };
        for y in [0.3, 0.7, 1.1, 1.5] {
            all.push(Surface { top: centre + Vec3::Y * y, half: (1.0, 0.2) });
        }
    }
    all
}

/// The cluttered scene with `objects` objects (16 to [`MAX_OBJECTS`]): the
/// reference scene's hands and held boxes, without its tower, and
/// `objects − 16` boxes of mixed sizes resting on the surfaces, nearest the
/// hands first. Only the boards that hold boxes are added.
pub fn cluttered_scene(
    config: InteractionConfig,
    objects: usize,
) -> Result<InteractionWorld, WorldError> {
    let (mut world, _) = held_boxes_scene(config, HELD, false)?;
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let mut left = objects.clamp(HELD, MAX_OBJECTS) - HELD;
    for (s, surface) in surfaces().into_iter().enumerate() {
        if left == 0 {
            break;
        }
        world.add_static(&surface.board(format!("board{s}")))?;
        for cell in surface.cells().take(left) {
            let size = Vec3::new(
                rng.random_range(SIDES.0..SIDES.1),
                rng.random_range(SIDES.0..SIDES.1),
                rng.random_range(SIDES.0..SIDES.1),
            );
            let mass = DENSITY * size.x * size.y * size.z;
            let centre = cell + Vec3::Y * (size.y / 2.0 + 1e-4);
            let name = format!("clutter{}", objects - HELD - left);
            world.add_object(&ObjectDesc::cuboid(&name, size, mass, centre))?;
            left -= 1;
        }
    }
    Ok(world)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_surfaces_hold_the_most_objects_and_do_not_overlap() {
        let all = surfaces();
        let cells: usize = all.iter().map(|s| s.cells().count()).sum();
        assert!(cells >= MAX_OBJECTS - HELD, "{cells} cells");
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                let apart = (a.top.x - b.top.x).abs() >= a.half.0 + b.half.0
                    || (a.top.z - b.top.z).abs() >= a.half.1 + b.half.1
                    || (a.top.y - b.top.y).abs() >= 0.1;
                assert!(apart, "{a:?} and {b:?} overlap");
            }
        }
    }
}
