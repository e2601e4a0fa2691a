//! `scenario`: the catalogue, one or all, with their checks.

use super::options::{JsonOutput, MethodChoice, TraceOutput};
use super::{Outcome, progress_bar};
use coulomb_hands::RunError;
use coulomb_hands::run::scenario::{Scenario, ScenarioReport, ScenarioReports, shipped};
use std::time::Instant;

/// Run a scenario of the interaction catalogue and print its checks.
#[derive(clap::Args)]
#[command(after_help = concat!(
    r#"With --json, one object: {"scenarios": [{"name", "passed", "checks": [..]}]}. "#,
    "The checks were written for friction hands (--method coulomb)."
))]
pub struct ScenarioArgs {
    /// A shipped scenario's name (e.g. push) or a scenario file.
    #[arg(required_unless_present = "all", conflicts_with = "all")]
    scenario: Option<String>,
    /// Run every shipped scenario and print a pass/fail table.
    #[arg(long, conflicts_with = "trace")]
    all: bool,
    #[command(flatten)]
    trace: TraceOutput,
    #[command(flatten)]
    output: JsonOutput,
    #[command(flatten)]
    method: MethodChoice,
}

/// A scenario's report, its wall-clock time (s) and its description.
type Ran = (ScenarioReport, f64, String);

impl ScenarioArgs {
    /// Runs the scenarios and prints their checks; fails naming every
    /// failed check, as `scenario: check`.
    pub fn run(self) -> Outcome {
        let started = Instant::now();
        let reports = self.run_all()?;
        if self.output.json {
            let scenarios = reports.iter().map(|r| &r.0).collect();
            println!("{}", serde_json::to_string(&ScenarioReports { scenarios })?);
        } else if self.all {
            print_table(&reports, started);
        } else {
            print_checks(&reports);
        }
        let failed: Vec<String> = reports
            .iter()
            .flat_map(|(r, ..)| r.checks.iter().filter(|c| !c.passed).map(|c| (&r.name, &c.name)))
            .map(|(scenario, check)| format!("{scenario}: {check}"))
            .collect();
        if failed.is_empty() {
            return Ok(());
        }
        Err(format!("failed checks: {}", failed.join("; ")).into())
    }

    /// Runs one scenario or all shipped ones, with a progress bar for all.
    fn run_all(&self) -> Result<Vec<Ran>, RunError> {
        let names: Vec<String> = match &self.scenario {
            Some(n) if !self.all => vec![n.clone()],
            _ => shipped().iter().map(|s| s.0.to_string()).collect(),
        };
        // Every file is checked before anything runs.
        let method = self.method.method;
        let scenarios = names
            .iter()
            .map(|n| Scenario::find(n).map(|s| s.with_method(method)))
            .collect::<Result<Vec<_>, _>>()?;
        let mut writer = self.trace.writer()?;
        let template = "{bar:30} {pos}/{len} {msg} ({elapsed})";
        let bar = progress_bar(self.all && !self.output.json, scenarios.len() as u64, template);
        let mut reports = Vec::new();
        for s in &scenarios {
            bar.set_message(s.name.clone());
            let t0 = Instant::now();
            let report = match writer.as_mut() {
                Some(w) => s.run(&mut [w])?,
                None => s.run(&mut [])?,
            };
            reports.push((report, t0.elapsed().as_secs_f64(), s.description.clone()));
            bar.inc(1);
        }
        bar.finish_and_clear();
        if let Some(w) = writer {
            w.finish()?;
        }
        Ok(reports)
    }
}

/// `--all`: one row per scenario, and how many passed.
fn print_table(reports: &[Ran], started: Instant) {
    println!("{:<20} {:<6} {:>7}  failed checks", "scenario", "result", "wall[s]");
    for (r, wall, _) in reports {
        let failed: Vec<&str> =
            r.checks.iter().filter(|c| !c.passed).map(|c| c.name.as_str()).collect();
        let result = if r.passed { "pass" } else { "FAIL" };
        let row = format!("{:<20} {result:<6} {wall:>7.2}  {}", r.name, failed.join("; "));
        println!("{}", row.trim_end());
    }
    let n = reports.iter().filter(|r| r.0.passed).count();
    println!("{n}/{} passed in {:.1} s", reports.len(), started.elapsed().as_secs_f64());
}

/// One scenario: its description, and each check with its value and bound.
fn print_checks(reports: &[Ran]) {
    for (r, wall, description) in reports {
        println!("{}: {description}", r.name);
        for c in &r.checks {
            println!(
                "  {:<4} {:<40} {:>10.4}  bound {}",
                if c.passed { "ok" } else { "FAIL" },
                c.name,
                c.value,
                c.bound
            );
        }
        println!("{} in {wall:.2} s", if r.passed { "passed" } else { "FAILED" });
    }
}
