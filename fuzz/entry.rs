//! What each fuzz target feeds its input to. Shared, by `#[path]`, by the
//! cargo-fuzz targets (`fuzz/fuzz_targets/*.rs`) and by the corpus replay
//! test (`tests/fuzz_corpus.rs`), so both call the same public entry points
//! the same way. Every input must give `Ok` or `Err`, never a panic, and
//! whatever parses must hold only finite numbers.

use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::playback::DEFAULT_GRACE;
use coulomb_hands::input::skeleton::hand_pose;
use coulomb_hands::input::{TrackingFrame, live, mediapipe, recording};
use coulomb_hands::output::session::Session;
use coulomb_hands::pipeline::Call;
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::scene::Scene;
use coulomb_hands::scene::mesh::TriangleMesh;
use coulomb_hands::{HandPose, InteractionConfig, InteractionWorld, PoseError};
use glam::Vec3;
use std::path::{Path, PathBuf};

/// Every target, as named in `fuzz/Cargo.toml` and under `fuzz/corpus/`.
pub const TARGETS: [&str; 12] = [
    "leap_json",
    "leap_lz",
    "joints",
    "mediapipe_pbtxt",
    "live_frame",
    "session",
    "scene",
    "scenario",
    "mesh_obj",
    "mesh_stl",
    "mesh_gltf",
    "mesh_glb",
];

/// Steps a world is run for after a successful parse: enough to put every
/// body through rapier once, cheap enough for millions of inputs.
const STEPS: usize = 2;

/// Feeds `data` to `target`'s parser.
pub fn run(target: &str, data: &[u8]) {
    match target {
        "leap_json" => leap_recording("fuzz.json", data),
        "leap_lz" => leap_recording("fuzz.json.lz", data),
        "joints" => leap_recording("fuzz.jsonl", data),
        "mediapipe_pbtxt" => mediapipe_frame(data),
        "live_frame" => live_frame(data),
        "session" => session(data),
        "scene" => scene(data),
        "scenario" => scenario(data),
        "mesh_obj" => mesh("fuzz.obj", data),
        "mesh_stl" => mesh("fuzz.stl", data),
        "mesh_gltf" => mesh("fuzz.gltf", data),
        "mesh_glb" => mesh("fuzz.glb", data),
        other => panic!("unknown fuzz target {other}"),
    }
}

/// The repository's root, from the main crate or from `fuzz/`.
fn root() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    if dir.ends_with("fuzz") { dir.parent().unwrap().to_path_buf() } else { dir.to_path_buf() }
}

/// Where the scene and scenario targets resolve relative file names: the
/// shipped scenarios' folder, so seeds that name real meshes and
/// recordings load them.
fn scenarios_dir() -> PathBuf {
    root().join("scenarios")
}

/// A pose may be rejected by the world for its shape, but never hold a
/// non-finite number.
fn finite_pose(pose: &HandPose) {
    if let Err(e @ PoseError::NonFinite { .. }) = pose.validate(0) {
        panic!("{e}");
    }
}

fn check_frame(frame: &TrackingFrame) {
    for hand in &frame.hands {
        let points = hand.joints.iter().flatten().chain(hand.carps.iter().flatten());
        let vectors = [hand.palm_position, hand.palm_normal, hand.direction];
        assert!(points.chain(&vectors).all(|v| v.is_finite()), "non-finite hand: {hand:?}");
        assert!(hand.widths.iter().all(|w| w.is_finite() && *w > 0.0), "{:?}", hand.widths);
        let strengths = [hand.grab, hand.pinch];
        assert!(strengths.iter().flatten().all(|s| (0.0..=1.0).contains(s)), "{strengths:?}");
    }
}

/// A Leap recording, parsed, then played back as the replay and scenario
/// commands do: every hand posed, and sampled across the recording.
fn leap_recording(name: &str, data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(recording) = recording::parse(name, text, name.ends_with(".jsonl")) else { return };
    recording.frames.iter().for_each(check_frame);
    let Ok(playback) = recording.playback(Vec3::ZERO, DEFAULT_GRACE) else { return };
    assert!(playback.duration.is_finite() && playback.duration >= 0.0, "{}", playback.duration);
    for k in 0..playback.tracks.len() {
        for i in 0..=8 {
            let t = playback.duration * i as f64 / 8.0;
            if let Some(sample) = playback.sample(k, t) {
                finite_pose(&sample.pose);
            }
        }
    }
}

/// A MediaPipe hand landmarker result (pbtxt), read and posed both ways
/// its label can be meant.
fn mediapipe_frame(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(frame) = mediapipe::parse("fuzz.pbtxt", text) else { return };
    for label in [mediapipe::Label::Subject, mediapipe::Label::Mirrored] {
        let Ok(hand) = frame.tracked_hand("fuzz.pbtxt", 0, label) else { return };
        if let Ok(pose) = hand_pose(&hand, &Conversion::identity()) {
            finite_pose(&pose);
        }
    }
}

/// One WebSocket text message, as the live client parses it, then posed as
/// the live runner does.
fn live_frame(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(Some(frame)) = live::parse_message("ws://fuzz", 0, text) else { return };
    check_frame(&frame);
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    for hand in &frame.hands {
        if let Ok(pose) = hand_pose(hand, &conversion) {
            finite_pose(&pose);
        }
    }
}

fn check_world(world: &InteractionWorld) {
    for id in world.object_ids() {
        let s = world.object_state(id).unwrap();
        let all = [s.position, s.linvel, s.angvel, s.hand_force];
        assert!(all.iter().all(|v| v.is_finite()) && s.rotation.is_finite(), "{id}: {s:?}");
    }
}

/// A session file, then replayed for its first few steps.
fn session(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(mut session) = Session::parse("fuzz.session.json", text) else { return };
    let mut steps = 0;
    session.calls.retain(|c| {
        steps += matches!(c, Call::Step) as usize;
        steps <= STEPS
    });
    if let Ok(world) = session.replay(check_world) {
        check_world(&world);
    }
}

/// A scene file, then added to a world that runs a few steps.
fn scene(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(scene) = Scene::parse_in("fuzz.json", text, &scenarios_dir()) else { return };
    let config = InteractionConfig::default().with_scene(&scene);
    let mut world = InteractionWorld::new(config).expect("a scene's gravity is checked");
    if world.add_scene(&scene).is_err() {
        return;
    }
    for _ in 0..STEPS {
        world.step();
        check_world(&world);
    }
}

/// A scenario file, then run for its first few steps with its checks
/// evaluated.
fn scenario(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(mut scenario) = Scenario::parse("fuzz.json", text, &scenarios_dir()) else { return };
    scenario.duration = scenario.config.dt * STEPS as f32;
    let mut finite = |step: &coulomb_hands::run::drive::StepView| {
        check_world(step.world);
        Ok(())
    };
    let _ = scenario.run(&mut [&mut finite]);
}

/// A mesh file, then voxelized as a scene's `Voxels` body would be.
fn mesh(name: &str, data: &[u8]) {
    let Ok(mesh) = TriangleMesh::parse(name, data, &root().join("fuzz/no-such-dir")) else {
        return;
    };
    let (lo, hi) = mesh.bounds();
    assert!(lo.is_finite() && hi.is_finite(), "checked meshes are finite: {lo} {hi}");
    let size = (hi - lo).max_element() / 8.0;
    if let Ok(boxes) = mesh.voxel_boxes(size, coulomb_hands::scene::object::MAX_VOXEL_BOXES) {
        assert!(boxes.iter().all(|(c, h)| c.is_finite() && h.is_finite()), "{boxes:?}");
    }
}
