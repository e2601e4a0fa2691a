//! Playback in a headless app: seeking back replays from t = 0 to the very
//! same state, pausing stops the physics, and `.` steps it once.

use super::keys::press;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::pipeline::Method;
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::headless_app;
use coulomb_hands_view::source::{LoadOptions, Source};
use coulomb_hands_view::transport::Transport;
use std::time::Duration;

/// grasp-lift in an app with the transport, 7 ms frames.
fn app() -> App {
    let source = Source::load(Some("grasp-lift"), &LoadOptions::default()).expect("shipped");
    let mut app = headless_app(source, Method::Coulomb).expect("a world");
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(7)));
    app
}

fn time(app: &App) -> f64 {
    app.world().resource::<HandPhysics>().world().time()
}

/// The cube's pose and velocity, as bits.
fn cube(app: &App) -> Vec<u32> {
    let i = app.world().resource::<HandPhysics>();
    let s = i.world().object_state(ObjectId(0)).expect("the cube");
    [s.position.to_array(), s.linvel.to_array(), s.angvel.to_array()]
        .concat()
        .into_iter()
        .chain(s.rotation.to_array())
        .map(f32::to_bits)
        .collect()
}

#[test]
fn seeking_back_replays_to_the_same_state_and_pause_holds_the_physics() {
    let mut app = app();
    let mut at_1_4 = None;
    while time(&app) < 2.5 {
        app.update();
        if (time(&app) - 1.4).abs() < 1e-6 {
            at_1_4 = Some(cube(&app));
        }
    }
    let at_1_4 = at_1_4.expect("a frame ended at 1.4 s (200 frames of 7 ms)");
    app.world_mut().resource_mut::<Transport>().seek = Some(1.4);
    app.update();
    assert!((time(&app) - 1.4).abs() < 1e-6, "at {}", time(&app));
    assert_eq!(cube(&app), at_1_4, "the replayed state is the state");
    press(&mut app, KeyCode::Space);
    let paused = (time(&app), cube(&app));
    (0..20).for_each(|_| app.update());
    assert_eq!((time(&app), cube(&app)), paused, "paused: nothing moves");
    press(&mut app, KeyCode::Period);
    assert!((time(&app) - paused.0 - 0.001).abs() < 1e-9, "one step of 1 ms");
    // The end holds the run: at 16x, a few frames reach 4.3 s and stay.
    press(&mut app, KeyCode::Space);
    app.world_mut().resource_mut::<Transport>().speed = 8;
    (0..100).for_each(|_| app.update());
    assert!((time(&app) - 4.3).abs() < 1e-6, "held at the end: {}", time(&app));
}
