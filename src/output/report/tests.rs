//! The page builder with every section absent and present, bad numbers,
//! and the two JSON inputs.

use super::capture_page::CAPTURE_FILE;
use super::page::{ACCURACY_COMMAND, BENCH_COMMAND, SECTIONS};
use super::study_page::{ABLATION_COMMAND, SWEEP_COMMAND};
use super::*;

/// The thesis's Table 5.2, as the page prints it.
const THESIS_NUMBERS: [&str; 3] = ["9.2 ± 5.5 / 8.2", "11.1 ± 6.9 / 9.6", "14.3 ± 8.5 / 12.2"];

/// Nothing is loaded from elsewhere: links are anchors, and no address
/// but the SVG namespace appears.
#[track_caller]
fn assert_self_contained(page: &str) {
    for attr in ["src=\"", "href=\""] {
        for (at, _) in page.match_indices(attr) {
            let value = &page[at + attr.len()..];
            assert!(value.starts_with('#'), "{attr}{}", &value[..value.len().min(40)]);
        }
    }
    let page = page.replace("xmlns=\"http://www.w3.org/2000/svg\"", "");
    for bad in ["http://", "https://", "<script", "<link", "@import", "url("] {
        assert!(!page.contains(bad), "the page contains {bad}");
    }
}

fn svgs(page: &str) -> usize {
    page.matches("<svg").count()
}

const ACCURACY_JSON: &str = r#"{"users":6,"trials":20,"seed":1,"methods":[
  {"method":"coulomb","errors_mm":[1.5,2.0,9.0],"mean_mm":4.1,"sd_mm":4.2,"median_mm":2.0,
   "mean_time_s":5.5,"failed":1,"drops":0},
  {"method":"kinematic","errors_mm":[],"mean_mm":null,"sd_mm":null,"median_mm":null,
   "mean_time_s":null,"failed":20,"drops":3}],
 "thesis":[{"method":"coulomb","mean_mm":9.2,"sd_mm":5.5,"median_mm":8.2},
   {"method":"heuristic","mean_mm":11.1,"sd_mm":6.9,"median_mm":9.6},
   {"method":"kinematic","mean_mm":14.3,"sd_mm":8.5,"median_mm":12.2}]}"#;

const BENCH_JSON: &str = r#"{"sweep":[
  {"bones":6,"hands":1,"samples_per_contact":8,"interaction_us":4.5,"rapier_us":3.1,"full_us":7.6},
  {"bones":32,"hands":2,"samples_per_contact":8,"interaction_us":18.0,"rapier_us":8.0,
   "full_us":26.0}],
 "reference":{"bones_pressing":32,"objects":70,
   "asleep":{"interaction_us":18.0,"rapier_us":20.1,"full_us":38.1},
   "awake":{"interaction_us":18.5,"rapier_us":160.0,"full_us":178.5},"settling_us":170.0},
 "mujoco":{"step_us":770.0,"settings":"pyramidal, Euler","ratio_awake":0.23,"ratio_asleep":0.05}}"#;

/// A sweep of two methods, both strategies, two noise strengths, in the
/// order `eval sweep` writes them (method by method, so the strategies
/// interleave); one row with no completed trial.
const SWEEP_JSON: &str = r#"{"users":2,"trials":3,"seeds":[1,2],"perception":1.0,
 "noise":{"sources":["data/leap/grab.json.lz"],"rms_mm":0.72,"dropouts_per_s":0.7,
   "dropout_ms":17.6},
 "rows":[
  {"method":"coulomb","strategy":"lift","noise":0.0,"trials":12,
   "error_mm":{"value":1.9,"low":1.4,"high":2.4},"median_mm":1.7,
   "time_s":{"value":9.1,"low":8.0,"high":10.2},"failed":{"value":0.0,"low":0.0,"high":0.24},
   "drops":{"value":0.0,"low":0.0,"high":0.0},"held_across_mm":0.1},
  {"method":"coulomb","strategy":"lift","noise":2.0,"trials":12,
   "error_mm":{"value":2.6,"low":1.9,"high":3.3},"median_mm":2.2,
   "time_s":{"value":10.1,"low":9.0,"high":11.2},"failed":{"value":0.08,"low":0.01,"high":0.35},
   "drops":{"value":0.1,"low":-0.1,"high":0.3},"held_across_mm":0.3},
  {"method":"thesis","strategy":"slide","noise":0.0,"trials":12,
   "error_mm":{"value":null,"low":null,"high":null},"median_mm":null,
   "time_s":{"value":null,"low":null,"high":null},"failed":{"value":1.0,"low":0.76,"high":1.0},
   "drops":{"value":3.5,"low":2.0,"high":5.0},"held_across_mm":null},
  {"method":"thesis","strategy":"lift","noise":0.0,"trials":12,
   "error_mm":{"value":4.4,"low":3.0,"high":5.8},"median_mm":3.9,
   "time_s":{"value":15.2,"low":13.0,"high":17.4},"failed":{"value":0.17,"low":0.05,"high":0.45},
   "drops":{"value":0.5,"low":0.1,"high":0.9},"held_across_mm":6.5}]}"#;

