//! Option groups that the studies share, each one struct that they
//! flatten: how every trial runs (all of them, and `report`), one draw of
//! users (`eval accuracy`, `eval ablation`), the methods compared (`eval
//! accuracy`, `eval sweep`) and the users' strategies (all of them).

use crate::cli::args::count;
use coulomb_hands::Method;
use coulomb_hands::eval::ablation::AblationOptions;
use coulomb_hands::eval::sweep::SweepOptions;
use coulomb_hands::eval::{AccuracyOptions, Conditions, NoiseUnit, Strategy, trial};
use std::fmt::Display;
use std::path::PathBuf;
use std::sync::LazyLock;

/// How every trial of a study runs, besides its noise strength: shared by
/// `eval accuracy`, `eval sweep`, `eval ablation` and `report`.
#[derive(clap::Args)]
pub struct ConditionArgs {
    /// The users' glance errors, times those of the thesis's headset (0: exact sight).
    #[arg(long, value_name = "SCALE", default_value_t = Conditions::PERCEPTION,
          value_parser = scale)]
    perception: f32,
    #[command(flatten)]
    noise_source: NoiseSourceArgs,
    /// Threads to run trials on (the results do not depend on it) [default: the cores].
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..))]
    threads: Option<u16>,
}

impl ConditionArgs {
    /// The conditions these options ask for, with noise strengths counted
    /// in `noise_unit`s.
    pub fn conditions(self, noise_unit: NoiseUnit) -> Conditions {
        let threads = self.threads.map_or_else(trial::default_threads, usize::from);
        let NoiseSourceArgs { noise_from, noise_white } = self.noise_source;
        Conditions { perception: self.perception, noise_from, noise_white, noise_unit, threads }
    }
}

/// Where a study's tracking noise comes from: shared by the studies' conditions and
/// `eval latency`.
#[derive(clap::Args)]
pub struct NoiseSourceArgs {
    /// Take the tracking noise from these recordings, comma-separated (default: the
    /// bundled Leap Motion recordings).
    #[arg(long, value_name = "FILE,...", value_delimiter = ',')]
    pub noise_from: Vec<PathBuf>,
    /// Draw white tracking noise instead, for a tracker at this frame rate: every joint off
    /// by a fresh Gaussian error each frame (1 mm rms per axis at --noise 1).
    #[arg(long, value_name = "HZ", conflicts_with = "noise_from")]
    pub noise_white: Option<f32>,
}

/// How many synthetic users a study draws, and how many trials each runs,
/// written once for `eval accuracy` (and `report`), `eval ablation` and
/// `eval sweep`, each struct with its study's defaults. (A struct generic
/// over its defaults would not do: clap keeps a default's text in a static,
/// which all its instances would share.)
macro_rules! size_args {
    ($name:ident, $options:ty) => {
        #[doc = concat!("How many users and trials, by default `", stringify!($options), "`'s.")]
        #[derive(clap::Args)]
        pub struct $name {
            /// Synthetic users, drawn from each seed.
            #[arg(long, default_value_t = <$options>::USERS, value_parser = count())]
            pub users: usize,
            /// Trials per user.
            #[arg(long, default_value_t = <$options>::TRIALS, value_parser = count())]
            pub trials: usize,
        }
    };
}

size_args!(AccuracySize, AccuracyOptions);
size_args!(AblationSize, AblationOptions);
size_args!(SweepSize, SweepOptions);

/// One draw of users and their tracker's noise: `eval accuracy` (and
/// `report`) and `eval ablation`, whose users are drawn alike.
#[derive(clap::Args)]
pub struct DrawArgs {
    /// Seed of users, squares, tracking noise and glances.
    #[arg(long, default_value_t = AccuracyOptions::SEED)]
    pub seed: u64,
    /// Tracking noise, times the recordings' (0: a perfect tracker).
    #[arg(long, value_name = "SCALE", default_value_t = AccuracyOptions::NOISE,
          value_parser = scale)]
    noise: f32,
    /// Tracking noise by its rms per joint and axis: the recordings' residuals scaled to
    /// it (instead of --noise).
    #[arg(long, value_name = "MM", value_parser = scale, conflicts_with = "noise")]
    noise_mm: Option<f32>,
}

impl DrawArgs {
    /// The noise strength asked for, and what it counts.
    pub fn noise(&self) -> (f32, NoiseUnit) {
        NoiseUnit::choose(self.noise, self.noise_mm)
    }
}

/// Every method, as `--method` takes them.
static ALL_METHODS: LazyLock<String> = LazyLock::new(|| comma_list(&Method::ALL));

/// The methods a study compares: `eval accuracy` (and `report`) and `eval sweep`.
#[derive(clap::Args)]
pub struct MethodsArg {
    /// The methods to compare, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = ALL_METHODS.as_str())]
    pub method: Vec<Method>,
}

/// Every strategy, as `--strategy` takes them.
static ALL_STRATEGIES: LazyLock<String> = LazyLock::new(|| comma_list(&Strategy::ALL));

/// How a study's users move the cube: every study.
#[derive(clap::Args)]
pub struct StrategiesArg {
    /// How the users move the cube, comma-separated: lift (and place) or slide (it
    /// over the board between the fingers). Every method or configuration runs with each.
    #[arg(long, value_delimiter = ',', default_value = ALL_STRATEGIES.as_str())]
    pub strategy: Vec<Strategy>,
}

/// `items` as a comma-separated list, as the command line takes it: a
/// list's default, for clap to parse and show.
pub fn comma_list<T: Display>(items: &[T]) -> String {
    items.iter().map(T::to_string).collect::<Vec<_>>().join(",")
}

/// A scale of noise or of glance errors: a finite number ≥ 0.
pub fn scale(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err(format!("expected a finite scale ≥ 0, got {text}")),
    }
}
