//! The chessboard task (§5.2) for a person, with scripted keys: the hand
//! pushes the cube one square forward, watching it, and Enter ends the
//! trial. The logged error is the cube's distance from the target square,
//! the row sits beside a synthetic study's, and the next trial is set up.

use super::keys::press;
use super::mouse_hand::{app_of, cube, fingertip, hand, hold, hold_while};
use bevy::prelude::*;
use coulomb_hands::eval::board::{Placement, square_center};
use coulomb_hands::eval::{AccuracyStudy, Trial, summarise, thesis_table};
use coulomb_hands::pipeline::Method;
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::task::{ChessboardTask, TaskOptions, TaskPlugin};
use std::path::Path;

fn task(app: &App) -> &ChessboardTask {
    app.world().resource::<ChessboardTask>()
}

#[test]
fn a_scripted_trial_logs_its_error_and_time_beside_a_synthetic_study() {
    let log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("task-accuracy.json");
    // A synthetic study, as `eval accuracy --json` writes it: its row is kept.
    let synthetic = Trial { error: 0.0123, time: 7.5, failed: false, drops: 1 };
    let methods = vec![summarise("kinematic", &[synthetic])];
    let study = AccuracyStudy {
        users: 2,
        trials: 3,
        seed: 9,
        noise: Some(1.0),
        noise_rms_mm: Some(0.72),
        noise_source: None,
        perception: Some(1.0),
        methods,
        thesis: thesis_table(),
    };
    std::fs::write(&log, serde_json::to_string(&study).expect("JSON")).expect("written");

    // One square forward (+z), the cube turned 0.12 rad; then a second trial elsewhere.
    let first = Placement { start: (3, 3), target: (3, 4), yaw: 0.12 };
    let second = Placement { start: (6, 1), target: (2, 5), yaw: -0.2 };
    let options = TaskOptions { trials: 2, seed: 0, log: Some(log.clone()), person: "ada".into() };
    let session = ChessboardTask::new(options, Method::Coulomb, vec![first, second]);
    let mut app = app_of(session.source().expect("a trial"));
    app.insert_resource(session).add_plugins(TaskPlugin { draw: false });

    // The person: fingertips 3 cm behind the cube, down to 3 cm over the board, the
    // middle fingertip lined up with the cube (finely), then forward, watching the cube
    // until it is within 3 mm of the target's centre, and back off.
    let start = cube(&app);
    let target = square_center(first.target);
    let behind = start.z - 0.02 - 0.03;
    hold_while(&mut app, &[KeyCode::KeyS], 2.0, |a| fingertip(a).z > behind);
    hold_while(&mut app, &[KeyCode::KeyQ], 2.0, |a| hand(a).palm.y > 0.03);
    // Right is -x here (no camera: the default view's axes).
    let right = fingertip(&app).x > start.x;
    let key = if right { KeyCode::KeyD } else { KeyCode::KeyA };
    let fine = [key, KeyCode::ShiftLeft];
    hold_while(&mut app, &fine, 2.0, |a| (fingertip(a).x > start.x) == right);
    hold_while(&mut app, &[KeyCode::KeyW], 3.0, |a| cube(a).z < target.z - 0.003);
    hold(&mut app, &[KeyCode::KeyS], 0.3);
    hold(&mut app, &[], 0.2);

    let world_time = app.world().resource::<HandPhysics>().world().time();
    let at = cube(&app);
    let expected = ((at - target) * glam::Vec3::new(1.0, 0.0, 1.0)).length();
    assert!(at.z - start.z > 0.03, "the cube was pushed: {start} -> {at}");
    press(&mut app, KeyCode::Enter);

    let results = &task(&app).results;
    assert_eq!(results.len(), 1, "Enter ends the trial");
    let trial = results[0];
    assert!((trial.error - expected).abs() < 1e-6, "{} logged, {expected} measured", trial.error);
    assert!(trial.error < 0.01, "within a centimetre: {} m", trial.error);
    assert!((trial.time - world_time).abs() < 0.011, "{} s, ended at {world_time} s", trial.time);
    assert!(!trial.failed && task(&app).log_error.is_none());

    let read = AccuracyStudy::load(&log).expect("the log is an accuracy JSON");
    assert_eq!(read.methods[0], study.methods[0], "the synthetic row is kept");
    let person = read.methods.iter().find(|m| m.method == "coulomb (ada)").expect("the row");
    assert_eq!(person.errors_mm.len(), 1);
    assert!((person.errors_mm[0] - f64::from(trial.error) * 1e3).abs() < 1e-3);
    assert_eq!(person.times_s, vec![trial.time]);
    assert_eq!((read.users, read.trials, read.seed), (2, 3, 9));

    // The next trial: a fresh board, the cube on its start square.
    app.update();
    let world = app.world().resource::<HandPhysics>().world();
    assert!(world.time() < 0.05, "restarted: t = {}", world.time());
    let next = square_center(second.start) + glam::Vec3::Y * 0.02;
    assert!((cube(&app) - next).length() < 0.001, "{} not at {next}", cube(&app));
}
