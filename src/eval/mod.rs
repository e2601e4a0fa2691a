//! The evaluation of thesis Ch. 5, headless. [`accuracy`] is the
//! positioning-accuracy study of §5.2 (Table 5.2): synthetic users move a
//! cube across a chessboard with each method, and the placement errors
//! are compared. [`sweep::sweep`] runs it at several strengths of real
//! tracking noise and seeds, with confidence intervals; [`ablation`]
//! gives the thesis's law as written this crate's departures one at a
//! time.
//!
//! * [`board`]: the task's world (board, cube, squares);
//! * [`grip`]: the users' hand;
//! * [`noise`]: tracking noise and dropouts taken from real recordings;
//! * [`perception`]: what a user sees of the cube, and how well;
//! * [`user`]: a synthetic user, a closed-loop controller of one tracked
//!   hand, and the eyes through which it sees the cube;
//! * [`trial`]: one trial, and many on several threads;
//! * [`stats`]: means and proportions with confidence intervals;
//! * [`latency`]: how far the hand that acts lags the tracked hand.

pub mod ablation;
pub mod board;
pub mod glitch;
pub mod grip;
pub mod latency;
pub mod noise;
pub mod perception;
pub mod stats;
pub mod sweep;
pub mod trial;
pub mod user;

pub use crate::output::report::{AccuracyStudy, MethodResult, ThesisResult};
pub use trial::{TRIAL_LIMIT, Trial};
pub use user::Strategy;

use crate::output::report::THESIS_TABLE_5_2;
use crate::pipeline::{InteractionConfig, Method};
use crate::run::RunError;
use noise::TrackingNoise;
use std::path::PathBuf;
use trial::{Condition, TrialRun};

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct AccuracyOptions {
    /// Synthetic users (the thesis had 6).
    pub users: usize,
    /// Trials per user (the thesis had 20).
    pub trials: usize,
    /// Seed of users, squares, tracking noise and glances.
    pub seed: u64,
    /// The methods compared, each on the same users and trials.
    pub methods: Vec<Method>,
    /// How the users move the cube: each method is run with each.
    pub strategies: Vec<Strategy>,
    /// Tracking noise, in [`Conditions::noise_unit`]s (0: a perfect
    /// tracker).
    pub noise: f32,
    /// How the trials run, besides the noise's strength.
    pub conditions: Conditions,
}

/// What a study's noise strengths count.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NoiseUnit {
    /// Times the recordings' own residuals.
    #[default]
    Times,
    /// The residuals' rms per joint and axis, in mm: the recordings'
    /// residuals scaled to it.
    RmsMm,
}

impl NoiseUnit {
    /// The noise strengths asked for and what they count: `rms_mm` when
    /// given (`--noise-mm`), else `times` (`--noise`).
    pub fn choose<T>(times: T, rms_mm: Option<T>) -> (T, NoiseUnit) {
        match rms_mm {
            Some(mm) => (mm, NoiseUnit::RmsMm),
            None => (times, NoiseUnit::Times),
        }
    }

    /// The scale on `noise`'s residuals of the strength `level` in this
    /// unit.
    pub(crate) fn scale(self, noise: &TrackingNoise, level: f32) -> Result<f32, RunError> {
        match self {
            NoiseUnit::Times => Ok(level),
            NoiseUnit::RmsMm => noise.scale_for_rms_mm(level),
        }
    }

    /// Checks a strength in this unit: finite and ≥ 0, named by its option.
    pub(crate) fn check(self, level: f32) -> Result<(), RunError> {
        let option = match self {
            NoiseUnit::Times => "noise",
            NoiseUnit::RmsMm => "noise-mm",
        };
        check_scale(option, level)
    }
}

/// How every trial of a study runs, besides its noise strength: shared
/// by [`AccuracyOptions`], [`sweep::SweepOptions`] and
/// [`ablation::AblationOptions`].
#[derive(Debug, Clone, PartialEq)]
pub struct Conditions {
    /// The glances' errors, times the display's (0: exact sight).
    pub perception: f32,
    /// The recordings to take the noise from (none: the bundled ones).
    pub noise_from: Vec<PathBuf>,
    /// Or white noise, drawn for a tracker at this frame rate (Hz)
    /// ([`TrackingNoise::white`]), instead of recordings'.
    pub noise_white: Option<f32>,
    /// What the noise strengths count.
    pub noise_unit: NoiseUnit,
    /// Threads to run trials on (the outcomes do not depend on it).
    pub threads: usize,
}

impl Default for Conditions {
    fn default() -> Self {
        let threads = trial::default_threads();
        let (noise_from, noise_unit) = (Vec::new(), NoiseUnit::Times);
        let perception = Self::PERCEPTION;
        Conditions { perception, noise_from, noise_white: None, noise_unit, threads }
    }
}

impl Conditions {
    /// The default glance errors: the thesis's headset's.
    pub const PERCEPTION: f32 = 1.0;

    /// Checks the glance scale and loads the tracking noise.
    pub(crate) fn noise(&self) -> Result<TrackingNoise, RunError> {
        check_scale("perception", self.perception)?;
        TrackingNoise::choose(&self.noise_from, self.noise_white)
    }

    /// The scale on `noise`'s residuals of the strength `level`, in this
    /// study's [`NoiseUnit`].
    pub(crate) fn scale(&self, noise: &TrackingNoise, level: f32) -> Result<f32, RunError> {
        self.noise_unit.scale(noise, level)
    }

