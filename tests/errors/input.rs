//! Tracking input: InputError (recordings, their frames, playback),
//! SkeletonError and LayoutError. Each names the source, the frame and the
//! JSON path, or the hand and joint.

use crate::{Scratch, frame, leap_hand, names, recording};
use coulomb_hands::Side;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::layouts::{self, Joint};
use coulomb_hands::input::leap::{self, from_json, parse};
use coulomb_hands::input::playback::Playback;
use coulomb_hands::input::skeleton::hand_pose;
use glam::{Quat, Vec3};
use serde_json::{Value, json};

fn parse_error(root: &Value) -> String {
    from_json("rec.json", root).unwrap_err().to_string()
}

#[test]
fn unreadable_recordings_name_the_file_and_the_layer() {
    let dir = Scratch::new("input-files");
    let e = leap::load(&dir.path("gone.json.lz")).unwrap_err();
    assert_eq!((e.field.as_str(), e.frame), ("file", None));
    names(e, &[&dir.text("gone.json.lz"), ": file: "]);
    let e = leap::load(&dir.file("latin1.json", [b'{', 0xE9, b'}'])).unwrap_err();
    names(e, &["latin1.json: file: not UTF-8 text"]);
    let e = parse("x.json.lz", "this is not base64 LZ data at all!").unwrap_err();
    names(e, &["x.json.lz: lz-string: not valid LZ-String base64 data"]);
    let lone_surrogate = lz_str::compress_to_base64(&[0xD800u16, 0x41][..]);
    let e = parse("x.json.lz", &lone_surrogate).unwrap_err();
    names(e, &["x.json.lz: lz-string: decompressed data is not valid text"]);
    let e = parse("x.json", "{\"metadata\": ").unwrap_err();
    names(e.clone(), &["x.json: json: invalid JSON, line 1 column 12: EOF while parsing"]);
    assert_eq!(e.to_string().matches("line").count(), 1, "the place is said once: {e}");
}

#[test]
fn garbage_is_never_a_panic() {
    for text in ["", "=", "A", "AAAA", "////", "====", "\u{1F600}", "{", "[1, 2]", "null"] {
        assert!(parse("g.json.lz", text).is_err(), "{text:?}");
    }
}

#[test]
fn the_recording_envelope_is_checked_field_by_field() {
    names(parse_error(&json!({})), &["rec.json: metadata: missing"]);
    let e = parse_error(&json!({"metadata": {"formatVersion": "1"}}));
    names(e, &["rec.json: metadata.formatVersion: missing or not a number"]);
    let e = parse_error(&json!({"metadata": {"formatVersion": 1}, "frames": {}}));
    names(e, &["rec.json: frames: missing or not an array"]);
    let e = parse_error(&json!({"metadata": {"formatVersion": 3}, "frames": []}));
    names(e, &["rec.json: metadata.formatVersion: unknown format version 3 (known: 0.1, 1, 2)"]);
    let e = parse_error(&json!({"metadata": {"formatVersion": 1}, "frames": []}));
    names(e, &["rec.json: frames: the recording has no frames"]);
    let e = parse_error(&json!({"metadata": {"formatVersion": 2}, "frames": []}));
    names(e, &["rec.json: frame 0: header: format 2 needs a header frame"]);
}

fn packed(header: Value, frame: Value) -> String {
    parse_error(&json!({"metadata": {"formatVersion": 2}, "frames": [header, frame]}))
}

#[test]
fn format_2_packing_errors_name_the_frame_and_the_path() {
    let e = packed(json!({"timestamp": 0}), json!([1]));
    names(e, &["rec.json: frame 0: header: format 2 header is not an array"]);
    let e = packed(json!(["timestamp"]), json!({"timestamp": 1}));
    names(e, &["rec.json: frame 1: frame: packed value is not an array"]);
    let e = packed(json!(["timestamp", "hands"]), json!([1]));
    names(e, &["frame 1: frame: packed array has 1 values but the header has 2 keys"]);
    let e = packed(json!(["timestamp", 5]), json!([1, 2]));
    names(e, &["rec.json: frame 0: frame: header entries must be keys or objects"]);
    let e = packed(json!(["timestamp", {"hands": "id"}]), json!([1, []]));
    names(e, &["rec.json: frame 0: frame.hands: header entry must list keys, got \"id\""]);
    let e = packed(json!(["timestamp", {"hands": [["id", "type"]]}]), json!([1, 5]));
    names(e, &["rec.json: frame 1: frame.hands: packed list is not an array"]);
    let e = packed(json!(["timestamp", {"hands": [["id", "type"]]}]), json!([1, [[7]]]));
    names(e, &["frame 1: frame.hands[0]: packed array has 1 values but the header has 2 keys"]);
    let e = packed(json!(["timestamp", {"hand": ["id", "type"]}]), json!([1, [7, "right", 0]]));
    names(e, &["frame 1: frame.hand: packed array has 3 values but the header has 2 keys"]);
}

