//! The thesis's law as written, given this crate's departures back one at
//! a time: which of them restore a grasp that carries the cube.

use super::stats;
use super::trial::{self, Condition, TrialRun};
use super::{AccuracyOptions, Conditions, Strategy, check_some};
use crate::friction::KineticFriction;
pub use crate::output::report::{Ablation, AblationRow};
use crate::pipeline::{InteractionConfig, Method};
use crate::run::RunError;

/// A departure from the thesis's law: its name, and what it sets back to
/// this crate's default.
pub type Departure = (&'static str, fn(&mut InteractionConfig, &InteractionConfig));

/// Every departure of [`Method::Coulomb`] from [`Method::Thesis`]; each
/// takes its value from the default config, the one home of the values.
pub const DEPARTURES: [Departure; 13] = [
    ("Coulomb's kinetic friction", |c, _| c.kinetic = KineticFriction::Coulomb),
    ("contact damper", |c, d| c.damping_ratio = d.damping_ratio),
    ("force cap", |c, d| c.force_cap = d.force_cap),
    ("penetration-speed limit", |c, d| c.max_penetration_speed = d.max_penetration_speed),
    ("second, wider release offset", |c, d| c.release_offset = d.release_offset),
    ("stability limit, step-aware", |c, d| {
        (c.stability_limit, c.step_aware) = (d.stability_limit, d.step_aware)
    }),
    ("virtual fingers", |c, d| c.virtual_fingers = d.virtual_fingers),
    ("patch deviation springs", |c, d| c.deviation_springs = d.deviation_springs),
    ("slip re-centring", |c, d| c.slip_recentre = d.slip_recentre),
    ("line contacts", |c, d| c.line_contacts = d.line_contacts),
    ("rolling contacts", |c, d| c.rolling = d.rolling),
    ("Stribeck fade", |c, d| c.stribeck_speed = d.stribeck_speed),
    ("tracking filter", |c, d| c.tracking = d.tracking),
];

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct AblationOptions {
    /// Synthetic users.
    pub users: usize,
    /// Trials per user.
    pub trials: usize,
    /// Seed of users, squares, tracking noise and glances.
    pub seed: u64,
    /// How the users move the cube: each configuration runs with each.
    pub strategies: Vec<Strategy>,
    /// Tracking noise, in [`Conditions::noise_unit`]s.
    pub noise: f32,
    /// How the trials run, besides the noise's strength.
    pub conditions: Conditions,
}

impl Default for AblationOptions {
    fn default() -> Self {
        AblationOptions {
            users: Self::USERS,
            trials: Self::TRIALS,
            seed: AccuracyOptions::SEED,
            strategies: Strategy::ALL.to_vec(),
            noise: AccuracyOptions::NOISE,
            conditions: Conditions::default(),
        }
    }
}

impl AblationOptions {
    /// The default users.
    pub const USERS: usize = 3;
    /// The default trials per user.
    pub const TRIALS: usize = 5;
}

/// The configurations compared: the thesis's law, each departure added to
/// it alone, all of them (this crate's method), and all but the tracking
/// filter, which shows what it adds to the rest.
pub fn configurations() -> Vec<(String, InteractionConfig)> {
    let default = InteractionConfig::default();
    let thesis = Method::Thesis.config(default);
    let mut out = vec![("thesis as written".to_string(), thesis)];
    for (name, give_back) in DEPARTURES {
        let mut config = thesis;
        give_back(&mut config, &default);
        out.push((format!("+ {name}"), config));
    }
    let coulomb = Method::Coulomb.config(default);
    out.push(("coulomb (all of them)".to_string(), coulomb));
    let raw = InteractionConfig { tracking: None, ..coulomb };
    out.push(("coulomb without tracking filter".to_string(), raw));
    out
}

/// Runs the ablation. `progress(done, total)` is called as trials finish.
pub fn ablation(
    options: &AblationOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Ablation, RunError> {
    options.conditions.check_noise(options.noise)?;
    for (field, n) in [
        ("users", options.users),
        ("trials", options.trials),
        ("strategy", options.strategies.len()),
    ] {
        check_some(field, n)?;
    }
    let noise = options.conditions.noise()?;
    let scale = options.conditions.scale(&noise, options.noise)?;
    let tasks = trial::tasks(options.users, options.trials, options.seed);
    let configs = configurations();
    let total = configs.len() * options.strategies.len() * tasks.len();
    let mut rows = Vec::new();
    for (name, config) in configs {
        for &strategy in &options.strategies {
            let condition = Condition {
                config,
                strategy,
                noise: &noise,
                noise_scale: scale,
                perception: options.conditions.perception,
            };
            let done = rows.len() * tasks.len();
            let mut each = |n| progress(done + n, total);
            let threads = options.conditions.threads;
            let runs = trial::run_all(&condition, &tasks, threads, &mut each)?;
            rows.push(row(&name, strategy, &runs));
        }
    }
    Ok(Ablation { users: options.users, trials: options.trials, seed: options.seed, rows })
}

fn row(config: &str, strategy: Strategy, runs: &[TrialRun]) -> AblationRow {
    let done: Vec<&TrialRun> = runs.iter().filter(|r| !r.trial.failed).collect();
    let errors: Vec<f64> = done.iter().map(|r| f64::from(r.trial.error) * 1e3).collect();
    let drops: Vec<f64> = runs.iter().map(|r| r.trial.drops as f64).collect();
    AblationRow {
        config: config.to_string(),
        strategy: strategy.name().to_string(),
        trials: runs.len(),
        completed: done.len(),
        failed: stats::proportion_ci(runs.len() - done.len(), runs.len()),
        drops: stats::nonnegative_ci(&drops),
        error_mm: stats::nonnegative_ci(&errors),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_departure_changes_the_thesis_config_and_all_of_them_make_coulomb() {
        let default = InteractionConfig::default();
        let thesis = Method::Thesis.config(default);
        let mut all = thesis;
        for (name, give_back) in DEPARTURES {
            let mut one = thesis;
            give_back(&mut one, &default);
            assert_ne!(one, thesis, "{name} changes nothing");
            give_back(&mut all, &default);
        }
        assert_eq!(all, Method::Coulomb.config(default), "a departure is missing");
    }
}
