//! The plugin in a headless app (`MinimalPlugins`, no window), with frame
//! times set by hand: a shipped scenario's grasp lifts its object's entity,
//! contact messages arrive, the physics rate does not follow the frame
//! rate, pushed hands pose the world, and a failed step stops the physics
//! without stopping the app.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::contact::ContactEventKind;
use coulomb_hands::hand::{Bone, Finger, Phalanx, Side};
use coulomb_hands::pipeline::{InteractionConfig, InteractionWorld};
use coulomb_hands::run::drive::{Driver, PoseFn, StepView};
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::scene::{ObjectDesc, ObjectId, StaticDesc};
use coulomb_hands_bevy::CoulombHandsPlugin;
use coulomb_hands_bevy::contacts::{ContactBegan, ContactChange, ContactEnded, Contacts};
use coulomb_hands_bevy::convert::{to_bevy_quat, to_bevy_vec3};
use coulomb_hands_bevy::entities::{
    BoneSize, HandBone, InteractionEntities, InteractionHand, InteractionObject, bone_transform,
};
use coulomb_hands_bevy::interaction::{Interaction, Stopped};
use coulomb_hands_bevy::sources::PushedHand;
use std::time::Duration;

/// Every contact message the app's `Update` saw, in order.
#[derive(Resource, Default)]
struct Seen {
    began: Vec<ContactChange>,
    ended: Vec<ContactChange>,
}

fn record(
    mut seen: ResMut<Seen>,
    mut began: MessageReader<ContactBegan>,
    mut ended: MessageReader<ContactEnded>,
) {
    seen.began.extend(began.read().map(|m| m.0));
    seen.ended.extend(ended.read().map(|m| m.0));
}

/// A headless app around `interaction`, whose every frame lasts `frame`.
fn app(interaction: Interaction, frame: Duration) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, CoulombHandsPlugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(frame))
        .init_resource::<Seen>()
        .add_systems(Update, record)
        .insert_non_send(interaction);
    app
}

fn interaction(app: &App) -> &Interaction {
    app.world().non_send::<Interaction>()
}

fn scenario(name: &str) -> Scenario {
    Scenario::find(name).unwrap()
}

/// Updates `app` until `steps` physics steps have run; fails if a frame
/// runs none.
fn run_until(app: &mut App, steps: usize) {
    while interaction(app).steps() < steps {
        let before = interaction(app).steps();
        app.update();
        assert!(interaction(app).steps() > before, "a frame without a physics step");
    }
}

/// The transform of the object's entity.
fn object_transform(app: &mut App, id: ObjectId) -> Transform {
    let entity = app.world().resource::<InteractionEntities>().object(id).unwrap();
    assert_eq!(app.world().get::<InteractionObject>(entity), Some(&InteractionObject(id)));
    *app.world().get::<Transform>(entity).unwrap()
}

#[test]
fn a_scripted_grasp_lifts_the_object_entity_as_the_headless_driver_does() {
    let s = scenario("grasp-lift");
    let steps = (s.duration / s.config.dt).round() as usize;
    // The same scenario through the core's driver loop, without Bevy.
    let mut world = InteractionWorld::new(s.config).unwrap();
    world.add_scene(&s.scene).unwrap();
    let mut events = Vec::new();
    let mut driver = Driver::new(&mut world);
    for hand in &s.hands {
        driver.add_hand(hand.clone());
    }
    let mut watch = |step: &StepView| {
        events.extend(step.world.events().iter().map(|e| (e.kind, e.hand, e.bone, e.time)));
        Ok(())
    };
    driver.run(steps, &mut [&mut watch]).unwrap();
    let cube = world.object_ids().next().unwrap();
    let headless = world.object_state(cube).unwrap();

    let mut app = app(Interaction::of_scenario(&s).unwrap(), Duration::from_millis(20));
    app.update();
    let start = object_transform(&mut app, cube).translation;
    run_until(&mut app, steps);
    assert_eq!(interaction(&app).steps(), steps, "20 ms frames end on a whole step");
    let end = object_transform(&mut app, cube);
    // The scenario's own bound: the hand lifts 20 cm, the cube may lag 2 cm.
    assert!(end.translation.y - start.y >= 0.18, "lifted {} m", end.translation.y - start.y);
    // The same physics, bit for bit, and the transform is the world's pose.
    assert_eq!(end.translation, to_bevy_vec3(headless.position));
    assert_eq!(end.rotation, to_bevy_quat(headless.rotation));
    let seen = app.world().resource::<Seen>();
    let kinds = [(ContactEventKind::Began, &seen.began), (ContactEventKind::Ended, &seen.ended)];
    for (kind, messages) in kinds {
        let want: Vec<_> = events.iter().filter(|e| e.0 == kind).map(|e| (e.1, e.2, e.3)).collect();
        let got: Vec<_> = messages.iter().map(|m| (m.hand, m.bone, m.time)).collect();
        assert_eq!(got, want, "{kind:?} messages");
    }
    assert!(seen.began.len() >= 2, "a grasp needs the thumb and a finger: {}", seen.began.len());
    // Still held at the end: the contacts resource shows the grip.
    let contacts = app.world().resource::<Contacts>();
    assert_eq!(contacts.0.len(), interaction(&app).world().contacts().len());
    assert!(contacts.0.iter().filter(|c| c.object == cube).count() >= 2);
}