const ABLATION_JSON: &str = r#"{"users":3,"trials":5,"seed":1,"rows":[
  {"config":"thesis as written","strategy":"lift","trials":15,"completed":4,
   "failed":{"value":0.73,"low":0.48,"high":0.89},"drops":{"value":2.1,"low":1.2,"high":3.0},
   "error_mm":{"value":5.5,"low":1.0,"high":10.0}},
  {"config":"+ contact damper","strategy":"lift","trials":15,"completed":15,
   "failed":{"value":0.0,"low":0.0,"high":0.2},"drops":{"value":0.0,"low":0.0,"high":0.0},
   "error_mm":{"value":2.2,"low":1.6,"high":2.8}}]}"#;

fn scenario(name: &str, objects: usize) -> ScenarioRun {
    let series = |k: usize| ObjectSeries {
        name: format!("block{k}"),
        hand_force_n: (0..2000)
            .map(|i| if i > 500 && k.is_multiple_of(3) { 0.4 } else { 0.0 })
            .collect(),
        height_m: (0..2000).map(|i| 0.02 + (k * i) as f32 * 1e-5).collect(),
    };
    ScenarioRun {
        name: name.into(),
        description: "A <b>test</b> & more".into(),
        passed: true,
        wall_s: 0.5,
        checks: vec![Verdict {
            name: "lifted (m)".into(),
            value: 0.2,
            bound: ">= 0.18".into(),
            passed: true,
        }],
        error: None,
        dt: 0.001,
        objects: (0..objects).map(series).collect(),
    }
}

/// A capture replayed by three methods over 50 frames: one lifts the object
/// with the capture, one leaves it on the table, one stopped.
fn captures() -> CaptureRuns {
    let time_s: Vec<f64> = (0..50).map(|i| f64::from(i) / 30.0).collect();
    let lift = |i: usize| (200.0 * (i as f32 / 49.0 * std::f32::consts::PI).sin()).max(0.0);
    let captured_height_mm: Vec<f32> = (0..50).map(lift).collect();
    let method = |name: &str, held: bool| CaptureMethodRun {
        method: name.into(),
        simulated_height_mm: (0..50).map(|i| if held { lift(i) + 5.0 } else { -2.0 }).collect(),
        translation_error_mm: (0..50).map(|i| if held { 5.0 } else { lift(i) }).collect(),
        translation_mean_mm: if held { 5.0 } else { 120.0 },
        captured_lift_mm: 200.0,
        simulated_lift_mm: if held { 205.0 } else { 0.0 },
        on_target: held,
        ..CaptureMethodRun::default()
    };
    let stopped = CaptureMethodRun {
        method: "thesis".into(),
        error: Some("the world rejected <a> call".into()),
        ..CaptureMethodRun::default()
    };
    CaptureRuns {
        capture: "data/taco/a <capture>.json".into(),
        credit: "TACO (Liu et al., CVPR 2024), CC BY 4.0".into(),
        mass_kg: 0.3,
        material: "wood".into(),
        time_s,
        captured_height_mm,
        methods: vec![method("coulomb", false), stopped, method("kinematic", true)],
    }
}

