//! When contacts begin and end, and what they do in between.

use super::*;
use coulomb_hands::pipeline::{ENGINE_SUBSTEPS, HAND_SUBSTEPS};
use coulomb_hands::{
    ContactEventKind, Finger, FrictionState, InteractionConfig, ObjectDesc, Phalanx, StaticDesc,
};

const INDEX_DISTAL: Bone = Bone::Finger(Finger::Index, Phalanx::Distal);

/// The index distal bone lowered onto / raised from the top of a box: its
/// lowest surface point at height `gap(t)` above the box top (y = 0.05).
fn finger_above(gap: f32) -> HandPose {
    let mut pose = parked_hand(Side::Right);
    let y = 0.05 + 0.008 + gap;
    set_bone(
        &mut pose,
        INDEX_DISTAL,
        Capsule { a: Vec3::new(0.0, y, -0.01), b: Vec3::new(0.0, y, 0.01), radius: 0.008 },
    );
    pose
}

#[test]
fn a_contact_begins_within_the_offset_pushes_only_when_pressing_and_ends_beyond_release() {
    let config = InteractionConfig::default();
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let id = world
        .add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.1, Vec3::new(0.0, 0.025, 0.0)))
        .unwrap();
    let hand = world.add_hand(Side::Right);
    // Down from 2 cm above to 2 mm inside over 1 s, hold, back up to 2 cm.
    let gap = |t: f32| {
        if t < 1.0 {
            0.02 - 0.022 * t
        } else if t < 1.5 {
            -0.002
        } else {
            -0.002 + 0.022 * (t - 1.5)
        }
    };
    // The real gap: the box settles a little into the ground.
    let real_gap = |w: &InteractionWorld, t: f32| {
        let top = w.object_state(id).unwrap().position.y + 0.025;
        0.05 + gap(t) - top
    };
    let mut began_at = None;
    let mut ended_at = None;
    let mut pushed_while_hovering = false;
    let mut pressed = false;
    run(
        &mut world,
        hand,
        2.6,
        |t| finger_above(gap(t)),
        |w, t| {
            let g = real_gap(w, t - config.dt);
            for e in w.events() {
                assert_eq!((e.hand, e.bone, e.object), (hand, INDEX_DISTAL, id));
                match e.kind {
                    ContactEventKind::Began => began_at = began_at.or(Some(g)),
                    ContactEventKind::Ended => ended_at = ended_at.or(Some(g)),
                }
            }
            for c in w.contacts() {
                if g > 0.0005 && c.force.length() > 0.0 {
                    pushed_while_hovering = true;
                }
                if g < -0.001 && c.state == FrictionState::Static && c.normal_force > 0.5 {
                    pressed = true;
                }
            }
        },
    );
    let began = began_at.expect("a contact began");
    let ended = ended_at.expect("the contact ended");
    assert!(
        began <= config.contact_offset && began > config.contact_offset - 0.001,
        "began at gap {began}"
    );
    assert!(
        ended > config.release_offset && ended < config.release_offset + 0.001,
        "ended at gap {ended}"
    );
    assert!(!pushed_while_hovering, "a hovering bone must not push");
    assert!(pressed, "pressing 2 mm in pushes with ≈ γ·2 mm = 0.8 N and sticks");
}

#[test]
fn losing_tracking_releases_the_hands_contacts() {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    world
        .add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.1, Vec3::new(0.0, 0.025, 0.0)))
        .unwrap();
    let hand = world.add_hand(Side::Right);
    run(&mut world, hand, 0.2, |_| finger_above(-0.002), |_, _| {});
    assert_eq!(world.contacts().len(), 1);
    world.clear_hand_pose(hand).unwrap();
    world.step();
    assert!(world.contacts().is_empty());
    assert_eq!(world.events().len(), 1);
    assert_eq!(world.events()[0].kind, ContactEventKind::Ended);
    // The box is pushed by nothing now: it rests on the ground.
    assert!(world.object_state(coulomb_hands::ObjectId(0)).unwrap().hand_force.length() == 0.0);
}

