//! `eval accuracy`: the positioning-accuracy study, printed beside the
//! thesis's Table 5.2.

use super::options::{AccuracySize, ConditionArgs, DrawArgs, MethodsArg, StrategiesArg};
use super::{num, shows_progress, with_bar};
use crate::cli::Outcome;
use crate::cli::options::JsonOutput;
use coulomb_hands::RunError;
use coulomb_hands::eval::{AccuracyOptions, AccuracyStudy, accuracy};

/// The positioning-accuracy study (§5.2, Table 5.2): synthetic users move a cube to a
/// target square with each method.
#[derive(clap::Args)]
pub struct AccuracyArgs {
    #[command(flatten)]
    study: StudyArgs,
    #[command(flatten)]
    output: JsonOutput,
}

impl AccuracyArgs {
    /// Runs the study and prints its table, or one JSON object.
    pub fn run(self) -> Outcome {
        let report = study(&self.study.options(), shows_progress(&self.output))?;
        Ok(self.output.print(&report, print_table)?)
    }
}

/// What `eval accuracy` and `report` run of the accuracy study.
#[derive(clap::Args)]
pub struct StudyArgs {
    #[command(flatten)]
    size: AccuracySize,
    #[command(flatten)]
    draw: DrawArgs,
    #[command(flatten)]
    methods: MethodsArg,
    #[command(flatten)]
    strategies: StrategiesArg,
    #[command(flatten)]
    condition: ConditionArgs,
}

impl StudyArgs {
    /// The study these options ask for.
    pub fn options(self) -> AccuracyOptions {
        let (noise, unit) = self.draw.noise();
        AccuracyOptions {
            users: self.size.users,
            trials: self.size.trials,
            seed: self.draw.seed,
            methods: self.methods.method,
            strategies: self.strategies.strategy,
            noise,
            conditions: self.condition.conditions(unit),
        }
    }
}

/// Runs the study with a progress bar on stderr if `show`.
pub fn study(options: &AccuracyOptions, show: bool) -> Result<AccuracyStudy, RunError> {
    let runs = options.methods.len() * options.strategies.len();
    with_bar(show, options.users * options.trials * runs, |p| accuracy(options, p))
}

/// Table 5.2's shape: one row per method and strategy, the thesis's figure
/// beside it.
fn print_table(r: &AccuracyStudy) {
    let noise = match (r.noise, r.noise_rms_mm, &r.noise_source) {
        (Some(n), Some(mm), Some(source)) => format!("x{n} ({mm:.2} mm rms, {})", source.kind()),
        (Some(n), Some(mm), None) => format!("x{n} ({mm:.2} mm rms)"),
        (Some(n), None, _) => format!("x{n}"),
        (None, ..) => "—".into(),
    };
    let sight = r.perception.map_or("—".into(), |p| format!("{p}"));
    println!(
        "positioning accuracy (thesis §5.2): {} synthetic users x {} trials, seed {}, \
         tracking noise {noise}, glance errors x{sight}",
        r.users, r.trials, r.seed
    );
    println!(
        "{:<10} {:<6} {:>24} {:>7} {:>7} {:>6} {:>9}  {:>20}",
        "method",
        "moves",
        "error mm: mean ± sd / med",
        "time s",
        "failed",
        "drops",
        "held mm",
        "thesis (Table 5.2)"
    );
    for m in &r.methods {
        let thesis =
            r.thesis.iter().find(|t| t.method == m.method).map_or("—".to_string(), |t| {
                format!("{:.1} ± {:.1} / {:.1}", t.mean_mm, t.sd_mm, t.median_mm)
            });
        let error =
            format!("{} ± {} / {}", num(m.mean_mm, 1), num(m.sd_mm, 1), num(m.median_mm, 1));
        let held = m.held_across_mm.map_or("—".into(), |h| format!("{h:+.1}"));
        println!(
            "{:<10} {:<6} {error:>24} {:>7} {:>7} {:>6} {held:>9}  {thesis:>20}",
            m.method,
            m.strategy.as_deref().unwrap_or("—"),
            num(m.mean_time_s, 2),
            m.failed,
            m.drops
        );
    }
    let rows = "its method, the Leap Motion Interaction Engine, its re-implementation of [23]";
    println!("(the thesis's rows: {rows})");
    println!(
        "(held mm: where the cube sat across the grip as the hand began to open on it, \
         towards the fingers)"
    );
}
