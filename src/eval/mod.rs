//! The evaluation of thesis Ch. 5, headless. [`accuracy`] is the
//! positioning-accuracy study of §5.2 (Table 5.2): synthetic users move a
//! cube across a chessboard with each method, and the placement errors
//! are compared.
//!
//! * [`board`]: the task's world (board, cube, squares);
//! * [`grip`]: the users' hand;
//! * [`user`]: a synthetic user, a closed-loop controller of one tracked
//!   hand, and the eyes through which it sees the cube.

pub mod board;
pub mod grip;
pub mod user;

pub use crate::output::report::{AccuracyStudy, MethodResult, ThesisResult};

use crate::output::report::THESIS_TABLE_5_2;
use crate::pipeline::{InteractionConfig, Method};
use crate::run::RunError;
use crate::run::drive::Driver;
use glam::Vec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use user::{Eyes, User, UserParams};

/// A trial that has not finished after this long (s) has failed.
pub const TRIAL_LIMIT: f64 = 40.0;

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct AccuracyOptions {
    /// Synthetic users (the thesis had 6).
    pub users: usize,
    /// Trials per user (the thesis had 20).
    pub trials: usize,
    /// Seed of users, squares and jitter.
    pub seed: u64,
    /// The methods compared, each on the same users and trials.
    pub methods: Vec<Method>,
}

impl Default for AccuracyOptions {
    fn default() -> Self {
        AccuracyOptions { users: 6, trials: 20, seed: 1, methods: Method::ALL.to_vec() }
    }
}

/// One trial's outcome.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Trial {
    /// Horizontal distance from the cube's centre to the target square's
    /// centre at the end (m).
    pub error: f32,
    /// Time until the user was done (s), or the limit.
    pub time: f64,
    /// The user did not finish within [`TRIAL_LIMIT`], or the cube left
    /// the board.
    pub failed: bool,
    /// Times the cube fell out of the hand while lifted or carried.
    pub drops: usize,
}

/// Table 5.2 of the thesis, as the study compares with it.
pub fn thesis_table() -> Vec<ThesisResult> {
    let row = |&(method, _, mean_mm, sd_mm, median_mm): &(&str, &str, f64, f64, f64)| {
        ThesisResult { method: method.into(), mean_mm, sd_mm, median_mm }
    };
    THESIS_TABLE_5_2.iter().map(row).collect()
}

/// One task: a user and their start and target squares.
#[derive(Debug, Clone, Copy)]
struct Task {
    params: UserParams,
    start: (usize, usize),
    target: (usize, usize),
    yaw: f32,
    seed: u64,
}

/// The tasks of the study, the same for every method.
fn tasks(options: &AccuracyOptions) -> Vec<Task> {
    let mut out = Vec::new();
    for u in 0..options.users {
        let mut rng = ChaCha8Rng::seed_from_u64(options.seed ^ ((u as u64 + 1) * 0x9E37_79B9));
        let params = UserParams::draw(&mut rng);
        for _ in 0..options.trials {
            let board::Placement { start, target, yaw } = board::draw_placement(&mut rng);
            out.push(Task { params, start, target, yaw, seed: rng.random() });
        }
    }
    out
}

/// Runs one trial with `method`.
fn trial(method: Method, task: &Task) -> Result<Trial, RunError> {
    let config = method.config(InteractionConfig::default());
    let (mut world, cube) = board::world(config, task.start, task.yaw)?;
    let target = board::square_center(task.target);
    let begin = board::square_center(task.start) + Vec3::new(-0.1, 0.15, 0.0);
    let sight = user::Sight::default();
    let mut user = User::new(task.params, target, begin, sight.clone(), task.seed);
    let mut eyes = Eyes { cube, sight };
    let steps = (TRIAL_LIMIT / config.dt as f64).round() as usize;
    {
        let mut driver = Driver::new(&mut world);
        driver.add_hand(&mut user);
        driver.run(steps, &mut [&mut eyes])?;
    }
    let state = world.object_state(cube)?;
    let error = board::placement_error(state.position, target);
    let failed = user.done_at.is_none() || !board::on_board(state.position);
    Ok(Trial { error, time: user.done_at.unwrap_or(TRIAL_LIMIT), failed, drops: user.drops })
}

/// Mean, sample standard deviation and median of `v`: not numbers for
/// none, since a method that completed no trial has no error, not a zero
/// one (the JSON writes `null`, the table and the report `—`).
fn stats(v: &[f64]) -> (f64, f64, f64) {
    if v.is_empty() {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    let mut sorted = v.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mid = sorted.len() / 2;
    let median = if sorted.len().is_multiple_of(2) {
        (sorted[mid - 1] + sorted[mid]) / 2.0
    } else {
        sorted[mid]
    };
    (mean, var.sqrt(), median)
}

/// One method's results from its trials, under the name `method` (a
/// method's, or a person's row from the viewer's task).
pub fn summarise(method: &str, trials: &[Trial]) -> MethodResult {
    let done: Vec<&Trial> = trials.iter().filter(|t| !t.failed).collect();
    let errors_mm: Vec<f64> = done.iter().map(|t| t.error as f64 * 1e3).collect();
    let (mean_mm, sd_mm, median_mm) = stats(&errors_mm);
    let times: Vec<f64> = done.iter().map(|t| t.time).collect();
    MethodResult {
        method: method.into(),
        mean_mm,
        sd_mm,
        median_mm,
        errors_mm,
        mean_time_s: stats(&times).0,
        times_s: times,
        failed: trials.len() - done.len(),
        drops: trials.iter().map(|t| t.drops).sum(),
    }
}

/// The positioning-accuracy study: every method on the same users and
/// trials. `progress(done, total)` is called after each trial.
pub fn accuracy(
    options: &AccuracyOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<AccuracyStudy, RunError> {
    let tasks = tasks(options);
    let total = tasks.len() * options.methods.len();
    let mut methods = Vec::new();
    for (m, &method) in options.methods.iter().enumerate() {
        let mut trials = Vec::with_capacity(tasks.len());
        for (k, task) in tasks.iter().enumerate() {
            trials.push(trial(method, task)?);
            progress(m * tasks.len() + k + 1, total);
        }
        methods.push(summarise(method.name(), &trials));
    }
    Ok(AccuracyStudy {
        users: options.users,
        trials: options.trials,
        seed: options.seed,
        methods,
        thesis: thesis_table(),
    })
}
