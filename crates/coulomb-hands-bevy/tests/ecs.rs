//! The plugin ECS-first: an entity spawned with an `ObjectDescription` is
//! an object of the world (a scripted grasp lifts it as it lifts the
//! scenario's own cube), despawning it removes it (the hand holding it
//! lets go), a description the world rejects says why, a new world gets
//! the app's objects again, and the plugin runs in the schedule it is
//! given, on that schedule's time.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::pipeline::{InteractionWorld, WorldError};
use coulomb_hands::run::drive::Driver;
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::scene::{ObjectDesc, ObjectError, ObjectId, StaticDesc};
use coulomb_hands_bevy::convert::{to_bevy_quat, to_bevy_vec3, transform};
use coulomb_hands_bevy::prelude::*;
use std::time::Duration;

/// What the app saw: contact ends, releases and rejections, by entity.
#[derive(Resource, Default)]
struct Seen {
    ended: Vec<Entity>,
    released: Vec<Entity>,
    rejected: Vec<(Entity, WorldError)>,
}

fn app(plugin: CoulombHandsPlugin, physics: HandPhysics, frame: Duration) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, plugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(frame))
        .init_resource::<Seen>()
        .add_systems(Update, |mut seen: ResMut<Seen>, mut m: MessageReader<ContactEnded>| {
            seen.ended.extend(m.read().map(|e| e.object));
        })
        .add_observer(|r: On<ObjectReleased>, mut seen: ResMut<Seen>| seen.released.push(r.entity))
        .add_observer(|r: On<ObjectRejected>, mut seen: ResMut<Seen>| {
            seen.rejected.push((r.entity, r.error.clone()));
        })
        .insert_resource(physics);
    app
}

fn physics(app: &App) -> &HandPhysics {
    app.world().resource::<HandPhysics>()
}

/// grasp-lift's world and hand without its cube, and the cube.
fn grasp_lift_without_its_cube() -> (HandPhysics, ObjectDesc, usize) {
    let mut s = Scenario::find("grasp-lift").unwrap();
    let cube = s.scene.objects.remove(0);
    assert!(s.scene.objects.is_empty() && s.scene.towers.is_empty(), "one cube");
    let steps = s.steps();
    (HandPhysics::of_scenario(&s).unwrap(), cube, steps)
}

/// The cube as an app spawns it: its description, placed by a transform.
fn spawn_cube(app: &mut App, cube: &ObjectDesc) -> Entity {
    let unplaced = ObjectDesc { position: glam::Vec3::ZERO, ..cube.clone() };
    let placed = transform(cube.position, cube.rotation);
    app.world_mut().spawn((ObjectDescription(unplaced), placed)).id()
}

fn run_until(app: &mut App, steps: usize) {
    while physics(app).steps() < steps {
        app.update();
    }
}

#[test]
fn a_cube_spawned_as_an_entity_is_lifted_as_the_scenario_s_own_cube_is() {
    let s = Scenario::find("grasp-lift").unwrap();
    let mut world = InteractionWorld::new(s.config).unwrap();
    world.add_scene(&s.scene).unwrap();
    let mut driver = Driver::new(&mut world);
    for hand in &s.hands {
        driver.add_hand(hand.clone());
    }
    let (bare, cube, steps) = grasp_lift_without_its_cube();
    driver.run(steps, &mut []).unwrap();
    let headless = world.object_state(ObjectId(0)).unwrap();

    let mut app = app(CoulombHandsPlugin::default(), bare, Duration::from_millis(20));
    let entity = spawn_cube(&mut app, &cube);
    run_until(&mut app, steps);
    assert_eq!(app.world().get::<InteractionObject>(entity), Some(&InteractionObject(ObjectId(0))));
    let end = *app.world().get::<Transform>(entity).unwrap();
    assert!(end.translation.y - cube.position.y >= 0.18, "lifted to {}", end.translation.y);
    assert_eq!(end.translation, to_bevy_vec3(headless.position), "the same physics, bit for bit");
    assert_eq!(end.rotation, to_bevy_quat(headless.rotation));
    assert!(app.world().resource::<Seen>().rejected.is_empty());
}

