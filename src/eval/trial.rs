//! One placement trial, and many at once: a user, a start and a target
//! square, run under one condition (a config, a strategy, how noisy the
//! tracking and how keen the eyes).

use super::board;
use super::noise::TrackingNoise;
use super::perception::{EYE, Perception};
use super::user::{Eyes, Sight, Strategy, User, UserParams};
use crate::pipeline::InteractionConfig;
use crate::run::RunError;
use crate::run::drive::Driver;
use glam::Vec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A trial that has not finished after this long (s) has failed.
pub const TRIAL_LIMIT: f64 = 40.0;

/// One task: a user and their start and target squares.
#[derive(Debug, Clone, Copy)]
pub struct Task {
    /// The user.
    pub params: UserParams,
    /// The cube's start square.
    pub start: (usize, usize),
    /// The target square.
    pub target: (usize, usize),
    /// The cube's turn at the start (rad).
    pub yaw: f32,
    /// Draws the trial's tracking noise, dropouts and glances.
    pub seed: u64,
}

/// The tasks of `users` users with `trials` each, drawn from `seed`: the
/// same for every method and condition.
pub fn tasks(users: usize, trials: usize, seed: u64) -> Vec<Task> {
    let mut out = Vec::new();
    for u in 0..users {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ ((u as u64 + 1) * 0x9E37_79B9));
        let params = UserParams::draw(&mut rng);
        for _ in 0..trials {
            let board::Placement { start, target, yaw } = board::draw_placement(&mut rng);
            out.push(Task { params, start, target, yaw, seed: rng.random() });
        }
    }
    out
}

/// How a trial runs, apart from its task.
#[derive(Debug, Clone, Copy)]
pub struct Condition<'a> {
    /// The method, as a config.
    pub config: InteractionConfig,
    /// How the user moves the cube.
    pub strategy: Strategy,
    /// The tracking noise.
    pub noise: &'a TrackingNoise,
    /// Its scale (0: a perfect tracker).
    pub noise_scale: f32,
    /// The glances' errors, times the display's (0: exact).
    pub perception: f32,
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
    /// Times the cube fell out of the hand while lifted, carried or slid.
    pub drops: usize,
}

/// A trial's outcome and, for the study's explanation, where the cube sat
/// across the grip when the hand first began to let it go.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrialRun {
    /// What the study counts.
    pub trial: Trial,
    /// The cube's centre in the intended grip's frame (m; x from the
    /// thumb towards the fingers) as the hand first began to open on it
    /// ([`User::held_at`]).
    pub held_at: Option<Vec3>,
}

/// Runs one trial.
pub fn trial(condition: &Condition, task: &Task) -> Result<TrialRun, RunError> {
    let (mut world, cube) = board::world(condition.config, task.start, task.yaw)?;
    let target = board::square_center(task.target);
    let begin = board::square_center(task.start) + Vec3::new(-0.1, 0.15, 0.0);
    let mut rng = ChaCha8Rng::seed_from_u64(task.seed);
    let tracking = (condition.noise_scale > 0.0)
        .then(|| condition.noise.stream(condition.noise_scale, &mut rng));
    let sight = Sight::default();
    let eyes = Perception::new(EYE, condition.perception);
    let mut user = User::new(
        task.params,
        condition.strategy,
        target,
        begin,
        (sight.clone(), eyes),
        tracking,
        rng.random(),
    );
    let mut eyes = Eyes { cube, sight };
    let steps = (TRIAL_LIMIT / f64::from(condition.config.dt)).round() as usize;
    {
        let mut driver = Driver::new(&mut world);
        driver.add_hand(&mut user);
        driver.run(steps, &mut [&mut eyes])?;
    }
    let state = world.object_state(cube)?;
    let error = board::placement_error(state.position, target);
    let failed = user.done_at.is_none() || !board::on_board(state.position);
    let time = user.done_at.unwrap_or(TRIAL_LIMIT);
    Ok(TrialRun { trial: Trial { error, time, failed, drops: user.drops }, held_at: user.held_at })
}

/// Runs `tasks` under `condition` on `threads` threads, each taking the
/// next task as it finishes one (each trial on its own world, so the
/// outcomes do not depend on how many), calling `progress(done)` as they
/// finish. The outcomes are in task order; the first error is returned.
/// One thread, or a target without threads (wasm32), runs them in turn on
/// the caller's.
pub fn run_all(
    condition: &Condition,
    tasks: &[Task],
    threads: usize,
    progress: &mut dyn FnMut(usize),
) -> Result<Vec<TrialRun>, RunError> {
    if threads <= 1 || cfg!(target_arch = "wasm32") {
        let mut out = Vec::with_capacity(tasks.len());
        for (done, task) in tasks.iter().enumerate() {
            out.push(trial(condition, task));
            progress(done + 1);
        }
        return out.into_iter().collect();
    }
    use std::sync::atomic::{AtomicUsize, Ordering};
    let next = AtomicUsize::new(0);
    let mut out: Vec<Option<Result<TrialRun, RunError>>> = (0..tasks.len()).map(|_| None).collect();
    std::thread::scope(|scope| {
        let (sender, finished) = std::sync::mpsc::channel();
        for _ in 0..threads.clamp(1, tasks.len().max(1)) {
            let (sender, next) = (sender.clone(), &next);
            scope.spawn(move || {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(task) = tasks.get(k) else { break };
                    if sender.send((k, trial(condition, task))).is_err() {
                        break;
                    }
                }
            });
        }
        drop(sender);
        for (done, (k, outcome)) in finished.into_iter().enumerate() {
            out[k] = Some(outcome);
            progress(done + 1);
        }
    });
    out.into_iter().map(|o| o.expect("every task ran")).collect()
}

/// How many threads to run trials on: the machine's cores.
pub fn default_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}
