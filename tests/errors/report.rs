//! `report`: an `--out` that cannot be written is an error naming it before
//! any work, malformed `--accuracy` and `--bench` files name the file, the
//! line and what is wrong; and, for contrast, the JSON that `eval accuracy`
//! and `bench` write reads as the report's types, and a report on a reduced
//! set works, with the study and the bench run by the report itself or left
//! out, and with the bundled hand–object capture replayed by every method.

use crate::{Scratch, cli_error, names, run, usage_error};
use coulomb_hands::eval::board::{SQUARE, SQUARES};
use coulomb_hands::run::bench::SWEEP_BONES;

#[test]
fn an_unwritable_out_is_named_before_any_work() {
    let dir = Scratch::new("report-out");
    let plain = dir.file("plain", "a file, not a directory");
    let under = dir.text("plain/report");
    // Every other input is bad too: the --out error comes first, before
    // anything is read or run.
    let missing = dir.text("missing.json");
    let args = ["report", "--out", &under, "--accuracy", &missing, "--scenarios", "no-such"];
    names(cli_error(&args), &[&format!("--out {under}: cannot write there: ")]);
    let file = plain.display().to_string();
    names(cli_error(&["report", "--out", &file]), &[&format!("--out {file}: cannot write there")]);
    // A MuJoCo that cannot run is found before the study and the scenarios.
    let out = dir.text("out");
    let args = ["report", "--out", &out, "--mujoco", "--python", "/no/such/python"];
    names(cli_error(&args), &["cannot run /no/such/python", "bench/mujoco.sh"]);
    assert!(!dir.path("out/index.html").exists());
    let given = dir.file("given.json", "{}").display().to_string();
    let both = ["report", "--out", &out, "--bench", &given, "--no-bench"];
    names(usage_error(&both), &["--bench <FILE>", "--no-bench"]);
}

