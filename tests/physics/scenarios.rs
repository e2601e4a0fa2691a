//! The shipped scenarios of the interaction catalogue (thesis Ch. 4): each
//! must pass its own checks (and `controls.rs`: changing the physics that
//! makes it work must make it fail).

use coulomb_hands::run::drive::StepView;
use coulomb_hands::run::scenario::{Scenario, ScenarioReport, shipped};
use std::path::Path;

pub fn run(s: &Scenario) -> ScenarioReport {
    // The NaN firewall's check, every step of every scenario and control.
    let mut finite = |step: &StepView| {
        if let Some(bad) = step.world.first_non_finite() {
            panic!("{}: {bad} is not finite at t = {}", s.name, step.t);
        }
        Ok(())
    };
    s.run(&mut [&mut finite]).unwrap()
}

pub fn table(r: &ScenarioReport) -> String {
    r.checks
        .iter()
        .map(|c| {
            format!(
                "\n  {} {} = {} (bound {})",
                if c.passed { "ok" } else { "FAIL" },
                c.name,
                c.value,
                c.bound
            )
        })
        .collect()
}

#[test]
fn every_shipped_scenario_passes_its_checks() {
    let mut failed = Vec::new();
    for (name, _) in shipped() {
        let report = run(&Scenario::find(name).unwrap());
        if !report.passed {
            failed.push(format!("{name}:{}", table(&report)));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// The shipped scenario `name` with `from` replaced by `to` in its file.
pub fn variant(name: &str, from: &str, to: &str) -> ScenarioReport {
    variants(name, &[(from, to)])
}

/// The shipped scenario `name` with each `from` replaced by its `to`.
pub fn variants(name: &str, changes: &[(&str, &str)]) -> ScenarioReport {
    let mut text = shipped().iter().find(|s| s.0 == name).unwrap().1.to_string();
    for (from, to) in changes {
        assert!(text.contains(from), "{name} has no {from}");
        text = text.replace(from, to);
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    run(&Scenario::parse(name, &text, &dir).unwrap())
}

/// The first check of `r` whose name starts with `name`.
pub fn check<'a>(
    r: &'a ScenarioReport,
    name: &str,
) -> &'a coulomb_hands::run::scenario::check::CheckResult {
    r.checks.iter().find(|c| c.name.starts_with(name)).unwrap()
}

#[test]
fn a_scenario_hand_may_replay_a_recording() {
    // The clapping hands of a real recording sweep through a cube on a
    // table (as in `replay --scene`), now as a scenario with a check.
    let text = r#"{
      "name": "claps", "duration": 3.0,
      "scene": {"statics": [{"name": "table",
                             "shape": {"Box": {"half_extents": [0.3, 0.02, 0.3]}},
                             "position": [0.0, 0.08, 0.0], "rotation": [0, 0, 0, 1],
                             "friction": 0.5}],
                "objects": [{"name": "cube",
                             "shape": {"Box": {"half_extents": [0.025, 0.025, 0.025]}},
                             "mass": 0.05, "material": "wood", "position": [0.0, 0.125, 0.0]}]},
      "hands": [{"recording": "../data/leap/three-claps.json.lz", "side": "left"},
                {"recording": "../data/leap/three-claps.json.lz", "side": "right"}],
      "checks": [{"name": "knocked (m)", "min": 0.005,
                  "measure": {"kind": "displacement", "object": "cube", "from": 0.0}}]
    }"#;
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let s = Scenario::parse("claps.json", text, &dir).unwrap();
    let report = run(&s);
    assert!(report.passed, "{}", table(&report));
    let bad = Scenario::parse("claps.json", &text.replace("three-claps", "four-claps"), &dir)
        .unwrap_err()
        .to_string();
    assert!(bad.contains("claps.json: hands[0].recording") && bad.contains("four-claps"), "{bad}");
}

#[test]
fn the_contacts_measure_counts_only_contacts_that_press() {
    // A palm facing down 2 mm above a 4 cm box on the floor is within the
    // 4 mm contact offset: it has a contact, but it does not press, so the
    // measure does not count it. Lowered 4 mm, 2 mm into the box, it presses.
    let text = r#"{
      "name": "hover", "duration": 0.5,
      "scene": {"ground": {"height": 0.0, "friction": 0.5},
                "objects": [{"name": "box", "shape": {"Box": {"half_extents": [0.02, 0.02, 0.02]}},
                             "mass": 0.05, "material": "wood", "position": [0.0, 0.02, 0.0]}]},
      "hands": [{"side": "right",
                 "keys": [{"t": 0.0, "palm": [0.0, 0.052, 0.0], "rotation_deg": [0, 0, 180]}]}],
      "checks": [{"name": "pressing", "max": 0,
                  "measure": {"kind": "contacts", "object": "box", "at": 0.5}}]
    }"#;
    let run_counting = |text: &str| {
        let s = Scenario::parse("hover.json", text, Path::new(".")).unwrap();
        let mut touching = 0;
        let mut count = |step: &StepView| {
            touching = step.world.contacts().len();
            Ok(())
        };
        let report = s.run(&mut [&mut count]).unwrap();
        (report, touching)
    };
    let (hover, touching) = run_counting(text);
    assert!(touching >= 1, "the hovering palm has a contact");
    assert!(hover.passed, "{}", table(&hover));
    let pressing = text.replace("0.052", "0.048").replace(r#""max": 0"#, r#""min": 1"#);
    let (press, _) = run_counting(&pressing);
    assert!(press.passed, "{}", table(&press));
}
