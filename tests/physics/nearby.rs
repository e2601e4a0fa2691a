//! New contacts are found among the objects rapier's broad phase puts near
//! each hand (its BVH, as of rapier's last step): objects it has not seen
//! yet, and objects that moved farther than its boxes' margin since, must
//! be found all the same, at the step they come within the contact offset.

use crate::position;
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::hand::{HandPose, Side};
use coulomb_hands::scene::{ObjectDesc, ObjectId, ShapeDesc};
use coulomb_hands::{ContactEventKind, InteractionConfig, InteractionWorld};
use glam::{Quat, Vec3};

/// A flat right hand, its palm's centre at `centre` (m), in a world
/// without gravity.
fn open_hand(centre: Vec3) -> (InteractionWorld, HandPose) {
    let config = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).expect("a valid config");
    let pose = HandRig::adult(Side::Right).pose(centre, Quat::IDENTITY, [0.0; 5]);
    let hand = world.add_hand(Side::Right);
    world.set_hand_pose(hand, &pose).expect("a valid pose");
    (world, pose)
}

/// A 3 cm ball of 45 g at `at`.
fn ball(name: &str, at: Vec3) -> ObjectDesc {
    let shape = ShapeDesc::Sphere { radius: 0.015 };
    ObjectDesc { shape, ..ObjectDesc::cuboid(name, Vec3::splat(0.03), 0.045, at) }
}

/// A ball `gap` (m) off the palm of a hand posed `pose`, added, stepped
/// once, then sent towards the palm at `speed` (m/s).
fn ball_towards_palm(
    world: &mut InteractionWorld,
    pose: &HandPose,
    name: &str,
    gap: f32,
    speed: f32,
) -> ObjectId {
    let start = pose.palm.to_world(Vec3::Y * (pose.palm.half_extents.y + 0.015 + gap));
    let id = world.add_object(&ball(name, start)).expect("a valid ball");
    world.step();
    let body = world.object_body(id).expect("an object");
    let towards = pose.palm.rotation * -Vec3::Y * speed;
    world.physics_mut().bodies[body].set_linvel(towards, true);
    id
}

/// Whether the last step began a contact on `object`.
fn began(world: &InteractionWorld, object: ObjectId) -> bool {
    world.events().iter().any(|e| e.object == object && e.kind == ContactEventKind::Began)
}

/// The gap (m) between the ball's surface and the palm's grasping face.
fn gap(world: &InteractionWorld, pose: &HandPose, ball: ObjectId) -> f32 {
    let local = pose.palm.to_local(position(world, ball));
    local.y - pose.palm.half_extents.y - 0.015
}

#[test]
fn a_ball_thrown_faster_than_the_broad_phase_margin_is_caught_at_once() {
    // 90 m/s at 1 kHz is 9 cm a step: beyond the 5 cm by which rapier's
    // broad phase fattens its boxes, so its BVH has lost the ball by the
    // time it reaches the palm. Gaps of 361, 271, 181, 91, then 1 mm.
    let (mut world, pose) = open_hand(Vec3::new(0.1, 0.55, -0.2));
    let id = ball_towards_palm(&mut world, &pose, "thrown", 0.361, 90.0);
    let offset = world.config().contact_offset;
    for _ in 0..8 {
        let before = gap(&world, &pose, id);
        world.step();
        if before <= offset {
            assert!(before > -0.005, "the ball went through the palm: {before} m");
            assert!(began(&world, id), "a ball {before} m from the palm was missed");
            return;
        }
        assert!(!began(&world, id), "touched {before} m away");
    }
    panic!("the ball never came near the palm");
}

#[test]
fn objects_added_or_put_down_touch_the_hand_in_their_first_step() {
    let (mut world, pose) = open_hand(Vec3::new(-0.2, 0.47, 0.05));
    for _ in 0..3 {
        world.step();
    }
    // Resting in the palm, 1 mm into it: rapier has never seen it.
    let in_palm = pose.palm.to_world(Vec3::Y * (pose.palm.half_extents.y + 0.014));
    let added = world.add_object(&ball("added", in_palm)).expect("a valid ball");
    world.step();
    assert!(began(&world, added), "an object added in the palm is touched at once");
    // One far away, then put down beside the first: its broad-phase box is
    // still where it was.
    let far = world.add_object(&ball("far", Vec3::new(2.0, 0.3, -1.5))).expect("a ball");
    for _ in 0..3 {
        world.step();
    }
    assert!(world.contacts_on(far).is_empty());
    let beside = in_palm + pose.palm.rotation * Vec3::X * 0.035;
    world.place_object(far, beside, Quat::IDENTITY).expect("a valid place");
    world.step();
    assert!(began(&world, far), "an object put down in the palm is touched at once");
}

