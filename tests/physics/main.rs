//! Physical-outcome tests of the core: every test asserts what happens to
//! objects (held, slipped, slid, tipped, launched), never timings.

mod acting;
mod balance;
mod baselines;
mod bench;
mod captures;
mod carry;
mod closings;
mod controls;
mod energy;
mod evaluation;
mod flat;
mod frames;
mod glitch;
mod grasp;
mod grip;
mod host;
mod lifecycle;
#[cfg(feature = "live")]
mod live;
#[cfg(feature = "live")]
mod live_feed;
mod meshes;
mod nearby;
mod object_friction;
mod pinch;
mod push;
mod recordings;
mod release;
mod removal;
mod rolling;
mod safety;
mod scenarios;
mod stacks;
mod throw;
mod tilt;
mod trackers;
mod tracking;

use coulomb_hands::hand::rig::HandRig;
pub use coulomb_hands::run::drive::{Driver, PoseFn, StepView};
use coulomb_hands::{Bone, Capsule, HandId, HandPose, InteractionWorld, Material, ObjectId, Side};
use glam::{Quat, Vec3};

/// A hand with every bone parked far from everything (3 m up, spread
/// apart), so a test can place just the bones it needs.
pub fn parked_hand(side: Side) -> HandPose {
    let x = if side == Side::Left { -1.0 } else { 1.0 };
    let mut pose = HandRig::adult(side).pose(Vec3::new(x, 3.0, 0.0), Quat::IDENTITY, [0.0; 5]);
    for finger in pose.fingers.iter_mut() {
        for bone in finger.iter_mut() {
            bone.a.y += 0.5;
            bone.b.y += 0.5;
        }
    }
    pose
}

/// An adult right hand about the origin, palm down, pointing along +x with
/// its index straight and the other fingers curled, and the tip of its
/// index (the end of its distal capsule).
pub fn pointing_hand() -> (HandPose, Vec3) {
    let rig = HandRig::adult(Side::Right);
    let down = coulomb_hands::Palm::from_normal_direction(
        Vec3::ZERO,
        -Vec3::Y,
        Vec3::X,
        rig.palm_half_extents,
    )
    .expect("a palm");
    let pointing = rig.pose(Vec3::ZERO, down.rotation, [1.0, 0.0, 1.0, 1.0, 1.0]);
    let index = pointing.fingers[coulomb_hands::Finger::Index as usize][2];
    let tip = index.b + (index.b - index.a).normalize() * index.radius;
    (pointing, tip)
}

/// Puts one capsule bone into a pose.
pub fn set_bone(pose: &mut HandPose, bone: Bone, capsule: Capsule) {
    if let Bone::Finger(f, p) = bone {
        pose.fingers[f as usize][p as usize] = capsule;
    }
}

/// A material with round test coefficients (μ_st 0.5, μ_dyn 0.4).
pub fn test_material(surface_friction: f32) -> Material {
    Material::custom("test", 0.5, 0.4, surface_friction)
}

/// Steps the world `seconds` long through the driver, posing `hand` with
/// `pose(t)` each step, and calls `each(world, t)` after each step.
pub fn run(
    world: &mut InteractionWorld,
    hand: HandId,
    seconds: f32,
    mut pose: impl FnMut(f32) -> HandPose + Send,
    mut each: impl FnMut(&InteractionWorld, f32),
) {
    let steps = (seconds / world.config().dt).round() as usize;
    let side = world.hand_side(hand).expect("hand exists");
    let mut driver = Driver::new(world);
    driver.drive(hand, PoseFn::new(side, |t| Some(pose(t as f32)))).expect("hand exists");
    let mut observe = |step: &StepView| {
        each(step.world, step.t as f32);
        Ok(())
    };
    driver.run(steps, &mut [&mut observe]).expect("valid poses");
}

pub fn position(world: &InteractionWorld, id: ObjectId) -> Vec3 {
    world.object_state(id).expect("object exists").position
}
