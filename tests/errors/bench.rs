//! `bench`: bad arguments and a missing MuJoCo are clear errors, and a
//! quick run's `--json` has the shape the HTML report reads.

use crate::{Scratch, cli_error, names, run, usage_error};
use coulomb_hands::run::bench::{BenchReport, SAMPLES, SWEEP_BONES};
use serde_json::Value;

#[test]
fn bad_bench_arguments_name_the_argument() {
    names(usage_error(&["bench", "--steps", "0"]), &["'0'", "--steps"]);
    names(usage_error(&["bench", "--boxes", "17"]), &["'17'", "--boxes", "1..=16"]);
    names(usage_error(&["bench", "--python", "python3"]), &["--python", "--mujoco"]);
}

#[test]
fn a_missing_python_or_mujoco_says_what_to_install() {
    let e = cli_error(&["bench", "--mujoco", "--python", "/no/such/python", "--steps", "1"]);
    names(e, &["cannot run /no/such/python", "bench/mujoco.sh", "pip install mujoco"]);
}

#[cfg(unix)]
#[test]
fn a_python_without_mujoco_says_what_to_install() {
    use std::os::unix::fs::PermissionsExt;
    let python3 = std::process::Command::new("python3").arg("--version").output();
    if !python3.is_ok_and(|o| o.status.success()) {
        return; // no python3 to stand in for one without mujoco
    }
    // A Python without site-packages has no mujoco, wherever pip put it.
    let dir = Scratch::new("bench-python");
    let fake = dir.file("python", "#!/bin/sh\nexec python3 -S \"$@\"\n");
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).expect("chmod");
    let e = cli_error(&["bench", "--mujoco", "--python", &dir.text("python"), "--steps", "1"]);
    names(e, &[&format!("{} cannot import mujoco", dir.text("python")), "bench/mujoco.sh"]);
}

/// A stand-in for the Python that runs `bench/mujoco_reference.py`: an
/// executable file that answers the version check, then, asked to serve,
/// says it is ready and runs `serve`, shell code that answers the blocks.
#[cfg(unix)]
fn stand_in_python(dir: &Scratch, serve: &str) -> String {
    use std::os::unix::fs::PermissionsExt;
    let script = format!(
        "#!/bin/sh\n# Called as: python -c SCRIPT ARGS...\n\
         if [ \"$3\" = --check ]; then echo '{{\"mujoco\": \"stand-in\"}}'; exit 0; fi\n\
         echo '{{\"settings\": \"stand-in settings\"}}'\n{serve}\n"
    );
    let python = dir.file("python", script);
    std::fs::set_permissions(&python, std::fs::Permissions::from_mode(0o755)).expect("chmod");
    python.display().to_string()
}

#[cfg(unix)]
#[test]
fn mujoco_times_a_block_as_long_after_each_block_of_ours() {
    let dir = Scratch::new("bench-rival");
    // 7 µs per step per step asked for: a block's answer says how long it was.
    let log = dir.text("blocks.log");
    let serve = format!(
        "while read n; do echo $n >> '{log}'; echo \"{{\\\"step_us\\\": $((n * 7))}}\"; done"
    );
    let python = stand_in_python(&dir, &serve);
    let args = ["bench", "--mujoco", "--python", &python, "--steps", "130", "--no-objects"];
    let (code, stdout, stderr) = run(&[&args[..], &["--json"]].concat());
    assert_eq!(code, Some(0), "{stderr}");
    // Asleep, then awake: 100 and 30 steps each, each after a block of ours.
    let blocks = std::fs::read_to_string(&log).expect("the stand-in's log");
    assert_eq!(blocks.split_whitespace().collect::<Vec<_>>(), ["100", "30", "100", "30"]);
    let report: BenchReport = serde_json::from_str(&stdout).expect("a BenchReport");
    let mujoco = report.mujoco.expect("MuJoCo's step");
    assert_eq!(mujoco.settings, "stand-in settings");
    // The median of 700, 210, 700 and 210 µs per step.
    assert_eq!(mujoco.step_us, 455.0);
    for ratio in [mujoco.ratio_awake, mujoco.ratio_asleep] {
        assert!(ratio.is_finite() && ratio > 0.0, "{ratio}");
    }
    // The text names the same figures.
    let (code, text, stderr) = run(&args);
    assert_eq!(code, Some(0), "{stderr}");
    names(&text, &["mujoco (stand-in settings): 455.0 µs per mj_step", "ours / mujoco: awake "]);
}

