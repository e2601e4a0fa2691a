//! Option groups that several subcommands share: the accuracy study's
//! (`eval accuracy`, `report`) and the bench's (`bench`, `report`).

use coulomb_hands::eval::AccuracyOptions;
use coulomb_hands::run::bench::{BenchOptions, mujoco};

/// What `eval accuracy` and `report` run of the accuracy study.
#[derive(clap::Args)]
pub struct StudyArgs {
    /// Synthetic users.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u16).range(1..))]
    users: u16,
    /// Trials per user.
    #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u16).range(1..))]
    trials: u16,
    /// Seed of users, squares and tracking jitter.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// The methods to compare, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "coulomb,thesis,kinematic,heuristic")]
    method: Vec<coulomb_hands::Method>,
}

impl StudyArgs {
    /// The study these options ask for.
    pub fn options(self) -> AccuracyOptions {
        let (users, trials) = (self.users.into(), self.trials.into());
        AccuracyOptions { users, trials, seed: self.seed, methods: self.method }
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
