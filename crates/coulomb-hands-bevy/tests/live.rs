//! The live Leap client's hands in a headless app, from a loopback service
//! that the test paces frame by frame with a real recording: the app's
//! frames never wait for the service, and the hand pushes a cube's entity.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::hand::Side;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::leap;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::pipeline::{InteractionConfig, InteractionWorld};
use coulomb_hands::run::live::LiveFeed;
use coulomb_hands::scene::ObjectDesc;
use coulomb_hands_bevy::CoulombHandsPlugin;
use coulomb_hands_bevy::contacts::ContactBegan;
use coulomb_hands_bevy::entities::{InteractionEntities, InteractionHand};
use coulomb_hands_bevy::physics::HandPhysics;
use std::net::TcpListener;
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;
use tungstenite::Message;

fn pinch_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data/leap/pinch.json.lz")
}

/// The recording's frames as the service sends them.
fn pinch_messages(count: usize) -> Vec<String> {
    let text = std::fs::read_to_string(pinch_path()).unwrap();
    let json = String::from_utf16(&lz_str::decompress_from_base64(text.trim()).unwrap()).unwrap();
    let root: serde_json::Value = serde_json::from_str(&json).unwrap();
    root["frames"].as_array().unwrap()[..count].iter().map(|f| f.to_string()).collect()
}

/// A loopback service that sends each frame the test hands it; returns
/// its URL. It drops the connection when the sender goes.
fn paced() -> (String, mpsc::Sender<String>, std::thread::JoinHandle<()>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let url = format!("ws://{}/v6.json", listener.local_addr().unwrap());
    let (tx, rx) = mpsc::channel::<String>();
    let server = std::thread::spawn(move || {
        let (stream, _) = listener.accept().unwrap();
        let mut ws = tungstenite::accept(stream).unwrap();
        ws.send(Message::text(r#"{"serviceVersion":"2.3.1","version":6}"#)).unwrap();
        while let Ok(frame) = rx.recv() {
            ws.send(Message::text(frame)).unwrap();
        }
    });
    (url, tx, server)
}

/// ContactBegan messages the app saw.
#[derive(Resource, Default)]
struct Began(usize);

fn count(mut began: ResMut<Began>, mut messages: MessageReader<ContactBegan>) {
    began.0 += messages.read().count();
}

fn set_frame(app: &mut App, frame: Duration) {
    app.insert_resource(TimeUpdateStrategy::ManualDuration(frame));
}

#[test]
fn a_live_leap_hand_pushes_a_cube_and_the_app_never_waits_for_the_service() {
    // 160 frames of the real pinch; a weightless 25 mm, 30 g cube floats
    // where the index fingertip is 55 % of the way through them.
    let frames = 160;
    let recorded = leap::load(&pinch_path()).unwrap();
    let conversion = Conversion::leap_desktop(glam::Vec3::ZERO);
    let head = &recorded.frames[..frames];
    let replay = Playback::new("pinch", head, &conversion, DEFAULT_GRACE).unwrap();
    let tip = replay.sample(0, 0.55 * replay.duration).unwrap().pose.fingers[1][2].b;
    let micros: Vec<i64> = head.iter().map(|f| f.timestamp_us - head[0].timestamp_us).collect();
    let messages = pinch_messages(frames);
    let (url, tx, server) = paced();
    let (done, result) = mpsc::channel();
    // On a thread of its own, so an app that waits for the service fails
    // the test rather than hang it.
    std::thread::spawn(move || {
        let weightless = InteractionConfig { gravity: glam::Vec3::ZERO, ..Default::default() };
        let mut world = InteractionWorld::new(weightless).unwrap();
        let cube =
            world.add_object(&ObjectDesc::cuboid("cube", glam::Vec3::splat(0.025), 0.03, tip));
        let cube = cube.unwrap();
        let feed = LiveFeed::connect(&url, conversion, DEFAULT_GRACE).unwrap();
        let mut driven = HandPhysics::new(world);
        let hand = driven.add_hand(feed.hand(Side::Right));
        let mut app = App::new();
        app.add_plugins((MinimalPlugins, CoulombHandsPlugin::default()))
            .init_resource::<Began>()
            .add_systems(Update, count)
            .insert_resource(driven);
        set_frame(&mut app, Duration::from_millis(10));
        // The service says nothing yet: frames go on, the physics steps,
        // and the hand is untracked.
        for _ in 0..6 {
            app.update();
        }
        let steps = app.world().resource::<HandPhysics>().steps();
        assert_eq!(steps, 50, "five 10 ms frames after the one that starts the clock");
        let entity = app.world().resource::<InteractionEntities>().hand(hand).unwrap();
        assert!(!app.world().get::<InteractionHand>(entity).unwrap().tracked);
        let entity = app.world().resource::<InteractionEntities>().object(cube).unwrap();
        let start = app.world().get::<Transform>(entity).unwrap().translation;
        // Then the recording, each frame sent when its time comes on the
        // app's clock.
        let mut tracked = 0;
        for (k, message) in messages.into_iter().enumerate() {
            tx.send(message).unwrap();
            while feed.stats().frames <= k {
                std::thread::sleep(Duration::from_millis(1));
            }
            let gap = if k == 0 { 0 } else { micros[k] - micros[k - 1] };
            set_frame(&mut app, Duration::from_micros(gap as u64));
            app.update();
            let hand = app.world().resource::<InteractionEntities>().hand(hand).unwrap();
            tracked += usize::from(app.world().get::<InteractionHand>(hand).unwrap().tracked);
        }
        let end = app.world().get::<Transform>(entity).unwrap().translation;
        let interaction = app.world().resource::<HandPhysics>();
        assert!(interaction.stopped().is_none(), "{:?}", interaction.stopped());
        let _ = done.send((tracked, app.world().resource::<Began>().0, end.distance(start)));
    });
    let (tracked, began, moved) = result.recv_timeout(Duration::from_secs(60)).expect("in time");
    server.join().unwrap();
    // Tracked but in the first frame (which runs no step) and while the
    // played time is still before the stream's first frame: the playout
    // delay, four frames at this recording's 115 Hz.
    assert!(tracked >= frames - 6, "tracked in {tracked} of {frames} frames");
    assert!(began > 0, "no contact began");
    assert!(moved > 0.001, "the cube's entity moved {moved} m");
}