fn full() -> ReportData {
    let sourced = |source: &str| source.to_string();
    ReportData {
        header: Header { command: "coulomb-hands report --out 'a b'".into(), ..Header::default() },
        accuracy: Some(Sourced {
            source: sourced("accuracy.json"),
            data: serde_json::from_str(ACCURACY_JSON).unwrap(),
        }),
        sweep: Some(Sourced {
            source: sourced("sweep.json"),
            data: serde_json::from_str(SWEEP_JSON).unwrap(),
        }),
        ablation: Some(Sourced {
            source: sourced("ablation.json"),
            data: serde_json::from_str(ABLATION_JSON).unwrap(),
        }),
        bench: Some(Sourced {
            source: sourced("bench.json"),
            data: serde_json::from_str(BENCH_JSON).unwrap(),
        }),
        scenarios: Some(Sourced {
            source: sourced("run here"),
            data: vec![scenario("push", 1), scenario("tower <&>", 12)],
        }),
        replays: Some(Sourced {
            source: sourced("replayed here"),
            data: vec![
                ReplayRun { recording: "data/leap/pinch.json.lz".into(), ..ReplayRun::default() },
                ReplayRun {
                    recording: "twitch.json".into(),
                    not_judged: vec![
                        "closing-1 (hand 4, closed 1.05-1.07 s, by aperture): too short to \
                         judge (0.02 s; a hold is 0.15 s) <x>"
                            .into(),
                    ],
                    ..ReplayRun::default()
                },
            ],
        }),
        captures: Some(Sourced { source: sourced("replayed here"), data: captures() }),
    }
}

#[test]
fn with_every_section_absent_the_page_says_how_to_make_them() {
    let page = html(&ReportData::default());
    for heading in SECTIONS {
        assert!(page.contains(&markup::escape(heading)), "{heading}");
    }
    assert_eq!(svgs(&page), 0);
    for text in THESIS_NUMBERS.iter().chain(&["0.6 ms at 6 bones, 1.5 ms at 32 bones"]) {
        assert!(page.contains(text), "{text}");
    }
    for command in [ACCURACY_COMMAND, BENCH_COMMAND, SWEEP_COMMAND, ABLATION_COMMAND] {
        assert!(page.contains(&markup::escape(command)), "{command}");
    }
    assert!(page.contains("--accuracy accuracy.json") && page.contains("--bench bench.json"));
    assert!(page.contains("--sweep sweep.json") && page.contains("--ablation ablation.json"));
    let replay = format!("coulomb-hands replay {CAPTURE_FILE} --method METHOD");
    assert!(page.contains(&replay), "how to replay the capture");
    assert_eq!(page.matches("class=\"absent\"").count(), SECTIONS.len());
    assert_self_contained(&page);
}

#[test]
fn with_every_section_present_there_is_one_svg_per_plot() {
    let page = html(&full());
    for heading in SECTIONS {
        assert!(page.contains(&markup::escape(heading)), "{heading}");
    }
    // Accuracy 1, noise 4 (error and drops, lift and slide), performance 3
    // (linear, log, reference), one per scenario, the capture's 2.
    assert_eq!(svgs(&page), 1 + 4 + 3 + 2 + 2);
    assert!(page.contains("Object height: captured and simulated"));
    assert!(page.contains("Distance from the captured object"));
    assert!(page.contains("data/taco/a &lt;capture&gt;.json") && page.contains("0.3 kg"));
    assert!(page.contains("thesis: the replay stopped: the world rejected &lt;a&gt; call"));
    assert!(page.contains("Capture data: TACO (Liu et al., CVPR 2024), CC BY 4.0."));
    let rows = ["<tr><td>coulomb</td>", "<tr><td>thesis</td>", "<tr><td>kinematic</td>"];
    assert!(rows.iter().all(|r| page.contains(r)), "a row per method");
    assert_eq!(page.matches("<span class=\"pass\">yes</span>").count(), 1, "on target");
    for text in THESIS_NUMBERS {
        assert!(page.contains(text), "{text}");
    }
    assert!(page.contains("Our approach") && page.contains("Leap Motion Interaction Engine"));
    assert!(page.contains("4.1 ± 4.2 / 2.0"), "the study's own numbers");
    assert!(page.contains("— ± — / —"), "a method with no completed trial");
    assert!(page.contains("MuJoCo") && page.contains("pyramidal, Euler"));
    assert!(page.contains("tower &lt;&amp;&gt;") && !page.contains("tower <&>"));
    assert!(page.contains("A &lt;b&gt;test&lt;/b&gt; &amp; more"));
    assert!(page.contains("Showing 5 of 12 objects"));
    assert!(page.contains("pinch.json.lz") && page.contains("No hand closes"));
    assert_eq!(page.matches("No hand closes").count(), 1, "a closing not judged is a closing");
    assert!(page.contains("Closings not judged") && page.contains("0.15 s) &lt;x&gt;</li>"));
    assert!(page.contains("lifted (m)") && page.contains("&gt;= 0.18"));
    assert!(page.contains("--out &#39;a b&#39;"));
    assert!(page.contains("2.6 [1.9, 3.3]") && page.contains("+ contact damper"));
    assert!(page.contains("0.72 mm") && page.contains("— [—, —]"), "the sweep's numbers");
    assert!(page.contains("×2 (1.44 mm)") && page.contains("mm rms per joint and axis"));
    assert_self_contained(&page);
}