#[cfg(unix)]
#[test]
fn a_mujoco_that_warns_at_length_does_not_stall_the_bench() {
    let dir = Scratch::new("bench-rival-warns");
    // 200 kB of warnings a block: more than a pipe holds.
    let warn = "yes 'UserWarning: something' | head -c 200000 >&2";
    let serve = format!("while read n; do {warn}; echo '{{\"step_us\": 900}}'; done");
    let python = stand_in_python(&dir, &serve);
    let args = ["bench", "--mujoco", "--python", &python, "--steps", "130", "--no-objects"];
    let (code, stdout, stderr) = run(&[&args[..], &["--json"]].concat());
    assert_eq!(code, Some(0), "{stderr}");
    let report: BenchReport = serde_json::from_str(&stdout).expect("a BenchReport");
    assert_eq!(report.mujoco.expect("MuJoCo's step").step_us, 900.0);
}

#[cfg(unix)]
#[test]
fn a_mujoco_that_stops_answering_is_named() {
    let dir = Scratch::new("bench-rival-ends");
    // It ends while timing its first block, or before it is asked for one
    // (a write to it then would end the bench by SIGPIPE, without a word).
    for (serve, last) in [
        ("read n; echo 'RuntimeError: boom' >&2; exit 1", "RuntimeError: boom"),
        ("echo 'ImportError: gone' >&2; exit 1", "ImportError: gone"),
    ] {
        let python = stand_in_python(&dir, serve);
        let e = cli_error(&["bench", "--mujoco", "--python", &python, "--steps", "10"]);
        let ended = "bench/mujoco_reference.py failed: it ended (exit status: 1)";
        assert_eq!(e, format!("{python} {ended}: {last}"));
    }
}

#[test]
fn bench_json_has_the_reports_shape() {
    let (code, stdout, stderr) = run(&["bench", "--steps", "20", "--objects", "25,60", "--json"]);
    assert_eq!(code, Some(0), "{stderr}");
    let json: Value = serde_json::from_str(&stdout).expect("one JSON object");
    let keys = |v: &Value| -> Vec<String> {
        let mut keys: Vec<_> = v.as_object().expect("an object").keys().cloned().collect();
        keys.sort();
        keys
    };
    assert_eq!(keys(&json), ["mujoco", "objects", "reference", "sweep"]);
    assert_eq!(json["mujoco"], Value::Null);
    let times = ["full_us", "interaction_us", "rapier_us"];
    let positive = |v: &Value| v.as_f64().is_some_and(|x| x.is_finite() && x > 0.0);
    let sweep = json["sweep"].as_array().expect("an array");
    assert_eq!(sweep.len(), SWEEP_BONES.len());
    for (row, bones) in sweep.iter().zip(SWEEP_BONES) {
        let mut expected = vec!["bones", "hands", "samples_per_contact"];
        expected.extend(times);
        expected.sort();
        assert_eq!(keys(row), expected);
        assert_eq!(row["bones"], bones);
        assert_eq!(row["hands"], bones.div_ceil(16));
        assert_eq!(row["samples_per_contact"], SAMPLES);
        assert!(times.iter().all(|t| positive(&row[t])), "{row}");
    }
    let reference = &json["reference"];
    let expected = ["asleep", "awake", "bones_pressing", "objects", "settling_us"];
    assert_eq!(keys(reference), expected);
    assert_eq!(reference["bones_pressing"], 32);
    assert_eq!(reference["objects"], 70);
    assert!(positive(&reference["settling_us"]));
    for state in ["asleep", "awake"] {
        assert_eq!(keys(&reference[state]), times);
        assert!(times.iter().all(|t| positive(&reference[state][t])));
    }
    // The cluttered scenes: the same 32 bones press among more objects.
    let objects = json["objects"].as_array().expect("an array");
    assert_eq!(objects.iter().map(|o| o["objects"].clone()).collect::<Vec<_>>(), [25, 60]);
    for row in objects {
        let mut expected = vec!["awake", "bones_pressing", "objects"];
        expected.extend(times);
        expected.sort();
        assert_eq!(keys(row), expected);
        assert_eq!(row["bones_pressing"], 32);
        assert!(times.iter().all(|t| positive(&row[t])), "{row}");
    }
    let report: BenchReport = serde_json::from_value(json).expect("a BenchReport");
    assert!(report.mujoco.is_none());
}