#[test]
fn malformed_inputs_name_the_file_the_line_and_the_fault() {
    let dir = Scratch::new("report-inputs");
    let out = dir.text("out");
    let report = |flag: &str, file: &std::path::Path| {
        cli_error(&["report", "--out", &out, flag, &file.display().to_string()])
    };
    let typed = dir.file("typed.json", "{\"users\": 6,\n \"trials\": \"twenty\"}");
    let e = report("--accuracy", &typed);
    let expected = "invalid type: string \"twenty\", expected usize";
    names(e, &[&format!("{}: line 2 column ", typed.display()), expected]);
    let short = dir.file("short.json", r#"{"users": 6, "trials": 20, "seed": 1, "methods": []}"#);
    names(report("--accuracy", &short), &["short.json: line 1 column", "missing field `thesis`"]);
    let cut = dir.file("bench.json", "{\"sweep\": [");
    names(report("--bench", &cut), &["bench.json: line 1 column", "EOF while parsing"]);
    let gone = dir.path("gone.json");
    names(report("--bench", &gone), &["gone.json: ", "No such file"]);
}

#[test]
fn a_report_of_one_scenario_and_one_replay_has_every_section() {
    let dir = Scratch::new("report-run");
    // Shapes only: these numbers are made up for the test.
    let accuracy = dir.file(
        "accuracy.json",
        r#"{"users": 1, "trials": 2, "seed": 3, "methods": [{"method": "coulomb",
            "errors_mm": [1.0, 2.0], "mean_mm": 1.5, "sd_mm": 0.7, "median_mm": 1.5,
            "mean_time_s": 4.0, "failed": 0, "drops": 0}], "thesis": []}"#,
    );
    let times = r#"{"interaction_us": 1.0, "rapier_us": 2.0, "full_us": 3.0}"#;
    let bench = dir.file(
        "bench.json",
        format!(
            r#"{{"sweep": [{{"bones": 6, "hands": 1, "samples_per_contact": 8,
                "interaction_us": 1.0, "rapier_us": 2.0, "full_us": 3.0}}],
                "reference": {{"bones_pressing": 32, "objects": 70, "asleep": {times},
                "awake": {times}, "settling_us": 9.0}}, "mujoco": null}}"#
        ),
    );
    let out = dir.text("out");
    let (accuracy, bench) = (accuracy.display().to_string(), bench.display().to_string());
    let (code, stdout, stderr) = run(&[
        "report",
        "--out",
        &out,
        "--accuracy",
        &accuracy,
        "--bench",
        &bench,
        "--scenarios",
        "push",
        "--replays",
        "data/leap/pinch.json.lz",
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    let index = dir.path("out/index.html");
    let summary =
        "1 scenarios (1 passed), 1 replays, 4 capture replays; accuracy: given, bench: given";
    assert_eq!(stdout, format!("wrote {}: {summary}\n", index.display()));
    let files: Vec<_> = std::fs::read_dir(dir.path("out")).unwrap().collect();
    assert_eq!(files.len(), 1, "only index.html, no probe left: {files:?}");
    let page = std::fs::read_to_string(&index).unwrap();
    // Accuracy 1, performance 3, one scenario, the capture's 2.
    assert_eq!(page.matches("<svg").count(), 7);
    for text in [
        "Placement accuracy",
        "9.2 ± 5.5 / 8.2",
        "Performance",
        "Scenarios",
        "id=\"scenario-push\"",
        "pushed forward (m)",
        "Replays",
        "data/leap/pinch.json.lz",
        "a 2.0 cm, 10 g box at",
        "contacts begun",
        "Real hands moving real objects",
        "data/taco/taco_20231104_017.json with each method",
        "report --out",
        "cores",
    ] {
        assert!(page.contains(text), "the report lacks {text}");
    }
    assert!(!page.replace("xmlns=\"http://www.w3.org/2000/svg\"", "").contains("http"));
}

#[test]
fn the_json_of_eval_accuracy_and_bench_reads_as_the_reports_inputs() {
    use coulomb_hands::eval::{AccuracyStudy, MethodResult, ThesisResult};
    use coulomb_hands::output::report;
    use coulomb_hands::run::bench::{
        BenchReport, MujocoStep, ObjectsPoint, ReferenceScene, StepTimes, SweepPoint,
    };
    let times = StepTimes { interaction_us: 1.0, rapier_us: 2.0, full_us: 3.0 };
    let sweep = vec![SweepPoint { bones: 6, hands: 1, samples_per_contact: 8, times }];
    let (asleep, awake) = (times, StepTimes { rapier_us: 20.0, full_us: 21.0, ..times });
    let reference =
        ReferenceScene { bones_pressing: 32, objects: 70, asleep, awake, settling_us: 9.0 };
    let settings = "pyramidal, Euler".to_string();
    let mujoco = MujocoStep { step_us: 700.0, settings, ratio_awake: 0.03, ratio_asleep: 0.01 };
    let objects = vec![ObjectsPoint { objects: 1500, bones_pressing: 30, awake: 19, times }];
    let bench = BenchReport { sweep, reference, mujoco: Some(mujoco), objects };
    let text = serde_json::to_string(&bench).unwrap();
    // The same type: what bench writes, the report reads back whole.
    assert_eq!(serde_json::from_str::<report::BenchReport>(&text).unwrap(), bench);
    // A method that completed no trial has no mean: serde_json writes null.
    let method = |name: &str, errors_mm: Vec<f64>, mean_mm: f64| MethodResult {
        method: name.into(),
        strategy: Some("slide".into()),
        errors_mm,
        mean_mm,
        sd_mm: mean_mm,
        median_mm: mean_mm,
        mean_time_s: 10.0,
        times_s: Vec::new(),
        failed: 0,
        drops: 1,
        held_across_mm: Some(-0.4),
    };
    let study = AccuracyStudy {
        users: 2,
        trials: 5,
        seed: 7,
        noise: Some(0.5),
        noise_rms_mm: None,
        noise_source: None,
        perception: Some(1.0),
        methods: vec![method("coulomb", vec![1.0, 3.0], 2.0), method("thesis", vec![], f64::NAN)],
        thesis: vec![ThesisResult {
            method: "coulomb".into(),
            mean_mm: 9.2,
            sd_mm: 5.5,
            median_mm: 8.2,
        }],
    };
    let text = serde_json::to_string(&study).unwrap();
    let read: report::AccuracyStudy = serde_json::from_str(&text).unwrap();
    assert_eq!((read.users, read.trials, read.seed), (2, 5, 7));
    assert_eq!((read.noise, read.methods[0].strategy.as_deref()), (Some(0.5), Some("slide")));
    assert_eq!(
        (read.methods[0].errors_mm.as_slice(), read.methods[0].mean_mm),
        (&[1.0, 3.0][..], 2.0)
    );
    assert!(read.methods[1].mean_mm.is_nan() && read.methods[1].errors_mm.is_empty());
    assert_eq!(read.thesis[0].median_mm, 8.2);
}

/// The text of each cell of the table row whose first cell is `first`.
fn row(page: &str, first: &str) -> Vec<String> {
    let start = [format!("<tr><td>{first}</td>"), format!("<tr><td class=\"num\">{first}</td>")]
        .iter()
        .find_map(|r| page.find(r.as_str()))
        .unwrap_or_else(|| panic!("no table row starts with {first}"));
    let line = &page[start..page[start..].find("</tr>").map_or(page.len(), |e| start + e)];
    let text = |cell: &str| cell.rsplit('>').next().unwrap_or("").to_string();
    line.split("</td>").filter(|c| c.contains("<td")).map(text).collect()
}

#[test]
fn the_bundled_capture_replayed_by_every_method_shows_who_lifts_it() {
    use coulomb_hands::output::report::{ReportData, Sourced, html};
    use coulomb_hands::run::report::CaptureInput;
    let input = CaptureInput::bundled().expect("it reads").expect("it is in the repository");
    let runs = input.run_every_method();
    // The captured hand lifts the object about 0.2 m, and each replay has a
    // height and an error at every captured frame.
    let captured = runs.captured_height_mm.iter().copied().fold(f32::MIN, f32::max);
    assert!(captured > 150.0, "the captured object rises {captured} mm");
    for m in &runs.methods {
        assert_eq!(m.error, None, "{}", m.method);
        assert_eq!(m.simulated_height_mm.len(), runs.time_s.len(), "{}", m.method);
        assert_eq!(m.translation_error_mm.len(), runs.time_s.len(), "{}", m.method);
    }
    let data = ReportData {
        captures: Some(Sourced { source: "replayed here".into(), data: runs }),
        ..ReportData::default()
    };
    let page = html(&data);
    let section = &page[page.find("<section id=\"captures\">").expect("the section")..];
    assert!(section.contains("7. Real hands moving real objects"));
    assert!(section.contains("Capture data: TACO (Liu et al., CVPR 2024), CC BY 4.0."));
    // Two plots: heights, errors; the TACO credit under each.
    assert_eq!(section.matches("<svg").count(), 2);
    assert_eq!(section.matches("Data: TACO (Liu et al., CVPR 2024), CC BY 4.0").count(), 2);
    let lift = |method: &str| {
        let cells = row(section, method);
        assert_eq!(cells.len(), 8, "{method}: {cells:?}");
        let n = |i: usize| numbers(&cells[i]).map(|v| v[0]).expect("a number");
        assert!((1..=6).all(|i| n(i) >= 0.0), "{method}: {cells:?}");
        (n(5), n(6))
    };
    for method in ["coulomb", "thesis", "heuristic"] {
        lift(method);
    }
    // A grab baseline holds the object to the hand: it rises with it.
    let (reached, captured) = lift("kinematic");
    assert!(captured > 150.0 && reached >= 0.5 * captured, "{reached} of {captured} mm");
}

/// The numbers in a cell such as `2.0 ± 0.5 / 1.8`; none if any is not one.
fn numbers(cell: &str) -> Option<Vec<f64>> {
    let parts = cell.split(['±', '/', ' ']).filter(|p| !p.is_empty());
    parts.map(|p| p.parse::<f64>().ok().filter(|x| x.is_finite())).collect()
}

#[test]
fn a_plain_report_runs_the_study_and_the_bench_itself() {
    let dir = Scratch::new("report-self");
    let out = dir.text("out");
    let tiny = ["--users", "1", "--trials", "1", "--steps", "20", "--objects", "20,45"];
    let reduced = ["--scenarios", "push", "--replays", "data/leap/pinch.json.lz"];
    let command = ["report", "--out", &out];
    let args: Vec<&str> = command.iter().chain(&tiny).chain(&reduced).copied().collect();
    let (code, stdout, stderr) = run(&args);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.ends_with("accuracy: run, bench: run\n"), "{stdout}");
    let page = std::fs::read_to_string(dir.path("out/index.html")).unwrap();
    // Only the sweep and the ablation, which it does not run, are absent.
    assert_eq!(page.matches("class=\"absent\"").count(), 2, "a section says how to produce it");
    assert!(page.contains("eval sweep --json &gt; sweep.json"));
    assert!(page.contains(" build): 1 synthetic users × 1 trials, seed 1, methods coulomb,"));
    assert!(page.contains(" build): 20 timed steps per figure; the reference scene with 16"));
    // Step time against objects: the plot.
    assert!(page.contains("Step time against objects in the scene"));
    // Every method's one trial, completed with an error on the board or
    // counted as failed.
    let diagonal_mm = SQUARES as f64 * SQUARE as f64 * 2f64.sqrt() * 1e3;
    let rows = ["coulomb", "thesis", "kinematic", "heuristic"]
        .into_iter()
        .flat_map(|m| ["lift", "slide"].map(|s| format!("{m} {s}")));
    for method in rows {
        let cells = row(&page, &method);
        let count = |i: usize| cells[i].parse::<usize>().expect("a count");
        assert_eq!(count(1) + count(5), 1, "{method}: {cells:?}");
        if count(1) == 0 {
            // No completed trial, so no error: not a zero one.
            assert_eq!(cells[2], "— ± — / —", "{method}: {cells:?}");
            continue;
        }
        let error = numbers(&cells[2]).expect("mean ± sd / median");
        assert!(error.iter().all(|&e| (0.0..diagonal_mm).contains(&e)), "{method}: {cells:?}");
    }
    // Every sweep point and the reference scene timed: step times > 0.
    let timed = |cells: &[String]| cells[1..].iter().filter_map(|c| numbers(c)).flatten().count();
    for bones in SWEEP_BONES {
        let cells = row(&page, &bones.to_string());
        let full = numbers(&cells[5]).expect("a time");
        assert!(full[0] > 0.0 && timed(&cells) == 6, "{bones} bones: {cells:?}");
    }
    for state in ["tower asleep", "tower awake"] {
        let cells = row(&page, state);
        assert!(timed(&cells) == 3 && numbers(&cells[3]).unwrap()[0] > 0.0, "{cells:?}");
    }
    // A row per cluttered scene: its objects, the 32 bones pressing, times.
    for objects in ["20", "45"] {
        let cells = row(&page, objects);
        assert_eq!(cells[2], "32", "{cells:?}");
        assert!(timed(&cells[2..]) == 3 && numbers(&cells[5]).unwrap()[0] > 0.0, "{cells:?}");
    }
}

