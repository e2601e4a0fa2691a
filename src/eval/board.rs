//! The placement task of thesis §5.2: a cube on a chessboard, moved from a
//! start square to a target square.

use crate::pipeline::{InteractionConfig, InteractionWorld, WorldError};
use crate::scene::{Material, ObjectDesc, ObjectId, StaticDesc};
use glam::{Quat, Vec3};
use rand::Rng;

/// Squares per side.
pub const SQUARES: usize = 8;
/// A square's side (m).
pub const SQUARE: f32 = 0.05;
/// The cube's half size (m): a 4 cm cube.
pub const CUBE_HALF: f32 = 0.02;
/// The cube's mass (kg): 40 g.
pub const CUBE_MASS: f32 = 0.04;
/// The board's friction with the cube (rapier's coefficient): wood on
/// wood.
pub const BOARD_FRICTION: f32 = 0.45;

/// One trial's squares: the cube starts on `start`, turned `yaw` (rad)
/// about the vertical, and is to be moved to `target`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// The start square (column, row).
    pub start: (usize, usize),
    /// The target square, never the start.
    pub target: (usize, usize),
    /// The cube's turn on the start square (rad, within ±0.3).
    pub yaw: f32,
}

/// Draws a trial's squares and turn, uniformly, from `rng`.
pub fn draw_placement(rng: &mut impl Rng) -> Placement {
    let mut square = || (rng.random_range(0..SQUARES), rng.random_range(0..SQUARES));
    let start = square();
    let target = loop {
        let t = square();
        if t != start {
            break t;
        }
    };
    Placement { start, target, yaw: rng.random_range(-0.3..=0.3) }
}

/// `count` trials' squares and turns, drawn from `seed`: the same for the
/// same seed.
pub fn placements(seed: u64, count: usize) -> Vec<Placement> {
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed);
    (0..count).map(|_| draw_placement(&mut rng)).collect()
}

/// A square's centre on the board (m, y = 0 on the board's surface).
pub fn square_center(square: (usize, usize)) -> Vec3 {
    let at = |i: usize| (i as f32 + 0.5 - SQUARES as f32 / 2.0) * SQUARE;
    Vec3::new(at(square.0), 0.0, at(square.1))
}

/// A placement's error: the horizontal distance from the cube's centre
/// `cube` to the target square's centre `target` (m).
pub fn placement_error(cube: Vec3, target: Vec3) -> f32 {
    ((cube - target) * Vec3::new(1.0, 0.0, 1.0)).length()
}

/// Whether a point is over the board (m).
pub fn on_board(p: Vec3) -> bool {
    let half = SQUARES as f32 * SQUARE / 2.0;
    p.x.abs() <= half && p.z.abs() <= half
}

/// The task's world: the board, and the cube resting on the start square
/// turned `yaw` radians about the vertical.
pub fn world(
    config: InteractionConfig,
    start: (usize, usize),
    yaw: f32,
) -> Result<(InteractionWorld, ObjectId), WorldError> {
    let mut world = InteractionWorld::new(config)?;
    world.add_static(&StaticDesc::ground(0.0, BOARD_FRICTION))?;
    let at = square_center(start) + Vec3::Y * CUBE_HALF;
    let mut cube = ObjectDesc::cuboid("cube", Vec3::splat(2.0 * CUBE_HALF), CUBE_MASS, at)
        .with_material(Material::wood());
    cube.rotation = Quat::from_rotation_y(yaw);
    let id = world.add_object(&cube)?;
    Ok((world, id))
}
