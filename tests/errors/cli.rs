//! The command line: argument validation (clap, with the binary's own
//! parsers and GraspObjectError), and the RunError of each command, each
//! naming the argument, file or value that is wrong.

use crate::{Scratch, cli_error, frame, leap_hand, names, recording, repo, run, usage_error};
use coulomb_hands::run::replay::{GraspObject, GraspObjectError};

fn pinch() -> String {
    repo("data/leap/pinch.json.lz").display().to_string()
}

#[test]
fn grasp_objects_name_the_part_that_is_wrong() {
    let parse = |s: &str| s.parse::<GraspObject>().unwrap_err();
    let e = parse("box:0.04");
    assert_eq!(e, GraspObjectError::Form("box:0.04".into()));
    names(e, &["expected SHAPE:SIZE_M:MASS_KG, e.g. box:0.045:0.05, got \"box:0.04\""]);
    names(parse("cube:0.04:0.05"), &["unknown shape \"cube\" (box or sphere)"]);
    names(parse("box:-0.04:0.05"), &["SIZE_M must be a positive number, got \"-0.04\""]);
    names(parse("sphere:0.04:heavy"), &["MASS_KG must be a positive number, got \"heavy\""]);
    names(parse("sphere:0.04:inf"), &["MASS_KG must be a positive number, got \"inf\""]);
    let e =
        usage_error(&["replay", "--object-at", "grasp", "--object", "ball:0.04:0.05", &pinch()]);
    names(e, &["'ball:0.04:0.05'", "--object", "unknown shape \"ball\""]);
    let e = usage_error(&["replay", "--object-at", "grip", &pinch()]);
    names(e, &["'grip'", "--object-at", "expected \"grasp\" or x,y,z in metres"]);
}

#[test]
fn the_binarys_own_parsers_name_the_value() {
    let e = usage_error(&["replay", "--device", "1,x,3", &pinch()]);
    names(e, &["'1,x,3'", "--device", "expected three finite numbers \"x,y,z\", got \"1,x,3\""]);
    let e = usage_error(&["replay", "--device", "0,0", &pinch()]);
    names(e, &["--device", "expected three finite numbers \"x,y,z\", got \"0,0\""]);
    let e = usage_error(&["live", "--device", "0,inf,0"]);
    names(e, &["--device", "got \"0,inf,0\""]);
    let e = usage_error(&["replay", "--gamma=-1", &pinch()]);
    names(e, &["--gamma", "expected \"auto\" or a positive number of N/m, got \"-1\""]);
    let e = usage_error(&["replay", "--gamma", "stiff", &pinch()]);
    names(e, &["--gamma", "got \"stiff\""]);
}

#[test]
fn clap_names_missing_and_conflicting_arguments() {
    names(usage_error(&["scenario"]), &["required arguments", "<SCENARIO>"]);
    names(usage_error(&["scenario", "--all", "push"]), &["'--all'", "'[SCENARIO]'"]);
    names(usage_error(&["scenario", "--all", "--trace", "t.jsonl"]), &["'--trace"]);
    names(usage_error(&["replay"]), &["<FILE>"]);
    names(usage_error(&["bench", "--steps", "many"]), &["'many'", "--steps"]);
    names(usage_error(&["fly"]), &["unrecognized subcommand 'fly'"]);
}

#[test]
fn bad_recordings_name_the_file_frame_and_field() {
    let dir = Scratch::new("cli-recording");
    let e = cli_error(&["replay", &dir.text("gone.json.lz")]);
    assert_eq!(
        e,
        format!("{}: file: No such file or directory (os error 2)", dir.text("gone.json.lz"))
    );
    let mut hand = leap_hand(7);
    hand.0["type"] = "both".into();
    let file = dir.file("r.json", recording(&[frame(0, &[]), frame(1000, &[hand])]));
    let e = cli_error(&["replay", &file.display().to_string()]);
    names(e, &[&dir.text("r.json"), ": frame 1: hands[0].type: ", "got \"both\""]);
    let long = dir.file("long.json", recording(&[frame(0, &[]), frame(i64::MAX, &[])]));
    let e = cli_error(&["replay", &long.display().to_string()]);
    names(e, &["long.json: frame 1: timestamp: ", "more than 3600 s"]);
}

