//! `eval`: the positioning-accuracy study, printed beside the thesis's
//! Table 5.2 (`accuracy`); the same swept over tracking noise (`sweep`);
//! and the thesis's law given its departures back one at a time
//! (`ablation`).

use super::progress_bar;
use coulomb_hands::RunError;
use coulomb_hands::eval::ablation::{Ablation, AblationOptions};
use coulomb_hands::eval::stats::Estimate;
use coulomb_hands::eval::sweep::{SweepOptions, SweepStudy};
use coulomb_hands::eval::{AccuracyOptions, AccuracyStudy, accuracy};
use std::io::IsTerminal;

const BAR: &str = "{bar:30} {pos}/{len} trials ({elapsed}, eta {eta})";

/// Runs `study` with a progress bar of `total` trials on stderr if `show`.
fn with_bar<T>(
    show: bool,
    total: usize,
    study: impl FnOnce(&mut dyn FnMut(usize, usize)) -> Result<T, RunError>,
) -> Result<T, RunError> {
    let bar = progress_bar(show, total as u64, BAR);
    let out = study(&mut |done, _| bar.set_position(done as u64));
    bar.finish_and_clear();
    out
}

/// Prints `value` as pretty JSON if `json`, else as `table` prints it.
fn print<T: serde::Serialize>(value: &T, json: bool, table: fn(&T)) -> Result<(), RunError> {
    if json {
        println!("{}", serde_json::to_string_pretty(value).map_err(std::io::Error::other)?);
    } else {
        table(value);
    }
    Ok(())
}

/// Runs the study with a progress bar on stderr if `show`.
pub fn study(options: &AccuracyOptions, show: bool) -> Result<AccuracyStudy, RunError> {
    let runs = options.methods.len() * options.strategies.len();
    with_bar(show, options.users * options.trials * runs, |p| accuracy(options, p))
}

/// `eval accuracy`: runs the study and prints its table, or one JSON object.
pub fn run(options: &AccuracyOptions, json: bool) -> Result<(), RunError> {
    let report = study(options, !json && std::io::stderr().is_terminal())?;
    print(&report, json, print_table)
}

/// A number to `digits` places, or `—`.
fn num(v: f64, digits: usize) -> String {
    if v.is_finite() { format!("{v:.digits$}") } else { "—".into() }
}

/// `value [low, high]` to `digits` places.
fn ci(e: &Estimate, digits: usize) -> String {
    format!("{} [{}, {}]", num(e.value, digits), num(e.low, digits), num(e.high, digits))
}

/// Table 5.2's shape: one row per method and strategy, the thesis's figure
/// beside it.
fn print_table(r: &AccuracyStudy) {
    let noise = r.noise.map_or("—".into(), |n| format!("{n}"));
    let sight = r.perception.map_or("—".into(), |p| format!("{p}"));
    println!(
        "positioning accuracy (thesis §5.2): {} synthetic users x {} trials, seed {}, \
         tracking noise x{noise}, glance errors x{sight}",
        r.users, r.trials, r.seed
    );
    println!(
        "{:<10} {:<6} {:>24} {:>7} {:>7} {:>6} {:>9}  {:>20}",
        "method",
        "moves",
        "error mm: mean ± sd / med",
        "time s",
        "failed",
        "drops",
        "held mm",
        "thesis (Table 5.2)"
    );
    for m in &r.methods {
        let thesis =
            r.thesis.iter().find(|t| t.method == m.method).map_or("—".to_string(), |t| {
                format!("{:.1} ± {:.1} / {:.1}", t.mean_mm, t.sd_mm, t.median_mm)
            });
        let error =
            format!("{} ± {} / {}", num(m.mean_mm, 1), num(m.sd_mm, 1), num(m.median_mm, 1));
        let held = m.held_across_mm.map_or("—".into(), |h| format!("{h:+.1}"));
        println!(
            "{:<10} {:<6} {error:>24} {:>7} {:>7} {:>6} {held:>9}  {thesis:>20}",
            m.method,
            m.strategy.as_deref().unwrap_or("—"),
            num(m.mean_time_s, 2),
            m.failed,
            m.drops
        );
    }
    let rows = "its method, the Leap Motion Interaction Engine, its re-implementation of [23]";
    println!("(the thesis's rows: {rows})");
    println!(
        "(held mm: where the cube sat across the grip as the hand began to open on it, \
         towards the fingers)"
    );
}

/// `eval sweep`: runs the sweep and prints its table, or one JSON object.
pub fn sweep(options: &SweepOptions, json: bool) -> Result<(), RunError> {
    let conditions = options.methods.len() * options.strategies.len() * options.noise.len();
    let total = conditions * options.seeds.len() * options.users * options.trials;
    let show = !json && std::io::stderr().is_terminal();
    let study = with_bar(show, total, |p| coulomb_hands::eval::sweep::sweep(options, p))?;
    print(&study, json, print_sweep)
}

fn print_sweep(s: &SweepStudy) {
    let seeds: Vec<String> = s.seeds.iter().map(u64::to_string).collect();
    println!(
        "placement study over tracking noise: seeds {}, {} users x {} trials each, \
         glance errors x{}",
        seeds.join(","),
        s.users,
        s.trials,
        s.perception
    );
    println!(
        "noise x1: {} (rms {:.2} mm per joint and axis; {:.2} dropouts/s of {:.0} ms)",
        s.noise.sources.join(", "),
        s.noise.rms_mm,
        s.noise.dropouts_per_s,
        s.noise.dropout_ms
    );
    println!(
        "{:<10} {:<6} {:>5} {:>20} {:>6} {:>20} {:>18} {:>18}",
        "method",
        "moves",
        "noise",
        "error mm [95% CI]",
        "median",
        "time s",
        "failed %",
        "drops/trial"
    );
    for r in &s.rows {
        let pct = |e: &Estimate| Estimate {
            value: e.value * 100.0,
            low: e.low * 100.0,
            high: e.high * 100.0,
        };
        println!(
            "{:<10} {:<6} {:>5} {:>20} {:>6} {:>20} {:>18} {:>18}",
            r.method,
            r.strategy,
            format!("x{}", r.noise),
            ci(&r.error_mm, 1),
            num(r.median_mm, 1),
            ci(&r.time_s, 1),
            ci(&pct(&r.failed), 0),
            ci(&r.drops, 2)
        );
    }
}

/// `eval ablation`: runs the ablation and prints its table, or one JSON
/// object.
pub fn ablation(options: &AblationOptions, json: bool) -> Result<(), RunError> {
    let configs = coulomb_hands::eval::ablation::configurations().len();
    let total = configs * options.strategies.len() * options.users * options.trials;
    let show = !json && std::io::stderr().is_terminal();
    let study = with_bar(show, total, |p| coulomb_hands::eval::ablation::ablation(options, p))?;
    print(&study, json, print_ablation)
}

fn print_ablation(a: &Ablation) {
    println!(
        "the thesis's law, with one departure at a time: {} users x {} trials, seed {}",
        a.users, a.trials, a.seed
    );
    println!(
        "{:<32} {:<6} {:>10} {:>18} {:>20}",
        "configuration", "moves", "completed", "drops/trial", "error mm [95% CI]"
    );
    for r in &a.rows {
        println!(
            "{:<32} {:<6} {:>10} {:>18} {:>20}",
            r.config,
            r.strategy,
            format!("{} of {}", r.completed, r.trials),
            ci(&r.drops, 2),
            ci(&r.error_mm, 1)
        );
    }
}
