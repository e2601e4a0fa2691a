//! Other trackers' hands: a joint recording (JSON lines, OpenXR layout)
//! converted from a real Leap Motion recording replays the same hand, and
//! a real MediaPipe frame of a fist becomes a closed fist.

use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::mediapipe::{self, Label};
use coulomb_hands::input::playback::DEFAULT_GRACE;
use coulomb_hands::input::skeleton::hand_pose;
use coulomb_hands::input::{TrackedHand, joints, layouts, leap, recording};
use coulomb_hands::run::scenario::{Scenario, ScenarioHand};
use coulomb_hands::{HandPose, Side};
use glam::{Quat, Vec3};
use std::path::PathBuf;

fn repo(path: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(path)
}

const LEAP: &str = "data/leap/pinch-57fps.json.lz";
const JOINTS: &str = "data/joints/pinch-57fps.jsonl";

#[test]
fn the_shipped_joint_recording_is_the_converters_output() {
    // `cargo run --example leap_to_joints -- LEAP JOINTS` wrote it.
    let leap = leap::load(&repo(LEAP)).unwrap();
    let text = joints::openxr_recording(&leap.frames, &Conversion::mm_to_m());
    assert!(text == std::fs::read_to_string(repo(JOINTS)).unwrap(), "{JOINTS} is stale");
}

/// The largest distance between corresponding points of two poses: bone
/// ends, palm box corners, and the radii's difference.
fn pose_distance(a: &HandPose, b: &HandPose) -> f32 {
    let corners = |p: &HandPose| -> Vec<Vec3> {
        let (palm, e) = (p.palm, p.palm.half_extents);
        (0..8)
            .map(|i| {
                let s = |bit: usize| if i & (1 << bit) == 0 { -1.0 } else { 1.0 };
                palm.to_world(Vec3::new(s(0) * e.x, s(1) * e.y, s(2) * e.z))
            })
            .collect()
    };
    let bones = |p: &HandPose| {
        p.fingers.iter().flatten().flat_map(|c| [c.a, c.b, Vec3::splat(c.radius)]).collect()
    };
    let (ba, bb): (Vec<Vec3>, Vec<Vec3>) = (bones(a), bones(b));
    let bone = ba.iter().zip(&bb).map(|(x, y)| x.distance(*y));
    corners(a).iter().zip(corners(b)).map(|(x, y)| x.distance(y)).chain(bone).fold(0.0, f32::max)
}

#[test]
fn a_joint_recording_replays_the_same_hand_as_its_leap_original() {
    // The file stores positions to 1 µm, so each point is off by at most
    // √3 · 0.5 µm; the palm box, built from averages of such points and a
    // normal and direction stored to 1e-6, moves by a few of them. 5 µm is
    // far below anything a contact notices (its offset is 4 mm).
    let device = Vec3::new(0.1, 0.75, -0.2);
    let leap = recording::load(&repo(LEAP)).unwrap();
    let lines = recording::load(&repo(JOINTS)).unwrap();
    assert_eq!(lines.format, recording::Format::Joints(1));
    let (a, b) = (leap.playback(device, DEFAULT_GRACE).unwrap(), lines.playback(device, 0.1));
    let b = b.unwrap();
    assert_eq!((a.frames, a.tracks.len()), (b.frames, b.tracks.len()));
    assert!((a.duration - b.duration).abs() < 1e-6);
    let mut worst = 0.0f32;
    for step in 0..=(a.duration * 1000.0) as usize {
        let t = step as f64 * 1e-3;
        let (x, y) = (a.sample(0, t), b.sample(0, t));
        assert_eq!(x.is_some(), y.is_some(), "tracked in one and not the other at {t} s");
        let (Some(x), Some(y)) = (x, y) else { continue };
        worst = worst.max(pose_distance(&x.pose, &y.pose));
        assert_eq!((x.grab, x.pinch).0.is_some(), y.grab.is_some());
        assert!((x.pinch.unwrap() - y.pinch.unwrap()).abs() <= 1e-6, "pinch at {t} s");
        let confidence = (x.confidence.unwrap() - y.confidence.unwrap()).abs();
        assert!(confidence <= 1e-6, "confidence at {t} s");
    }
    assert!(worst < 5e-6, "the poses differ by up to {:.2} µm", worst * 1e6);
}