#[test]
fn despawning_a_held_object_s_entity_removes_it_and_the_hand_lets_go() {
    let (bare, cube, _) = grasp_lift_without_its_cube();
    let mut app = app(CoulombHandsPlugin::default(), bare, Duration::from_millis(16));
    let entity = spawn_cube(&mut app, &cube);
    // Into the hold: lifted and gripped from about 1.6 s on.
    run_until(&mut app, 2200);
    let holding = physics(&app).world().contacts().len();
    assert!(holding >= 2, "held by {holding} contacts");
    app.world_mut().resource_mut::<Seen>().ended.clear();
    app.world_mut().entity_mut(entity).despawn();
    app.update();
    let world = physics(&app).world();
    assert_eq!(world.object_ids().count(), 0, "the world has no object");
    assert_eq!((world.contacts().len(), app.world().resource::<Contacts>().0.len()), (0, 0));
    let seen = app.world().resource::<Seen>();
    assert_eq!(seen.ended, vec![entity; holding], "each contact ended, naming the entity");
    assert_eq!(seen.released, vec![entity], "released once");
    // The hand goes on closing on nothing; a new cube where the old one
    // was is a new object.
    let again = spawn_cube(&mut app, &cube);
    app.update();
    assert_eq!(app.world().get::<InteractionObject>(again), Some(&InteractionObject(ObjectId(1))));
}

#[test]
fn removing_the_component_removes_the_object_and_keeps_the_entity() {
    let (bare, cube, _) = grasp_lift_without_its_cube();
    let mut app = app(CoulombHandsPlugin::default(), bare, Duration::from_millis(16));
    let entity = spawn_cube(&mut app, &cube);
    app.update();
    assert_eq!(physics(&app).world().object_ids().count(), 1);
    app.world_mut().entity_mut(entity).remove::<InteractionObject>();
    assert_eq!(physics(&app).world().object_ids().count(), 0, "removed at once");
    app.update();
    assert!(app.world().get_entity(entity).is_ok());
    assert_eq!(physics(&app).world().object_ids().count(), 0, "and not added back");
}

#[test]
fn a_description_the_world_rejects_says_why_and_a_new_one_is_added() {
    let (bare, cube, _) = grasp_lift_without_its_cube();
    let mut app = app(CoulombHandsPlugin::default(), bare, Duration::from_millis(16));
    let weightless = ObjectDesc { mass: -0.05, ..cube.clone() };
    let entity = spawn_cube(&mut app, &weightless);
    app.update();
    app.update();
    let rejected = &app.world().resource::<Seen>().rejected;
    assert_eq!(rejected.len(), 1, "said once: {rejected:?}");
    assert_eq!(rejected[0].0, entity);
    let WorldError::Object(ObjectError { field, .. }) = &rejected[0].1 else { panic!() };
    assert_eq!(field, "mass");
    assert_eq!(app.world().get::<InteractionObject>(entity), None);
    assert_eq!(physics(&app).world().object_count(), 0);
    app.world_mut().entity_mut(entity).insert(ObjectDescription(cube.clone()));
    app.update();
    assert_eq!(app.world().get::<InteractionObject>(entity), Some(&InteractionObject(ObjectId(0))));
}

