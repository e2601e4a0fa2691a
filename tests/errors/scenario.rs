//! Scenario files (FileError holding HandError, KeyError and CheckError
//! messages): every error names the file and the place in it, before the
//! run; and runs that cannot measure are failed checks, not panics.

use crate::{Scratch, cli_error, frame, leap_hand, names, recording};
use coulomb_hands::Side;
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::run::scenario::check::{Check, History, Measure};
use coulomb_hands::run::scenario::script::Script;
use std::path::Path;

const CHECK: &str = r#"{"name": "h", "measure": {"kind": "height", "object": "box", "at": 0.01},
    "min": 0.0}"#;
const HAND: &str = r#"{"side": "right", "keys": [{"t": 0.0, "palm": [0, 0.3, 0]}]}"#;

const SCENARIO: &str = r#"{"name": "x", "duration": 0.01, "config": {},
    "scene": {"objects": [{"name": "box", "shape": {"Sphere": {"radius": 0.02}}, "mass": 0.1,
        "material": "wood", "position": [0, 0.1, 0]}]},
    "hands": [HAND], "checks": [CHECK]}"#;

/// A scenario of a 2 cm ball, one scripted hand and one check, with
/// `(from, to)` text replacements made.
fn text(replace: &[(&str, &str)]) -> String {
    let base = SCENARIO.replace("HAND", HAND).replace("CHECK", CHECK);
    replace.iter().fold(base, |t, (from, to)| {
        assert!(t.contains(from), "{from} is not in the scenario");
        t.replace(from, to)
    })
}

/// The error of parsing the changed scenario as `x.json` in `dir`; it
/// starts with the file.
fn error_in(dir: &Path, replace: &[(&str, &str)]) -> String {
    let e = Scenario::parse("x.json", &text(replace), dir).unwrap_err().to_string();
    assert!(e.starts_with("x.json: "), "{e}");
    e
}

fn error(replace: &[(&str, &str)]) -> String {
    error_in(Path::new("."), replace)
}

#[test]
fn the_base_scenario_is_valid() {
    let s = Scenario::parse("x.json", &text(&[]), Path::new(".")).unwrap();
    assert!(s.run(&mut []).unwrap().passed);
}

#[test]
fn unknown_names_and_files_list_what_there_is() {
    let e = Scenario::find("no-such-scenario").unwrap_err().to_string();
    let listed = "no such file, nor a shipped scenario (push, push-steady, pull, ";
    names(e, &[listed]);
    let dir = Scratch::new("scenario-find");
    let e = Scenario::find(&dir.text("")).unwrap_err().to_string();
    names(e, &[&dir.text(""), "directory"]);
    let bad = dir.file("bad.json", text(&[("\"duration\": 0.01", "\"duration\": -1")]));
    let e = Scenario::find(&bad.display().to_string()).unwrap_err().to_string();
    names(e, &[&dir.text("bad.json"), "duration: must be a positive number of seconds, got -1"]);
}

#[test]
fn json_errors_give_the_line_and_the_field() {
    let e = error(&[("\"config\": {}", "\"config\": {}, \"seed\": 1")]);
    names(e, &["x.json: line 1", "unknown field `seed`"]);
    let e = error(&[("\"config\": {}", "\"config\": {\"dt\": 0.001, \"step\": 1}")]);
    names(e, &["x.json: line 1", "unknown field `step`"]);
    let e = error(&[("\"at\": 0.01", "\"when\": 0.01")]);
    names(e, &["x.json: line ", "unknown field `when`"]);
    let e = error(&[("\"kind\": \"height\"", "\"kind\": \"depth\"")]);
    names(e, &["x.json: line ", "unknown variant `depth`"]);
    let e = error(&[("\"palm\": [0, 0.3, 0]", "\"palm\": [0, 0.3, 0], \"pose\": 1")]);
    names(e, &["x.json: line ", "unknown field `pose`"]);
    let e = error(&[(&format!(", \"checks\": [{CHECK}]"), "")]);
    names(e, &["x.json: line ", "missing field `checks`"]);
}