#[test]
fn a_scenario_hand_reads_a_joint_recording() {
    let text = r#"{"name": "j", "description": "a joint recording", "duration": 0.01,
        "scene": {"objects": [{"name": "cube", "mass": 0.05, "material": "wood",
            "shape": {"Box": {"half_extents": [0.02, 0.02, 0.02]}}, "position": [1, 0.02, 0]}]},
        "hands": [{"recording": "../data/joints/pinch-57fps.jsonl", "offset": [0, 0.1, 0]}],
        "checks": [{"name": "h", "min": 0,
                    "measure": {"kind": "height", "object": "cube", "at": 0.01}}]}"#;
    let s = Scenario::parse("j.json", text, &repo("scenarios")).unwrap_or_else(|e| panic!("{e}"));
    let ScenarioHand::Recording { playback, track } = &s.hands[0] else { panic!("not recorded") };
    let leap = recording::load(&repo(LEAP)).unwrap();
    let original = leap.playback(Vec3::new(0.0, 0.1, 0.0), DEFAULT_GRACE).unwrap();
    let (x, y) = (original.sample(0, 1.0).unwrap(), playback.sample(*track, 1.0).unwrap());
    assert!(pose_distance(&x.pose, &y.pose) < 5e-6);
}

/// How closed each of the four fingers is, in the palm's frame: the
/// fingertip's height above the palm face (towards the grasping side), how
/// far it lies ahead of its own knuckle along the hand, and the angle (°)
/// between the hand's forward direction and the distal phalanx.
struct Finger {
    height: f32,
    ahead: f32,
    bend_deg: f32,
    length: f32,
}

fn fingers(pose: &HandPose) -> Vec<Finger> {
    let forward = pose.palm.rotation * Vec3::Z;
    let face = pose.palm.to_world(Vec3::new(0.0, pose.palm.half_extents.y, 0.0));
    (1..5)
        .map(|f| {
            let bones = &pose.fingers[f];
            let tip = bones[2].b + (bones[2].b - bones[2].a).normalize() * bones[2].radius;
            Finger {
                height: (tip - face).dot(pose.palm.normal()),
                ahead: (tip - bones[0].a).dot(forward),
                bend_deg: forward.angle_between(bones[2].b - bones[2].a).to_degrees(),
                length: bones.iter().map(|c| c.a.distance(c.b)).sum::<f32>() + bones[2].radius,
            }
        })
        .collect()
}

/// A closed fist: every finger folded back over the palm. Its tip lies on
/// the grasping side, behind its own knuckle (the finger has turned through
/// more than 90° in all), its last phalanx points backwards (more than 90°
/// from the hand's forward direction), and it is nearer the palm face than
/// half the finger's length (a finger bent only at the knuckle would stand
/// its whole length above it).
fn is_fist(pose: &HandPose) -> bool {
    fingers(pose)
        .iter()
        .all(|f| f.height > 0.0 && f.ahead < 0.0 && f.bend_deg > 90.0 && f.height < 0.5 * f.length)
}

fn fist_frame() -> (String, mediapipe::HandLandmarks) {
    let path = repo("data/mediapipe/fist_landmarks.pbtxt");
    (path.display().to_string(), mediapipe::load(&path).unwrap_or_else(|e| panic!("{e}")))
}

