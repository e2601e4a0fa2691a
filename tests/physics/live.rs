//! The live Leap Motion WebSocket client against a local server on
//! loopback that streams a real recording's frames.

use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::leap;
use coulomb_hands::input::live::LiveLeap;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::run::live::run_live;
use coulomb_hands::run::replay::world_with_objects;
use coulomb_hands::{InteractionConfig, ObjectDesc};
use glam::Vec3;
use std::net::TcpListener;
use tungstenite::Message;

pub(crate) fn pinch_path() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/leap/pinch.json.lz")
}

/// The recording's frames as the service sends them (JSON objects).
pub(crate) fn pinch_frames() -> Vec<serde_json::Value> {
    let text = std::fs::read_to_string(pinch_path()).unwrap();
    let json = String::from_utf16(&lz_str::decompress_from_base64(text.trim()).unwrap()).unwrap();
    let root: serde_json::Value = serde_json::from_str(&json).unwrap();
    root["frames"].as_array().unwrap().clone()
}

/// The service's side of a loopback connection.
pub(crate) type Socket = tungstenite::WebSocket<std::net::TcpStream>;

/// A loopback Leap service: greets its first client as the service does,
/// then runs `then` on the connection. Returns the URL.
pub(crate) fn service(
    then: impl FnOnce(&mut Socket) + Send + 'static,
) -> (String, std::thread::JoinHandle<()>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let url = format!("ws://{}/v6.json", listener.local_addr().unwrap());
    let server = std::thread::spawn(move || {
        let (stream, _) = listener.accept().unwrap();
        let mut ws = tungstenite::accept(stream).unwrap();
        ws.send(Message::text(r#"{"serviceVersion":"2.3.1","version":6}"#)).unwrap();
        then(&mut ws);
    });
    (url, server)
}

/// Closes the stream, draining until the client acknowledges the close.
pub(crate) fn close(ws: &mut Socket) {
    ws.close(None).unwrap();
    while ws.read().is_ok() {}
}

/// Serves `messages` to the first client on a loopback WebSocket after the
/// service's greeting, then closes; returns the URL.
fn serve(messages: Vec<String>) -> (String, std::thread::JoinHandle<()>) {
    service(move |ws| {
        for m in messages {
            ws.send(Message::text(m)).unwrap();
        }
        close(ws);
    })
}

/// Runs `client` on its own thread, so a hang fails the test instead of
/// stalling the suite.
pub(crate) fn within_a_minute<T: Send + 'static>(client: impl FnOnce() -> T + Send + 'static) -> T {
    let (done, result) = std::sync::mpsc::channel();
    std::thread::spawn(move || done.send(client()).ok());
    result.recv_timeout(std::time::Duration::from_secs(60)).expect("finished within 60 s")
}

#[test]
fn streams_a_recording_over_a_local_websocket_and_skips_malformed_frames() {
    let all = pinch_frames();
    let mut broken = all[100].clone();
    broken["hands"][0].as_object_mut().unwrap().remove("palmPosition");
    let mut messages: Vec<String> = all[..100].iter().map(|f| f.to_string()).collect();
    messages.insert(50, broken.to_string());
    messages.insert(50, "{not json".to_string());
    let (url, server) = serve(messages);
    let (live, received) = within_a_minute(move || {
        let mut live = LiveLeap::connect(&url).unwrap();
        let mut received = Vec::new();
        while let Some(frame) = live.next_frame().unwrap() {
            received.push(frame);
        }
        (live, received)
    });
    server.join().unwrap();
    assert_eq!(live.frames, 100);
    assert_eq!(live.skipped, 2, "the bad JSON and the frame without a palm");
    let e = live.last_error.unwrap().to_string();
    assert!(e.contains("palmPosition") && e.contains("missing"), "{e}");
    // The same frames a recording gives: the same pipeline downstream.
    let recorded = leap::load(&pinch_path()).unwrap();
    assert_eq!(received, recorded.frames[..100]);
}

#[test]
fn the_live_driver_steps_the_physics_through_the_stream_and_touches_what_is_there() {
    // 200 frames of the real pinch, and a cube floating (no gravity) where
    // the index fingertip is half-way through them: the hand sweeps into it.
    let frames = 200;
    let recorded = leap::load(&pinch_path()).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let head = &recorded.frames[..frames];
    let playback = Playback::new("pinch", head, &conversion, DEFAULT_GRACE).unwrap();
    let tip = playback.sample(0, 0.5 * playback.duration).unwrap().pose.fingers[1][2].b;
    let cube = ObjectDesc::cuboid("cube", Vec3::splat(0.03), 0.05, tip);
    let messages = pinch_frames()[..frames].iter().map(|f| f.to_string()).collect();
    let (url, server) = serve(messages);
    let summary = within_a_minute(move || {
        let weightless = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
        let (mut world, _) = world_with_objects(weightless, &[cube]).unwrap();
        run_live(&url, &mut world, conversion, DEFAULT_GRACE, 60.0, &mut []).unwrap()
    });
    server.join().unwrap();
    assert_eq!((summary.frames, summary.skipped, summary.hands_seen), (frames, 0, 1));
    // The physics ran through the stream: up to its last frame, then stopped.
    let dt = f64::from(InteractionConfig::default().dt);
    let last = playback.duration;
    assert!((summary.simulated - last).abs() <= 2.0 * dt, "{} s of {last} s", summary.simulated);
    assert!(summary.contacts_begun > 0, "the hand never touched the cube: {summary:?}");
    assert!(summary.objects[0].displacement > 0.001, "the cube did not move: {summary:?}");
}

#[test]
fn a_live_stream_with_a_burst_stale_frames_and_duplicate_hands_stays_calm() {
    // The first 200 frames of the real pinch, sent as a glitching service
    // would: frames 60–90 each followed by nine copies 100 µs apart (a
    // 10 kHz burst), every 20th frame followed by a stale one 30 ms old, and
    // frames 120–130 carrying their hand twice.
    let frames = pinch_frames()[..200].to_vec();
    let (mut messages, mut stale, mut doubled) = (Vec::new(), 0, 0);
    for (i, frame) in frames.iter().enumerate() {
        let mut frame = frame.clone();
        if (120..130).contains(&i) {
            let hand = frame["hands"][0].clone();
            frame["hands"].as_array_mut().unwrap().push(hand);
            doubled += 1;
        }
        messages.push(frame.to_string());
        let timestamp = frame["timestamp"].as_i64().unwrap();
        if (60..90).contains(&i) {
            for k in 1..10 {
                let mut copy = frame.clone();
                copy["timestamp"] = (timestamp + 100 * k).into();
                messages.push(copy.to_string());
            }
        }
        if i % 20 == 10 {
            let mut old = frame.clone();
            old["timestamp"] = (timestamp - 30_000).into();
            messages.push(old.to_string());
            stale += 1;
        }
    }
    let recorded = leap::load(&pinch_path()).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let playback = Playback::new("pinch", &recorded.frames[..200], &conversion, DEFAULT_GRACE);
    let tip = playback.unwrap().sample(0, 0.9).unwrap().pose.fingers[1][2].b;
    let cube = ObjectDesc::cuboid("cube", Vec3::splat(0.03), 0.05, tip);
    let (url, server) = serve(messages);
    let (summary, top) = within_a_minute(move || {
        let weightless = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
        let (mut world, _) = world_with_objects(weightless, &[cube]).unwrap();
        let mut top = 0.0f32;
        let mut calm = |step: &coulomb_hands::run::drive::StepView| {
            if let Some(bad) = step.world.first_non_finite() {
                panic!("{bad} is not finite at t = {}", step.t);
            }
            let v = step.world.object_state(coulomb_hands::ObjectId(0)).unwrap().linvel;
            top = top.max(v.length());
            Ok(())
        };
        let summary =
            run_live(&url, &mut world, conversion, DEFAULT_GRACE, 60.0, &mut [&mut calm]).unwrap();
        (summary, top)
    });
    server.join().unwrap();
    assert_eq!((summary.skipped, summary.dropped), (0, stale + doubled), "{summary:?}");
    assert!(summary.contacts_begun > 0, "the hand never touched the cube: {summary:?}");
    assert!(top <= 2.0, "the cube reached {top:.2} m/s");
}

#[test]
fn a_frame_that_jumps_far_ahead_is_dropped_and_the_stream_goes_on() {
    // Frame 50 of the real pinch claims to be 2000 s later. Taken at its
    // word, every later frame would be stale and the clock would stop
    // reading the stream.
    let mut frames = pinch_frames()[..200].to_vec();
    let t = frames[50]["timestamp"].as_i64().unwrap();
    frames[50]["timestamp"] = (t + 2_000_000_000).into();
    let messages = frames.iter().map(|f| f.to_string()).collect();
    let (url, server) = serve(messages);
    let summary = within_a_minute(move || {
        let (mut world, _) = world_with_objects(InteractionConfig::default(), &[]).unwrap();
        let conversion = Conversion::leap_desktop(Vec3::ZERO);
        run_live(&url, &mut world, conversion, DEFAULT_GRACE, 60.0, &mut []).unwrap()
    });
    server.join().unwrap();
    let recorded = leap::load(&pinch_path()).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let head = Playback::new("pinch", &recorded.frames[..200], &conversion, DEFAULT_GRACE);
    let last = head.unwrap().duration;
    assert_eq!((summary.frames, summary.dropped), (200, 1), "{summary:?}");
    assert!((summary.simulated - last).abs() < 0.01, "{} s of {last} s", summary.simulated);
}

/// Runs the built binary; returns (exit code, stdout, stderr).
fn binary(args: &[&str]) -> (Option<i32>, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_coulomb-hands"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.code(), text(out.stdout), text(out.stderr))
}

/// `live` with these arguments on `frames` of the real pinch streamed over
/// loopback; its `--json` summary.
fn live_binary(frames: usize, args: &[&str]) -> serde_json::Value {
    let messages = pinch_frames()[..frames].iter().map(|f| f.to_string()).collect();
    let (url, server) = serve(messages);
    let mut all = vec!["live".to_string(), "--url".into(), url, "--seconds".into(), "60".into()];
    all.extend(args.iter().map(|a| a.to_string()));
    all.push("--json".into());
    let (code, stdout, stderr) =
        within_a_minute(move || binary(&all.iter().map(String::as_str).collect::<Vec<_>>()));
    assert_eq!(code, Some(0), "{stderr}"); // before joining: a failed client never connects
    server.join().unwrap();
    serde_json::from_str(&stdout).unwrap_or_else(|e| panic!("{e}: {stdout}"))
}

/// The index fingertip's bone half-way through the first `frames` frames
/// of the real pinch, the device at the origin.
fn midway_index_tip(frames: usize) -> coulomb_hands::Capsule {
    let recorded = leap::load(&pinch_path()).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let playback =
        Playback::new("pinch", &recorded.frames[..frames], &conversion, DEFAULT_GRACE).unwrap();
    playback.sample(0, 0.5 * playback.duration).unwrap().pose.fingers[1][2]
}

#[test]
fn live_with_a_scene_pushes_its_object_and_records_a_session_that_replays_it() {
    // A weightless 3 cm, 50 g cube where the index fingertip is half-way
    // through 200 frames of the real pinch. Had it stayed put, the tip
    // (radius r) would reach its centre, sunk half a side plus r; the
    // contact law lets a bone sink at most the 20 % of the cube's bounding
    // diameter its force cap allows, before the capped force (γ·0.2·d,
    // 4 N here) throws a free 50 g cube off at 80 m/s². So the cube must
    // move at least half a side + r − 0.2·d.
    let frames = 200;
    let tip = midway_index_tip(frames);
    let side = 0.03f32;
    let dir = std::env::temp_dir().join(format!("coulomb-hands-live-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("scene.json");
    let cube = serde_json::json!({"name": "cube", "mass": 0.05, "material": "wood",
        "shape": {"Box": {"half_extents": [side / 2.0, side / 2.0, side / 2.0]}},
        "position": tip.b.to_array()});
    let text = serde_json::json!({"gravity": [0.0, 0.0, 0.0], "objects": [cube]});
    std::fs::write(&scene, text.to_string()).unwrap();
    let session = dir.join("session.json");
    let (scene_arg, session_arg) = (scene.display().to_string(), session.display().to_string());
    let live = live_binary(frames, &["--scene", &scene_arg, "--record", &session_arg]);
    let moved = live["objects"][0]["displacement"].as_f64().unwrap() as f32;
    let bound = side / 2.0 + tip.radius - 0.2 * side * 3f32.sqrt();
    assert!(moved > bound, "the cube moved {moved} m, less than {bound} m: {live}");
    assert!(live["contacts_begun"].as_u64().unwrap() > 0);
    // The recorded session replays to the same object, bit for bit.
    let (code, stdout, stderr) = binary(&["replay", &session_arg, "--json"]);
    assert_eq!(code, Some(0), "{stderr}");
    let replayed: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    // (Both print f32s, one by way of f64: compare them as f32.)
    let numbers = |v: &serde_json::Value| -> Vec<f32> {
        let o = &v["objects"][0];
        let mut out = vec![o["displacement"].as_f64().unwrap(), o["max_speed"].as_f64().unwrap()];
        out.extend(o["end"].as_array().unwrap().iter().map(|c| c.as_f64().unwrap()));
        out.into_iter().map(|x| x as f32).collect()
    };
    assert_eq!(numbers(&replayed), numbers(&live), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn live_object_at_puts_a_box_where_the_hand_passes() {
    // The default object: a 4 cm, 50 g wooden box, resting on the ground;
    // the device is lowered so that the index fingertip's half-way point
    // is the box's centre, and the hand, sweeping through it, moves it.
    let frames = 200;
    let tip = midway_index_tip(frames).b;
    // The device sits so that this tip is 2 cm up: the box's centre height.
    let device = Vec3::new(0.0, 0.02 - tip.y, 0.0);
    let at = Vec3::new(tip.x, 0.02, tip.z);
    let text = |v: Vec3| v.to_array().map(|c| c.to_string()).join(",");
    let (device, at) = (format!("--device={}", text(device)), format!("--object-at={}", text(at)));
    let live = live_binary(frames, &[&device, &at]);
    let object = &live["objects"][0];
    assert_eq!(object["name"], "object");
    assert!(object["displacement"].as_f64().unwrap() > 0.001, "{live}");
}

#[test]
fn live_poses_are_interpolated_on_the_physics_clock_and_short_gaps_bridged() {
    // 200 frames of the real pinch with two dropouts: frames 50–54 (about
    // 50 ms, inside the 0.1 s grace) and 120–159 (about 0.35 s, beyond it).
    // Every physics step, the live hand must be what a replay of the same
    // frames gives at that instant: interpolated between frames at 1 kHz,
    // bridged across the short gap, and lost in the long one.
    let dropped = |i: usize| (50..55).contains(&i) || (120..160).contains(&i);
    let recorded = leap::load(&pinch_path()).unwrap();
    let kept = recorded.frames[..200].iter().enumerate().filter(|(i, _)| !dropped(*i));
    let kept: Vec<_> = kept.map(|f| f.1.clone()).collect();
    let at = |i: usize| (recorded.frames[i].timestamp_us - recorded.frames[0].timestamp_us) as f64;
    let (short, long) = ((at(55) - at(49)) * 1e-6, (at(160) - at(119)) * 1e-6);
    assert!(short < DEFAULT_GRACE && long > DEFAULT_GRACE, "gaps of {short} s and {long} s");
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let playback = Playback::new("kept", &kept, &conversion, DEFAULT_GRACE).unwrap();
    let messages = pinch_frames()[..200]
        .iter()
        .enumerate()
        .filter(|(i, _)| !dropped(*i))
        .map(|(_, f)| f.to_string())
        .collect();
    let (url, server) = serve(messages);
    let (steps, between, untracked) = within_a_minute(move || {
        let dt = f64::from(InteractionConfig::default().dt);
        let (mut steps, mut between, mut untracked) = (0, 0, 0);
        let mut previous: Option<coulomb_hands::HandPose> = None;
        let mut same = |step: &coulomb_hands::run::drive::StepView| {
            let t = step.index as f64 * dt;
            let live = step.hands.iter().find(|h| h.side == coulomb_hands::Side::Right);
            let live = live.and_then(|h| h.sample.clone());
            let replayed = playback.sample(0, t);
            assert_eq!(live, replayed, "at {t} s");
            steps += 1;
            match &live {
                None => untracked += 1,
                // A pose that differs from the last step's.
                Some(s) if previous.as_ref().is_some_and(|p| *p != s.pose) => between += 1,
                Some(_) => {}
            }
            previous = live.map(|s| s.pose);
            Ok(())
        };
        let (mut world, _) = world_with_objects(InteractionConfig::default(), &[]).unwrap();
        run_live(&url, &mut world, conversion, DEFAULT_GRACE, 60.0, &mut [&mut same]).unwrap();
        (steps, between, untracked)
    });
    server.join().unwrap();
    // Lost only across the long gap: its steps, give or take one.
    let lost = (long * 1000.0).round() as i64;
    assert!((untracked as i64 - lost).abs() <= 1, "{untracked} steps untracked, not {lost}");
    // The hand moves on almost every tracked step: a pose held from frame
    // to frame (about 115 a second) would change on at most 12 % of the
    // 1000 steps a second.
    let tracked = steps - untracked;
    assert!(between as f64 > 0.9 * tracked as f64, "{between} of {tracked} steps moved the hand");
}
