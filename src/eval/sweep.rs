//! The placement study swept over tracking noise: every method with every
//! strategy, at several strengths of the real tracking noise, on the users
//! and trials of several seeds, with 95 % confidence intervals.

use super::noise::TrackingNoise;
use super::stats;
use super::trial::{self, Condition, TrialRun};
use super::{Conditions, Strategy, check_some};
pub use crate::output::report::{NoiseSummary, SweepRow, SweepStudy};
use crate::pipeline::{InteractionConfig, Method};
use crate::run::RunError;

/// What to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepOptions {
    /// Users per seed.
    pub users: usize,
    /// Trials per user.
    pub trials: usize,
    /// One set of users and trials per seed.
    pub seeds: Vec<u64>,
    /// The noise strengths, in [`Conditions::noise_unit`]s (0: a perfect
    /// tracker).
    pub noise: Vec<f32>,
    /// The methods compared.
    pub methods: Vec<Method>,
    /// How the users move the cube.
    pub strategies: Vec<Strategy>,
    /// How the trials run, besides the noise's strength.
    pub conditions: Conditions,
}

impl Default for SweepOptions {
    fn default() -> Self {
        SweepOptions {
            users: Self::USERS,
            trials: Self::TRIALS,
            seeds: Self::SEEDS.to_vec(),
            noise: Self::NOISE.to_vec(),
            methods: Method::ALL.to_vec(),
            strategies: Strategy::ALL.to_vec(),
            conditions: Conditions::default(),
        }
    }
}

impl SweepOptions {
    /// The default users per seed.
    pub const USERS: usize = 4;
    /// The default trials per user.
    pub const TRIALS: usize = 5;
    /// The default seeds: three draws of users and trials.
    pub const SEEDS: [u64; 3] = [1, 2, 3];
    /// The default noise strengths: none, half, the recordings' own, twice.
    pub const NOISE: [f32; 4] = [0.0, 0.5, 1.0, 2.0];
}

/// The summary of `noise`.
pub(crate) fn summary(noise: &TrackingNoise) -> NoiseSummary {
    let lengths: Vec<f64> = noise.dropout_lengths.iter().map(|l| l * 1e3).collect();
    NoiseSummary {
        sources: noise.sources.clone(),
        rms_mm: noise.rms_mm(1.0),
        dropouts_per_s: noise.dropout_rate,
        dropout_ms: if lengths.is_empty() { 0.0 } else { stats::describe(&lengths).0 },
    }
}

/// The row of `runs`, all of one condition.
fn row(method: &str, strategy: Strategy, noise: f32, runs: &[TrialRun]) -> SweepRow {
    let done: Vec<&TrialRun> = runs.iter().filter(|r| !r.trial.failed).collect();
    let errors: Vec<f64> = done.iter().map(|r| f64::from(r.trial.error) * 1e3).collect();
    let times: Vec<f64> = done.iter().map(|r| r.trial.time).collect();
    let drops: Vec<f64> = runs.iter().map(|r| r.trial.drops as f64).collect();
    let across: Vec<f64> =
        runs.iter().filter_map(|r| r.held_at).map(|p| f64::from(p.x) * 1e3).collect();
    SweepRow {
        method: method.to_string(),
        strategy: strategy.name().to_string(),
        noise,
        trials: runs.len(),
        error_mm: stats::nonnegative_ci(&errors),
        median_mm: stats::describe(&errors).2,
        time_s: stats::mean_ci(&times),
        failed: stats::proportion_ci(runs.len() - done.len(), runs.len()),
        drops: stats::nonnegative_ci(&drops),
        held_across_mm: (!across.is_empty()).then(|| stats::describe(&across).0),
    }
}

/// Runs the sweep. `progress(done, total)` is called as trials finish.
pub fn sweep(
    options: &SweepOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<SweepStudy, RunError> {
    for &s in &options.noise {
        options.conditions.check_noise(s)?;
    }
    for (field, n) in [
        ("users", options.users),
        ("trials", options.trials),
        ("seed", options.seeds.len()),
        ("noise", options.noise.len()),
        ("method", options.methods.len()),
        ("strategy", options.strategies.len()),
    ] {
        check_some(field, n)?;
    }
    let noise = options.conditions.noise()?;
    let tasks: Vec<_> = options
        .seeds
        .iter()
        .flat_map(|&seed| trial::tasks(options.users, options.trials, seed))
        .collect();
    let conditions = options.methods.len() * options.strategies.len() * options.noise.len();
    let total = conditions * tasks.len();
    let mut rows = Vec::new();
    for &method in &options.methods {
        for &strategy in &options.strategies {
            for &level in &options.noise {
                let scale = options.conditions.scale(&noise, level)?;
                let condition = Condition {
                    config: method.config(InteractionConfig::default()),
                    strategy,
                    noise: &noise,
                    noise_scale: scale,
                    perception: options.conditions.perception,
                };
                let done = rows.len() * tasks.len();
                let mut each = |n| progress(done + n, total);
                let threads = options.conditions.threads;
                let runs = trial::run_all(&condition, &tasks, threads, &mut each)?;
                rows.push(row(method.name(), strategy, scale, &runs));
            }
        }
    }
    Ok(SweepStudy {
        users: options.users,
        trials: options.trials,
        seeds: options.seeds.clone(),
        perception: options.conditions.perception,
        noise: summary(&noise),
        rows,
    })
}
