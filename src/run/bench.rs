//! The benchmark scene and the `bench` command's timing: two hands
//! squeezing held boxes beside a 54-block tower.

use crate::hand::rig::HandRig;
use crate::hand::{BONES_PER_HAND, Bone, BoneShape, Capsule, HandId, Palm, Side};
use crate::pipeline::{InteractionConfig, InteractionWorld, WorldError};
use crate::scene::{ObjectDesc, StaticDesc, Tower};
use glam::{Quat, Vec3};
use std::time::Instant;

/// The benchmark scene of the issue tracker: optional ground and 54-block
/// wooden tower, and `boxes` (≤ 16) 3 cm, 20 g boxes held mid-air, box k
/// squeezed between bone k of the left hand and bone k of the right hand.
/// Bone 0 is the palm box; the others are capsules of radius 8 mm.
/// Returns the world and both hands' poses (already set).
pub fn held_boxes_scene(
    config: InteractionConfig,
    boxes: usize,
    tower: bool,
) -> Result<(InteractionWorld, [HandId; 2]), WorldError> {
    let boxes = boxes.min(BONES_PER_HAND);
    let mut world = InteractionWorld::new(config)?;
    world.add_static(&StaticDesc::ground(0.0, 0.5))?;
    if tower {
        let tower = Tower { base: Vec3::new(-0.4, 0.0, 0.0) };
        for block in tower.blocks() {
            world.add_object(&block)?;
        }
    }
    let half = 0.015;
    let squeeze = 0.002;
    let radius = 0.008;
    let centre =
        |k: usize| Vec3::new(0.2 + 0.08 * (k % 4) as f32, 0.3 + 0.08 * (k / 4) as f32, 0.0);
    for k in 0..boxes {
        world.add_object(&ObjectDesc::cuboid(
            &format!("box{k}"),
            Vec3::splat(2.0 * half),
            0.02,
            centre(k),
        ))?;
    }
    let mut hands = [HandId(0); 2];
    for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let s = if i == 0 { -1.0 } else { 1.0 };
        let mut pose = HandRig::adult(side).pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        for bone in Bone::all() {
            let k = bone.index();
            // Unused bones wait 2 m away from everything, spread apart.
            let c = if k < boxes { centre(k) } else { Vec3::new(3.0 + 0.1 * k as f32, 2.0, s) };
            match pose.bone(bone) {
                BoneShape::Palm(_) => {
                    pose.palm = Palm::from_normal_direction(
                        c + Vec3::X * s * (half + 0.01 - squeeze),
                        -Vec3::X * s,
                        Vec3::Y,
                        Vec3::new(0.04, 0.01, 0.045),
                    )
                    .unwrap_or(pose.palm);
                }
                BoneShape::Capsule(_) => {
                    let x = c.x + s * (half + radius - squeeze);
                    let cap = Capsule {
                        a: Vec3::new(x, c.y - 0.015, c.z),
                        b: Vec3::new(x, c.y + 0.015, c.z),
                        radius,
                    };
                    if let Bone::Finger(f, p) = bone {
                        pose.fingers[f as usize][p as usize] = cap;
                    }
                }
            }
        }
        hands[i] = world.add_hand(side);
        world.set_hand_pose(hands[i], &pose)?;
    }
    Ok((world, hands))
}

/// What [`time_steps`] measured, in µs per step.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct BenchReport {
    /// Bones pressing on an object in steady state.
    pub bones_pressing: usize,
    /// Objects in the world.
    pub objects: usize,
    /// Contacts and forces only ([`InteractionWorld::apply_hand_forces`]).
    pub interaction_layer_us: f64,
    /// The whole step, rapier's included.
    pub full_step_us: f64,
    /// The whole step during the first simulated second, while a tower
    /// settles and falls asleep.
    pub settling_us: f64,
}

/// Times `world`: the first simulated second whole, then `steps` more
/// steps with the interaction layer timed apart from rapier's step.
pub fn time_steps(world: &mut InteractionWorld, steps: usize) -> BenchReport {
    let settle = Instant::now();
    let settle_steps = (1.0 / world.config().dt).round() as usize;
    for _ in 0..settle_steps {
        world.step();
    }
    let settling_us = settle.elapsed().as_secs_f64() / settle_steps as f64 * 1e6;
    let (mut hands_ns, mut total_ns) = (0u128, 0u128);
    for _ in 0..steps {
        let t0 = Instant::now();
        world.apply_hand_forces();
        let t1 = Instant::now();
        world.step_physics();
        let t2 = Instant::now();
        hands_ns += (t1 - t0).as_nanos();
        total_ns += (t2 - t0).as_nanos();
    }
    let n = steps.max(1) as f64;
    BenchReport {
        bones_pressing: world.contacts().iter().filter(|c| c.normal_force > 0.0).count(),
        objects: world.object_count(),
        interaction_layer_us: hands_ns as f64 / n / 1e3,
        full_step_us: total_ns as f64 / n / 1e3,
        settling_us,
    }
}