#[test]
fn mediapipes_own_fist_frame_is_a_closed_fist() {
    let (name, frame) = fist_frame();
    assert_eq!(frame.handedness, Some(Side::Left), "as labelled");
    assert!(frame.landmarks.is_some(), "the image landmarks are read too");
    // A real hand's size: wrist to middle knuckle 7–11 cm for adults.
    let world = frame.world_landmarks.unwrap();
    let palm_length = world[0].distance(world[9]);
    assert!((0.07..0.11).contains(&palm_length), "palm {palm_length} m");
    // The label is MediaPipe's mirrored one: read as the subject's left
    // hand, the fingers would curl out of the back of the hand.
    let pose = |label| {
        let hand = frame.tracked_hand(&name, 0, label).unwrap();
        hand_pose(&hand, &Conversion::identity()).unwrap()
    };
    assert!(fingers(&pose(Label::Subject)).iter().all(|f| f.height < 0.0));
    let fist = pose(Label::Mirrored);
    fist.validate(0).unwrap();
    for (f, m) in fingers(&fist).iter().enumerate() {
        println!(
            "finger {}: {:.1} mm above the palm, {:.1} mm ahead of its knuckle, bent {:.0}°, \
             {:.1} mm long",
            f + 1,
            m.height * 1e3,
            m.ahead * 1e3,
            m.bend_deg,
            m.length * 1e3
        );
    }
    assert!(is_fist(&fist), "MediaPipe's fist is not a closed fist");
}

/// The joints a tracker would report for a rig pose (metres).
fn tracked(pose: &HandPose, side: Side) -> TrackedHand {
    TrackedHand {
        id: 0,
        side,
        palm_position: pose.palm.to_world(Vec3::new(0.0, pose.palm.half_extents.y, 0.0)),
        palm_normal: pose.palm.normal(),
        direction: pose.palm.rotation * Vec3::Z,
        joints: pose.fingers.map(|f| [f[0].a, f[0].b, f[1].b, f[2].b]),
        carps: None,
        widths: pose.fingers.map(|f| 2.0 * f[0].radius),
        grab: None,
        pinch: None,
        confidence: None,
    }
}

#[test]
fn an_open_hand_is_not_a_fist_by_the_same_measure() {
    let rig = HandRig::adult(Side::Left);
    let palm_down = Quat::from_rotation_x(std::f32::consts::PI);
    let (_, frame) = fist_frame();
    for (curl, fist) in [(0.0, false), (0.5, false), (1.0, true)] {
        let pose = rig.pose(Vec3::new(0.0, 0.2, 0.0), palm_down, [curl; 5]);
        assert_eq!(is_fist(&pose), fist, "the rig at curl {curl}");
        // The same hand through MediaPipe's 21 landmarks.
        let hand = tracked(&pose, Side::Left);
        let wrist = pose.palm.to_world(Vec3::new(0.0, 0.0, -pose.palm.half_extents.z));
        let landmarks = layouts::to_mediapipe(&hand, wrist);
        let back = layouts::from_mediapipe(0, Side::Left, &landmarks).unwrap();
        let pose = hand_pose(&back, &Conversion::identity()).unwrap();
        assert_eq!(is_fist(&pose), fist, "the rig at curl {curl}, as landmarks");
    }
    // MediaPipe's fist with its fingers straightened: each finger's joints
    // laid out along its knuckle's direction from the wrist.
    let mut flat = frame.world_landmarks.unwrap();
    for f in 1..5 {
        let base = 1 + 4 * f;
        let along = (flat[base] - flat[0]).normalize();
        for j in 1..4 {
            let length = frame.world_landmarks.unwrap()[base + j - 1]
                .distance(frame.world_landmarks.unwrap()[base + j]);
            flat[base + j] = flat[base + j - 1] + along * length;
        }
    }
    let open = mediapipe::HandLandmarks { world_landmarks: Some(flat), ..frame };
    let hand = open.tracked_hand("flat", 0, Label::Mirrored).unwrap();
    let pose = hand_pose(&hand, &Conversion::identity());
    assert!(!is_fist(&pose.unwrap()), "straightened landmarks");
}
