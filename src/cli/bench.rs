//! `bench`: the performance analysis of thesis §5.3 (Fig. 5.6), printed.

use super::progress_bar;
use coulomb_hands::run::bench::{self, BenchOptions, BenchReport, StepTimes, linear_fit, mujoco};
use std::io::IsTerminal;

/// The interaction layer's target at 32 bones (µs per step).
const INTERACTION_TARGET_US: f64 = 10.0;
/// The awake reference step's target, as a share of MuJoCo's step.
const MUJOCO_TARGET_RATIO: f64 = 0.15;

/// `bench`'s arguments.
pub struct BenchArgs {
    pub steps: usize,
    pub boxes: usize,
    pub tower: bool,
    pub json: bool,
    pub mujoco: bool,
    pub python: Option<std::path::PathBuf>,
}

pub fn bench(args: BenchArgs) -> Result<(), String> {
    let python = args.python.unwrap_or_else(mujoco::default_python);
    let options = BenchOptions {
        steps: args.steps,
        boxes: args.boxes,
        tower: args.tower,
        mujoco: args.mujoco.then_some(python),
    };
    let show = std::io::stderr().is_terminal();
    let bar = progress_bar(show, options.total_steps(), "{bar:30} {pos}/{len} steps {msg}");
    let report = bench::run(&options, &mut |n| bar.inc(n)).map_err(|e| e.to_string());
    bar.finish_and_clear();
    let report = report?;
    if args.json {
        println!("{}", serde_json::to_string(&report).map_err(|e| e.to_string())?);
    } else {
        print_report(&report, &options);
    }
    Ok(())
}

fn print_report(r: &BenchReport, options: &BenchOptions) {
    println!(
        "sweep: held boxes, each squeezed by 2 bones; {} samples per contact; µs per step, \
         median of {}-step blocks over {} steps",
        bench::SAMPLES,
        bench::BLOCK,
        options.steps
    );
    println!("bones  hands  interaction  rapier    full  µs/bone");
    for row in &r.sweep {
        let t = row.times;
        let per_bone = t.full_us / row.bones as f64;
        println!(
            "{:5}  {:5}  {:11.2}  {:6.2}  {:6.2}  {per_bone:7.3}",
            row.bones, row.hands, t.interaction_us, t.rapier_us, t.full_us
        );
    }
    print_linearity(r);
    let reference = &r.reference;
    println!(
        "reference: 2 hands, {} held boxes, tower: {}; {} bones pressing, {} objects",
        options.boxes, options.tower, reference.bones_pressing, reference.objects
    );
    print_times("asleep (rapier's sleeping on, tower at rest)", reference.asleep);
    print_times("awake (sleeping off, as under a hand)", reference.awake);
    println!("first second (settling, sleeping on):         full {:8.2}", reference.settling_us);
    if let Some(at32) = r.sweep.iter().find(|row| row.bones == 32) {
        let us = at32.times.interaction_us;
        let verdict = if us <= INTERACTION_TARGET_US { "met" } else { "not met" };
        println!(
            "target: interaction layer ≤ {INTERACTION_TARGET_US} µs at 32 bones: {verdict} \
             ({us:.2} µs)"
        );
    }
    if let Some(m) = &r.mujoco {
        println!("mujoco ({}): {:.1} µs per mj_step", m.settings, m.step_us);
        println!(
            "ours / mujoco: awake {:.3}, asleep {:.3}; target awake ≤ {MUJOCO_TARGET_RATIO}: {}",
            m.ratio_awake,
            m.ratio_asleep,
            if m.ratio_awake <= MUJOCO_TARGET_RATIO { "met" } else { "not met" }
        );
    }
}

fn print_times(what: &str, t: StepTimes) {
    println!(
        "{what:45} interaction {:6.2}, rapier {:7.2}, full {:7.2}",
        t.interaction_us, t.rapier_us, t.full_us
    );
}

/// How well a straight line in bones fits the sweep's times.
fn print_linearity(r: &BenchReport) {
    let points = |f: fn(&StepTimes) -> f64| -> Vec<(f64, f64)> {
        r.sweep.iter().map(|row| (row.bones as f64, f(&row.times))).collect()
    };
    for (name, f) in [
        ("interaction", (|t: &StepTimes| t.interaction_us) as fn(&StepTimes) -> f64),
        ("full step", |t: &StepTimes| t.full_us),
    ] {
        if let Some(fit) = linear_fit(&points(f)) {
            println!(
                "linear in bones ({name}): {:.3} µs per bone + {:.2} µs, R² {:.4}",
                fit.slope, fit.intercept, fit.r_squared
            );
        }
    }
    let per_bone = |bones: usize| {
        let row = r.sweep.iter().find(|row| row.bones == bones)?;
        Some(row.times.interaction_us / bones as f64)
    };
    if let (Some(low), Some(high)) = (per_bone(32), per_bone(128)) {
        println!("interaction per bone at 128 bones / at 32 bones: {:.2}", high / low);
    }
}