#[test]
fn a_fast_bone_pushes_nothing_before_it_touches() {
    // Coming down at 1 m/s from 2 cm above: the damper must not push early.
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let id = world
        .add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.1, Vec3::new(0.0, 0.025, 0.0)))
        .unwrap();
    let hand = world.add_hand(Side::Right);
    let gap = |t: f32| 0.02 - 1.0 * t;
    let mut early = Vec::new();
    let mut touched = false;
    run(
        &mut world,
        hand,
        0.03,
        |t| finger_above(gap(t)),
        |w, t| {
            let top = w.object_state(id).unwrap().position.y + 0.025;
            let real_gap = 0.05 + gap(t - w.config().dt) - top;
            for c in w.contacts() {
                if real_gap > 0.0 && c.force.length() > 0.0 {
                    early.push((real_gap, c.force.length()));
                }
                touched |= c.normal_force > 0.0;
            }
        },
    );
    assert!(early.is_empty(), "pushed before touching: (gap m, force N) {early:?}");
    assert!(touched, "it did press once through the surface");
}

#[test]
fn removing_a_support_drops_what_rested_on_it() {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let shelf = world.add_static(&StaticDesc::ground(0.3, 0.5)).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let id = world
        .add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.1, Vec3::new(0.0, 0.325, 0.0)))
        .unwrap();
    for _ in 0..200 {
        world.step();
    }
    assert!((position(&world, id).y - 0.325).abs() < 0.002, "rests on the shelf");
    // An object's own collider is not scenery.
    let body = world.object_body(id).unwrap();
    let collider = world.physics().bodies[body].colliders()[0];
    assert!(!world.remove_static(collider));
    assert!(world.remove_static(shelf));
    assert!(!world.remove_static(shelf), "already gone");
    for _ in 0..1000 {
        world.step();
    }
    assert!(
        (position(&world, id).y - 0.025).abs() < 0.002,
        "fell to the floor: {}",
        position(&world, id).y
    );
}

#[test]
fn a_released_fixture_with_reseated_contacts_is_not_dragged_by_the_sweep_behind_it() {
    // Gravity off; a finger pressed 2 mm into a locked box's top slides
    // 2 cm along x, so its contact slips and keeps the kinetic stretch
    // μ_dyn·f_n/γ ≈ 0.4 · 0.8 N / 400 N/m = 0.8 mm pulling towards +x. The
    // finger then stops right above the centre (no torque from the normal
    // push) and the box is unlocked. Kept, that stretch drags the box along
    // while the push sends it off (measured 3.6 mm); re-seated, the fresh
    // contact pushes straight down (measured 0.09 mm sideways).
    let lateral_drift = |reseat: bool| {
        let config = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
        let mut world = InteractionWorld::new(config).unwrap();
        let desc = ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.1, Vec3::new(0.0, 0.025, 0.0))
            .with_material(test_material(0.5));
        let id = world.add_object(&desc).unwrap();
        world.set_object_locked(id, true).unwrap();
        let hand = world.add_hand(Side::Right);
        let at = |x: f32| {
            let mut pose = finger_above(-0.002);
            let bone = &mut pose.fingers[1][2];
            bone.a.x += x;
            bone.b.x += x;
            pose
        };
        run(&mut world, hand, 0.5, |t| at(-0.02 + 0.04 * t), |_, _| {});
        assert_eq!(world.contacts().len(), 1, "still pressing after the slide");
        assert_eq!(world.contacts()[0].state, FrictionState::Dynamic, "the sweep made it slip");
        world.set_object_locked(id, false).unwrap();
        if reseat {
            world.reseat_contacts(id).unwrap();
        }
        let x0 = position(&world, id).x;
        let mut events = Vec::new();
        run(
            &mut world,
            hand,
            0.3,
            |_| at(0.0),
            |w, _| events.extend(w.events().iter().map(|e| e.kind)),
        );
        if reseat {
            assert_eq!(
                &events[..2],
                &[ContactEventKind::Ended, ContactEventKind::Began],
                "re-seated at once"
            );
        }
        position(&world, id).x - x0
    };
    let kept = lateral_drift(false);
    let reseated = lateral_drift(true);
    assert!(
        kept > 0.001,
        "the kept kinetic stretch drags the box {:.2} mm along the sweep",
        kept * 1e3
    );
    assert!(
        reseated.abs() < 0.0003,
        "re-seated, only the normal push remains: {:.3} mm sideways",
        reseated * 1e3
    );
}

/// rapier's own substeps, then those a body adds to them, on top.
fn substeps(w: &InteractionWorld, id: ObjectId) -> usize {
    let physics = w.physics();
    let body = &physics.bodies[w.object_body(id).unwrap()];
    physics.integration_parameters.num_solver_iterations + body.additional_solver_iterations()
}