#[test]
fn no_accuracy_and_no_bench_leave_them_out() {
    let dir = Scratch::new("report-skip");
    let out = dir.text("out");
    let (code, stdout, stderr) = run(&[
        "report",
        "--out",
        &out,
        "--no-accuracy",
        "--no-bench",
        "--scenarios",
        "push",
        "--replays",
        "data/leap/pinch.json.lz",
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.ends_with("accuracy: skipped, bench: skipped\n"), "{stdout}");
    let page = std::fs::read_to_string(dir.path("out/index.html")).unwrap();
    assert_eq!(page.matches("class=\"absent\"").count(), 4);
    assert!(page.contains("--no-accuracy") && page.contains("--no-bench"));
    assert!(!page.contains("synthetic users ×") && !page.contains("tower awake"));
}

#[test]
fn the_sweep_and_the_ablation_come_from_their_files() {
    let dir = Scratch::new("report-studies");
    let tiny = ["--users", "1", "--trials", "1", "--strategy", "lift", "--json"];
    let (code, sweep, stderr) = run(&[
        &["eval", "sweep", "--seeds", "4", "--noise", "0,1", "--method", "kinematic"][..],
        &tiny,
    ]
    .concat());
    assert_eq!(code, Some(0), "{stderr}");
    let (code, ablation, stderr) = run(&[&["eval", "ablation"][..], &tiny].concat());
    assert_eq!(code, Some(0), "{stderr}");
    let sweep_file = dir.file("sweep.json", &sweep).display().to_string();
    let ablation_file = dir.file("ablation.json", &ablation).display().to_string();
    let out = dir.text("out");
    let quick = ["--no-accuracy", "--no-bench", "--scenarios", "push", "--replays"];
    let args = [&["report", "--out", &out][..], &quick, &["data/leap/pinch.json.lz"]].concat();
    let with = [&args[..], &["--sweep", &sweep_file, "--ablation", &ablation_file]].concat();
    let (code, _, stderr) = run(&with);
    assert_eq!(code, Some(0), "{stderr}");
    let page = std::fs::read_to_string(dir.path("out/index.html")).unwrap();
    // Only the accuracy study and the bench are absent; the sweep has a
    // plot (one strategy) and a row per noise strength.
    assert_eq!(page.matches("class=\"absent\"").count(), 2);
    for noise in ["×0 (0.00 mm)", "×1 (0.70 mm)"] {
        let row = format!("<tr><td>kinematic</td><td>lift</td><td class=\"num\">{noise}</td>");
        assert!(page.contains(&row), "no sweep row for noise {noise}");
    }
    assert!(page.contains("Placement error, lift") && page.contains("+ contact damper"));
    assert!(page.contains(&format!("{sweep_file}, written by coulomb-hands eval sweep --json")));
    // A sweep file that is not one is an error naming it, before any work.
    let bad = dir.file("bad.json", r#"{"users": 1, "rows": "none"}"#).display().to_string();
    let e = cli_error(&[&args[..], &["--sweep", &bad]].concat());
    names(e, &[&bad, "line 1 column"]);
}
