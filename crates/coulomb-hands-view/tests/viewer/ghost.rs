//! A hand–object capture in the viewer: the bundled TACO sequence loads as
//! a capture, its ghost takes the captured pose of the physics time
//! (between two frames, linear and slerped), and in a headless app the
//! ghost rises with the captured object as the physics plays, the simulated
//! object is where the core's `replay_capture` has it, and the ghost goes
//! back to the first pose on a restart.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::pipeline::Method;
use coulomb_hands::run::capture::{CaptureOptions, replay_capture};
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::convert::to_core_vec3;
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::ghost::{Ghost, GhostPlugin};
use coulomb_hands_view::headless_app;
use coulomb_hands_view::hud::HudLines;
use coulomb_hands_view::source::{LoadOptions, Source};
use coulomb_hands_view::transport::Transport;
use std::time::Duration;

const TACO: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/taco/taco_20231104_017.json");

fn taco() -> Source {
    Source::load(Some(TACO), &LoadOptions::default()).expect("the bundled capture")
}

#[test]
fn a_capture_loads_and_its_ghost_is_between_the_frames_about_the_time() {
    let source = taco();
    let Source::Capture { credit, playback, .. } = &source else { panic!("not a capture") };
    assert!(credit.as_deref().is_some_and(|c| c.contains("TACO") && c.contains("CC BY 4.0")));
    let capture = source.captured().expect("its capture");
    let poses = &capture.poses;
    assert_eq!((poses.len(), playback.tracks.len()), (146, 1));
    assert!(source.duration().is_some_and(|d| (d - 145.0 / 30.0).abs() < 1e-5), "4.83 s");
    assert_eq!(capture.pose_at(0.0), poses[0]);
    assert_eq!(capture.pose_at(60.0), poses[145], "the last pose held");
    // A third of the way from frame 36 (1.2 s) to 37, while it rises fast.
    let (a, b) = (poses[36], poses[37]);
    let (p, q) = capture.pose_at((36.0 + 1.0 / 3.0) / 30.0);
    assert!(b.0.y - a.0.y > 5e-3, "rising: {} to {}", a.0.y, b.0.y);
    assert!((p - a.0.lerp(b.0, 1.0 / 3.0)).length() < 1e-6, "{p} between {} and {}", a.0, b.0);
    let turned = |x: glam::Quat, y: glam::Quat| x.angle_between(y);
    let whole = turned(a.1, b.1);
    assert!(
        (turned(a.1, q) - whole / 3.0).abs() < 1e-4
            && (turned(q, b.1) - whole * 2.0 / 3.0).abs() < 1e-4
    );
    // A scenario with a hand and an object is still a scenario.
    let scenario = Source::load(Some("grasp-lift"), &LoadOptions::default()).expect("shipped");
    assert!(scenario.captured().is_none());
}

/// The ghost's position (world, m), if there is a ghost.
fn ghost(app: &mut App) -> Option<glam::Vec3> {
    let mut ghosts = app.world_mut().query_filtered::<&Transform, With<Ghost>>();
    let found: Vec<_> = ghosts.iter(app.world()).map(|t| to_core_vec3(t.translation)).collect();
    assert!(found.len() <= 1, "one ghost: {found:?}");
    found.first().copied()
}

fn time(app: &App) -> f64 {
    app.world().resource::<HandPhysics>().world().time()
}

#[test]
fn the_ghost_rises_with_the_captured_object_and_restarts_with_the_run() {
    let source = taco();
    let Source::Capture { capture, .. } = &source else { panic!("not a capture") };
    let (capture, start) = (capture.clone(), capture.poses[0].0);
    let capture = &*capture;
    let mut app = headless_app(source, Method::Coulomb).expect("a world");
    app.add_plugins(GhostPlugin { draw: false })
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(50)));
    app.update();
    assert!((ghost(&mut app).expect("a ghost") - start).length() < 1e-6, "at its first pose");
    while time(&app) < 1.5 {
        app.update();
    }
    // Captured, the object rose about 60 mm by 1.2 s and 130 mm by 1.5 s.
    let risen = ghost(&mut app).expect("a ghost").y - start.y;
    assert!(risen > 0.06, "the ghost rose {risen} m by {} s", time(&app));
    // The simulated object is where the core's replay has it at 1.5 s.
    assert!((time(&app) - 1.5).abs() < 1e-6, "at {}", time(&app));
    let replayed = replay_capture(capture, &CaptureOptions::default()).expect("a replay");
    let world = app.world().resource::<HandPhysics>().world();
    let object = world.object_state(ObjectId(0)).expect("the object");
    let height = (object.position.y - start.y) * 1e3;
    let frame = &replayed.frames[45];
    assert!((height - frame.simulated_height_mm).abs() < 1e-3, "{height} mm: {frame:?}");
    let hud = app.world().resource::<HudLines>().text();
    assert!(hud.contains("translation error") && hud.contains("CC BY 4.0"), "{hud}");
    app.world_mut().resource_mut::<Transport>().seek = Some(0.0);
    app.update();
    assert_eq!(time(&app), 0.0);
    assert!((ghost(&mut app).expect("a ghost") - start).length() < 1e-6, "back at the start");
}
