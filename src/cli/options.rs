//! Option groups that several subcommands share: the studies' (`eval
//! accuracy`, `eval sweep`, `eval ablation`, `report`) and the bench's
//! (`bench`, `report`).

use coulomb_hands::Method;
use coulomb_hands::eval::ablation::AblationOptions;
use coulomb_hands::eval::sweep::SweepOptions;
use coulomb_hands::eval::{AccuracyOptions, Conditions, Strategy, trial};
use coulomb_hands::run::bench::{BenchOptions, mujoco};
use std::path::PathBuf;

/// How every trial of a study runs, besides its noise strength: shared by
/// `eval accuracy`, `eval sweep`, `eval ablation` and `report`.
#[derive(clap::Args)]
pub struct ConditionArgs {
    /// The users' glance errors, times those of the thesis's headset (0: exact sight).
    #[arg(long, value_name = "SCALE", default_value_t = 1.0, value_parser = scale)]
    perception: f32,
    /// Take the tracking noise from these recordings, comma-separated (default: the
    /// bundled Leap Motion recordings).
    #[arg(long, value_name = "FILE,...", value_delimiter = ',')]
    noise_from: Vec<PathBuf>,
    /// Threads to run trials on (the results do not depend on it) [default: the cores].
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..))]
    threads: Option<u16>,
}

impl ConditionArgs {
    /// The conditions these options ask for.
    fn conditions(self) -> Conditions {
        let threads = self.threads.map_or_else(trial::default_threads, usize::from);
        Conditions { perception: self.perception, noise_from: self.noise_from, threads }
    }
}

/// A scale of noise or of glance errors: a finite number ≥ 0.
fn scale(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err(format!("expected a finite scale ≥ 0, got {text}")),
    }
}

/// What `eval accuracy` and `report` run of the accuracy study.
#[derive(clap::Args)]
pub struct StudyArgs {
    /// Synthetic users.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u16).range(1..))]
    users: u16,
    /// Trials per user.
    #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u16).range(1..))]
    trials: u16,
    /// Seed of users, squares, tracking noise and glances.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// The methods to compare, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "coulomb,thesis,kinematic,heuristic")]
    method: Vec<Method>,
    /// How the users move the cube, comma-separated: lift (and place) or slide (it
    /// over the board between the fingers). Each method runs with each.
    #[arg(long, value_delimiter = ',', default_value = "lift,slide")]
    strategy: Vec<Strategy>,
    /// Tracking noise, times the recordings' (0: a perfect tracker).
    #[arg(long, value_name = "SCALE", default_value_t = 1.0, value_parser = scale)]
    noise: f32,
    #[command(flatten)]
    condition: ConditionArgs,
}

impl StudyArgs {
    /// The study these options ask for.
    pub fn options(self) -> AccuracyOptions {
        let (users, trials) = (self.users.into(), self.trials.into());
        AccuracyOptions {
            users,
            trials,
            seed: self.seed,
            methods: self.method,
            strategies: self.strategy,
            noise: self.noise,
            conditions: self.condition.conditions(),
        }
    }
}

/// What `eval sweep` runs.
#[derive(clap::Args)]
pub struct SweepArgs {
    /// Synthetic users per seed.
    #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u16).range(1..))]
    users: u16,
    /// Trials per user.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u16).range(1..))]
    trials: u16,
    /// Seeds, comma-separated: each draws its own users and trials.
    #[arg(long, value_delimiter = ',', default_value = "1,2,3")]
    seeds: Vec<u64>,
    /// Tracking noise strengths, times the recordings', comma-separated.
    #[arg(long, value_name = "SCALE,...", value_delimiter = ',', default_value = "0,0.5,1,2",
          value_parser = scale)]
    noise: Vec<f32>,
    /// The methods, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "coulomb,thesis,kinematic,heuristic")]
    method: Vec<Method>,
    /// The strategies, comma-separated: lift, slide.
    #[arg(long, value_delimiter = ',', default_value = "lift,slide")]
    strategy: Vec<Strategy>,
    #[command(flatten)]
    condition: ConditionArgs,
}

impl SweepArgs {
    /// The sweep these options ask for.
    pub fn options(self) -> SweepOptions {
        SweepOptions {
            users: self.users.into(),
            trials: self.trials.into(),
            seeds: self.seeds,
            noise: self.noise,
            methods: self.method,
            strategies: self.strategy,
            conditions: self.condition.conditions(),
        }
    }
}

/// What `eval ablation` runs.
#[derive(clap::Args)]
pub struct AblationArgs {
    /// Synthetic users.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u16).range(1..))]
    users: u16,
    /// Trials per user.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u16).range(1..))]
    trials: u16,
    /// Seed of users, squares, tracking noise and glances.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// The strategies, comma-separated: lift, slide.
    #[arg(long, value_delimiter = ',', default_value = "lift,slide")]
    strategy: Vec<Strategy>,
    /// Tracking noise, times the recordings'.
    #[arg(long, value_name = "SCALE", default_value_t = 1.0, value_parser = scale)]
    noise: f32,
    #[command(flatten)]
    condition: ConditionArgs,
}

impl AblationArgs {
    /// The ablation these options ask for.
    pub fn options(self) -> AblationOptions {
        AblationOptions {
            users: self.users.into(),
            trials: self.trials.into(),
            seed: self.seed,
            strategies: self.strategy,
            noise: self.noise,
            conditions: self.condition.conditions(),
        }
    }
}

/// What `bench` and `report` time.
#[derive(clap::Args)]
pub struct BenchRunArgs {
    /// Timed steps per figure, after a warm-up.
    #[arg(long, default_value_t = 5000, value_parser = clap::value_parser!(u32).range(1..))]
    steps: u32,
    /// Held boxes in the reference scene (2 bones in contact each), 1..=16.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u16).range(1..=16))]
    boxes: u16,
    /// Leave the reference scene's tower out.
    #[arg(long)]
    no_tower: bool,
    /// Also time MuJoCo's mj_step on the reference scene (bench/mujoco_reference.py).
    #[arg(long)]
    mujoco: bool,
    /// The Python with pip's mujoco [default: target/mujoco-venv/bin/python if there,
    /// else python3].
    #[arg(long, requires = "mujoco")]
    python: Option<std::path::PathBuf>,
}

impl BenchRunArgs {
    /// The bench run these options ask for.
    pub fn options(self) -> BenchOptions {
        let python = self.python.unwrap_or_else(mujoco::default_python);
        BenchOptions {
            steps: self.steps as usize,
            boxes: self.boxes.into(),
            tower: !self.no_tower,
            mujoco: self.mujoco.then_some(python),
        }
    }
}