#[test]
fn objects_at_closings_the_recording_lacks_or_that_cannot_exist() {
    let dir = Scratch::new("cli-grasp");
    let empty = dir.file("empty.json", recording(&[frame(0, &[]), frame(1000, &[])]));
    let empty = empty.display().to_string();
    // No hand closes: the replay runs and says so.
    let (code, stdout, stderr) = run(&["replay", "--object-at", "grasp", &empty]);
    assert_eq!(code, Some(0), "{stderr}");
    names(&stdout, &["closings: 0 (no hand closes"]);
    // An object that cannot exist is refused before the replay, closings or not.
    let one = dir.file("one.json", recording(&[frame(0, &[leap_hand(7)])]));
    let huge = ["replay", "--object-at", "grasp", "--object", "box:1e30:0.05"];
    let e = cli_error(&[&huge[..], &[&one.display().to_string()]].concat());
    names(e, &["object 'closing-1': shape.half_extents: must be finite and within ±10000 m"]);
    let e = cli_error(&[&huge[..], &[&empty]].concat());
    names(e, &["object 'closing-1': shape.half_extents"]);
    let e = cli_error(&["replay", "--object-at", "grasp", "--loop", "1s", &empty]);
    assert_eq!(e, "the recording has 0 grasps held long enough to judge, so there is no grasp 1");
}

#[test]
fn outputs_that_cannot_be_written_are_named() {
    let dir = Scratch::new("cli-outputs");
    let one = dir.file("one.json", recording(&[frame(0, &[leap_hand(7)])]));
    let one = one.display().to_string();
    let trace = dir.text("no-dir/trace.jsonl");
    let e = cli_error(&["replay", "--trace", &trace, &one]);
    assert_eq!(e, format!("output: {trace}: No such file or directory (os error 2)"));
    let e = cli_error(&["scenario", "push", "--trace", &trace]);
    assert_eq!(e, format!("output: {trace}: No such file or directory (os error 2)"));
    // Named before the run too: a folder, and a file taken for a folder.
    std::fs::create_dir(dir.path("traces")).expect("a folder");
    let e = cli_error(&["replay", "--trace", &dir.text("traces"), &one]);
    assert_eq!(e, format!("output: {}: is a directory", dir.text("traces")));
    let under_a_file = format!("{one}/trace.jsonl");
    let e = cli_error(&["scenario", "push", "--trace", &under_a_file]);
    assert_eq!(e, format!("output: {under_a_file}: its parent is not a directory"));
    let record = dir.text("no-dir/session.json");
    let e = cli_error(&["replay", "--record", &record, &one]);
    assert_eq!(e, format!("{record}: No such file or directory (os error 2)"));
    let out = dir.file("meshes", "a file, not a directory");
    let e = cli_error(&["mesh", "--out", &out.display().to_string()]);
    names(e, &[&dir.text("meshes"), "exists"]);
}

#[test]
fn a_run_that_fails_before_its_first_step_leaves_its_trace_path_as_it_was() {
    let dir = Scratch::new("cli-trace-kept");
    let one = dir.file("one.json", recording(&[frame(0, &[leap_hand(7)])]));
    let one = one.display().to_string();
    let earlier = "{\"t\":0.25}\n";
    let kept = dir.file("kept.jsonl", earlier);
    let unborn = dir.path("unborn.jsonl");
    for trace in [&kept, &unborn] {
        // The object cannot exist, so the replay fails before its first step.
        let trace = trace.display().to_string();
        let e = cli_error(&[
            "replay",
            "--object-at",
            "grasp",
            "--object",
            "box:1e30:0.05",
            "--trace",
            &trace,
            &one,
        ]);
        names(e, &["object 'closing-1': shape.half_extents"]);
    }
    assert_eq!(std::fs::read_to_string(&kept).unwrap(), earlier);
    assert!(!unborn.exists(), "a failed run left {}", unborn.display());
    // The same replay that runs writes its trace: a line per step.
    let (code, _, stderr) = run(&["replay", "--trace", &unborn.display().to_string(), &one]);
    assert_eq!(code, Some(0), "{stderr}");
    let lines = std::fs::read_to_string(&unborn).unwrap().lines().count();
    assert!(lines > 0, "no trace lines");
}

#[cfg(target_os = "linux")]
#[test]
fn a_full_disk_while_tracing_names_the_trace_file() {
    let dir = Scratch::new("cli-full");
    let one = dir.file("one.json", recording(&[frame(0, &[leap_hand(7)])]));
    let e = cli_error(&["replay", "--trace", "/dev/full", &one.display().to_string()]);
    assert_eq!(e, "output: /dev/full: No space left on device (os error 28)");
}