#[test]
fn durations_config_and_scene_are_checked_by_field() {
    let e = error(&[("\"duration\": 0.01", "\"duration\": 1e39")]);
    names(e, &["x.json: duration: must be a positive number of seconds, got inf"]);
    let e = error(&[("\"duration\": 0.01", "\"duration\": 0.0001")]);
    names(e, &["x.json: duration: must be at least one step (dt 0.001 s), got 0.0001"]);
    let e = error(&[("\"config\": {}", "\"config\": {\"dt\": 0.5}")]);
    assert!(e.starts_with("x.json: config: dt: must be in (0, 0.1] s, got 0.5"), "{e}");
    let e = error(&[("\"mass\": 0.1", "\"mass\": 0")]);
    names(e, &["x.json: object 'box': mass: ", "got 0"]);
    let e = error(&[
        ("\"objects\"", "\"gravity\": [0, 0, 0], \"objects\""),
        ("{}", r#"{"gamma": "Auto"}"#),
    ]);
    names(e, &["x.json: object 'box': gamma: \"Auto\" needs gravity", "got 0 m/s²"]);
}

#[test]
fn scripted_hands_are_checked_by_field() {
    let hand = |h: &str| error(&[(HAND, h)]);
    let e = hand(r#"{"side": "right", "keys": [], "offset": [0, 0, 0]}"#);
    names(e, &["x.json: hands[0].keys: a scripted hand needs keys (or give a recording)"]);
    let e = hand(r#"{"keys": [{"t": 0.0, "palm": [0, 0.3, 0]}]}"#);
    names(e, &["x.json: hands[0].side: a scripted hand needs \"left\" or \"right\""]);
    let e = hand(r#"{"side": "left", "keys": [{"t": 0, "palm": [0, 0, 0]}], "offset": [0, 1, 0]}"#);
    names(e, &["x.json: hands[0].offset: only for recordings"]);
    let e = hand(r#"{"side": "left", "keys": [{"t": 0, "palm": [0, 0, 0]}], "scale": 3}"#);
    names(e, &["x.json: hands[0].scale: must be in [0.5, 1.5]", "got 3"]);
    let e = hand(r#"{"side": "up", "keys": [{"t": 0, "palm": [0, 0, 0]}]}"#);
    names(e, &["x.json: line ", "unknown variant `up`"]);
}

#[test]
fn keyframes_are_checked_naming_the_key_and_field() {
    let key = |k: &str| error(&[("{\"t\": 0.0, \"palm\": [0, 0.3, 0]}", k)]);
    let e = key(r#"{"t": -1, "palm": [0, 0, 0]}"#);
    names(e, &["x.json: hands[0].keys[0].t: must be a finite time ≥ 0 s, got -1"]);
    let e = key(r#"{"t": 1, "palm": [0, 0, 0]}, {"t": 0.5, "palm": [0, 0, 0]}"#);
    names(e, &["x.json: hands[0].keys[1].t: times must increase, got 0.5 after 1"]);
    let e = key(r#"{"t": 0, "palm": [0, 2e4, 0]}"#);
    names(e, &["x.json: hands[0].keys[0].palm: must be finite and within ±10000 m", "20000"]);
    let e = key(r#"{"t": 0, "palm": [0, 0, 0], "rotation_deg": [0, 1e39, 0]}"#);
    names(e, &["x.json: hands[0].keys[0].rotation_deg: must be finite, got Vec3(0.0, inf"]);
    let e = key(r#"{"t": 0, "palm": [0, 0, 0], "curl": [0, 0, 1.5, 0, 0]}"#);
    names(e, &["x.json: hands[0].keys[0].curl: each flexion must be in [0, 1], got 1.5"]);
    let e = key(r#"{"t": 0, "palm": [0, 0, 0], "knuckle": -0.1}"#);
    names(e, &["x.json: hands[0].keys[0].knuckle: each flexion must be in [0, 1], got -0.1"]);
    let e = key(r#"{"t": 0, "palm": [0, 0, 0], "opposition": 2}"#);
    names(e, &["x.json: hands[0].keys[0].opposition: must be in [0, 1], got 2"]);
    let e = key(r#"{"t": 0, "palm": [0, 0, 0], "spread_deg": [0, 45, 0, 0]}"#);
    names(e, &["x.json: hands[0].keys[0].spread_deg: each must be within ±30°, got 45"]);
    let e = Script::new(Side::Left, vec![]).unwrap_err();
    names(e, &["keys: at least one keyframe is needed"]);
}

#[test]
fn recorded_hands_are_checked_by_field() {
    let dir = Scratch::new("scenario-recording");
    dir.file("empty.json", recording(&[frame(0, &[])]));
    dir.file("right.json", recording(&[frame(0, &[leap_hand(7)])]));
    let hand = |h: &str| error_in(&dir.0, &[(HAND, h)]);
    let e = hand(r#"{"recording": "right.json", "keys": [{"t": 0, "palm": [0, 0, 0]}]}"#);
    names(e, &["x.json: hands[0].keys: a hand is either scripted (keys) or recorded"]);
    let e = hand(r#"{"recording": "right.json", "scale": 1.2}"#);
    names(e, &["x.json: hands[0].scale: only for scripted hands"]);
    let e = hand(r#"{"recording": "right.json", "offset": [0, 1e39, 0]}"#);
    names(e, &["x.json: hands[0].offset: must be finite, got Vec3(0.0, inf, 0.0)"]);
    let e = hand(r#"{"recording": "left.json"}"#);
    names(e, &["x.json: hands[0].recording: ", &dir.text("left.json"), ": file: "]);
    let e = hand(r#"{"recording": "right.json", "side": "left"}"#);
    names(e, &["x.json: hands[0].side: the recording has no left hand"]);
    let e = hand(r#"{"recording": "empty.json"}"#);
    names(e, &["x.json: hands[0].recording: it tracks no hands"]);
    dir.file("late.json", recording(&[frame(9, &[]), frame(5, &[leap_hand(7)])]));
    let e = hand(r#"{"recording": "late.json"}"#);
    // Its only hand is in a stale frame, which playback leaves out.
    let stale = "it tracks no hands (left out: frame 1: timestamp goes backwards (5 after 9))";
    names(e, &["x.json: hands[0].recording: ", stale]);
}

#[test]
fn checks_are_checked_naming_the_check() {
    let check = |c: &str| error(&[(CHECK, c)]);
    let height = |rest: &str| {
        format!(
            r#"{{"name": "h", "measure": {{"kind": "height", "object": "box", "at": 1}}{rest}}}"#
        )
    };
    names(check(&height("")), &["x.json: checks[0] 'h': needs a bound: min, max or both"]);
    let e = check(&height(r#", "min": 0, "max": 1e39"#));
    names(e, &["x.json: checks[0] 'h': max: must be finite, got inf"]);
    let e = check(&height(r#", "min": -1e39"#).replace("\"h\"", "\"low\""));
    names(e, &["x.json: checks[0] 'low': min: must be finite, got -inf"]);
    let e = check(&height(r#", "min": 0"#).replace("\"box\"", "\"bxo\""));
    names(e, &["x.json: checks[0] 'h': no object named 'bxo' in the scene"]);
    let group = r#"{"name": "g", "measure": {"kind": "group_displacement", "prefix": "b",
        "except": ["box", "ball"], "from": 0}, "max": 1}"#;
    names(check(group), &["x.json: checks[0] 'g': no object named 'ball' in the scene"]);
    let drift = r#"{"name": "d", "measure": {"kind": "drift_in_hand", "object": "box",
        "hand": 1, "from": 0}, "max": 1}"#;
    names(check(drift), &["x.json: checks[0] 'd': hand 1: the scenario has 1 hands"]);
    let axis = r#"{"name": "a", "measure": {"kind": "displacement", "object": "box", "from": 0,
        "axis": [1, 1, 0]}, "min": 0}"#;
    let e = check(axis);
    names(e, &["x.json: checks[0] 'a': measure.axis: must be a unit vector, got Vec3(1.0, 1.0"]);
    let path = r#"{"name": "p", "measure": {"kind": "path_deviation", "object": "box",
        "path": [[0, 0]], "from": 0}, "max": 1}"#;
    let e = check(path);
    names(e, &["x.json: checks[0] 'p': measure.path: needs at least two finite [x, z] points"]);
    let e = error(&[(&format!("[{CHECK}]"), "[]")]);
    names(e, &["x.json: checks: a scenario needs at least one check"]);
}

#[test]
fn a_run_too_short_to_measure_fails_its_checks_instead_of_panicking() {
    let mut s = Scenario::parse("x.json", &text(&[]), Path::new(".")).unwrap();
    s.duration = 1.0e-6;
    assert!(s.run(&mut []).unwrap().passed, "a scenario runs at least one step");
    let check = Check {
        name: "h".into(),
        measure: Measure::Height { object: "box".into(), at: 0.0 },
        min: Some(0.0),
        max: None,
    };
    let result = check.evaluate(&History::default());
    assert!(!result.passed && result.value.is_nan(), "{result:?}");
}

#[test]
fn the_cli_names_the_checks_that_failed() {
    let dir = Scratch::new("scenario-cli");
    let high = CHECK.replace("\"min\": 0.0", "\"min\": 5.0").replace("\"h\"", "\"too high\"");
    let file = dir.file("x.json", text(&[(CHECK, &high)]));
    let e = cli_error(&["scenario", &file.display().to_string()]);
    assert_eq!(e, "failed checks: x: too high");
    let e = cli_error(&["scenario", &dir.text("x.json").replace("x.json", "y.json")]);
    names(e, &["y.json: no such file, nor a shipped scenario (push"]);
}