#[test]
fn hand_bones_are_child_entities_posed_as_the_world_poses_them() {
    let s = scenario("grasp-lift");
    let mut app = app(Interaction::of_scenario(&s).unwrap(), Duration::from_millis(20));
    for _ in 0..10 {
        app.update();
    }
    let world = app.world();
    let driven = &interaction(&app).hands()[0];
    let (id, side) = (driven.id, driven.side);
    let entities = world.resource::<InteractionEntities>();
    let hand = entities.hand(id).unwrap();
    let tracked = world.get::<InteractionHand>(hand).unwrap();
    assert_eq!((tracked.id, tracked.side, tracked.tracked), (id, side, true));
    assert_eq!(world.get::<Children>(hand).unwrap().len(), 16);
    let pose = interaction(&app).world().hand_pose(id).unwrap();
    for bone in Bone::all() {
        let entity = entities.bone(id, bone).unwrap();
        assert_eq!(world.get::<ChildOf>(entity).unwrap().parent(), hand);
        let b = world.get::<HandBone>(entity).unwrap();
        let (transform, size) = bone_transform(pose, bone);
        assert_eq!((b.hand, b.bone, b.size), (id, bone, size));
        assert_eq!(*world.get::<Transform>(entity).unwrap(), transform);
    }
    // A fingertip capsule: its transform's y axis runs along the bone.
    let tip = Bone::Finger(Finger::Index, Phalanx::Distal);
    let (t, size) = bone_transform(pose, tip);
    let BoneSize::Capsule { half_length, .. } = size else { panic!("{size:?}") };
    let coulomb_hands::hand::BoneShape::Capsule(c) = pose.bone(tip) else { unreachable!() };
    let b_end = t.translation + t.rotation * Vec3::Y * half_length;
    assert!((b_end - to_bevy_vec3(c.b)).length() < 1e-6, "{b_end} vs {}", c.b);
}

#[test]
fn the_physics_rate_does_not_follow_the_frame_rate() {
    let s = scenario("grasp-lift");
    // 1.6 s of app time in frames of 20 ms, 8 ms and a 60 Hz display's,
    // after a first frame that only starts Bevy's clock.
    let frames = [(20_000_000, 81), (8_000_000, 201), (16_666_667, 97)];
    let mut ends = Vec::new();
    for (nanos, count) in frames {
        let mut app = app(Interaction::of_scenario(&s).unwrap(), Duration::from_nanos(nanos));
        for _ in 0..count {
            app.update();
        }
        let elapsed = app.world().resource::<Time<Virtual>>().elapsed();
        let fixed = app.world().resource::<Time<Fixed>>().timestep();
        assert_eq!(fixed, Duration::from_millis(1), "the world's dt");
        // One step per whole dt of app time, however the frames cut it.
        let steps = interaction(&app).steps();
        assert_eq!(steps as u128, elapsed.as_nanos() / fixed.as_nanos(), "{nanos} ns frames");
        let cube = interaction(&app).world().object_ids().next().unwrap();
        ends.push((steps, object_transform(&mut app, cube)));
    }
    assert_eq!(ends[0].0, 1600);
    assert!(ends.iter().all(|e| *e == ends[0]), "same steps, same cube: {ends:?}");
}

