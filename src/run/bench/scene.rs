//! The benchmark scenes: held 3 cm, 20 g boxes, each squeezed 2 mm deep
//! between two bones, with or without the 54-block wooden tower.

use crate::hand::rig::HandRig;
use crate::hand::{BONES_PER_HAND, Bone, Capsule, HandId, HandPose, Palm, Side};
use crate::pipeline::{InteractionConfig, InteractionWorld, WorldError};
use crate::scene::{ObjectDesc, StaticDesc, Tower};
use glam::{Quat, Vec3};

/// Half the side of a held box (m).
const HALF: f32 = 0.015;
/// A held box's mass (kg).
const BOX_MASS: f32 = 0.02;
/// How far each bone presses into its box (m).
const SQUEEZE: f32 = 0.002;
/// The finger bones' radius (m).
const RADIUS: f32 = 0.008;
/// Boxes one hand holds in [`sweep_scene`]: a pair of bones each.
pub const BOXES_PER_HAND: usize = BONES_PER_HAND / 2;
/// Hands in the largest [`sweep_scene`].
pub const MAX_HANDS: usize = 8;

/// The reference scene of the issue tracker: optional ground and 54-block
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
    let centre =
        |k: usize| Vec3::new(0.2 + 0.08 * (k % 4) as f32, 0.3 + 0.08 * (k / 4) as f32, 0.0);
    for k in 0..boxes {
        add_box(&mut world, k, centre(k))?;
    }
    let mut hands = [HandId(0); 2];
    for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let s = if i == 0 { -1.0 } else { 1.0 };
        let mut pose = HandRig::adult(side).pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        for bone in Bone::all() {
            let k = bone.index();
            // Unused bones wait 2 m away from everything, spread apart.
            let c = if k < boxes { centre(k) } else { Vec3::new(3.0 + 0.1 * k as f32, 2.0, s) };
            press(&mut pose, bone, c, s);
        }
        hands[i] = world.add_hand(side);
        world.set_hand_pose(hands[i], &pose)?;
    }
    Ok((world, hands))
}

/// The scene of the bone sweep: a ground and `boxes` (1..=64) held boxes,
/// each squeezed between two bones of one hand (bones 2j and 2j + 1 hold
/// the hand's box j: the palm and the thumb's first bone, and so on), so
/// `2·boxes` bones press, in `⌈boxes / 8⌉` hands of up to 16 pressing bones
/// (8 hands at 128 bones). A hand's unused bones wait 2 m away. Hand h's
/// boxes stand on a 4 × 2 grid 8 cm apart at z = 0.12·h m.
/// Returns the world and the hands (their poses set).
pub fn sweep_scene(
    config: InteractionConfig,
    boxes: usize,
) -> Result<(InteractionWorld, Vec<HandId>), WorldError> {
    let boxes = boxes.clamp(1, MAX_HANDS * BOXES_PER_HAND);
    let mut world = InteractionWorld::new(config)?;
    world.add_static(&StaticDesc::ground(0.0, 0.5))?;
    let mut hands = Vec::new();
    for h in 0..boxes.div_ceil(BOXES_PER_HAND) {
        let z = 0.12 * h as f32;
        let centre =
            |j: usize| Vec3::new(0.2 + 0.08 * (j % 4) as f32, 0.3 + 0.08 * (j / 4) as f32, z);
        let held = (boxes - h * BOXES_PER_HAND).min(BOXES_PER_HAND);
        for j in 0..held {
            add_box(&mut world, h * BOXES_PER_HAND + j, centre(j))?;
        }
        let side = if h % 2 == 0 { Side::Left } else { Side::Right };
        let mut pose = HandRig::adult(side).pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        for bone in Bone::all() {
            let (k, s) = (bone.index(), if bone.index() % 2 == 0 { -1.0 } else { 1.0 });
            let c =
                if k / 2 < held { centre(k / 2) } else { Vec3::new(3.0 + 0.1 * k as f32, 2.0, z) };
            press(&mut pose, bone, c, s);
        }
        let hand = world.add_hand(side);
        world.set_hand_pose(hand, &pose)?;
        hands.push(hand);
    }
    Ok((world, hands))
}

/// Adds held box `k` at `centre`.
fn add_box(world: &mut InteractionWorld, k: usize, centre: Vec3) -> Result<(), WorldError> {
    let name = format!("box{k}");
    world.add_object(&ObjectDesc::cuboid(&name, Vec3::splat(2.0 * HALF), BOX_MASS, centre))?;
    Ok(())
}

/// Poses `bone` of `pose` pressing [`SQUEEZE`] into the side of the box at
/// `c` that faces `s·x` (`s` = −1: the bone is on the box's −x side): the
/// palm flat against it, a capsule upright.
fn press(pose: &mut HandPose, bone: Bone, c: Vec3, s: f32) {
    match bone {
        Bone::Palm => {
            pose.palm = Palm::from_normal_direction(
                c + Vec3::X * s * (HALF + 0.01 - SQUEEZE),
                -Vec3::X * s,
                Vec3::Y,
                Vec3::new(0.04, 0.01, 0.045),
            )
            .unwrap_or(pose.palm);
        }
        Bone::Finger(f, p) => {
            let x = c.x + s * (HALF + RADIUS - SQUEEZE);
            pose.fingers[f as usize][p as usize] = Capsule {
                a: Vec3::new(x, c.y - 0.015, c.z),
                b: Vec3::new(x, c.y + 0.015, c.z),
                radius: RADIUS,
            };
        }
    }
}