/// Steps until the ball is within the contact offset of the hand, its gap
/// to the ball by `gap` (at most 400 steps), asserting that it is touched
/// then and not before.
fn touched_on_arrival(
    world: &mut InteractionWorld,
    pose: impl Fn(usize) -> HandPose,
    gap: impl Fn(&InteractionWorld, &HandPose) -> f32,
    id: ObjectId,
) {
    let offset = world.config().contact_offset;
    let hand = coulomb_hands::hand::HandId(0);
    for step in 0..400 {
        let pose = pose(step);
        world.set_hand_pose(hand, &pose).expect("a valid pose");
        let before = gap(world, &pose);
        world.step();
        if before <= offset {
            assert!(began(world, id), "a ball {before} m from the hand was missed at step {step}");
            return;
        }
        assert!(!began(world, id), "touched {before} m away");
    }
    panic!("the ball never came near the hand");
}

#[test]
fn a_ball_drifting_into_a_still_hand_is_touched_on_arrival() {
    // A hand that holds still keeps its broad-phase answer from step to
    // step: the ball, 23 mm out at 0.37 m/s, must still be found when it
    // arrives, some 60 steps later.
    let (mut world, pose) = open_hand(Vec3::new(0.04, 0.61, 0.12));
    let id = ball_towards_palm(&mut world, &pose, "drifting", 0.023, 0.37);
    let from_palm = |world: &InteractionWorld, pose: &HandPose| gap(world, pose, id);
    touched_on_arrival(&mut world, |_| pose.clone(), from_palm, id);
}

#[test]
fn a_hand_creeping_onto_a_resting_ball_touches_it_on_arrival() {
    // The ball rests 31 mm from the palm; the hand comes 0.45 mm a step
    // closer, so its box leaves the box its answer was asked for.
    let (mut world, pose) = open_hand(Vec3::new(-0.13, 0.52, 0.07));
    let at = pose.palm.to_world(Vec3::Y * (pose.palm.half_extents.y + 0.015 + 0.031));
    let id = world.add_object(&ball("resting", at)).expect("a valid ball");
    world.step();
    let towards = pose.palm.rotation * Vec3::Y * 0.000_45;
    let moved = |step: usize| pose.transformed(Vec3::ZERO, Quat::IDENTITY, towards * step as f32);
    let from_palm = |world: &InteractionWorld, pose: &HandPose| gap(world, pose, id);
    touched_on_arrival(&mut world, moved, from_palm, id);
}

#[test]
fn a_fingertip_bending_onto_a_ball_beside_a_still_hand_touches_it_on_arrival() {
    // Only the index fingertip moves, 0.35 mm a step, towards a ball 17 mm
    // off its pad. The little finger points 7 cm up, so the hand's box
    // holds the fingertip's whole way: only the fingertip's own reach
    // leaves the box its hand's answer was asked for.
    let (mut world, mut pose) = open_hand(Vec3::new(0.07, 0.58, -0.09));
    let towards = pose.palm.rotation * Vec3::Y;
    let little = &mut pose.fingers[4][2];
    little.b = little.a + towards * 0.07;
    world.set_hand_pose(coulomb_hands::hand::HandId(0), &pose).expect("a valid pose");
    let tip = pose.fingers[1][2];
    let centre = tip.b + towards * (tip.radius + 0.015 + 0.017);
    let id = world.add_object(&ball("beside", centre)).expect("a valid ball");
    world.step();
    let bent = |step: usize| {
        let mut pose = pose.clone();
        let tip = &mut pose.fingers[1][2];
        let shift = towards * 0.000_35 * step as f32;
        (tip.a, tip.b) = (tip.a + shift, tip.b + shift);
        pose
    };
    let from_tip = |world: &InteractionWorld, pose: &HandPose| {
        let tip = pose.fingers[1][2];
        let axis = tip.b - tip.a;
        let at = position(world, id);
        let s = ((at - tip.a).dot(axis) / axis.length_squared()).clamp(0.0, 1.0);
        (at - (tip.a + s * axis)).length() - tip.radius - 0.015
    };
    touched_on_arrival(&mut world, bent, from_tip, id);
}
