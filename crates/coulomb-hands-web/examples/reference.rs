//! The native library's numbers for the browser test (`web/tests/page.mjs`): the demo and
//! the grasp-lift scenario run to their end, traced every 250 steps ([`sim::trace`]), with
//! the scenario's report; every shipped scenario's report; the bundled recording's closings'
//! verdicts; as one JSON object. Run with the page's feature:
//!
//!   cargo run -p coulomb-hands-web --features enhanced-determinism --example reference

use coulomb_hands_web::sim::{self, Sim};

/// Steps between the trace's rows.
const EVERY: usize = 250;

fn main() -> Result<(), sim::Error> {
    let mut demo = Sim::demo()?;
    let demo_rows = sim::trace(&mut demo, EVERY)?;
    let mut scenario = Sim::shipped_scenario("grasp-lift")?;
    let scenario_rows = sim::trace(&mut scenario, EVERY)?;
    let mut reports = serde_json::Map::new();
    for name in sim::shipped_names() {
        let mut run = Sim::shipped_scenario(&name)?;
        while !run.finished() {
            run.step(10_000)?;
        }
        reports.insert(name, run.report_json().into());
    }
    let grab = include_bytes!("../../../data/leap/grab.json.lz").to_vec();
    let mut replay = Sim::recording("grab.json.lz", grab, Some(sim::CLOSING_OBJECT))?;
    while !replay.finished() {
        replay.step(10_000)?;
    }
    let reference = serde_json::json!({
        "every": EVERY,
        "demo": { "steps": demo.steps(), "rows": demo_rows },
        "grasp-lift": {
            "steps": scenario.steps(),
            "rows": scenario_rows,
            "report": scenario.report_json(),
        },
        "reports": reports,
        "recording": { "steps": replay.steps(), "verdicts": replay.verdicts_json() },
    });
    println!("{reference}");
    Ok(())
}
