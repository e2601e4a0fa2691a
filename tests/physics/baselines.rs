//! The grab baselines of the evaluation (thesis §3.9, Table 5.2): the
//! kinematic grasp carries an object rigidly and lets it fall when the hand
//! opens; the heuristic grab helper throws above 0.5 m/s and stops below.

use super::{position, run};
use coulomb_hands::eval::grip::grip;
use coulomb_hands::run::scenario::script::smoothstep;
use coulomb_hands::{InteractionConfig, InteractionWorld, Method, ObjectDesc, Side, StaticDesc};
use glam::{Quat, Vec3};

/// A 4.4 cm, 65 g cube at the origin on the ground, and a right hand.
fn world(method: Method) -> (InteractionWorld, coulomb_hands::ObjectId, coulomb_hands::HandId) {
    let h = 0.022;
    let mut world = InteractionWorld::new(method.config(InteractionConfig::default())).unwrap();
    world.add_static(&StaticDesc::ground(-h, 0.5)).unwrap();
    let cube =
        world.add_object(&ObjectDesc::cuboid("cube", Vec3::splat(2.0 * h), 0.065, Vec3::ZERO));
    let hand = world.add_hand(Side::Right);
    (world, cube.unwrap(), hand)
}

/// The cube's position and rotation in the palm's frame.
fn in_palm(world: &InteractionWorld, cube: coulomb_hands::ObjectId) -> (Vec3, Quat) {
    let palm = world.hand_pose(coulomb_hands::HandId(0)).unwrap().palm;
    let s = world.object_state(cube).unwrap();
    let inverse = palm.rotation.inverse();
    (inverse * (s.position - palm.center), inverse * s.rotation)
}

#[test]
fn kinematic_grasp_carries_a_cube_rigidly_and_drops_it_when_the_hand_opens() {
    let (mut world, cube, hand) = world(Method::Kinematic);
    // Close, then lift 15 cm, carry 10 cm and turn 40° about the vertical,
    // hold, open.
    let pose = |t: f32| {
        let closure = smoothstep(0.3, 0.7, t) * (1.0 - smoothstep(2.2, 2.5, t));
        let s = smoothstep(0.9, 1.8, t);
        let motion = Vec3::new(0.1 * s, 0.15 * s, 0.0);
        grip(0.022, closure, 0.004).transformed(Vec3::ZERO, Quat::from_rotation_y(0.7 * s), motion)
    };
    let (mut grabbed, mut drift, mut turn) = (None, 0.0f32, 0.0f32);
    let mut held_until = 0.0;
    run(&mut world, hand, 3.4, pose, |w, t| {
        if (0.85..2.2).contains(&t) {
            let (at, rotation) = in_palm(w, cube);
            let (at0, rotation0) = *grabbed.get_or_insert((at, rotation));
            drift = drift.max(at.distance(at0));
            turn = turn.max(rotation.angle_between(rotation0));
        }
        if w.held_by(cube).is_some() {
            held_until = t;
        }
    });
    assert!(drift < 1e-4 && turn < 1e-3, "drift {drift} m, {turn} rad in the hand");
    assert!((2.2..2.6).contains(&held_until), "let go at {held_until} s, while opening");
    let end = position(&world, cube);
    assert!(end.y < 0.005, "fell to the ground when the hand opened: y {}", end.y);
    assert!((end.x - 0.1).abs() < 0.03, "fell below where it was carried: x {}", end.x);
}

/// Grips the cube, lifts it 10 cm, swings it along +x at `speed` (m/s) and
/// opens during the swing. Returns the cube's horizontal velocity just
/// after the grab let go, the hand's x then, and the cube's x at landing.
fn swing_and_open(speed: f32) -> (Vec3, f32, f32) {
    let (mut world, cube, hand) = world(Method::Heuristic);
    let x = move |t: f32| {
        // Accelerate over 0.2 s from t = 1.2 s, then constant speed.
        let ramp = (t - 1.2).clamp(0.0, 0.2);
        speed * (ramp * ramp / 0.4 + (t - 1.4).max(0.0))
    };
    let pose = move |t: f32| {
        let closure = smoothstep(0.3, 0.7, t) * (1.0 - smoothstep(1.7, 1.85, t));
        let motion = Vec3::new(x(t), 0.1 * smoothstep(0.8, 1.1, t), 0.0);
        grip(0.022, closure, 0.004).transformed(Vec3::ZERO, Quat::IDENTITY, motion)
    };
    let (mut was_held, mut released) = (false, None);
    let mut landing = None;
    run(&mut world, hand, 2.6, pose, |w, t| {
        let s = w.object_state(cube).unwrap();
        let held = w.held_by(cube).is_some();
        if was_held && !held && released.is_none() {
            released = Some((s.linvel * Vec3::new(1.0, 0.0, 1.0), x(t)));
        }
        was_held |= held;
        if released.is_some() && landing.is_none() && s.position.y < 0.001 {
            landing = Some(s.position.x);
        }
    });
    let (velocity, hand_x) = released.expect("the hand grabbed and let go");
    (velocity, hand_x, landing.unwrap_or(position(&world, cube).x))
}

#[test]
fn heuristic_grab_throws_a_fast_release_and_stops_a_slow_one() {
    let (fast, _, _) = swing_and_open(1.3);
    assert!(
        fast.x > 0.5 && (fast.x - 1.3).abs() < 0.2 && fast.z.abs() < 0.1,
        "thrown at the swing's velocity: {fast}"
    );
    let (slow, hand_x, landing) = swing_and_open(0.35);
    assert!(slow.length() < 0.02, "stopped dead below 0.5 m/s: {slow}");
    assert!((landing - hand_x).abs() < 0.02, "fell straight down: {landing} m below {hand_x} m");
}
