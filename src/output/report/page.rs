//! The report page: [`html`] turns a [`ReportData`] into one HTML file
//! with inline CSS and SVG, and nothing loaded from elsewhere.

use super::capture_page::{self, CAPTURE_FILE};
use super::markup::{cell, escape, num, plot, plot_with_legend, table};
use super::plots;
use super::scenario_plot;
use super::study_page::{self, ABLATION_COMMAND, SWEEP_COMMAND};
use super::{
    AccuracyStudy, BenchReport, Header, ObjectsPoint, ReplayRun, ReportData, ScenarioRun, Sourced,
    StepTimes, THESIS_FIG_5_6, THESIS_TABLE_5_2, Verdict, thesis_name,
};
use std::fmt::Write;

/// The sections' headings, in page order.
pub const SECTIONS: [&str; 7] = [
    "1. Placement accuracy (thesis Table 5.2)",
    "2. Placement under tracking noise",
    "3. The thesis's law, departure by departure",
    "4. Performance (thesis Fig. 5.6)",
    "5. Scenarios",
    "6. Replays",
    "7. Real hands moving real objects",
];

/// The sections' anchors, in page order.
const SECTION_IDS: [&str; 7] =
    ["accuracy", "noise", "ablation", "performance", "scenarios", "replays", "captures"];

/// The command that writes the accuracy study's JSON.
pub const ACCURACY_COMMAND: &str = "coulomb-hands eval accuracy --json > accuracy.json";
/// The command that writes the benchmark's JSON.
pub const BENCH_COMMAND: &str = "coulomb-hands bench --json > bench.json";