/// The error of a one-frame recording whose frame (timestamp 0, one hand
/// with id 7) is changed; it names `rec.json` and frame 0.
fn frame_error(change: impl FnOnce(&mut Value)) -> String {
    let mut root: Value = serde_json::from_str(&recording(&[frame(0, &[leap_hand(7)])])).unwrap();
    from_json("rec.json", &root).expect("the unchanged frame is valid");
    change(&mut root["frames"][0]);
    let e = parse_error(&root);
    names(e.clone(), &["rec.json: frame 0: "]);
    e
}

#[test]
fn frame_fields_are_named_by_their_json_path() {
    let e = frame_error(|f| f["timestamp"] = json!(1.5));
    names(e, &["frame 0: timestamp: missing or not an integer (µs)"]);
    let e = frame_error(|f| drop(f["hands"][0].as_object_mut().unwrap().remove("id")));
    names(e, &["frame 0: hands[0].id: missing or not an integer"]);
    let e = frame_error(|f| f["hands"][0]["type"] = json!("middle"));
    names(e, &["frame 0: hands[0].type: expected \"left\" or \"right\", got \"middle\""]);
    let e = frame_error(|f| drop(f["hands"][0].as_object_mut().unwrap().remove("type")));
    names(e, &["frame 0: hands[0].type: expected \"left\" or \"right\", got nothing"]);
    let e = frame_error(|f| drop(f["hands"][0].as_object_mut().unwrap().remove("palmPosition")));
    names(e, &["frame 0: hands[0].palmPosition: missing"]);
    let e = frame_error(|f| f["hands"][0]["palmNormal"] = json!([0, 0]));
    names(e, &["frame 0: hands[0].palmNormal: not a 3-vector: [0,0]"]);
    let e = frame_error(|f| f["hands"][0]["direction"] = json!([0, 0, 0]));
    names(e, &["frame 0: hands[0].direction: zero-length direction"]);
    let e = frame_error(|f| f["hands"][0]["palmPosition"] = json!([0.0, "x", 0.0]));
    names(e, &["frame 0: hands[0].palmPosition[1]: not a number: \"x\""]);
    let e = frame_error(|f| f["pointables"][2]["tipPosition"] = json!([0.0, 1.0e12, 0.0]));
    names(e, &["frame 0: pointables[2].tipPosition[1]: absurd value 1000000000000"]);
    let e = frame_error(|f| f["pointables"].as_array_mut().unwrap().truncate(3));
    names(e, &["frame 0: hands[0].fingers: finger 3 of hand 7 is missing"]);
    // The replay finds closings from the strengths: out of 0..1, refused.
    let e = frame_error(|f| f["hands"][0]["grabStrength"] = json!(1.25));
    names(e, &["frame 0: hands[0].grabStrength: must be in [0, 1], got 1.25"]);
    let e = frame_error(|f| f["hands"][0]["pinchStrength"] = json!([0.5]));
    names(e, &["frame 0: hands[0].pinchStrength: not a number: [0.5]"]);
}

#[test]
fn pointable_fields_are_named_by_their_json_path() {
    let e = frame_error(|f| {
        let p = f["pointables"][1].as_object_mut().unwrap();
        p.remove("type");
        p.remove("id");
    });
    names(e, &["frame 0: pointables[1].type: missing finger type and id"]);
    let e = frame_error(|f| f["pointables"][1]["type"] = json!(7));
    names(e, &["frame 0: pointables[1].type: finger type 7 is not 0..4"]);
    let e =
        frame_error(|f| drop(f["pointables"][4].as_object_mut().unwrap().remove("dipPosition")));
    names(e, &["frame 0: pointables[4].dipPosition: missing"]);
    let e = frame_error(|f| f["pointables"][3]["carpPosition"] = json!("wrist"));
    names(e, &["frame 0: pointables[3].carpPosition: not a 3-vector: \"wrist\""]);
    let e = frame_error(|f| f["pointables"][0]["width"] = json!(-3));
    names(e, &["frame 0: pointables[0].width: must be positive, got -3"]);
    let e = frame_error(|f| f["pointables"][0]["width"] = json!("wide"));
    names(e, &["frame 0: pointables[0].width: not a number: \"wide\""]);
}

fn playback(frames: &[Value]) -> Result<Playback, String> {
    let rec = from_json("rec.json", &serde_json::from_str(&recording(frames)).unwrap()).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    Playback::new("rec.json", &rec.frames, &conversion, 0.1).map_err(|e| e.to_string())
}

fn playback_error(frames: &[Value]) -> String {
    playback(frames).unwrap_err()
}

/// What playback left out of `frames`, one line each.
fn left_out(frames: &[Value]) -> String {
    let skipped = playback(frames).unwrap().skipped;
    skipped.iter().map(|s| s.to_string()).collect::<Vec<_>>().join("\n")
}

