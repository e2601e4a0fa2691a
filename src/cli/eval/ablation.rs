//! `eval ablation`: the thesis's law as written, given this crate's
//! departures back one at a time.

use super::options::{AblationSize, ConditionArgs, DrawArgs, StrategiesArg};
use super::{ci, shows_progress, with_bar};
use crate::cli::Outcome;
use crate::cli::options::JsonOutput;
use coulomb_hands::eval::ablation::{Ablation, AblationOptions, ablation, configurations};

/// The thesis's law as written, given this crate's departures back one at a time:
/// which of them let the users carry the cube.
#[derive(clap::Args)]
pub struct AblationArgs {
    #[command(flatten)]
    size: AblationSize,
    #[command(flatten)]
    draw: DrawArgs,
    #[command(flatten)]
    strategies: StrategiesArg,
    #[command(flatten)]
    condition: ConditionArgs,
    #[command(flatten)]
    output: JsonOutput,
}

impl AblationArgs {
    /// Runs the ablation and prints its table, or one JSON object.
    pub fn run(self) -> Outcome {
        let show = shows_progress(&self.output);
        let (noise, unit) = self.draw.noise();
        let options = AblationOptions {
            users: self.size.users,
            trials: self.size.trials,
            seed: self.draw.seed,
            strategies: self.strategies.strategy,
            noise,
            conditions: self.condition.conditions(unit),
        };
        let total =
            configurations().len() * options.strategies.len() * options.users * options.trials;
        let study = with_bar(show, total, |p| ablation(&options, p))?;
        Ok(self.output.print(&study, print_ablation)?)
    }
}

fn print_ablation(a: &Ablation) {
    println!(
        "the thesis's law, with one departure at a time: {} users x {} trials, seed {}",
        a.users, a.trials, a.seed
    );
    println!(
        "{:<32} {:<6} {:>10} {:>18} {:>20}",
        "configuration", "moves", "completed", "drops/trial", "error mm [95% CI]"
    );
    for r in &a.rows {
        println!(
            "{:<32} {:<6} {:>10} {:>18} {:>20}",
            r.config,
            r.strategy,
            format!("{} of {}", r.completed, r.trials),
            ci(&r.drops, 2),
            ci(&r.error_mm, 1)
        );
    }
}
