//! The demo's release, explained: where its cube comes to rest, from where
//! it was when the hand began to open, with the grip as it is, with the
//! pads' rings alone (no line contacts), with the grip as it was (one γ
//! per contact, ζ 0.5, rings), and on a rigid thumb: a kinematic
//! rapier body of the scripted thumb's two pad bones' capsules, moved as
//! they are, carrying the cube from the instant the last finger let go,
//! with rapier's rigid contact and the skin's friction on wood. What the
//! rigid thumb does is what a support of the thumb's shape does.
//!
//! `cargo run --release --example demo_release`

use coulomb_hands::run::demo::GraspLiftCarry;
use coulomb_hands::run::drive::{Driver, PoseFn, StepView};
use coulomb_hands::{
    Bone, Finger, HandPose, InteractionConfig, InteractionWorld, ObjectDesc, ObjectState, Side,
    StaticDesc,
};
use glam::Vec3;
use rapier3d::prelude::{CoefficientCombineRule, ColliderBuilder, Pose, RigidBodyBuilder};

/// Where the cube came to rest (x, m), and whether on the ground (it
/// landed) or on the thumb.
type Rest = (f32, bool);

/// The demo under `config`: the cube's x when the hand starts to open,
/// where it came to rest, and its state when the last finger stopped
/// pressing (s, state).
fn demo(config: InteractionConfig) -> (f32, Rest, (f64, ObjectState)) {
    let demo = GraspLiftCarry::new(config).expect("the demo's world");
    let (cube, hand, half) = (demo.cube, demo.hand, demo.half);
    let script = move |t: f64| Some(demo_pose(half, t as f32));
    let mut world = demo.world;
    let (mut at_open, mut landed, mut let_go) = (None, None, None);
    let mut watch = |s: &StepView| {
        let state = s.world.object_state(cube)?;
        if s.t >= f64::from(GraspLiftCarry::OPEN.0) && at_open.is_none() {
            at_open = Some(state.position.x);
        }
        let fingers = s.world.contacts().iter().filter(|c| c.normal_force > 0.0);
        let pressing = fingers.filter(|c| !matches!(c.bone, Bone::Finger(Finger::Thumb, _)));
        if at_open.is_some() && let_go.is_none() && pressing.count() == 0 {
            let_go = Some((s.t, state));
        }
        if landed.is_none() && at_open.is_some() && state.position.y < -half + 0.03 {
            landed = Some(state.position.x);
        }
        Ok(())
    };
    let mut driver = Driver::new(&mut world);
    driver.drive(hand, PoseFn::new(Side::Right, script)).expect("the demo's hand");
    let steps = GraspLiftCarry::steps(config.dt);
    driver.run(steps, &mut [&mut watch]).expect("the demo runs");
    let rest = match landed {
        Some(x) => (x, true),
        None => (world.object_state(cube).expect("the cube").position.x, false),
    };
    (at_open.unwrap(), rest, let_go.unwrap())
}

fn demo_pose(half: f32, t: f32) -> HandPose {
    // The demo's own script, as `GraspLiftCarry::hand_pose` gives it.
    let demo = GraspLiftCarry::new(InteractionConfig::default()).expect("a world");
    debug_assert_eq!(demo.half, half);
    demo.hand_pose(t)
}

/// The cube, in the state it had when the last finger let go, dropped by a
/// rigid thumb that moves as the scripted one, in a world of the same
/// config with no hand: where it comes to rest within 2 s.
fn rigid_thumb(config: InteractionConfig, half: f32, (t0, cube): (f64, ObjectState)) -> Rest {
    let mut world = InteractionWorld::new(config).expect("a world");
    world.add_static(&StaticDesc::ground(-half, 0.5)).expect("the ground");
    let desc = ObjectDesc {
        rotation: cube.rotation,
        ..ObjectDesc::cuboid("cube", Vec3::splat(2.0 * half), 0.05, cube.position)
    };
    let id = world.add_object(&desc).expect("the cube");
    let body = world.object_body(id).expect("its body");
    world.physics_mut().bodies[body].set_linvel(cube.linvel, true);
    world.physics_mut().bodies[body].set_angvel(cube.angvel, true);
    let thumb_at = |t: f32| demo_pose(half, t).fingers[Finger::Thumb as usize];
    let start = thumb_at(t0 as f32);
    let thumb = world.physics_mut().insert_body(RigidBodyBuilder::kinematic_position_based());
    for bone in &start[1..] {
        // Skin on wood, μ 0.46 (the crate's material table), whatever the
        // cube's own coefficient.
        let pad = ColliderBuilder::capsule_from_endpoints(bone.a, bone.b, bone.radius)
            .friction(0.46)
            .friction_combine_rule(CoefficientCombineRule::Min);
        world.physics_mut().insert_collider(pad, Some(thumb));
    }
    let mid = |c: &[coulomb_hands::Capsule; 3]| 0.5 * (c[2].a + c[2].b);
    for i in 1..2000 {
        let t = (t0 as f32 + i as f32 * config.dt).min(GraspLiftCarry::END);
        let shift = mid(&thumb_at(t)) - mid(&start);
        let next = Pose::translation(shift.x, shift.y, shift.z);
        world.physics_mut().bodies[thumb].set_next_kinematic_position(next);
        world.step();
        let p = world.object_state(id).expect("the cube").position;
        if p.y < -half + 0.03 {
            return (p.x, true);
        }
    }
    (world.object_state(id).expect("the cube").position.x, false)
}

fn main() {
    let now = InteractionConfig::default();
    let rings = InteractionConfig { line_contacts: false, ..now };
    let before = InteractionConfig { virtual_fingers: false, damping_ratio: Some(0.5), ..rings };
    let said = |open: f32, (x, landed): Rest| {
        let side = format!("{:5.1} mm to the side", (x - open) * 1e3);
        if landed { format!("lands {side}") } else { format!("stays on the thumb, {side}") }
    };
    println!("The demo's cube comes to rest, from where it was when the hand began to open:");
    let (open, rest, let_go) = demo(now);
    println!("  with the grip as it is:                     {}", said(open, rest));
    let (open_rings, rest_rings, _) = demo(rings);
    println!("  with the pads' rings alone:                 {}", said(open_rings, rest_rings));
    let (open_before, rest_before, _) = demo(before);
    println!("  with rings, one γ per contact and ζ 0.5:    {}", said(open_before, rest_before));
    let rigid = said(open, rigid_thumb(now, 0.025, let_go));
    println!("  on a rigid thumb, from {:.3} s (last finger): {rigid}", let_go.0);
}
