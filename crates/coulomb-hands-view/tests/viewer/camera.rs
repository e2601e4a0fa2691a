//! The camera frames the whole run, headless: from grasp-lift's default
//! view (the one that shows its grasp), the cube stays inside the view's
//! field at every frame of the run, lifted and all, and F brings a camera
//! that was turned and zoomed away back to that framing. For every shipped
//! scenario, the default view has the hands' contacts in sight.

use super::keys::press;
use bevy::camera::PerspectiveProjection;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::pipeline::Method;
use coulomb_hands::run::scenario::shipped;
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::convert::{to_bevy_vec3, to_core_vec3};
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::camera::{CameraPlugin, DEFAULT_PITCH, Framing, Orbit};
use coulomb_hands_view::headless_app;
use coulomb_hands_view::source::{LoadOptions, Source};
use std::time::Duration;

/// The window's shape (1280 × 720).
const ASPECT: f32 = 16.0 / 9.0;

/// grasp-lift with the camera, framed, at 20 ms frames.
fn app() -> App {
    let source = Source::load(Some("grasp-lift"), &LoadOptions::default()).expect("shipped");
    let framing = Framing::of_run(&source, Method::Coulomb).expect("a run").expect("a volume");
    let mut app = headless_app(source, Method::Coulomb).expect("a world");
    app.add_plugins(CameraPlugin)
        .insert_resource(framing)
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(20)));
    app.update();
    app
}

fn orbit(app: &mut App) -> Orbit {
    let mut orbits = app.world_mut().query::<&Orbit>();
    *orbits.single(app.world()).expect("one orbit camera")
}

/// Where `point` lands in the view of a camera at `camera`: normalised
/// device coordinates, x and y in [−1, 1] inside the window, and whether it
/// is in front.
fn ndc(camera: &Transform, point: Vec3) -> (Vec2, bool) {
    let v = camera.compute_affine().inverse().transform_point3(point);
    let half = (PerspectiveProjection::default().fov / 2.0).tan();
    (Vec2::new(v.x / -v.z / (half * ASPECT), v.y / -v.z / half), v.z < 0.0)
}

#[test]
fn the_default_view_keeps_the_cube_in_frame_for_the_whole_run() {
    let mut app = app();
    let start = orbit(&mut app);
    let mut highest = f32::MIN;
    while app.world().resource::<HandPhysics>().world().time() < 4.3 - 1e-3 {
        app.update();
        let world = app.world().resource::<HandPhysics>().world();
        let (t, cube) = (world.time(), world.object_state(ObjectId(0)).expect("the cube"));
        let cube = to_bevy_vec3(cube.position);
        highest = highest.max(cube.y);
        let (at, ahead) = ndc(&orbit(&mut app).transform(), cube);
        assert!(ahead && at.abs().max_element() < 0.9, "t {t}: the cube at {at}");
    }
    assert!(highest > 0.18, "the cube was lifted: {highest} m");
    assert_eq!(orbit(&mut app).focus, start.focus, "the camera stays put");
}

#[test]
fn f_frames_the_run_again_after_the_camera_was_moved() {
    let mut app = app();
    let framed = orbit(&mut app);
    let framing = *app.world().resource::<Framing>();
    assert_eq!((framed.focus, framed.distance), (framing.center, framing.distance()));
    {
        let mut orbits = app.world_mut().query::<&mut Orbit>();
        let mut moved = orbits.single_mut(app.world_mut()).expect("one orbit camera");
        (moved.yaw, moved.pitch, moved.distance) = (2.0, -0.3, 3.5);
        moved.focus += Vec3::new(0.4, -0.2, 0.1);
    }
    press(&mut app, KeyCode::KeyF);
    let back = orbit(&mut app);
    let same = (back.focus, back.yaw, back.pitch, back.distance);
    assert_eq!(same, (framed.focus, framed.yaw, framed.pitch, framed.distance));
}

#[test]
fn every_shipped_scenario_s_default_view_has_its_contacts_in_sight() {
    // In sight: on a line from the camera's eye that no palm, finger or the
    // object itself crosses. Every scenario whose contacts the old fixed
    // view (behind and above) had in sight has some in sight from its
    // default view, and more scenarios than from the fixed view have a
    // tenth or more in sight; grasp-lift's, whose cube the palm covered
    // from behind, twice as many. (Contacts sandwiched between a flat hand
    // and what rests on it are in sight from no view.)
    let (mut seen, mut seen_before) = (0, 0);
    for (name, _) in shipped() {
        let source = Source::load(Some(name), &LoadOptions::default()).expect("shipped");
        let (framing, grasps) = Framing::survey(&source, Method::Coulomb).expect("a run");
        let framing = framing.expect("a volume");
        let Some((yaw, pitch)) = framing.view else {
            assert!(grasps.is_empty(), "{name}: contacts, but no view");
            continue;
        };
        let (center, distance) = (to_core_vec3(framing.center), framing.distance());
        let chosen = grasps.share_in_sight(center, distance, yaw, pitch);
        let fixed = grasps.share_in_sight(center, distance, 0.0, DEFAULT_PITCH);
        assert!(fixed == 0.0 || chosen > 0.0, "{name}: {chosen:.2} in sight, {fixed:.2} before");
        (seen, seen_before) =
            (seen + usize::from(chosen >= 0.1), seen_before + usize::from(fixed >= 0.1));
        if *name == "grasp-lift" {
            assert!(chosen > 2.0 * fixed, "grasp-lift: {chosen:.2} in sight, {fixed:.2} before");
        }
    }
    assert!(seen > seen_before + 3, "{seen} scenarios with a tenth in sight, {seen_before} before");
}
