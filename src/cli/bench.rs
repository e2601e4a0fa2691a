//! `bench`: the performance analysis of thesis §5.3 (Fig. 5.6), printed.

use super::options::JsonOutput;
use super::{Outcome, progress_bar};
use clap::builder::TypedValueParser;
use coulomb_hands::run::bench::{
    self, BenchOptions, BenchReport, DEFAULT_OBJECTS, HELD, MAX_OBJECTS, StepTimes, linear_fit,
    mujoco,
};
use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::LazyLock;

/// The interaction layer's target at 32 bones (µs per step).
const INTERACTION_TARGET_US: f64 = 8.0;
/// The awake reference step's target, as a share of MuJoCo's step.
const MUJOCO_TARGET_RATIO: f64 = 0.25;
/// The most the interaction layer may grow from the fewest objects timed to
/// the most (70 to 2,000 by default), as a ratio.
const OBJECTS_GROWTH_TARGET: f64 = 1.2;

/// Time steps against bones in contact (6..128) and the reference scene awake and
/// asleep (thesis §5.3, Fig. 5.6); with --mujoco, MuJoCo's step beside them.
#[derive(clap::Args)]
pub struct BenchArgs {
    #[command(flatten)]
    timing: BenchRunArgs,
    #[command(flatten)]
    output: JsonOutput,
}

impl BenchArgs {
    /// Runs the bench and prints its table, or one JSON object.
    pub fn run(self) -> Outcome {
        let options = self.timing.options();
        let report = measure(&options, std::io::stderr().is_terminal())?;
        if self.output.json {
            println!("{}", serde_json::to_string(&report)?);
        } else {
            print_report(&report, &options);
        }
        Ok(())
    }
}

/// `--python`'s help: the Python `--mujoco` runs when none is given.
static PYTHON_HELP: LazyLock<String> = LazyLock::new(|| {
    let (venv, system) = (mujoco::VENV_PYTHON, mujoco::SYSTEM_PYTHON);
    format!("The Python with pip's mujoco [default: {venv} if there, else {system}]")
});

/// What `bench` and `report` time.
#[derive(clap::Args)]
pub struct BenchRunArgs {
    /// Timed steps per figure, after a warm-up.
    #[arg(long, default_value_t = BenchOptions::STEPS,
          value_parser = clap::value_parser!(u32).range(1..).map(|n| n as usize))]
    steps: usize,
    /// Held boxes in the reference scene (2 bones in contact each), at most the default.
    #[arg(long, default_value_t = BenchOptions::MAX_BOXES,
          value_parser = clap::value_parser!(u16).range(1..=BenchOptions::MAX_BOXES as i64)
              .map(usize::from))]
    boxes: usize,
    /// Leave the reference scene's tower out.
    #[arg(long)]
    no_tower: bool,
    /// Also time MuJoCo's mj_step on the reference scene (bench/mujoco_reference.py).
    #[arg(long)]
    mujoco: bool,
    // The help names `default_python`'s choices, from their one home.
    #[arg(long, requires = "mujoco", help = PYTHON_HELP.as_str())]
    python: Option<PathBuf>,
    /// Objects in each cluttered scene timed: the reference scene's hands and 16 held boxes
    /// among boxes resting on a table and shelves, comma-separated (16 to 4000 each).
    #[arg(long, value_delimiter = ',', default_values_t = DEFAULT_OBJECTS,
          value_parser = clap::value_parser!(u16).range(HELD as i64..=MAX_OBJECTS as i64)
              .map(usize::from))]
    objects: Vec<usize>,
    /// Leave the cluttered scenes out.
    #[arg(long, conflicts_with = "objects")]
    no_objects: bool,
}

impl BenchRunArgs {
    /// The bench run these options ask for.
    pub fn options(self) -> BenchOptions {
        let python = self.python.unwrap_or_else(mujoco::default_python);
        BenchOptions {
            steps: self.steps,
            boxes: self.boxes,
            tower: !self.no_tower,
            mujoco: self.mujoco.then_some(python),
            objects: if self.no_objects { Vec::new() } else { self.objects },
        }
    }
}

/// Runs the bench with a progress bar on stderr if `show`.
pub fn measure(options: &BenchOptions, show: bool) -> Result<BenchReport, bench::BenchError> {
    let bar = progress_bar(show, options.total_steps(), "{bar:30} {pos}/{len} steps {msg}");
    let report = bench::run(options, &mut |n| bar.inc(n));
    bar.finish_and_clear();
    report
}

fn print_report(r: &BenchReport, options: &BenchOptions) {
    println!(
        "sweep: {} samples per contact; µs per step, median of {}-step blocks of {} steps",
        bench::SAMPLES,
        bench::BLOCK,
        options.steps
    );
    println!("bones  hands  interaction   rapier     full  interaction/bone  full/bone");
    for row in &r.sweep {
        let t = row.times;
        let bones = row.bones as f64;
        println!(
            "{:5}  {:5}  {:11.2}  {:7.2}  {:7.2}  {:16.3}  {:9.3}",
            row.bones,
            row.hands,
            t.interaction_us,
            t.rapier_us,
            t.full_us,
            t.interaction_us / bones,
            t.full_us / bones
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
    print_objects(r);
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

/// The cluttered scenes' table and the growth of the interaction layer.
fn print_objects(r: &BenchReport) {
    if r.objects.is_empty() {
        return;
    }
    println!("cluttered scenes: 32 bones pressing, rapier's sleeping on; µs per step");
    println!("objects  awake  pressing  interaction   rapier     full");
    for p in &r.objects {
        let t = p.times;
        println!(
            "{:7}  {:5}  {:8}  {:11.2}  {:7.2}  {:7.2}",
            p.objects, p.awake, p.bones_pressing, t.interaction_us, t.rapier_us, t.full_us
        );
    }
    if let Some((growth, fewest, most)) = bench::objects_growth(&r.objects) {
        let verdict = if growth <= OBJECTS_GROWTH_TARGET { "met" } else { "not met" };
        println!(
            "target: interaction layer from {fewest} to {most} objects grows ≤ {:.0} %: {verdict} \
             ({:+.1} %)",
            (OBJECTS_GROWTH_TARGET - 1.0) * 100.0,
            (growth - 1.0) * 100.0
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
