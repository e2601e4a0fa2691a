//! The plugin in a headless app (`MinimalPlugins`, no window), with frame
//! times set by hand: a shipped scenario's grasp lifts its object's entity,
//! contact messages and object events arrive with their entities, the
//! physics rate does not follow the frame rate (nor changes the app's fixed
//! clock), app hands pose the world and outlive it, and a failed step stops
//! the physics without stopping the app.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::contact::ContactEventKind;
use coulomb_hands::hand::{Bone, Finger, Phalanx, Side};
use coulomb_hands::pipeline::{InteractionConfig, InteractionWorld};
use coulomb_hands::run::drive::{Driver, PoseFn, StepView};
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::scene::{ObjectDesc, ObjectId, StaticDesc};
use coulomb_hands_bevy::convert::{to_bevy_quat, to_bevy_vec3};
use coulomb_hands_bevy::entities::bone_transform;
use coulomb_hands_bevy::prelude::*;
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

/// A headless app around `physics`, whose every frame lasts `frame`.
fn app(physics: HandPhysics, frame: Duration) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, CoulombHandsPlugin::default()))
        .insert_resource(TimeUpdateStrategy::ManualDuration(frame))
        .init_resource::<Seen>()
        .add_systems(Update, record)
        .insert_resource(physics);
    app
}

fn interaction(app: &App) -> &HandPhysics {
    app.world().resource::<HandPhysics>()
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
    let steps = s.steps();
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

    let mut app = app(HandPhysics::of_scenario(&s).unwrap(), Duration::from_millis(20));
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
    let entities = app.world().resource::<InteractionEntities>();
    let cube_entity = entities.object(cube).unwrap();
    let kinds = [(ContactEventKind::Began, &seen.began), (ContactEventKind::Ended, &seen.ended)];
    for (kind, messages) in kinds {
        let want: Vec<_> = (events.iter().filter(|e| e.0 == kind))
            .map(|e| (cube_entity, entities.hand(e.1), entities.bone(e.1, e.2), e.2, e.3))
            .collect();
        let got: Vec<_> = messages
            .iter()
            .map(|m| (m.object, Some(m.hand), Some(m.bone), m.kind, m.time))
            .collect();
        assert_eq!(got, want, "{kind:?} messages");
    }
    assert!(seen.began.len() >= 2, "a grasp needs the thumb and a finger: {}", seen.began.len());
    // Still held at the end: the contacts resource shows the grip.
    let contacts = app.world().resource::<Contacts>();
    assert_eq!(contacts.0.len(), interaction(&app).world().contacts().len());
    assert!(contacts.0.iter().filter(|c| c.object == cube_entity).count() >= 2);
}

