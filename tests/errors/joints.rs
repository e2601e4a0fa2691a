//! Joint recordings (JSON lines): a missing joint, an unknown layout and
//! numbers that are not finite are errors naming the file, the frame (and
//! its line) and the field, from the library and from the binary.

use crate::{Scratch, cli_error, names, repo};
use coulomb_hands::input::recording;
use serde_json::{Value, json};

/// The header and the first two frames of the shipped joint recording.
fn lines() -> Vec<String> {
    let text = std::fs::read_to_string(repo("data/joints/pinch-57fps.jsonl")).unwrap();
    text.lines().take(3).map(str::to_string).collect()
}

/// The recording with frame 1's first hand changed by `change`.
fn with_hand(change: impl FnOnce(&mut Value)) -> String {
    let mut lines = lines();
    let mut frame: Value = serde_json::from_str(&lines[2]).unwrap();
    change(&mut frame["hands"][0]);
    lines[2] = frame.to_string();
    lines.join("\n")
}

fn error(text: &str) -> String {
    recording::parse("rec.jsonl", text, true).unwrap_err().to_string()
}

#[test]
fn the_unchanged_lines_load() {
    let r = recording::parse("rec.jsonl", &lines().join("\n"), false).unwrap();
    assert_eq!((r.frames.len(), r.frames[1].hands.len()), (2, 1));
    assert_eq!(r.format.to_string(), "coulomb-hands-joints 1");
}

#[test]
fn a_missing_joint_is_named_by_index_and_name() {
    let e = error(&with_hand(|h| {
        h["joints"].as_array_mut().unwrap().pop();
    }));
    names(
        e,
        &[
            "rec.jsonl: frame 1: hands[0].joints[25]: ",
            "missing joint 25 of 26 (openxr little tip) (line 3)",
        ],
    );
    let e = error(&with_hand(|h| h["joints"][7] = Value::Null));
    names(
        e,
        &["rec.jsonl: frame 1: hands[0].joints[7]: missing joint 7 of 26 (openxr index proximal)"],
    );
    let e = error(&with_hand(|h| {
        h.as_object_mut().unwrap().remove("joints");
    }));
    names(e, &["rec.jsonl: frame 1: hands[0].joints: missing (line 3)"]);
    let e = error(&with_hand(|h| {
        h["layout"] = "webxr".into();
        h.as_object_mut().unwrap().remove("radii");
        h.as_object_mut().unwrap().remove("orientations");
    }));
    names(e, &["frame 1: hands[0].joints: 26 joints, but webxr has 25"]);
}

#[test]
fn an_unknown_layout_or_field_is_named() {
    let e = error(&with_hand(|h| h["layout"] = "leap".into()));
    names(
        e,
        &[
            "rec.jsonl: frame 1: hands[0].layout: ",
            "unknown layout \"leap\" (known: openxr, webxr, mediapipe) (line 3)",
        ],
    );
    let e = error(&with_hand(|h| {
        h.as_object_mut().unwrap().remove("layout");
    }));
    names(e, &["frame 1: hands[0].layout: unknown layout nothing"]);
    let e = error(&with_hand(|h| h["wrist"] = json!([0, 0, 0])));
    names(e, &["frame 1: hands[0].wrist: unknown field (known: side, layout, joints"]);
    let e = error(&with_hand(|h| h["side"] = "both".into()));
    names(e, &["frame 1: hands[0].side: expected \"left\" or \"right\", got \"both\""]);
    let e = error(&with_hand(|h| {
        h["layout"] = "mediapipe".into();
        let joints = h["joints"].as_array_mut().unwrap();
        joints.truncate(21);
    }));
    names(e, &["frame 1: hands[0].radii: mediapipe landmarks have none; leave it out"]);
}

