//! `eval sweep`: the accuracy study at several strengths of real
//! tracking noise and on several seeds' users, with confidence intervals.

use super::options::{ConditionArgs, MethodsArg, StrategiesArg, SweepSize, comma_list, scale};
use super::{ci, num, shows_progress, with_bar};
use crate::cli::Outcome;
use crate::cli::options::JsonOutput;
use coulomb_hands::eval::NoiseUnit;
use coulomb_hands::eval::stats::Estimate;
use coulomb_hands::eval::sweep::{SweepOptions, SweepStudy, sweep};
use std::sync::LazyLock;

/// The default seeds, as `--seeds` takes them.
static SEEDS: LazyLock<String> = LazyLock::new(|| comma_list(&SweepOptions::SEEDS));
/// The default noise strengths, as `--noise` takes them.
static NOISE: LazyLock<String> = LazyLock::new(|| comma_list(&SweepOptions::NOISE));

/// The accuracy study at several strengths of real tracking noise, on several seeds'
/// users, with 95 % confidence intervals.
#[derive(clap::Args)]
pub struct SweepArgs {
    #[command(flatten)]
    size: SweepSize,
    /// Seeds, comma-separated: each draws its own users and trials.
    #[arg(long, value_delimiter = ',', default_value = SEEDS.as_str())]
    seeds: Vec<u64>,
    /// Tracking noise strengths, times the recordings', comma-separated.
    #[arg(long, value_name = "SCALE,...", value_delimiter = ',', default_value = NOISE.as_str(),
          value_parser = scale)]
    noise: Vec<f32>,
    /// Tracking noise strengths by their rms per joint and axis, comma-separated: the
    /// recordings' residuals scaled to each (instead of --noise).
    #[arg(long, value_name = "MM,...", value_delimiter = ',', value_parser = scale,
          conflicts_with = "noise")]
    noise_mm: Option<Vec<f32>>,
    #[command(flatten)]
    methods: MethodsArg,
    #[command(flatten)]
    strategies: StrategiesArg,
    #[command(flatten)]
    condition: ConditionArgs,
    #[command(flatten)]
    output: JsonOutput,
}

impl SweepArgs {
    /// Runs the sweep and prints its table, or one JSON object.
    pub fn run(self) -> Outcome {
        let show = shows_progress(&self.output);
        let (noise, unit) = NoiseUnit::choose(self.noise, self.noise_mm);
        let options = SweepOptions {
            users: self.size.users,
            trials: self.size.trials,
            seeds: self.seeds,
            noise,
            methods: self.methods.method,
            strategies: self.strategies.strategy,
            conditions: self.condition.conditions(unit),
        };
        let conditions = options.methods.len() * options.strategies.len() * options.noise.len();
        let total = conditions * options.seeds.len() * options.users * options.trials;
        let study = with_bar(show, total, |p| sweep(&options, p))?;
        Ok(self.output.print(&study, print_sweep)?)
    }
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
        "noise x1: {} (rms {:.2} mm per joint and axis; {})",
        s.noise.sources.join(", "),
        s.noise.rms_mm,
        s.noise.dropouts()
    );
    println!(
        "{:<10} {:<6} {:>6} {:>6} {:>20} {:>6} {:>20} {:>18} {:>18}",
        "method",
        "moves",
        "noise",
        "rms mm",
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
            "{:<10} {:<6} {:>6} {:>6.2} {:>20} {:>6} {:>20} {:>18} {:>18}",
            r.method,
            r.strategy,
            format!("x{:.3}", r.noise).trim_end_matches('0').trim_end_matches('.'),
            s.noise.rms_mm_at(r.noise),
            ci(&r.error_mm, 1),
            num(r.median_mm, 1),
            ci(&r.time_s, 1),
            ci(&pct(&r.failed), 0),
            ci(&r.drops, 2)
        );
    }
}