const STYLE: &str = "
body { font-family: system-ui, sans-serif; margin: 0 auto; max-width: 1180px; padding: 0 16px;
       color: #222; line-height: 1.4; }
h1 { margin-bottom: 0.2em; }
h2 { border-bottom: 2px solid #ccc; margin-top: 1.8em; }
h3 { margin-bottom: 0.2em; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 14px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.pass { color: #1a7f37; font-weight: 600; }
.fail { color: #c62828; font-weight: 600; }
.source, .caption, .note { color: #555; font-size: 14px; }
.absent { background: #fff8e1; border-left: 4px solid #f0b400; padding: 6px 10px; }
.row { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; }
figure.plot { display: table; margin: 0; }
figure.plot figcaption { display: table-caption; caption-side: bottom; }
.plot svg { max-width: 100%; height: auto; }
.scenario { border-top: 1px solid #e4e4e4; margin-top: 1em; }
code { background: #f4f4f4; padding: 1px 4px; }
.legend { color: #222; font-weight: 600; display: block; }
";

/// The whole page for `data`. Pure: the same data gives the same text.
pub fn html(data: &ReportData) -> String {
    let mut p = String::with_capacity(1 << 16);
    p.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    p.push_str("<title>coulomb-hands report</title>\n<style>");
    p.push_str(STYLE);
    p.push_str("</style>\n</head>\n<body>\n");
    header(&mut p, data);
    section(&mut p, 0, data.accuracy.as_ref(), accuracy, |p| {
        let how = ("--no-accuracy", ACCURACY_COMMAND, "--accuracy accuracy.json");
        absent(p, "the accuracy study was left out.", Some(how));
        p.push_str("<p>The thesis's Table 5.2 (placement error, mm):</p>\n");
        let rows: Vec<Vec<String>> = thesis_rows(None)
            .iter()
            .map(|row| vec![escape(&row.0), thesis_cell(&row.0, Some(row))])
            .collect();
        table(p, &["method", "thesis: mean ± sd / median (mm)"], &rows);
    });
    section(&mut p, 1, data.sweep.as_ref(), study_page::sweep, |p| {
        let why = "the study was not swept over tracking noise (it takes minutes).";
        let how = ("", SWEEP_COMMAND, "--sweep sweep.json");
        absent(p, why, Some(how));
    });
    section(&mut p, 2, data.ablation.as_ref(), study_page::ablation, |p| {
        let how = ("", ABLATION_COMMAND, "--ablation ablation.json");
        absent(p, "the ablation was not run.", Some(how));
    });
    section(&mut p, 3, data.bench.as_ref(), performance, |p| {
        let how = ("--no-bench", BENCH_COMMAND, "--bench bench.json");
        absent(p, "the benchmark was left out.", Some(how));
        let _ = writeln!(p, "<p>{}</p>", escape(&thesis_fig_5_6()));
    });
    section(&mut p, 4, data.scenarios.as_ref(), scenarios, |p| {
        absent(p, "no scenarios were run.", None);
    });
    section(&mut p, 5, data.replays.as_ref(), replays, |p| {
        absent(p, "no recordings were replayed.", None);
    });
    section(&mut p, 6, data.captures.as_ref(), capture_page::captures, |p| {
        let _ = writeln!(
            p,
            "<p class=\"absent\">Not in this report: the bundled hand–object capture, \
             <code>{CAPTURE_FILE}</code>, is not beside this build (it is in the repository, \
             not in the published crate). Run <code>coulomb-hands report</code> built from the \
             repository, or replay it with one method with <code>coulomb-hands replay \
             {CAPTURE_FILE} --method METHOD</code>.</p>"
        );
    });
    p.push_str("</body>\n</html>\n");
    p
}

/// `mean ± sd / median`.
fn stats(mean: f64, sd: f64, median: f64) -> String {
    format!("{} ± {} / {}", num(mean, 1), num(sd, 1), num(median, 1))
}

/// An id for an anchor: letters, digits and `-`.
fn slug(prefix: &str, name: &str) -> String {
    let s: String = name.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '-' }).collect();
    format!("{prefix}-{s}")
}

fn verdict_class(passed: bool) -> (&'static str, &'static str) {
    if passed { ("pass", "pass") } else { ("fail", "FAIL") }
}

/// Section `i` ([`SECTIONS`]): its heading, then where its data came from
/// and `present` with them, or `absent`.
fn section<T>(
    p: &mut String,
    i: usize,
    data: Option<&Sourced<T>>,
    present: fn(&mut String, &T),
    absent: fn(&mut String),
) {
    let _ = writeln!(p, "<section id=\"{}\">\n<h2>{}</h2>", SECTION_IDS[i], escape(SECTIONS[i]));
    match data {
        Some(d) => {
            let _ = writeln!(p, "<p class=\"source\">Data: {}</p>", escape(&d.source));
            present(p, &d.data);
        }
        None => absent(p),
    }
    p.push_str("</section>\n");
}

/// A missing section's note; `how` is the option that left it out, and the
/// command and option that give it from a file.
fn absent(p: &mut String, why: &str, how: Option<(&str, &str, &str)>) {
    let _ = write!(p, "<p class=\"absent\">Not in this report: {}", escape(why));
    match how {
        Some(("", command, option)) => {
            let _ = write!(
                p,
                " Produce it with <code>{}</code> and pass <code>{}</code> to \
                 <code>coulomb-hands report</code>.",
                escape(command),
                escape(option)
            );
        }
        Some((skip, command, option)) => {
            let _ = write!(
                p,
                " Run <code>coulomb-hands report</code> without <code>{}</code>, or produce \
                 it with <code>{}</code> and pass <code>{}</code>.",
                escape(skip),
                escape(command),
                escape(option)
            );
        }
        None => {}
    }
    p.push_str("</p>\n");
}

fn header(p: &mut String, data: &ReportData) {
    let Header { version, date, machine, build, command } = &data.header;
    p.push_str("<header>\n<h1>coulomb-hands report</h1>\n");
    let mut cells: Vec<Vec<String>> = [("version", version), ("date", date)]
        .iter()
        .chain(&[("machine", machine), ("build", build)])
        .map(|(k, v)| vec![k.to_string(), escape(v)])
        .collect();
    cells.push(vec!["command".into(), format!("<code>{}</code>", escape(command))]);
    let sources = [
        (SECTIONS[0], data.accuracy.as_ref().map(|s| &s.source)),
        (SECTIONS[1], data.sweep.as_ref().map(|s| &s.source)),
        (SECTIONS[2], data.ablation.as_ref().map(|s| &s.source)),
        (SECTIONS[3], data.bench.as_ref().map(|s| &s.source)),
        (SECTIONS[4], data.scenarios.as_ref().map(|s| &s.source)),
        (SECTIONS[5], data.replays.as_ref().map(|s| &s.source)),
        (SECTIONS[6], data.captures.as_ref().map(|s| &s.source)),
    ];
    for (i, (name, source)) in sources.iter().enumerate() {
        let id = SECTION_IDS[i];
        let what = source.map_or("not in this report".to_string(), |s| escape(s));
        cells.push(vec![format!("<a href=\"#{id}\">{}</a>", escape(name)), what]);
    }
    table(p, &[], &cells);
    p.push_str("</header>\n");
}

/// The thesis's Table 5.2 rows as `(method, mean, sd, median)`: the
/// study's own, else the published ones.
fn thesis_rows(study: Option<&AccuracyStudy>) -> Vec<(String, f64, f64, f64)> {
    match study.filter(|s| !s.thesis.is_empty()) {
        Some(s) => {
            s.thesis.iter().map(|t| (t.method.clone(), t.mean_mm, t.sd_mm, t.median_mm)).collect()
        }
        None => THESIS_TABLE_5_2.iter().map(|r| (r.0.to_string(), r.2, r.3, r.4)).collect(),
    }
}

fn thesis_cell(method: &str, row: Option<&(String, f64, f64, f64)>) -> String {
    match row {
        Some((_, mean, sd, median)) => {
            let name = thesis_name(method).map_or(String::new(), |n| format!(" ({})", escape(n)));
            format!("{}{name}", stats(*mean, *sd, *median))
        }
        None => "—".to_string(),
    }
}

fn accuracy(p: &mut String, s: &AccuracyStudy) {
    let thesis = thesis_rows(Some(s));
    let _ = writeln!(
        p,
        "<p>{} synthetic users × {} trials per method, seed {}: a cube moved from a start \
         square to a target square of a chessboard, lifted and placed (<code>lift</code>) or \
         slid over the board between the fingers (<code>slide</code>).{}</p>",
        s.users,
        s.trials,
        s.seed,
        match (s.noise, s.perception, &s.noise_source) {
            (Some(n), Some(g), Some(source)) => format!(
                " Tracking noise ×{n} of {}, {:.2} mm rms per joint and axis; glance errors \
                 ×{g} those of the thesis's headset.",
                escape(&source.kind()),
                s.noise_rms_mm.unwrap_or(source.rms_mm_at(n))
            ),
            // Files written before the study recorded its noise's source
            // ran on the bundled recordings'.
            (Some(n), Some(g), None) => format!(
                " Tracking noise ×{n} the bundled recordings' own; glance errors ×{g} those \
                 of the thesis's headset."
            ),
            _ => String::new(),
        }
    );
    if s.methods.iter().any(|m| m.method.ends_with(')')) {
        p.push_str(
            "<p>A row named <code>METHOD (NAME)</code> is a person's trials of the same task in \
             the viewer (<code>coulomb-hands-view --task chessboard</code>).</p>\n",
        );
    }
    let caption = "Log axis. Blue: this study, each dot a completed trial; box from the first \
                   to the third quartile, line at the median, whiskers to the farthest trial \
                   within 1.5 interquartile ranges. Red: the thesis's Table 5.2, mean ± sd \
                   (bar, dot at the mean) and median (tick).";
    plot(p, &plots::placement(&s.methods, &thesis), caption);
    let find = |m: &str| thesis.iter().find(|t| t.0 == m);
    let mut rows: Vec<Vec<String>> = s
        .methods
        .iter()
        .map(|m| {
            vec![
                escape(&m.label()),
                format!("#{}", m.errors_mm.len()),
                stats(m.mean_mm, m.sd_mm, m.median_mm),
                thesis_cell(&m.method, find(&m.method)),
                cell(m.mean_time_s, 1),
                format!("#{}", m.failed),
                format!("#{}", m.drops),
            ]
        })
        .collect();
    for t in thesis.iter().filter(|t| !s.methods.iter().any(|m| m.method == t.0)) {
        let mut row = vec![escape(&t.0), "#0".into(), "—".into(), thesis_cell(&t.0, Some(t))];
        row.extend(["—", "—", "—"].map(String::from));
        rows.push(row);
    }
    let head = [
        "method",
        "completed trials",
        "error: mean ± sd / median (mm)",
        "thesis Table 5.2 (mm)",
        "time per trial (s)",
        "failed trials",
        "accidental drops",
    ];
    table(p, &head, &rows);
}

fn step_row(name: &str, t: &StepTimes) -> Vec<String> {
    vec![escape(name), cell(t.interaction_us, 1), cell(t.rapier_us, 1), cell(t.full_us, 1)]
}

/// The thesis's Fig. 5.6 in a sentence.
fn thesis_fig_5_6() -> String {
    let points: Vec<String> = THESIS_FIG_5_6
        .iter()
        .map(|(b, us)| format!("{:.1} ms at {b} bones", us / 1000.0))
        .collect();
    format!("The thesis's Fig. 5.6: {} in contact (total physics).", points.join(", "))
}

fn performance(p: &mut String, b: &BenchReport) {
    let thesis = thesis_fig_5_6();
    p.push_str("<div class=\"row\">\n");
    let caption = "Time per physics step (µs) against bones in contact: the interaction layer \
                   (contacts and forces), rapier's step, and the full step.";
    plot(p, &plots::step_time_linear(&b.sweep), caption);
    let caption = format!(
        "The same on a log axis, with the thesis's points and MuJoCo's mj_step on the \
         reference scene ({} bones) when measured. {thesis}",
        b.reference.bones_pressing
    );
    plot(p, &plots::step_time_log(b), &caption);
    p.push_str("</div>\n");
    let mut sweep: Vec<_> = b.sweep.iter().collect();
    sweep.sort_by_key(|s| (s.bones, s.hands));
    let rows: Vec<Vec<String>> = sweep
        .iter()
        .map(|s| {
            let t = s.times;
            let per_bone = if s.bones > 0 { t.full_us / s.bones as f64 } else { f64::NAN };
            let counts = [s.bones, s.hands, s.samples_per_contact].map(|n| format!("#{n}"));
            [&counts[..], &time_cells(&t), &[cell(per_bone, 2)]].concat()
        })
        .collect();
    let head = [
        "bones in contact",
        "hands",
        "samples per contact",
        "interaction layer (µs)",
        "rapier (µs)",
        "full step (µs)",
        "full step per bone (µs)",
    ];
    table(p, &head, &rows);
    let r = &b.reference;
    let _ = writeln!(
        p,
        "<h3>Reference scene</h3>\n<p>Ground, 54-block tower and held boxes: {} bones pressing, \
         {} objects. Asleep: rapier's sleeping as it is (the tower falls asleep); awake: \
         sleeping off, the tower awake as while a hand works on it.</p>\n<div class=\"row\">",
        r.bones_pressing, r.objects
    );
    let caption = "Time per step (µs, log axis) of the reference scene, and MuJoCo's mj_step \
                   on the same scene when measured.";
    plot(p, &plots::reference_bars(b), caption);
    let mut rows = vec![step_row("tower asleep", &r.asleep), step_row("tower awake", &r.awake)];
    rows.push(vec![
        "first second (settling)".into(),
        "—".into(),
        "—".into(),
        cell(r.settling_us, 1),
    ]);
    if let Some(m) = &b.mujoco {
        rows.push(vec!["MuJoCo mj_step".into(), "—".into(), "—".into(), cell(m.step_us, 1)]);
    }
    table(
        p,
        &["reference scene", "interaction layer (µs)", "rapier (µs)", "full step (µs)"],
        &rows,
    );
    p.push_str("</div>\n");
    match &b.mujoco {
        Some(m) => {
            let _ = writeln!(
                p,
                "<p>MuJoCo's settings: {}. Our full step over MuJoCo's step (the median over \
                 pairs of 100-step blocks, ours then MuJoCo's): awake {}, asleep {}.</p>",
                escape(&m.settings),
                num(m.ratio_awake, 3),
                num(m.ratio_asleep, 3)
            );
        }
        None => p.push_str("<p class=\"note\">MuJoCo was not measured in this benchmark.</p>\n"),
    }
    cluttered(p, &b.objects);
}

/// A step's three times as table cells: interaction layer, rapier, full.
fn time_cells(t: &StepTimes) -> [String; 3] {
    [t.interaction_us, t.rapier_us, t.full_us].map(|us| cell(us, 1))
}

/// The cluttered scenes (`bench --objects`): step time against objects.
fn cluttered(p: &mut String, objects: &[ObjectsPoint]) {
    if objects.is_empty() {
        return;
    }
    p.push_str(
        "<h3>Cluttered scenes</h3>\n<p>The reference scene's hands and 16 held boxes among \
         boxes resting on a table below the hands and on shelves around the room (rapier's \
         sleeping on): the interaction layer's cost follows what the hands are near, not the \
         size of the scene.</p>\n<div class=\"row\">",
    );
    let caption = "Time per step (µs) against objects in the scene: the interaction layer, \
                   rapier's step and the full step.";
    plot(p, &plots::step_time_objects(objects), caption);
    let mut sorted: Vec<_> = objects.iter().collect();
    sorted.sort_by_key(|o| o.objects);
    let rows: Vec<Vec<String>> = sorted
        .iter()
        .map(|o| {
            let counts = [o.objects, o.awake, o.bones_pressing].map(|n| format!("#{n}"));
            [&counts[..], &time_cells(&o.times)].concat()
        })
        .collect();
    let head = [
        "objects",
        "awake",
        "bones pressing",
        "interaction layer (µs)",
        "rapier (µs)",
        "full step (µs)",
    ];
    table(p, &head, &rows);
    p.push_str("</div>\n");
}

fn verdicts(p: &mut String, checks: &[Verdict]) {
    let rows: Vec<Vec<String>> = checks
        .iter()
        .map(|c| {
            let (class, word) = verdict_class(c.passed);
            vec![
                escape(&c.name),
                cell(c.value, 4),
                escape(&c.bound),
                format!("<span class=\"{class}\">{word}</span>"),
            ]
        })
        .collect();
    table(p, &["check", "value", "bound", "result"], &rows);
}

fn scenarios(p: &mut String, runs: &Vec<ScenarioRun>) {
    let passed = runs.iter().filter(|r| r.passed).count();
    let _ = writeln!(p, "<p>{passed} of {} scenarios passed every check.</p>", runs.len());
    let rows: Vec<Vec<String>> = runs
        .iter()
        .map(|r| {
            let (class, word) = verdict_class(r.passed);
            let ok = r.checks.iter().filter(|c| c.passed).count();
            vec![
                format!("<a href=\"#{}\">{}</a>", slug("scenario", &r.name), escape(&r.name)),
                format!("<span class=\"{class}\">{word}</span>"),
                format!("#{ok}/{}", r.checks.len()),
                cell(r.wall_s, 2),
            ]
        })
        .collect();
    table(p, &["scenario", "result", "checks passed", "wall-clock (s)"], &rows);
    for r in runs {
        let (class, word) = verdict_class(r.passed);
        let _ = writeln!(
            p,
            "<div class=\"scenario\">\n<h3 id=\"{}\">{} <span class=\"{class}\">{word}</span>\
             </h3>\n<p>{}</p>",
            slug("scenario", &r.name),
            escape(&r.name),
            escape(&r.description)
        );
        if let Some(e) = &r.error {
            let _ = writeln!(p, "<p class=\"fail\">The run stopped: {}</p>", escape(e));
        }
        p.push_str("<div class=\"row\">\n");
        let shown = scenario_plot::shown_objects(r);
        let legend: Vec<String> = shown
            .iter()
            .enumerate()
            .map(|(k, o)| {
                let color = scenario_plot::line_color(k);
                format!("<span style=\"color:{color}\">&#9632;</span>&nbsp;{}", escape(&o.name))
            })
            .collect();
        let mut caption = "Top: the magnitude of the total hand force on each object (Eq. 3.10, \
                           N); bottom: its centre's height (m)."
            .to_string();
        let shown = shown.len();
        if shown < r.objects.len() {
            let _ = write!(
                caption,
                " Showing {shown} of {} objects: those the hands pushed hardest, then those \
                 whose height changed most.",
                r.objects.len()
            );
        }
        let legend = format!("<span class=\"legend\">{}</span> ", legend.join(" &nbsp; "));
        plot_with_legend(p, &scenario_plot::scenario(r), &legend, &caption);
        verdicts(p, &r.checks);
        p.push_str("</div>\n</div>\n");
    }
}

fn replays(p: &mut String, runs: &Vec<ReplayRun>) {
    for r in runs {
        let _ = writeln!(
            p,
            "<h3 id=\"{}\">{}</h3>",
            slug("replay", &r.recording),
            escape(&r.recording)
        );
        if let Some(e) = &r.error {
            let _ = writeln!(p, "<p class=\"fail\">The replay stopped: {}</p>", escape(e));
        }
        let mut rows = vec![
            vec!["format".into(), escape(&r.format)],
            vec!["frames, hands".into(), format!("{}, {}", r.frames, r.hands)],
            vec![
                "duration (s), physics steps".into(),
                format!("{}, {}", num(r.duration_s, 2), r.steps),
            ],
            vec!["objects at the closings".into(), escape(&r.placed)],
            vec!["contacts begun".into(), r.contacts_begun.to_string()],
        ];
        for o in &r.objects {
            rows.push(vec![
                format!("object {}: displacement (m), max speed (m/s)", escape(&o.name)),
                format!("{}, {}", num(o.displacement_m, 3), num(o.max_speed_m_s, 3)),
            ]);
        }
        rows.push(vec!["all values finite".into(), r.all_finite.to_string()]);
        rows.push(vec!["tracking glitches left out".into(), r.glitches.to_string()]);
        table(p, &[], &rows);
        if r.verdicts.is_empty() && r.not_judged.is_empty() {
            p.push_str("<p class=\"note\">No hand closes in this recording.</p>\n");
        }
        if !r.verdicts.is_empty() {
            p.push_str("<p>Verdicts per closing of the hand:</p>\n");
            verdicts(p, &r.verdicts);
        }
        if !r.not_judged.is_empty() {
            p.push_str("<p>Closings not judged:</p>\n<ul>\n");
            for line in &r.not_judged {
                let _ = writeln!(p, "<li>{}</li>", escape(line));
            }
            p.push_str("</ul>\n");
        }
    }
}
