//! `eval accuracy`: the positioning-accuracy study, printed beside the
//! thesis's Table 5.2.

use super::progress_bar;
use coulomb_hands::RunError;
use coulomb_hands::eval::{AccuracyOptions, AccuracyStudy, accuracy};

/// Runs the study with a progress bar on stderr if `show`.
pub fn study(options: &AccuracyOptions, show: bool) -> Result<AccuracyStudy, RunError> {
    let total = (options.users * options.trials * options.methods.len()) as u64;
    let bar = progress_bar(show, total, "{bar:30} {pos}/{len} trials ({elapsed}, eta {eta})");
    let report = accuracy(options, &mut |done, _| bar.set_position(done as u64));
    bar.finish_and_clear();
    report
}

/// `eval accuracy`: runs the study and prints its table, or one JSON object.
pub fn run(options: &AccuracyOptions, json: bool) -> Result<(), RunError> {
    use std::io::IsTerminal;
    let report = study(options, !json && std::io::stderr().is_terminal())?;
    if json {
        println!("{}", serde_json::to_string_pretty(&report).map_err(std::io::Error::other)?);
    } else {
        print_table(&report);
    }
    Ok(())
}

/// Table 5.2's shape: one row per method, the thesis's figure beside it.
fn print_table(r: &AccuracyStudy) {
    println!(
        "positioning accuracy (thesis §5.2): {} synthetic users x {} trials, seed {}",
        r.users, r.trials, r.seed
    );
    println!(
        "{:<10} {:>24} {:>8} {:>7} {:>6}  {:>20}",
        "method", "error mm: mean ± sd / med", "time s", "failed", "drops", "thesis (Table 5.2)"
    );
    for m in &r.methods {
        let thesis =
            r.thesis.iter().find(|t| t.method == m.method).map_or("—".to_string(), |t| {
                format!("{:.1} ± {:.1} / {:.1}", t.mean_mm, t.sd_mm, t.median_mm)
            });
        let [mean, sd, median, time] =
            [(m.mean_mm, 1), (m.sd_mm, 1), (m.median_mm, 1), (m.mean_time_s, 2)].map(
                |(v, digits)| if v.is_finite() { format!("{v:.digits$}") } else { "—".into() },
            );
        let error = format!("{mean} ± {sd} / {median}");
        println!(
            "{:<10} {error:>24} {time:>8} {:>7} {:>6}  {thesis:>20}",
            m.method, m.failed, m.drops
        );
    }
    let rows = "its method, the Leap Motion Interaction Engine, its re-implementation of [23]";
    println!("(the thesis's rows: {rows})");
}