#[test]
fn a_live_service_that_is_not_there_is_named() {
    // A port that was free a moment ago: nothing listens on it.
    let port = std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    let url = format!("ws://127.0.0.1:{port}/v6.json");
    let e = cli_error(&["live", "--url", &url, "--seconds", "0.01"]);
    names(e, &[&format!("{url}: connection: ")]);
    let e = cli_error(&["live", "--url", "http://127.0.0.1/v6.json", "--seconds", "0.01"]);
    names(e, &["http://127.0.0.1/v6.json: connection: ", "scheme"]);
}

#[test]
fn live_objects_and_scenes_are_checked_before_connecting() {
    let e = usage_error(&["live", "--object", "sphere:0.03:0.02"]);
    names(e, &["required arguments were not provided", "--object-at"]);
    let e = usage_error(&["live", "--object-at", "0,0.1"]);
    names(e, &["'0,0.1'", "--object-at", "expected \"grasp\" or x,y,z in metres"]);
    let e = cli_error(&["live", "--object-at", "grasp"]);
    names(e, &["--object-at grasp needs a hand's closings", "put the object at x,y,z"]);
    let e = usage_error(&["live", "--object-at", "0,0.1,0", "--object", "cube:0.04:0.05"]);
    names(e, &["--object", "unknown shape \"cube\""]);
    let dir = Scratch::new("cli-live");
    let e = cli_error(&["live", "--scene", &dir.text("gone.json")]);
    names(e, &[&dir.text("gone.json"), "No such file"]);
}

#[test]
fn replay_lists_the_tracking_glitches_it_left_out() {
    // A stale frame and a hand given twice: the replay runs, and says what
    // it left out, in text and in JSON.
    let dir = Scratch::new("cli-glitches");
    let hand = leap_hand(3);
    let frames = [
        frame(0, std::slice::from_ref(&hand)),
        frame(10_000, &[hand.clone(), hand.clone()]),
        frame(4_000, std::slice::from_ref(&hand)),
        frame(20_000, std::slice::from_ref(&hand)),
    ];
    let file = dir.file("glitchy.json", recording(&frames)).display().to_string();
    let (code, stdout, stderr) = run(&["replay", &file]);
    assert_eq!(code, Some(0), "{stderr}");
    names(
        &stdout,
        &[
            "left out 2 tracking glitches:",
            "  frame 1 hands[1]: another Right hand with id 3",
            "  frame 2: timestamp goes backwards (4000 after 10000)",
        ],
    );
    let (_, json, _) = run(&["replay", &file, "--json"]);
    names(&json, &["\"skipped\": [", "frame 2: timestamp goes backwards"]);
}

#[test]
fn numbers_out_of_range_are_named_with_their_argument() {
    let e = usage_error(&["demo", "--every", "0"]);
    names(e, &["'--every <EVERY>'", "must be a finite number > 0, got 0"]);
    let e = usage_error(&["demo", "--every", "nan"]);
    names(e, &["'--every <EVERY>'", "got nan"]);
    let e = usage_error(&["replay", "data/leap/pinch.json.lz", "--grace=-0.5"]);
    names(e, &["'--grace <GRACE>'", "must be a finite number ≥ 0, got -0.5"]);
    let e = usage_error(&["bench", "--boxes", "17"]);
    names(e, &["'--boxes <BOXES>'", "17 is not in 1..=16"]);
    let e = usage_error(&["live", "--seconds=-3"]);
    names(e, &["'--seconds <SECONDS>'", "must be a finite number > 0, got -3"]);
}

#[test]
fn a_replay_scene_brings_its_gravity() {
    // A weightless scene: its box, far from the hand, stays where it is.
    let dir = Scratch::new("cli-gravity");
    let scene = r#"{"gravity": [0, 0, 0],
        "objects": [{"name": "box", "shape": {"Box": {"half_extents": [0.02, 0.02, 0.02]}},
                     "mass": 0.1, "material": "wood", "position": [1.0, 0.5, 1.0]}]}"#;
    let file = dir.file("floating.json", scene).display().to_string();
    let (code, json, stderr) =
        run(&["replay", "data/leap/pinch.json.lz", "--scene", &file, "--json"]);
    assert_eq!(code, Some(0), "{stderr}");
    let summary: serde_json::Value = serde_json::from_str(&json).unwrap();
    let moved = summary["objects"][0]["displacement"].as_f64().unwrap();
    assert!(moved < 1e-6, "the weightless box moved {moved} m");
}

