//! `scenario`: the catalogue, one or all, with their checks.

use super::{create, progress_bar};
use coulomb_hands::RunError;
use std::time::Instant;

/// Runs one scenario or all shipped ones. Returns the failed checks, as
/// `scenario: check`.
pub fn scenario(
    name: Option<&str>,
    all: bool,
    trace: Option<&std::path::Path>,
    json: bool,
    method: coulomb_hands::Method,
) -> Result<Vec<String>, RunError> {
    use coulomb_hands::run::observe::TraceWriter;
    use coulomb_hands::run::scenario::{Scenario, shipped};
    let names: Vec<String> = match name {
        Some(n) if !all => vec![n.to_string()],
        _ => shipped().iter().map(|s| s.0.to_string()).collect(),
    };
    // Every file is checked before anything runs.
    let mut scenarios = names.iter().map(|n| Scenario::find(n)).collect::<Result<Vec<_>, _>>()?;
    for s in scenarios.iter_mut() {
        s.config = method.config(s.config);
    }
    let mut writer = trace.map(create).transpose()?.map(TraceWriter::new);
    let template = "{bar:30} {pos}/{len} {msg} ({elapsed})";
    let bar = progress_bar(all && !json, scenarios.len() as u64, template);
    let mut reports = Vec::new();
    let started = Instant::now();
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
    let failed: Vec<String> = reports
        .iter()
        .flat_map(|(r, ..)| r.checks.iter().filter(|c| !c.passed).map(|c| (&r.name, &c.name)))
        .map(|(scenario, check)| format!("{scenario}: {check}"))
        .collect();
    if json {
        let list: Vec<_> = reports.iter().map(|r| &r.0).collect();
        println!("{}", serde_json::json!({ "scenarios": list }));
        return Ok(failed);
    }
    if all {
        println!("{:<20} {:<6} {:>7}  failed checks", "scenario", "result", "wall[s]");
        for (r, wall, _) in &reports {
            let failed: Vec<&str> =
                r.checks.iter().filter(|c| !c.passed).map(|c| c.name.as_str()).collect();
            let result = if r.passed { "pass" } else { "FAIL" };
            let row = format!("{:<20} {result:<6} {wall:>7.2}  {}", r.name, failed.join("; "));
            println!("{}", row.trim_end());
        }
        let n = reports.iter().filter(|r| r.0.passed).count();
        println!("{n}/{} passed in {:.1} s", reports.len(), started.elapsed().as_secs_f64());
    } else {
        for (r, wall, description) in &reports {
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
    Ok(failed)
}