/// A world with `engine_substeps` of `engine`, on the ground: a 5 cm box for
/// a finger to press, and one 30 cm aside.
fn two_boxes(engine: usize) -> (InteractionWorld, ObjectId, ObjectId) {
    let config = InteractionConfig { engine_substeps: engine, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let size = Vec3::splat(0.05);
    let pressed = ObjectDesc::cuboid("pressed", size, 0.1, Vec3::new(0.0, 0.025, 0.0));
    let pressed = world.add_object(&pressed).unwrap();
    let aside = ObjectDesc::cuboid("aside", size, 0.1, Vec3::new(0.3, 0.025, 0.0));
    let aside = world.add_object(&aside).unwrap();
    (world, pressed, aside)
}

#[test]
fn what_a_hand_pushes_runs_rapiers_four_substeps_whatever_the_rest_runs() {
    // rapier's own 4 for every body, the default, fewer and more for the rest.
    for engine in [HAND_SUBSTEPS, ENGINE_SUBSTEPS, 1, 6] {
        let (mut world, pressed, aside) = two_boxes(engine);
        let hand = world.add_hand(Side::Right);
        // 1.5 mm into the top of one box for 0.3 s, then 2 cm above it,
        // while the other box, awake, rests on the ground.
        let gap = |t: f32| if t < 0.3 { -0.0015 } else { 0.02 };
        let (mut while_pressed, mut after) = (Vec::new(), Vec::new());
        run(
            &mut world,
            hand,
            0.4,
            |t| finger_above(gap(t)),
            |w, t| {
                let pushed = w.contacts().iter().any(|c| c.force.length() > 0.1);
                let awake = !w.object_state(aside).unwrap().sleeping;
                let now = (substeps(w, pressed), substeps(w, aside));
                match t {
                    t if (0.1..0.29).contains(&t) => while_pressed.push((pushed, awake, now)),
                    t if t > 0.35 => after.push((pushed, awake, now)),
                    _ => {}
                }
            },
        );
        let hands = engine.max(HAND_SUBSTEPS);
        assert!(!while_pressed.is_empty() && !after.is_empty());
        for (pushed, awake, now) in while_pressed {
            assert!(pushed && awake, "engine {engine}: the finger presses, the other box is awake");
            assert_eq!(now, (hands, engine), "engine {engine}: pressed and aside");
        }
        for (pushed, _, now) in after {
            assert!(!pushed, "engine {engine}: the finger has left");
            assert_eq!(now, (engine, engine), "engine {engine}: both run the engine's");
        }
    }
}

/// A program's own per-body substeps (through `physics_mut`) stand: a box
/// the finger presses runs at least 4 while pressed and its own after; one
/// with more of its own keeps them; one the program changes while pressed
/// keeps the program's.
#[test]
fn a_programs_own_substeps_stand_under_the_hands() {
    let engine = 2;
    for (own, changed) in [(1, None), (3, None), (1, Some(7))] {
        let (mut world, pressed, aside) = two_boxes(engine);
        for (id, n) in [(pressed, own), (aside, 5)] {
            let body = world.object_body(id).unwrap();
            world.physics_mut().bodies[body].set_additional_solver_iterations(n);
        }
        let hand = world.add_hand(Side::Right);
        let step = |world: &mut InteractionWorld, gap: f32, steps: usize| {
            for _ in 0..steps {
                world.set_hand_pose(hand, &finger_above(gap)).unwrap();
                world.step();
            }
        };
        // Pressed 1.5 mm for 0.2 s: the box runs at least 4.
        step(&mut world, -0.0015, 200);
        assert!(world.object_state(pressed).unwrap().hand_force.length() > 0.1, "pressed");
        assert!(!world.object_state(aside).unwrap().sleeping, "the box aside is awake");
        let most = |n: usize| engine + n.max(HAND_SUBSTEPS - engine);
        assert_eq!(substeps(&world, pressed), most(own), "own {own}: while pressed");
        assert_eq!(substeps(&world, aside), engine + 5, "own {own}: the box aside");
        if let Some(n) = changed {
            let body = world.object_body(pressed).unwrap();
            world.physics_mut().bodies[body].set_additional_solver_iterations(n);
        }
        // 2 cm above it for 0.1 s: its own, or the program's since.
        step(&mut world, 0.02, 100);
        assert_eq!(world.object_state(pressed).unwrap().hand_force, Vec3::ZERO, "let go");
        let after = engine + changed.unwrap_or(own);
        assert_eq!(substeps(&world, pressed), after, "own {own}, then {changed:?}: after");
        assert_eq!(substeps(&world, aside), engine + 5, "own {own}: the box aside, after");
    }
}