/// A world with ground and a 5 cm, 50 g wooden cube centred at the
/// origin, held still so a hand can close on it where `claw_grasp` puts it.
fn cube_world() -> (InteractionWorld, ObjectId) {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(-0.025, 0.5)).unwrap();
    let desc = ObjectDesc::cuboid("cube", glam::Vec3::splat(0.05), 0.05, glam::Vec3::ZERO);
    let cube = world.add_object(&desc).unwrap();
    world.set_object_locked(cube, true).unwrap();
    (world, cube)
}

#[test]
fn a_pushed_hand_takes_the_newest_pose_and_loses_its_contacts_untracked() {
    let (world, cube) = cube_world();
    let mut driven = Interaction::new(world);
    let (source, inlet) = PushedHand::new(Side::Right);
    let hand = driven.add_hand(source);
    let mut app = app(driven, Duration::from_millis(20));
    app.update();
    assert!(app.world().resource::<Seen>().began.is_empty(), "untracked: no contacts");
    let closed = coulomb_hands::run::demo::claw_grasp(0.025, 1.0, 0.002);
    inlet.push(Some(coulomb_hands::hand::HandSample::from_pose(closed.clone())));
    app.update();
    assert_eq!(interaction(&app).world().hand_pose(hand), Some(&closed));
    let began = app.world().resource::<Seen>().began.clone();
    // The thumb's and the four fingers' pads press into the cube's faces.
    assert!(began.len() >= 5 && began.iter().all(|c| c.object == cube), "{began:?}");
    inlet.push(None);
    app.update();
    assert_eq!(interaction(&app).world().hand_pose(hand), None);
    let entity = app.world().resource::<InteractionEntities>().hand(hand).unwrap();
    assert!(!app.world().get::<InteractionHand>(entity).unwrap().tracked);
    let ended = &app.world().resource::<Seen>().ended;
    assert_eq!(ended.len(), began.len(), "every contact ends when tracking is lost");
    assert!(app.world().resource::<Contacts>().0.is_empty());
}

#[test]
fn a_failed_step_stops_the_physics_not_the_app() {
    let (world, _) = cube_world();
    let mut driven = Interaction::new(world);
    let pose = coulomb_hands::run::demo::claw_grasp(0.025, 0.0, 0.0);
    driven.add_hand(PoseFn::new(Side::Right, move |t| {
        let mut p = pose.clone();
        if t >= 0.05 {
            p.palm.center.x = f32::NAN;
        }
        Some(p)
    }));
    let mut app = app(driven, Duration::from_millis(20));
    for _ in 0..5 {
        app.update();
    }
    assert_eq!(interaction(&app).steps(), 50, "the steps before the bad pose");
    let Some(Stopped::Failed(error)) = interaction(&app).stopped() else {
        panic!("{:?}", interaction(&app).stopped())
    };
    let message = error.to_string();
    assert!(message.contains("palm") && message.contains("not finite"), "{message}");
    assert!(interaction(&app).world().first_non_finite().is_none());
}

#[test]
fn a_new_interaction_replaces_the_entities_of_the_old() {
    let mut app = app(Interaction::of_scenario(&scenario("grasp-lift")).unwrap(), Duration::ZERO);
    app.update();
    let old = app.world().resource::<InteractionEntities>().object(ObjectId(0)).unwrap();
    let (world, _) = cube_world();
    let mut replacement = Interaction::new(world);
    replacement.add_hand(PushedHand::new(Side::Left).0);
    replacement.add_hand(PushedHand::new(Side::Right).0);
    app.insert_non_send(replacement);
    app.update();
    assert!(app.world().get_entity(old).is_err(), "the old cube's entity is gone");
    let mut objects = app.world_mut().query::<&InteractionObject>();
    assert_eq!(objects.iter(app.world()).count(), 1);
    let mut hands = app.world_mut().query::<&InteractionHand>();
    let sides: Vec<Side> = hands.iter(app.world()).map(|h| h.side).collect();
    assert_eq!(sides.len(), 2, "{sides:?}");
    assert!(sides.contains(&Side::Left) && sides.contains(&Side::Right));
    let mut bones = app.world_mut().query::<&HandBone>();
    assert_eq!(bones.iter(app.world()).count(), 32, "the old hand's bones went with it");
}