    /// Checks a noise strength: finite and ≥ 0, in mm or times.
    pub(crate) fn check_noise(&self, level: f32) -> Result<(), RunError> {
        self.noise_unit.check(level)
    }
}

impl Default for AccuracyOptions {
    fn default() -> Self {
        AccuracyOptions {
            users: Self::USERS,
            trials: Self::TRIALS,
            seed: Self::SEED,
            methods: Method::ALL.to_vec(),
            strategies: Strategy::ALL.to_vec(),
            noise: Self::NOISE,
            conditions: Conditions::default(),
        }
    }
}

impl AccuracyOptions {
    /// The default users: the thesis's 6.
    pub const USERS: usize = 6;
    /// The default trials per user: the thesis's 20.
    pub const TRIALS: usize = 20;
    /// The default seed, of this study and of the ablation.
    pub const SEED: u64 = 1;
    /// The default tracking noise, of this study and of the ablation: the
    /// recordings' own.
    pub const NOISE: f32 = 1.0;

    /// Checks what a run needs: users, trials, a method and a strategy,
    /// and scales that are finite and not negative.
    pub fn validate(&self) -> Result<(), RunError> {
        self.conditions.check_noise(self.noise)?;
        check_some("users", self.users)?;
        check_some("trials", self.trials)?;
        check_some("method", self.methods.len())?;
        check_some("strategy", self.strategies.len())
    }
}

/// A scale of noise or of glance errors must be finite and ≥ 0.
pub(crate) fn check_scale(field: &'static str, v: f32) -> Result<(), RunError> {
    if v.is_finite() && v >= 0.0 {
        return Ok(());
    }
    Err(RunError::Study { field, reason: format!("must be a finite scale ≥ 0, got {v}") })
}

/// A count the study needs at least one of.
pub(crate) fn check_some(field: &'static str, n: usize) -> Result<(), RunError> {
    if n > 0 {
        return Ok(());
    }
    Err(RunError::Study { field, reason: "needs at least one".into() })
}

/// Table 5.2 of the thesis, as the study compares with it.
pub fn thesis_table() -> Vec<ThesisResult> {
    let row = |&(method, _, mean_mm, sd_mm, median_mm): &(&str, &str, f64, f64, f64)| {
        ThesisResult { method: method.into(), mean_mm, sd_mm, median_mm }
    };
    THESIS_TABLE_5_2.iter().map(row).collect()
}

/// One method's results from its trials, under the name `method` (a
/// method's, or a person's row from the viewer's task).
pub fn summarise(method: &str, trials: &[Trial]) -> MethodResult {
    let done: Vec<&Trial> = trials.iter().filter(|t| !t.failed).collect();
    let errors_mm: Vec<f64> = done.iter().map(|t| t.error as f64 * 1e3).collect();
    let (mean_mm, sd_mm, median_mm) = stats::describe(&errors_mm);
    let times: Vec<f64> = done.iter().map(|t| t.time).collect();
    MethodResult {
        method: method.into(),
        strategy: None,
        mean_mm,
        sd_mm,
        median_mm,
        errors_mm,
        mean_time_s: stats::describe(&times).0,
        times_s: times,
        failed: trials.len() - done.len(),
        drops: trials.iter().map(|t| t.drops).sum(),
        held_across_mm: None,
    }
}

/// The mean of where the cube sat across the grip (mm, towards the
/// fingers) as the hands began to open on it, over the trials that got
/// that far.
fn held_across_mm(runs: &[TrialRun]) -> Option<f64> {
    let across: Vec<f64> =
        runs.iter().filter_map(|r| r.held_at).map(|p| f64::from(p.x) * 1e3).collect();
    (!across.is_empty()).then(|| stats::describe(&across).0)
}

/// The positioning-accuracy study: every method with every strategy on
/// the same users and trials. `progress(done, total)` is called as trials
/// finish.
pub fn accuracy(
    options: &AccuracyOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<AccuracyStudy, RunError> {
    options.validate()?;
    let noise = options.conditions.noise()?;
    let scale = options.conditions.scale(&noise, options.noise)?;
    let tasks = trial::tasks(options.users, options.trials, options.seed);
    let runs = options.methods.len() * options.strategies.len();
    let total = tasks.len() * runs;
    let mut methods = Vec::new();
    for (k, (&method, &strategy)) in options
        .methods
        .iter()
        .flat_map(|m| options.strategies.iter().map(move |s| (m, s)))
        .enumerate()
    {
        let condition = Condition {
            config: method.config(InteractionConfig::default()),
            strategy,
            noise: &noise,
            noise_scale: scale,
            perception: options.conditions.perception,
        };
        let done = k * tasks.len();
        let outcomes = trial::run_all(&condition, &tasks, options.conditions.threads, &mut |n| {
            progress(done + n, total)
        })?;
        let trials: Vec<Trial> = outcomes.iter().map(|r| r.trial).collect();
        let mut row = summarise(method.name(), &trials);
        row.strategy = Some(strategy.name().to_string());
        row.held_across_mm = held_across_mm(&outcomes);
        methods.push(row);
    }
    Ok(AccuracyStudy {
        users: options.users,
        trials: options.trials,
        seed: options.seed,
        noise: Some(scale),
        noise_rms_mm: Some(noise.rms_mm(scale)),
        noise_source: Some(sweep::summary(&noise)),
        perception: Some(options.conditions.perception),
        methods,
        thesis: thesis_table(),
    })
}
