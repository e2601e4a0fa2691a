//! `--leap`: live hands from a Leap Motion service, here a loopback one the
//! test paces frame by frame with a real recording. The hand pushes a
//! scene's cube, a restart plays on from the same stream, and a service
//! that is not there is an error before any window.

use super::window::refused;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::hand::Side;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::leap;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::pipeline::Method;
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::headless_app;
use coulomb_hands_view::source::{LoadOptions, Source};
use coulomb_hands_view::transport::leap_line;
use coulomb_hands_view::transport::{Transport, Viewed};
use std::net::TcpListener;
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;
use tungstenite::Message;

fn pinch_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data/leap/pinch.json.lz")
}

/// The recording's first `count` frames as the service sends them.
fn pinch_messages(count: usize) -> Vec<String> {
    let text = std::fs::read_to_string(pinch_path()).expect("bundled");
    let json = lz_str::decompress_from_base64(text.trim()).expect("lz-string");
    let root: serde_json::Value =
        serde_json::from_str(&String::from_utf16(&json).expect("UTF-16")).expect("JSON");
    let frames = root["frames"].as_array().expect("frames");
    frames[..count].iter().map(|f| f.to_string()).collect()
}

/// A loopback service that sends each frame the test hands it; its URL.
fn paced() -> (String, mpsc::Sender<String>) {
    let listener = TcpListener::bind("127.0.0.1:0").expect("a port");
    let url = format!("ws://{}/v6.json", listener.local_addr().expect("bound"));
    let (tx, rx) = mpsc::channel::<String>();
    std::thread::spawn(move || {
        let (stream, _) = listener.accept().expect("the viewer connects");
        let mut ws = tungstenite::accept(stream).expect("a WebSocket");
        ws.send(Message::text(r#"{"serviceVersion":"2.3.1","version":6}"#)).expect("sent");
        while let Ok(frame) = rx.recv() {
            ws.send(Message::text(frame)).expect("sent");
        }
    });
    (url, tx)
}

fn interaction(app: &App) -> &HandPhysics {
    app.world().resource::<HandPhysics>()
}

/// Sends `frames[range]`, each followed by an app frame that lasts until
/// the next one's time (`micros`, from the first frame).
fn stream(app: &mut App, tx: &mpsc::Sender<String>, frames: &[String], micros: &[i64]) {
    for (k, frame) in frames.iter().enumerate() {
        let sent = feed_frames(app) + 1;
        tx.send(frame.clone()).expect("the service runs");
        while feed_frames(app) < sent {
            std::thread::sleep(Duration::from_millis(1));
        }
        let gap = micros.get(k + 1).map_or(0, |next| next - micros[k]);
        let frame = Duration::from_micros(gap as u64);
        app.insert_resource(TimeUpdateStrategy::ManualDuration(frame));
        app.update();
    }
}

fn feed_frames(app: &App) -> usize {
    let viewed = app.world().resource::<Viewed>();
    viewed.source.leap_feed().expect("--leap").stats().frames
}

#[test]
fn live_leap_hands_push_a_scenes_cube_and_a_restart_plays_on() {
    // A weightless scene (the pinch's fingertip moves down, and would only
    // press a cube on a table into it), with a 35 mm, 40 g cube where the
    // real pinch's index fingertip is 45 % of the way through 150 frames,
    // the device 12 cm under the scene's origin.
    let count = 150;
    let recorded = leap::load(&pinch_path()).expect("bundled");
    let head = &recorded.frames[..count + 30];
    let conversion = Conversion::leap_desktop(glam::Vec3::ZERO);
    let replay = Playback::new("pinch", &head[..count], &conversion, DEFAULT_GRACE).expect("ok");
    let tip = replay.sample(0, 0.45 * replay.duration).expect("tracked").pose.fingers[1][2].b;
    let device = glam::Vec3::new(0.0, -0.12, 0.0);
    let cube = serde_json::json!({"name": "cube", "mass": 0.04, "material": "wood",
        "shape": {"Box": {"half_extents": [0.0175, 0.0175, 0.0175]}},
        "position": (tip + device).to_array()});
    let scene = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("leap-weightless.json");
    let text = serde_json::json!({"gravity": [0.0, 0.0, 0.0], "objects": [cube]});
    std::fs::write(&scene, text.to_string()).expect("written");
    let micros: Vec<i64> = head.iter().map(|f| f.timestamp_us - head[0].timestamp_us).collect();
    let messages = pinch_messages(count + 30);
    let (url, tx) = paced();
    let (done, result) = mpsc::channel();
    // On a thread of its own, so a viewer that waits for the service fails
    // the test rather than hang it.
    std::thread::spawn(move || {
        let scene = Source::load(scene.to_str(), &LoadOptions::default()).expect("a scene");
        let source = scene.live_leap(&url, device).expect("the service is there");
        assert!(source.app_hands().is_empty(), "the stream poses both hands");
        let mut app = headless_app(source, Method::Coulomb).expect("a world");
        let sides: Vec<Side> = interaction(&app).hands().iter().map(|h| h.side).collect();
        assert_eq!(sides, [Side::Left, Side::Right]);
        let world = interaction(&app).world();
        let start = world.object_state(ObjectId(0)).expect("the cube").position;
        app.update();
        stream(&mut app, &tx, &messages[..count], &micros[..count]);
        let world = interaction(&app).world();
        let moved = world.object_state(ObjectId(0)).expect("the cube").position.distance(start);
        let stats = app.world().resource::<Viewed>().source.leap_feed().expect("--leap").stats();
        // Home: a fresh world from t = 0, its hands from the same stream.
        app.world_mut().resource_mut::<Transport>().seek = Some(0.0);
        app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::ZERO));
        app.update();
        let restarted = interaction(&app).world().time();
        stream(&mut app, &tx, &messages[count..], &micros[count..]);
        let right = interaction(&app).hands()[1].id;
        let tracked = interaction(&app).world().hand_pose(right).is_some();
        let _ = done.send((moved, stats, restarted, tracked, interaction(&app).steps()));
    });
    let (moved, stats, restarted, tracked, steps) =
        result.recv_timeout(Duration::from_secs(120)).expect("the viewer never waits");
    // Weightless and touched by nothing else: only the hand moves it.
    assert!(moved > 0.001, "the cube moved {moved} m");
    assert_eq!((stats.frames, stats.hands_seen, stats.skipped), (count, 1, 0));
    let line = leap_line(&stats);
    assert!(line.starts_with("Leap: 150 frames, 1 hands seen"), "{line}");
    assert_eq!(restarted, 0.0, "Home restarts at t = 0");
    // The restarted hands tie to the newest frames and play on.
    assert!(tracked, "the right hand is live again after the restart");
    assert!(steps > 200, "{steps} steps since the restart");
}

#[test]
fn a_leap_service_that_is_not_there_is_an_error_before_any_window() {
    // A port that was just free: nothing listens on it.
    let url = {
        let listener = TcpListener::bind("127.0.0.1:0").expect("a port");
        format!("ws://{}/v6.json", listener.local_addr().expect("bound"))
    };
    let stderr = refused(&["--leap".as_ref(), url.as_ref()], None);
    assert!(stderr.starts_with("error: ") && stderr.contains(&url), "{stderr}");
    assert!(!stderr.contains("display"), "before the display is looked for: {stderr}");
    let stderr = refused(&["grasp-lift".as_ref(), "--leap".as_ref()], None);
    assert!(stderr.contains("--leap takes a scene file, or none"), "{stderr}");
}
