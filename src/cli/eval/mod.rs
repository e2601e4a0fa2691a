//! `eval`: the positioning-accuracy study, printed beside the thesis's
//! Table 5.2 (`accuracy`); the same swept over tracking noise (`sweep`);
//! the thesis's law given its departures back one at a time
//! (`ablation`); and how far the hand that acts lags the tracked hand
//! (`latency`). One file each; `options` holds the option groups they
//! share.

pub mod ablation;
pub mod accuracy;
pub mod latency;
pub mod options;
pub mod sweep;

use super::options::JsonOutput;
use super::{Outcome, progress_bar};
use coulomb_hands::RunError;
use coulomb_hands::eval::stats::Estimate;
use std::io::IsTerminal;

/// The evaluation of thesis Ch. 5.
#[derive(clap::Args)]
pub struct EvalArgs {
    #[command(subcommand)]
    study: Study,
}

#[derive(clap::Subcommand)]
enum Study {
    Accuracy(accuracy::AccuracyArgs),
    Sweep(sweep::SweepArgs),
    Ablation(ablation::AblationArgs),
    Latency(latency::LatencyArgs),
}

impl EvalArgs {
    /// Runs the study asked for.
    pub fn run(self) -> Outcome {
        match self.study {
            Study::Accuracy(args) => args.run(),
            Study::Sweep(args) => args.run(),
            Study::Ablation(args) => args.run(),
            Study::Latency(args) => args.run(),
        }
    }
}

const BAR: &str = "{bar:30} {pos}/{len} trials ({elapsed}, eta {eta})";

/// Whether a study shows its progress: on a terminal, unless its output is JSON.
fn shows_progress(output: &JsonOutput) -> bool {
    !output.json && std::io::stderr().is_terminal()
}

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

/// A number to `digits` places, or `—`.
fn num(v: f64, digits: usize) -> String {
    if v.is_finite() { format!("{v:.digits$}") } else { "—".into() }
}

/// `value [low, high]` to `digits` places.
fn ci(e: &Estimate, digits: usize) -> String {
    format!("{} [{}, {}]", num(e.value, digits), num(e.low, digits), num(e.high, digits))
}