#[test]
fn bad_numbers_and_empty_data_neither_panic_nor_lose_plots() {
    let mut data = full();
    let study = &mut data.accuracy.as_mut().unwrap().data;
    study.methods[0].errors_mm = vec![f64::NAN, f64::INFINITY, -3.0, 1e300, f64::MAX];
    study.thesis.clear();
    let bench = &mut data.bench.as_mut().unwrap().data;
    bench.sweep[0].times.full_us = f64::NAN;
    bench.sweep[1].times.interaction_us = -1.0;
    bench.sweep[1].times.rapier_us = f64::MAX;
    bench.reference.asleep.rapier_us = f64::MAX;
    bench.reference.awake.full_us = 0.0;
    bench.mujoco.as_mut().unwrap().step_us = f64::INFINITY;
    let runs = &mut data.scenarios.as_mut().unwrap().data;
    runs[0].dt = 0.0;
    runs[1].dt = f64::MAX;
    runs[0].objects[0].height_m = vec![f32::NAN; 3];
    runs[1].objects.clear();
    runs[1].error = Some("the world rejected a call".into());
    let capture = &mut data.captures.as_mut().unwrap().data;
    capture.time_s[3] = f64::NAN;
    capture.captured_height_mm[7] = f32::INFINITY;
    capture.methods[0].simulated_height_mm = vec![f32::MAX, f32::NAN];
    capture.methods[2].translation_error_mm.clear();
    capture.methods[2].rotation_max_deg = f64::NAN;
    capture.mass_kg = f32::NAN;
    let sweep = &mut data.sweep.as_mut().unwrap().data;
    sweep.rows[0].error_mm = Estimate { value: f64::MAX, low: f64::NAN, high: f64::INFINITY };
    sweep.rows[1].noise = f32::NAN;
    let page = html(&data);
    assert_eq!(svgs(&page), 12, "{}", page.matches("could not be drawn").count());
    assert!(page.contains("of — kg"));
    assert!(page.contains("The run stopped: the world rejected a call"));
    // With no thesis rows in the study, the published ones are shown.
    assert!(THESIS_NUMBERS.iter().all(|t| page.contains(t)));
    let huge =
        ThesisResult { method: "coulomb".into(), mean_mm: f64::MAX, sd_mm: 1.0, median_mm: 1.0 };
    data.accuracy.as_mut().unwrap().data.thesis = vec![huge];
    assert_eq!(svgs(&html(&data)), 12);
    data.bench.as_mut().unwrap().data.sweep.clear();
    data.accuracy.as_mut().unwrap().data.methods.clear();
    data.sweep.as_mut().unwrap().data.rows.clear();
    let capture = &mut data.captures.as_mut().unwrap().data;
    (capture.time_s, capture.methods) = (Vec::new(), Vec::new());
    // No rows: no strategies to plot; an empty capture gives empty axes.
    assert_eq!(svgs(&html(&data)), 8);
}