#[test]
fn playback_names_the_frame_whose_time_or_hand_is_wrong() {
    let hand = leap_hand(7);
    // A stale frame is a tracking glitch: left out, and listed.
    let e =
        left_out(&[frame(5000, &[]), frame(6000, &[]), frame(4000, std::slice::from_ref(&hand))]);
    names(e, &["frame 2: timestamp goes backwards (4000 after 6000)"]);
    // So is one corrupt frame far ahead: the frames after it are kept.
    let at = |t: i64| frame(t, std::slice::from_ref(&hand));
    let frames = [at(0), at(10_000), at(3_000_000_000), at(20_000), at(30_000)];
    let e = left_out(&frames);
    names(e, &["frame 2: timestamp jumps ahead (3000000000 after 10000), and frame 3 comes back"]);
    let kept = playback(&frames).unwrap();
    assert_eq!((kept.duration, kept.skipped.len()), (0.03, 1), "{:?}", kept.skipped);
    let e = playback_error(&[frame(0, &[]), frame(3_600_000_001, &[])]);
    names(
        e,
        &["rec.json: frame 1: timestamp: 3600000001 µs is more than 3600 s", "first frame's 0"],
    );
    // Timestamps too far apart to subtract are the same error, not an overflow.
    // A negative timestamp is refused when the frame is read.
    let text = recording(&[frame(i64::MIN, &[]), frame(i64::MAX, &[])]);
    let e = from_json("rec.json", &serde_json::from_str(&text).unwrap()).unwrap_err();
    names(e, &["rec.json: frame 0: timestamp: must be ≥ 0 µs, got -9223372036854775808"]);
    let mut twisted = hand.clone();
    twisted.0["direction"] = json!([0.0, -1.0, 0.0]);
    let e = playback_error(&[frame(0, std::slice::from_ref(&hand)), frame(1000, &[twisted])]);
    names(e, &["rec.json: frame 1: hands[0]: hand 7: palm normal and direction are parallel"]);
    let mut folded = hand;
    folded.1[2]["pipPosition"] = folded.1[2]["mcpPosition"].clone();
    // So is a bone collapsed to a point.
    let e = left_out(&[frame(0, &[folded])]);
    names(e, &["frame 0 hands[0]: hand 0: bone middle-proximal: zero-length bone"]);
}

#[test]
fn a_grace_period_that_is_negative_or_not_a_number_is_named() {
    let rec = from_json("rec.json", &serde_json::from_str(&recording(&[frame(0, &[])])).unwrap());
    let rec = rec.unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    for grace in [-0.05, f64::NAN, f64::INFINITY] {
        let e = Playback::new("rec.json", &rec.frames, &conversion, grace).unwrap_err();
        names(e, &["rec.json: grace: must be a finite number ≥ 0 s, got"]);
    }
}

fn tracked() -> coulomb_hands::input::TrackedHand {
    let rec = from_json(
        "rec.json",
        &serde_json::from_str(&recording(&[frame(0, &[leap_hand(7)])])).unwrap(),
    )
    .unwrap();
    rec.frames[0].hands[0].clone()
}

#[test]
fn skeleton_errors_name_the_tracker_hand() {
    let mut hand = tracked();
    hand.widths[2] = f32::NAN;
    let e = hand_pose(&hand, &Conversion::mm_to_m()).unwrap_err();
    assert_eq!(e.hand, 7);
    names(e, &["hand 7: finger 2 width is not finite"]);
    let mut hand = tracked();
    hand.direction = Vec3::ZERO;
    let e = hand_pose(&hand, &Conversion::mm_to_m()).unwrap_err();
    names(e, &["hand 7: palm normal and direction are parallel or zero"]);
}

#[test]
fn layout_errors_name_the_layout_and_the_joint() {
    let joint = Joint { position: Vec3::ZERO, orientation: Quat::IDENTITY, radius: 0.01 };
    let mut openxr = [joint; layouts::openxr::COUNT];
    openxr[9].position.y = f32::NAN;
    let e = layouts::from_openxr(1, Side::Right, &openxr).unwrap_err();
    names(e, &["openxr joint 9: position Vec3(0.0, NaN, 0.0) is not finite"]);
    let mut webxr = [joint; layouts::webxr::COUNT];
    webxr[24].radius = -0.01;
    let e = layouts::from_webxr(1, Side::Left, &webxr).unwrap_err();
    names(e, &["webxr joint 24: radius -0.01 is not a finite non-negative number"]);
    let mut mediapipe = [Vec3::ZERO; layouts::mediapipe::COUNT];
    mediapipe[0].z = f32::INFINITY;
    let e = layouts::from_mediapipe(1, Side::Left, &mediapipe).unwrap_err();
    names(e, &["mediapipe joint 0: position ", "inf", "is not finite"]);
}