#[test]
fn an_unknown_method_is_a_usage_error_listing_the_valid_ones() {
    let valid = "expected one of coulomb, thesis, kinematic, heuristic";
    for args in [
        &["scenario", "push", "--method", "friction"][..],
        &["replay", "--method", "Coulomb", &pinch()],
        &["eval", "accuracy", "--method", "coulomb,magnet"],
    ] {
        let e = usage_error(args);
        assert!(e.contains("unknown method") && e.contains(valid), "{args:?}: {e}");
    }
    let e = usage_error(&["eval", "accuracy", "--users", "0"]);
    assert!(e.contains("--users"), "{e}");
}

#[test]
fn replay_json_carries_a_verdict_per_closing_and_the_text_a_line_each() {
    // In the old spelling, `--object-at-grasp`, which is still read.
    let args = ["replay", "data/leap/grab.json.lz", "--object-at-grasp", "box:0.045:0.05"];
    let (code, json, stderr) = run(&[&args[..], &["--json"]].concat());
    assert_eq!(code, Some(0), "{stderr}");
    let summary: serde_json::Value = serde_json::from_str(&json).unwrap();
    let closings = summary["closings"].as_array().unwrap();
    assert_eq!(closings.len(), 2, "{json}");
    for c in closings {
        let keys = [
            "slipped_at",
            "drift",
            "slip_bound",
            "released",
            "released_at",
            "release_by",
            "open_at",
        ];
        for key in keys {
            assert!(c.get(key).is_some(), "{key} missing: {c}");
        }
    }
    let (_, text, _) = run(&args);
    let lines: Vec<&str> = text.lines().filter(|l| l.starts_with("  closing-")).collect();
    assert_eq!(lines.len(), 2, "{text}");
}

#[test]
fn replay_puts_an_object_at_a_fixed_place_once_with_the_same_option() {
    // A 3 cm sphere of 20 g, 40 cm beside where the hand works: it rests.
    let args = ["replay", "data/leap/grab.json.lz", "--object-at", "0.4,0.015,0"];
    let (code, json, stderr) =
        run(&[&args[..], &["--object", "sphere:0.03:0.02", "--json"]].concat());
    assert_eq!(code, Some(0), "{stderr}");
    let summary: serde_json::Value = serde_json::from_str(&json).unwrap();
    let objects = summary["objects"].as_array().unwrap();
    assert_eq!(objects.len(), 1, "{json}");
    assert_eq!(objects[0]["name"], "object");
    let start = objects[0]["start"].as_array().unwrap();
    assert!((start[0].as_f64().unwrap() - 0.4).abs() < 1e-3, "{json}");
    assert!(objects[0]["displacement"].as_f64().unwrap() < 0.005, "at rest: {json}");
    assert!(summary["closings"].as_array().is_none_or(|c| c.is_empty()), "no closings: {json}");
}