#[test]
fn the_two_json_inputs_deserialize_as_written() {
    let study: AccuracyStudy = serde_json::from_str(ACCURACY_JSON).unwrap();
    assert_eq!((study.users, study.trials, study.seed), (6, 20, 1));
    assert_eq!(study.methods[0].errors_mm, [1.5, 2.0, 9.0]);
    assert_eq!((study.methods[0].failed, study.methods[1].drops), (1, 3));
    assert!(study.methods[1].mean_mm.is_nan(), "null is not a number");
    assert_eq!(study.thesis[2].median_mm, 12.2);
    let bench: BenchReport = serde_json::from_str(BENCH_JSON).unwrap();
    assert_eq!(bench.sweep[1].bones, 32);
    assert_eq!(bench.reference.awake.rapier_us, 160.0);
    assert_eq!(bench.mujoco.as_ref().map(|m| m.step_us), Some(770.0));
    let none = BENCH_JSON.split("\"mujoco\"").next().unwrap().to_string() + "\"mujoco\": null}";
    let bench: BenchReport = serde_json::from_str(&none).unwrap();
    assert_eq!(bench.mujoco, None);
    let e = FileError::json::<AccuracyStudy>("a.json", r#"{"users": 6, "trials": "x"}"#);
    let e = e.unwrap_err().to_string();
    assert!(e.starts_with("a.json: line 1 column ") && e.contains("invalid type"), "{e}");
}

#[test]
fn the_studies_json_reads_back() {
    let sweep: SweepStudy = serde_json::from_str(SWEEP_JSON).unwrap();
    assert_eq!(sweep.rows.len(), 4);
    assert!(sweep.rows[2].error_mm.value.is_nan() && sweep.rows[2].held_across_mm.is_none());
    assert_eq!(sweep.rows[1].failed.high, 0.35);
    let ablation: Ablation = serde_json::from_str(ABLATION_JSON).unwrap();
    assert_eq!(ablation.rows[1].completed, 15);
    let e = FileError::json::<SweepStudy>("s.json", r#"{"users": 2, "rows": 3}"#);
    assert!(e.unwrap_err().to_string().starts_with("s.json: line 1 column "));
}

#[test]
fn dates_are_civil_utc() {
    assert_eq!(utc_date(0), "1970-01-01 00:00 UTC");
    assert_eq!(utc_date(951_782_400), "2000-02-29 00:00 UTC");
    assert_eq!(utc_date(1_700_000_000), "2023-11-14 22:13 UTC");
}

#[test]
fn the_accuracy_section_names_the_noise_it_ran_under() {
    let mut study: AccuracyStudy = serde_json::from_str(ACCURACY_JSON).unwrap();
    let white = NoiseSummary {
        sources: vec!["white jitter at 75 Hz".into()],
        rms_mm: 1.0,
        dropouts_per_s: 0.0,
        dropout_ms: 0.0,
    };
    assert_eq!(white.kind(), "white jitter at 75 Hz");
    (study.noise, study.noise_rms_mm, study.perception) = (Some(2.5), Some(2.5), Some(1.0));
    study.noise_source = Some(white);
    let page_of = |study: &AccuracyStudy| {
        let data = ReportData {
            accuracy: Some(Sourced { source: "a.json".into(), data: study.clone() }),
            ..ReportData::default()
        };
        html(&data)
    };
    let page = page_of(&study);
    assert!(page.contains("Tracking noise ×2.5 of white jitter at 75 Hz, 2.50 mm rms"), "{page}");
    assert!(!page.contains("bundled recordings"));
    // Recordings are named by their file names; a file from before the
    // study recorded its source ran on the bundled recordings.
    let recorded = NoiseSummary {
        sources: vec!["data/leap/grab.json.lz".into(), "/tmp/x/flap.json".into()],
        ..study.noise_source.clone().unwrap()
    };
    assert_eq!(recorded.kind(), "the residuals of grab.json.lz, flap.json");
    study.noise_source = None;
    assert!(page_of(&study).contains("Tracking noise ×2.5 the bundled recordings' own"));
}
