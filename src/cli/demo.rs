//! `demo`: the scripted grasp-lift-carry, printed as a table.

use super::Outcome;
use super::args::positive;
use super::options::JsonOutput;
use clap::{Args, FromArgMatches};
use coulomb_hands::run::demo::{GraspLiftCarry, GraspReport};
use coulomb_hands::{InteractionConfig, KineticFriction};

/// The default time between printed rows (s).
pub const EVERY: f64 = 0.25;

/// Scripted grasp, lift, carry and release of a cube (the default).
#[derive(Args)]
pub struct DemoArgs {
    #[command(flatten)]
    output: JsonOutput,
    /// Use Eq. 3.8 as written instead of Coulomb's kinetic friction.
    #[arg(long)]
    thesis_kinetic: bool,
    /// Seconds between printed rows.
    #[arg(long, default_value_t = EVERY, value_parser = positive)]
    every: f64,
}

impl DemoArgs {
    /// The options of `coulomb-hands demo` with none given, which
    /// `coulomb-hands` alone runs: clap's defaults, so that they have one
    /// home.
    pub fn defaults() -> Result<DemoArgs, clap::Error> {
        let command = Self::augment_args(clap::Command::new("demo"));
        Self::from_arg_matches(&command.try_get_matches_from(["demo"])?)
    }

    /// Runs the demo and prints its table, or one JSON object; fails if
    /// the cube was not held, or the fingers did not let it go when the
    /// hand opened.
    pub fn run(self) -> Outcome {
        let kinetic =
            if self.thesis_kinetic { KineticFriction::Thesis } else { KineticFriction::Coulomb };
        let config = InteractionConfig { kinetic, ..InteractionConfig::default() };
        let report = GraspLiftCarry::new(config)?.run(self.every as f32)?;
        self.output.print(&report, print_table)?;
        // The JSON carries the heights to judge by; the table says and judges.
        if self.output.json || outcome(&report) == (true, true) {
            return Ok(());
        }
        Err("the demo's physical outcome was wrong".into())
    }
}

/// Whether the cube was held through the lift and turn, and whether the
/// fingers let it go when the hand opened. The turn put the thumb under
/// the cube: the open thumb may still carry it, as a real one does.
fn outcome(report: &GraspReport) -> (bool, bool) {
    let held = report.held_height > 0.15;
    (held, report.fingers_after_release == 0)
}

fn print_table(report: &GraspReport) {
    println!(
        "grasp-lift-carry: a 5 cm, 50 g wooden cube; thumb + 4 fingers; lift 20 cm; turn 90°; open"
    );
    println!(
        "{:>5} {:<8} {:>22} {:>22} {:>7} {:>4} {:>4} {:>4} {:>7} {:>5} {:>5}",
        "t[s]",
        "phase",
        "palm [m]",
        "cube [m]",
        "v[m/s]",
        "stat",
        "dyn",
        "sep",
        "F[N]",
        "begin",
        "end"
    );
    for r in &report.timeline {
        let v = |a: [f32; 3]| format!("({:6.3},{:6.3},{:6.3})", a[0], a[1], a[2]);
        println!(
            "{:5.2} {:<8} {:>22} {:>22} {:7.3} {:4} {:4} {:4} {:7.3} {:5} {:5}",
            r.t,
            r.phase,
            v(r.palm),
            v(r.cube),
            r.cube_speed,
            r.contacts_static,
            r.contacts_dynamic,
            r.contacts_separated,
            r.hand_force,
            r.began,
            r.ended
        );
    }
    println!();
    println!(
        "cube drift in the hand while carried: {:.1} mm, {:.1}°",
        report.max_drift * 1e3,
        report.max_drift_deg
    );
    println!(
        "held at {:.3} m with {} contacts; after opening: {:.3} m, {} contacts",
        report.held_height,
        report.contacts_held,
        report.final_height,
        report.contacts_after_release
    );
    println!("max cube speed {:.2} m/s", report.max_speed);
    let (held, let_go) = outcome(report);
    let after = if !let_go {
        "the fingers did NOT let go when the hand opened"
    } else if report.final_height < report.held_height - 0.1 {
        "fell when the hand opened"
    } else {
        "let go when the hand opened, resting on the open thumb"
    };
    println!(
        "outcome: {} and {after}",
        if held { "held through lift and turn" } else { "NOT held" }
    );
}