#[test]
fn hand_bones_are_child_entities_posed_as_the_world_poses_them() {
    let s = scenario("grasp-lift");
    let mut app = app(HandPhysics::of_scenario(&s).unwrap(), Duration::from_millis(20));
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
fn the_physics_rate_does_not_follow_the_frame_rate_nor_change_the_apps_fixed_clock() {
    let s = scenario("grasp-lift");
    // 1.6 s of app time in frames of 20 ms, 8 ms and a 60 Hz display's,
    // after a first frame that only starts Bevy's clock.
    let frames = [(20_000_000, 81), (8_000_000, 201), (16_666_667, 97)];
    let mut ends = Vec::new();
    for (nanos, count) in frames {
        let mut app = app(HandPhysics::of_scenario(&s).unwrap(), Duration::from_nanos(nanos));
        #[derive(Resource, Default)]
        struct FixedTicks(u32);
        app.init_resource::<FixedTicks>()
            .add_systems(FixedUpdate, |mut n: ResMut<FixedTicks>| n.0 += 1);
        for _ in 0..count {
            app.update();
        }
        let elapsed = app.world().resource::<Time<Virtual>>().elapsed();
        let dt = interaction(&app).timestep();
        assert_eq!(dt, Duration::from_millis(1), "the world's dt");
        // One step per whole dt of app time, however the frames cut it,
        // and the physics clock says so.
        let steps = interaction(&app).steps();
        assert_eq!(steps as u128, elapsed.as_nanos() / dt.as_nanos(), "{nanos} ns frames");
        let clock = app.world().resource::<Time<HandClock>>();
        assert_eq!(clock.elapsed(), dt * steps as u32);
        assert!(clock.context().overstep() < dt);
        // The app's own fixed loop keeps Bevy's 64 Hz.
        let fixed = app.world().resource::<Time<Fixed>>();
        assert_eq!(fixed.timestep(), Time::<Fixed>::default().timestep());
        let ticks = app.world().resource::<FixedTicks>().0;
        assert_eq!(u128::from(ticks), elapsed.as_nanos() / fixed.timestep().as_nanos());
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

fn closed_claw() -> coulomb_hands::hand::HandPose {
    coulomb_hands::run::demo::claw_grasp(0.025, 1.0, 0.002)
}

#[test]
fn an_app_hand_poses_the_world_by_its_input_and_loses_its_contacts_untracked() {
    let (world, cube) = cube_world();
    let mut app = app(HandPhysics::new(world), Duration::from_millis(20));
    let entity = app.world_mut().spawn(AppHand::new(Side::Right)).id();
    app.update();
    assert!(app.world().resource::<Seen>().began.is_empty(), "untracked: no contacts");
    let hand = app.world().get::<InteractionHand>(entity).expect("made a hand of the world");
    assert_eq!((hand.side, hand.tracked), (Side::Right, false));
    let id = hand.id;
    assert_eq!(app.world().resource::<InteractionEntities>().hand(id), Some(entity));
    assert_eq!(app.world().get::<Children>(entity).unwrap().len(), 16, "its bones");
    app.world_mut().get_mut::<HandInput>(entity).unwrap().set_pose(closed_claw());
    app.update();
    assert_eq!(interaction(&app).world().hand_pose(id), Some(&closed_claw()));
    assert!(app.world().get::<InteractionHand>(entity).unwrap().tracked);
    let began = app.world().resource::<Seen>().began.clone();
    let cube_entity = app.world().resource::<InteractionEntities>().object(cube).unwrap();
    // The thumb's and the four fingers' pads press into the cube's faces,
    // each message naming the app's hand and a bone of it.
    assert!(began.len() >= 5, "{began:?}");
    for b in &began {
        assert_eq!((b.object, b.hand), (cube_entity, entity));
        assert_eq!(app.world().get::<ChildOf>(b.bone).unwrap().parent(), entity);
        assert_eq!(app.world().get::<HandBone>(b.bone).unwrap().bone, b.kind);
    }
    app.world_mut().get_mut::<HandInput>(entity).unwrap().set(None);
    app.update();
    assert_eq!(interaction(&app).world().hand_pose(id), None);
    assert!(!app.world().get::<InteractionHand>(entity).unwrap().tracked);
    let ended = &app.world().resource::<Seen>().ended;
    assert_eq!(ended.len(), began.len(), "every contact ends when tracking is lost");
    assert!(app.world().resource::<Contacts>().0.is_empty());
}

/// The palm's x of every step's first driven hand (m), as the driver gave it.
#[derive(Clone, Default)]
struct Palms(std::sync::Arc<std::sync::Mutex<Vec<f32>>>);

impl coulomb_hands::run::drive::Observer for Palms {
    fn after_step(&mut self, step: &StepView) -> Result<(), coulomb_hands::run::RunError> {
        let x = step.hands[0].sample.as_ref().map_or(f32::NAN, |s| s.pose.palm.center.x);
        self.0.lock().unwrap().push(x);
        Ok(())
    }
}

#[test]
fn an_app_hands_input_is_reached_at_the_frames_last_step_from_where_it_was() {
    let (world, _) = cube_world();
    let mut physics = HandPhysics::new(world);
    let palms = Palms::default();
    physics.observe(palms.clone());
    // 8 ms frames: 8 steps of 1 ms each.
    let mut app = app(physics, Duration::from_millis(8));
    let entity = app.world_mut().spawn(AppHand::new(Side::Right)).id();
    app.update();
    let far = |x: f32| {
        closed_claw().transformed(
            glam::Vec3::ZERO,
            glam::Quat::IDENTITY,
            glam::Vec3::new(x, 0.5, 0.0),
        )
    };
    app.world_mut().get_mut::<HandInput>(entity).unwrap().set_pose(far(0.0));
    app.update();
    app.world_mut().get_mut::<HandInput>(entity).unwrap().set_pose(far(0.024));
    app.update();
    app.update();
    let seen = palms.0.lock().unwrap().clone();
    let x0 = far(0.0).palm.center.x;
    let moved: Vec<f32> = seen.iter().rev().take(24).rev().map(|x| x - x0).collect();
    // Found: there at once, held; then 3 mm a step to 24 mm at the frame's
    // last step; then held.
    let want: Vec<f32> = (0..24)
        .map(|k| match k {
            0..8 => 0.0,
            8..16 => 0.003 * (k - 7) as f32,
            _ => 0.024,
        })
        .collect();
    let close = moved.iter().zip(&want).all(|(a, b)| (a - b).abs() < 1e-5);
    assert!(close, "moved {moved:?}, want {want:?}");
}

/// What the cube's observers saw, in order.
#[derive(Resource, Default)]
struct CubeEvents(Vec<(&'static str, Entity, f64)>);

#[test]
fn an_object_is_touched_once_by_its_first_bone_and_released_once_by_its_last() {
    let (world, cube) = cube_world();
    let mut app = app(HandPhysics::new(world), Duration::from_millis(10));
    app.init_resource::<CubeEvents>();
    let hand = app.world_mut().spawn(AppHand::new(Side::Left)).id();
    app.update();
    let cube_entity = app.world().resource::<InteractionEntities>().object(cube).unwrap();
    app.world_mut()
        .entity_mut(cube_entity)
        .observe(|e: On<ObjectTouched>, mut seen: ResMut<CubeEvents>| {
            seen.0.push(("touched", e.contact.bone, e.contact.time));
        })
        .observe(|e: On<ObjectReleased>, mut seen: ResMut<CubeEvents>| {
            seen.0.push(("released", e.contact.bone, e.contact.time));
        });
    // A left hand closing on the cube over 0.3 s, holding, then opening.
    let pose_at = |closure: f32| coulomb_hands::run::demo::claw(0.025, closure, 0.002, 0.0);
    for frame in 0..60 {
        let t = frame as f32 * 0.01;
        let closure = if t < 0.3 {
            t / 0.3
        } else if t < 0.4 {
            1.0
        } else {
            1.0 - (t - 0.4) / 0.2
        };
        app.world_mut().get_mut::<HandInput>(hand).unwrap().set_pose(pose_at(closure.max(0.0)));
        app.update();
    }
    let seen = &app.world().resource::<CubeEvents>().0;
    let began = &app.world().resource::<Seen>().began;
    let ended = &app.world().resource::<Seen>().ended;
    assert!(
        began.len() >= 2 && ended.len() == began.len(),
        "{} began, {} ended",
        began.len(),
        ended.len()
    );
    // Touched when the first contact began, released when the last ended.
    assert_eq!(seen.len(), 2, "{seen:?}");
    assert_eq!(seen[0], ("touched", began[0].bone, began[0].time));
    let last = ended.last().unwrap();
    assert_eq!(seen[1], ("released", last.bone, last.time));
    assert!(seen[1].2 > seen[0].2);
}

#[test]
fn a_failed_step_stops_the_physics_not_the_app() {
    let (world, _) = cube_world();
    let mut driven = HandPhysics::new(world);
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

/// The `HandPhysicsReplaced` messages the app saw.
#[derive(Resource, Default)]
struct Replaced(Vec<u64>);

#[test]
fn a_new_world_replaces_the_plugins_entities_and_keeps_the_apps_hands() {
    let mut app = app(HandPhysics::of_scenario(&scenario("grasp-lift")).unwrap(), Duration::ZERO);
    app.init_resource::<Replaced>().add_systems(
        Update,
        |mut seen: ResMut<Replaced>, mut m: MessageReader<HandPhysicsReplaced>| {
            seen.0.extend(m.read().map(|r| r.serial));
        },
    );
    let app_hand = app.world_mut().spawn(AppHand::new(Side::Right)).id();
    app.update();
    let first = interaction(&app).serial();
    let old = app.world().resource::<InteractionEntities>().object(ObjectId(0)).unwrap();
    let old_bones: Vec<Entity> = app.world().get::<Children>(app_hand).unwrap().to_vec();
    let (world, _) = cube_world();
    let mut replacement = HandPhysics::new(world);
    replacement.add_hand(PoseFn::new(Side::Left, |_| None));
    app.insert_resource(replacement);
    app.update();
    let second = interaction(&app).serial();
    assert_eq!(app.world().resource::<Replaced>().0, vec![first, second]);
    assert!(app.world().get_entity(old).is_err(), "the old cube's entity is gone");
    assert!(old_bones.iter().all(|b| app.world().get_entity(*b).is_err()), "old bones gone");
    let mut objects = app.world_mut().query::<&InteractionObject>();
    assert_eq!(objects.iter(app.world()).count(), 1);
    // The scenario's hand went; the app's is a hand of the new world.
    let mut hands = app.world_mut().query::<(Entity, &InteractionHand)>();
    let hands: Vec<(Entity, InteractionHand)> =
        hands.iter(app.world()).map(|(e, h)| (e, *h)).collect();
    assert_eq!(hands.len(), 2, "{hands:?}");
    let (_, mine) = hands.iter().find(|(e, _)| *e == app_hand).expect("the app's hand stays");
    assert_eq!((mine.id, mine.side), (coulomb_hands::hand::HandId(1), Side::Right));
    let mut bones = app.world_mut().query::<&HandBone>();
    assert_eq!(bones.iter(app.world()).count(), 32, "the old hands' bones went with them");
    // And it poses the new world.
    app.world_mut().get_mut::<HandInput>(app_hand).unwrap().set_pose(closed_claw());
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(5)));
    app.update();
    assert_eq!(interaction(&app).world().hand_pose(mine.id), Some(&closed_claw()));
    // Despawned, it is untracked in the world from the next step.
    app.world_mut().entity_mut(app_hand).despawn();
    app.update();
    assert_eq!(interaction(&app).world().hand_pose(mine.id), None);
    assert!(interaction(&app).world().contacts().iter().all(|c| c.hand != mine.id));
}

#[test]
fn the_plugins_types_are_reflected_and_its_resource_is_send() {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<HandPhysics>();
    let mut app = app(HandPhysics::of_scenario(&scenario("grasp-lift")).unwrap(), Duration::ZERO);
    app.update();
    let registry = app.world().resource::<AppTypeRegistry>().read();
    let components = ["InteractionHand", "HandBone", "InteractionObject", "AppHand", "HandInput"];
    let resources = ["HandPhysics", "Contacts", "InteractionEntities"];
    for name in components.into_iter().chain(resources) {
        let found = registry.iter().any(|t| t.type_info().type_path_table().ident() == Some(name));
        assert!(found, "{name} is registered");
    }
    drop(registry);
    let hand = interaction(&app).hands()[0].id;
    let entity = app.world().resource::<InteractionEntities>().hand(hand).unwrap();
    let component = app.world().get::<InteractionHand>(entity).unwrap();
    // The core's Side, as an inspector sees it: an enum whose variant is the hand's side.
    let field = bevy::reflect::structs::Struct::field(component, "side").expect("a side field");
    let bevy::reflect::ReflectRef::Enum(side) = field.reflect_ref() else {
        panic!("{} is not reflected as an enum", field.reflect_type_path())
    };
    assert_eq!(side.variant_name(), format!("{:?}", component.side));
}
