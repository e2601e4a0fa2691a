//! Hand–object captures: a bad file, frame, point, pose or mesh is an error
//! naming the file, the frame and the field; the command line names its
//! own options and prints nothing of a replay it could not finish.

use crate::{Scratch, cli_error, names, repo, run};
use coulomb_hands::input::capture;
use coulomb_hands::input::mediapipe;
use serde_json::{Value, json};

/// The real MediaPipe fist (world landmarks, metres, y down) as one frame
/// of keypoints.
fn fist() -> Value {
    let hand = mediapipe::load(&repo("data/mediapipe/fist_landmarks.pbtxt")).unwrap();
    let world = hand.world_landmarks.expect("world landmarks");
    json!(world.iter().map(|p| [p.x, p.y, p.z]).collect::<Vec<_>>())
}

/// A 4 cm cube, in the capture's metres.
const CUBE: &str = "\
v -0.02 -0.02 -0.02\nv 0.02 -0.02 -0.02\nv -0.02 0.02 -0.02\nv 0.02 0.02 -0.02\n\
v -0.02 -0.02 0.02\nv 0.02 -0.02 0.02\nv -0.02 0.02 0.02\nv 0.02 0.02 0.02\n\
f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\n\
f 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n";

/// A pose 30 cm below the tracker (y down): a row-major 4×4.
fn pose() -> Value {
    json!([1, 0, 0, 0, 0, 1, 0, 0.3, 0, 0, 1, 0, 0, 0, 0, 1])
}

/// A good two-frame capture.
fn good() -> Value {
    json!({"frame_rate_hz": 30, "units": "metres", "up": "-y",
           "hand": {"side": "right", "keypoints": [fist(), fist()]},
           "object": {"mesh": "cube.obj", "poses": [pose(), pose()]}})
}

/// `capture` with the cube beside it, read.
fn load(
    dir: &Scratch,
    capture: &Value,
) -> Result<capture::Capture, coulomb_hands::input::InputError> {
    dir.file("cube.obj", CUBE);
    capture::load(&dir.file("c.json", capture.to_string()))
}

/// The error `change` makes of the good capture.
#[track_caller]
fn error(change: impl FnOnce(&mut Value)) -> coulomb_hands::input::InputError {
    let dir = Scratch::new("capture");
    let mut c = good();
    change(&mut c);
    load(&dir, &c).expect_err("a bad capture")
}