#[test]
fn a_confidence_out_of_range_is_named_with_its_frame() {
    let e = error(&with_hand(|h| h["confidence"] = json!(1.5)));
    names(
        e,
        &["rec.jsonl: frame 1: hands[0].confidence: absurd value 1.5 (at most 1 in size) (line 3)"],
    );
    let e = error(&with_hand(|h| h["confidence"] = json!(-0.25)));
    names(e, &["frame 1: hands[0].confidence: must be in [0, 1], got -0.25"]);
}

#[test]
fn numbers_that_are_not_finite_are_named_with_their_field() {
    // NaN and Infinity as Python's json module writes them; null as
    // JavaScript's JSON.stringify writes NaN.
    let nan = with_hand(|h| h["joints"][3][1] = "NAN_HERE".into()).replace("\"NAN_HERE\"", "NaN");
    names(
        error(&nan),
        &["rec.jsonl: frame 1: hands[0].joints[3][1]: not a finite number: NaN (line 3)"],
    );
    let inf = with_hand(|h| h["radii"][9] = "INF".into()).replace("\"INF\"", "-Infinity");
    names(error(&inf), &["frame 1: hands[0].radii[9]: not a finite number: -Infinity"]);
    let null = with_hand(|h| h["orientations"][0][2] = Value::Null);
    names(error(&null), &["frame 1: hands[0].orientations[0][2]: not a number: null"]);
    let far = with_hand(|h| h["joints"][0][0] = json!(1e6));
    names(error(&far), &["frame 1: hands[0].joints[0][0]: absurd value 1000000"]);
    let mut lines = lines();
    assert!(lines[1].contains("\"t\":0.0"), "{}", lines[1]);
    lines[1] = lines[1].replace("\"t\":0.0", "\"t\":Infinity");
    let e = error(&lines.join("\n"));
    assert!(e.contains("rec.jsonl: frame 0: t: not a finite number: Infinity (line 2)"), "{e}");
    // Out of f64's range: serde_json's own message, with the column.
    let huge = with_hand(|h| h["joints"][3][1] = "HUGE".into()).replace("\"HUGE\"", "1e999");
    names(error(&huge), &["rec.jsonl: frame 1: json: invalid JSON at column", "(line 3)"]);
}

#[test]
fn the_header_is_required_and_checked() {
    let mut lines = lines();
    let frames = lines.split_off(1).join("\n");
    names(
        error(&frames),
        &[
            "rec.jsonl: format: the first line must be the header ",
            "{\"format\":\"coulomb-hands-joints\",\"version\":1} (line 1)",
        ],
    );
    let v2 = format!("{{\"format\": \"coulomb-hands-joints\", \"version\": 2}}\n{frames}");
    names(error(&v2), &["rec.jsonl: version: unknown version 2 (known: 1) (line 1)"]);
    names(error(&lines[0]), &["rec.jsonl: frames: the recording has no frame lines"]);
}

#[test]
fn the_binary_names_the_file_frame_and_field_and_fails() {
    let dir = Scratch::new("joints-cli");
    let nan = with_hand(|h| h["joints"][3][1] = "NAN_HERE".into()).replace("\"NAN_HERE\"", "NaN");
    let file = dir.file("nan.jsonl", nan);
    let e = cli_error(&["replay", &file.display().to_string()]);
    assert_eq!(
        e,
        format!(
            "{}: frame 1: hands[0].joints[3][1]: not a finite number: NaN (line 3)",
            dir.text("nan.jsonl")
        )
    );
    let file = dir.file("layout.jsonl", with_hand(|h| h["layout"] = "leap".into()));
    let e = cli_error(&["replay", &file.display().to_string()]);
    names(e, &[&dir.text("layout.jsonl"), ": frame 1: hands[0].layout: unknown layout \"leap\""]);
    let file = dir.file(
        "short.jsonl",
        with_hand(|h| {
            h["joints"].as_array_mut().unwrap().pop();
        }),
    );
    let e = cli_error(&["replay", &file.display().to_string()]);
    names(e, &[&dir.text("short.jsonl"), ": frame 1: hands[0].joints[25]: missing joint 25"]);
}