#[cfg(unix)]
#[test]
fn a_reader_that_stops_early_ends_the_program_quietly() {
    // `coulomb-hands demo --every 0.001 | head -1`: the pipe closes after
    // one line of a table far longer than a pipe holds (64 KiB), so the
    // demo writes into a closed pipe.
    use std::io::{BufRead, BufReader};
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_coulomb-hands"))
        .args(["demo", "--every", "0.001"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut first).unwrap();
    assert!(first.starts_with("grasp-lift-carry"), "{first}");
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_ne!(out.status.code(), Some(101), "{stderr}");
}

#[test]
fn a_study_names_the_noise_recording_it_cannot_use() {
    let dir = Scratch::new("cli-noise");
    let quick = ["eval", "accuracy", "--users", "1", "--trials", "1", "--method", "kinematic"];
    // A file that is not there.
    let missing = dir.text("missing.json.lz");
    let e = cli_error(&[&quick[..], &["--noise-from", &missing]].concat());
    names(e, &[&missing, "No such file"]);
    // A recording whose hand is tracked for only a tenth of a second.
    let frames: Vec<_> = (0..12).map(|k| frame(k * 10_000, &[leap_hand(3)])).collect();
    let short = dir.file("short.json", recording(&frames)).display().to_string();
    for study in [&quick[..], &["eval", "sweep", "--users", "1", "--trials", "1"][..]] {
        let e = cli_error(&[study, &["--noise-from", &short]].concat());
        names(e, &[&short, "no hand is tracked for 1 s or more"]);
    }
    // A hand held perfectly still for 1.5 s has no jitter to scale to 2 mm.
    let frames: Vec<_> = (0..150).map(|k| frame(k * 10_000, &[leap_hand(3)])).collect();
    let still = dir.file("still.json", recording(&frames)).display().to_string();
    let sweep = ["eval", "sweep", "--users", "1", "--trials", "1", "--noise-from", &still];
    let e = cli_error(&[&sweep[..], &["--noise-mm", "2"]].concat());
    names(e, &["study: noise-mm: ", "the recordings have no jitter to scale to 2 mm"]);
    // Scales out of range are usage errors naming the option.
    let e = usage_error(&["eval", "accuracy", "--noise=-1"]);
    names(e, &["'--noise <SCALE>'", "expected a finite scale ≥ 0, got -1"]);
    let e = usage_error(&["eval", "sweep", "--noise", "0,nan"]);
    names(e, &["--noise", "got nan"]);
    let e = usage_error(&["eval", "ablation", "--perception", "inf"]);
    names(e, &["'--perception <SCALE>'", "got inf"]);
    let e = usage_error(&["eval", "sweep", "--noise-mm", "1,-2"]);
    names(e, &["--noise-mm", "expected a finite scale ≥ 0, got -2"]);
    let e = usage_error(&["eval", "accuracy", "--noise-mm", "2", "--noise", "1"]);
    names(e, &["'--noise-mm <MM>' cannot be used with '--noise <SCALE>'"]);
    let e = usage_error(&["eval", "latency", "--noise-mm", "nan"]);
    names(e, &["--noise-mm", "got nan"]);
    // White noise is drawn at a tracker's frame rate, and not from recordings.
    let e = cli_error(&["eval", "latency", "--noise-white", "4"]);
    names(e, &["study: noise-white: ", "frame rate in 10–1000 Hz, got 4"]);
    let e = cli_error(&["eval", "sweep", "--noise-white", "nan"]);
    names(e, &["study: noise-white: ", "got NaN"]);
    let e = usage_error(&["eval", "accuracy", "--noise-white", "60", "--noise-from", &still]);
    names(e, &["'--noise-white <HZ>' cannot be used with '--noise-from <FILE,...>'"]);
    let e = usage_error(&["eval", "accuracy", "--strategy", "throw"]);
    names(e, &["unknown strategy \"throw\": expected lift or slide"]);
}

#[test]
fn the_library_refuses_study_options_out_of_range_naming_them() {
    use coulomb_hands::eval::latency::{LatencyOptions, latency};
    use coulomb_hands::eval::sweep::{SweepOptions, sweep};
    use coulomb_hands::eval::{AccuracyOptions, NoiseUnit, accuracy};
    let bad = AccuracyOptions { noise: f32::NAN, ..AccuracyOptions::default() };
    names(accuracy(&bad, &mut |_, _| {}).unwrap_err(), &["study: noise: ", "got NaN"]);
    let bad = AccuracyOptions { strategies: Vec::new(), ..AccuracyOptions::default() };
    names(accuracy(&bad, &mut |_, _| {}).unwrap_err(), &["study: strategy: ", "at least one"]);
    let bad = SweepOptions { noise: vec![0.5, -2.0], ..SweepOptions::default() };
    names(sweep(&bad, &mut |_, _| {}).unwrap_err(), &["study: noise: ", "got -2"]);
    let mut in_mm = SweepOptions { noise: vec![1.0, f32::INFINITY], ..SweepOptions::default() };
    in_mm.conditions.noise_unit = NoiseUnit::RmsMm;
    names(sweep(&in_mm, &mut |_, _| {}).unwrap_err(), &["study: noise-mm: ", "got inf"]);
    let bad = LatencyOptions { streams: 0, ..LatencyOptions::default() };
    names(latency(&bad).unwrap_err(), &["study: streams: ", "at least one"]);
    let bad = LatencyOptions { noise: vec![-1.0], ..LatencyOptions::default() };
    names(latency(&bad).unwrap_err(), &["study: noise-mm: ", "got -1"]);
    let both = LatencyOptions {
        noise_white: Some(60.0),
        noise_from: vec!["data/leap/grab.json.lz".into()],
        ..LatencyOptions::default()
    };
    names(latency(&both).unwrap_err(), &["study: noise-white: ", "give one or the other"]);
    let mut fast = AccuracyOptions::default();
    fast.conditions.noise_white = Some(f32::INFINITY);
    names(accuracy(&fast, &mut |_, _| {}).unwrap_err(), &["study: noise-white: ", "got inf"]);
}
