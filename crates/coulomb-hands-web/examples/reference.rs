//! The native library's numbers for the browser test (`web/tests/page.mjs`): the demo and
//! the grasp-lift scenario run to their end, traced every 250 steps ([`sim::trace`]), with
//! the scenario's report, as one JSON object. Run with the page's feature:
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
    let reference = serde_json::json!({
        "every": EVERY,
        "demo": { "steps": demo.steps(), "rows": demo_rows },
        "grasp-lift": {
            "steps": scenario.steps(),
            "rows": scenario_rows,
            "report": scenario.report_json(),
        },
    });
    println!("{reference}");
    Ok(())
}