#[test]
fn a_good_capture_reads() {
    let dir = Scratch::new("capture-good");
    let c = load(&dir, &good()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((c.poses.len(), c.hand.keypoints.len()), (2, 2));
    // y down: 30 cm below the tracker is 30 cm down in the world.
    assert!((c.poses[0].0.y + 0.3).abs() < 1e-6, "{:?}", c.poses[0]);
}

#[test]
fn a_capture_names_the_field_and_frame_it_cannot_use() {
    let e = error(|c| c["hand"]["keypoints"] = json!([fist(), fist(), fist()]));
    assert_eq!((e.field.as_str(), e.frame), ("hand.keypoints", None));
    names(e, &["c.json", "3 frames, but object.poses has 2"]);
    let e = error(|c| c["hand"]["keypoints"][1].as_array_mut().unwrap().truncate(20));
    assert_eq!((e.field.as_str(), e.frame), ("hand.keypoints", Some(1)));
    names(e, &["20 points, expected 21"]);
    let e = error(|c| c["hand"]["keypoints"][0][3] = json!([0.0, 1e39, 0.0]));
    assert_eq!((e.field.as_str(), e.frame), ("hand.keypoints[3]", Some(0)));
    names(e, &["not 3 finite numbers"]);
    let e = error(|c| c["hand"]["vertices"] = json!([fist(), fist()]));
    names(e, &["hand", "exactly one of vertices"]);
    let e = error(|c| {
        c["hand"]["vertices"] = c["hand"]["keypoints"].take();
        c["hand"].as_object_mut().unwrap().remove("keypoints");
    });
    names(e, &["hand.vertices", "21 points, expected 778"]);
    let e = error(|c| c["object"]["poses"][1] = json!([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]));
    assert_eq!((e.field.as_str(), e.frame), ("object.poses", Some(1)));
    names(e, &["12 numbers, expected 16"]);
    let e = error(|c| c["object"]["poses"][0][0] = json!(2.0));
    names(e, &["object.poses", "not a rotation"]);
    let e = error(|c| c["object"]["poses"][0][15] = json!(0.5));
    names(e, &["object.poses", "last row"]);
    let e = error(|c| {
        c["object"]["poses"] = json!([pose()]);
        c["hand"]["keypoints"] = json!([fist()]);
    });
    names(e, &["object.poses", "1 frames; a replay needs 2"]);
    names(error(|c| c["units"] = json!("furlongs")), &["units", "furlongs"]);
    names(error(|c| c["up"] = json!("sideways")), &["up", "sideways"]);
    names(error(|c| c["hand"]["side"] = json!("both")), &["hand.side", "both"]);
    names(error(|c| c["frame_rate_hz"] = json!(0)), &["frame_rate_hz", "0"]);
    names(
        error(|c| c.as_object_mut().unwrap().remove("object").map(drop).unwrap()),
        &["c.json", "object"],
    );
}

#[test]
fn a_capture_names_its_missing_or_broken_mesh_and_an_empty_file() {
    let dir = Scratch::new("capture-mesh");
    let mut c = good();
    c["object"]["mesh"] = json!("gone.obj");
    let e = capture::load(&dir.file("c.json", c.to_string())).unwrap_err();
    assert_eq!(e.field, "object.mesh");
    names(e, &["c.json", "gone.obj"]);
    dir.file("broken.obj", "v 0 0 0\nf 1 2 3\n");
    c["object"]["mesh"] = json!("broken.obj");
    let e = capture::load(&dir.file("c.json", c.to_string())).unwrap_err();
    names(e, &["c.json", "object.mesh", "broken.obj"]);
    let e = capture::load(&dir.file("empty.json", "")).unwrap_err();
    names(e, &["empty.json", "file", "empty"]);
}

#[test]
fn replay_of_a_capture_checks_its_options_and_prints_nothing_it_could_not_finish() {
    let dir = Scratch::new("capture-cli");
    dir.file("cube.obj", CUBE);
    let mut bad = good();
    bad["object"]["poses"][1][15] = json!(2);
    let file = dir.file("bad.json", bad.to_string());
    let (code, stdout, stderr) = run(&["replay", file.to_str().unwrap(), "--json"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stdout.is_empty(), "half a report: {stdout}");
    names(stderr, &["bad.json", "frame 1", "object.poses"]);
    let good = dir.file("good.json", good().to_string());
    let good = good.to_str().unwrap();
    names(cli_error(&["replay", good, "--mass", "0.2,-1"]), &["mass: -1 kg"]);
    names(
        cli_error(&["replay", good, "--material", "wood,unobtainium"]),
        &["material: unknown material \"unobtainium\"", "known: ", "aluminium"],
    );
    names(cli_error(&["replay", good, "--trace", "t.jsonl"]), &["--trace"]);
    let leap = repo("data/leap/pinch.json.lz");
    names(cli_error(&["replay", leap.to_str().unwrap(), "--mass", "0.2"]), &["--mass", "capture"]);
    let surface = cli_error(&["replay", leap.to_str().unwrap(), "--hand-surface", "body"]);
    names(surface, &["--hand-surface", "capture"]);
    let (code, _, stderr) = run(&["replay", good, "--hand-surface", "skin"]);
    assert_eq!(code, Some(2), "clap's usage error: {stderr}");
    names(stderr, &["--hand-surface", "expected \"body\" or \"exact\", got \"skin\""]);
}

#[test]
fn a_capture_whose_mesh_is_not_closed_is_touched_on_its_parts_and_says_why() {
    // The cube without its last face has a hole: no inside to tell a
    // finger from, so the hand touches the convex parts the engine moves.
    let dir = Scratch::new("capture-open");
    let open = CUBE.trim_end().rsplit_once('\n').unwrap().0;
    dir.file("cube.obj", format!("{open}\n"));
    let file = dir.file("open.json", good().to_string());
    let (code, stdout, stderr) = run(&["replay", file.to_str().unwrap(), "--json"]);
    assert_eq!(code, Some(0), "{stderr}");
    let report: Value = serde_json::from_str(&stdout).unwrap();
    let touched = report["capture"]["touched"].as_str().unwrap();
    names(touched.to_string(), &["convex parts", "the mesh is not closed: 3 of its edges"]);
    dir.file("cube.obj", CUBE);
    let (_, closed, _) = run(&["replay", file.to_str().unwrap(), "--hand-surface", "exact"]);
    names(closed, &["the hand touches the mesh's exact surface"]);
    let (_, asked, _) = run(&["replay", file.to_str().unwrap(), "--hand-surface", "body"]);
    names(asked, &["the hand touches the mesh's convex parts, as asked"]);
}