#[test]
fn a_new_world_gets_the_app_s_objects_where_they_are() {
    let (bare, cube, _) = grasp_lift_without_its_cube();
    let ground = Scenario::find("grasp-lift").unwrap().scene.ground.expect("a ground").height;
    let mut app = app(CoulombHandsPlugin::default(), bare, Duration::from_millis(16));
    let entity = spawn_cube(&mut app, &cube);
    // A second cube, 12 cm up and aside: it falls onto the ground.
    let up = glam::Vec3::new(0.3, ground + 0.12, 0.0);
    let falling = spawn_cube(&mut app, &ObjectDesc { position: up, ..cube.clone() });
    run_until(&mut app, 600);
    let coulomb_hands::scene::ShapeDesc::Box { half_extents } = cube.shape else { panic!() };
    let landed = *app.world().get::<Transform>(falling).unwrap();
    let rest = ground + half_extents.y;
    assert!((landed.translation.y - rest).abs() < 0.002, "landed at {}", landed.translation.y);
    let config = *physics(&app).world().config();
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(ground, 0.5)).unwrap();
    app.insert_resource(HandPhysics::new(world));
    let mut entities = [entity, falling];
    entities.sort();
    let before = entities.map(|e| *app.world().get::<Transform>(e).unwrap());
    app.update();
    // The same entities, objects of the new world in entity order, from
    // where they were.
    let id = |e| app.world().get::<InteractionObject>(e).map(|o| o.0);
    assert_eq!(entities.map(id), [Some(ObjectId(0)), Some(ObjectId(1))]);
    assert_eq!(physics(&app).world().object_count(), 2);
    let mut fresh = InteractionWorld::new(config).unwrap();
    fresh.add_static(&StaticDesc::ground(ground, 0.5)).unwrap();
    for t in before {
        let desc = ObjectDesc {
            position: coulomb_hands_bevy::convert::to_core_vec3(t.translation),
            rotation: coulomb_hands_bevy::convert::to_core_quat(t.rotation),
            ..cube.clone()
        };
        fresh.add_object(&desc).unwrap();
    }
    let steps = physics(&app).steps();
    for _ in 0..steps {
        fresh.step();
    }
    for id in [ObjectId(0), ObjectId(1)] {
        let got = physics(&app).world().object_state(id).unwrap();
        assert_eq!(got, fresh.object_state(id).unwrap(), "{id} as a world built there");
    }
}

/// The physics steps each `Update` saw, over three frames of 16 ms.
#[derive(Resource, Default)]
struct StepsAtUpdate(Vec<usize>);

#[test]
fn the_plugin_runs_in_the_schedule_it_is_given_on_that_schedule_s_time() {
    let grasp = || HandPhysics::of_scenario(&Scenario::find("grasp-lift").unwrap()).unwrap();
    let frame = Duration::from_millis(16);
    // Around the fixed loop (the default), `Update` sees the frame's steps;
    // in `PostUpdate`, the last frame's.
    let cases = [
        (CoulombHandsPlugin::default(), [16, 32, 48]),
        (CoulombHandsPlugin::new(PostUpdate), [0, 16, 32]),
    ];
    for (plugin, want) in cases {
        let mut app = app(plugin, grasp(), frame);
        app.init_resource::<StepsAtUpdate>().add_systems(
            Update,
            |physics: Res<HandPhysics>, mut seen: ResMut<StepsAtUpdate>| {
                seen.0.push(physics.steps())
            },
        );
        // The first frame only starts Bevy's clock.
        app.update();
        app.world_mut().resource_mut::<StepsAtUpdate>().0.clear();
        for _ in 0..3 {
            app.update();
        }
        assert_eq!(app.world().resource::<StepsAtUpdate>().0, want, "{plugin:?}");
        // And the cube's entity follows the world.
        let entity = app.world().resource::<InteractionEntities>().object(ObjectId(0)).unwrap();
        let state = physics(&app).world().object_state(ObjectId(0)).unwrap();
        let t = app.world().get::<Transform>(entity).unwrap();
        assert_eq!(t.translation, to_bevy_vec3(state.position));
    }
    // In `FixedUpdate`, the steps follow the fixed clock (64 Hz: 15.625 ms
    // a run), not the frames.
    let mut app = app(CoulombHandsPlugin::new(FixedUpdate), grasp(), frame);
    for _ in 0..50 {
        app.update();
    }
    let fixed = app.world().resource::<Time<Fixed>>().elapsed();
    let virtual_time = app.world().resource::<Time<Virtual>>().elapsed();
    assert_ne!(fixed, virtual_time);
    assert_eq!(physics(&app).steps() as u128, fixed.as_nanos() / 1_000_000);
}
