//! `demo`: the scripted grasp-lift-carry, printed as a table.

use coulomb_hands::run::demo::GraspLiftCarry;
use coulomb_hands::{InteractionConfig, KineticFriction};

pub fn demo(json: bool, thesis_kinetic: bool, every: f32) -> Result<(), String> {
    let config = InteractionConfig {
        kinetic: if thesis_kinetic { KineticFriction::Thesis } else { KineticFriction::Coulomb },
        ..InteractionConfig::default()
    };
    let scene = GraspLiftCarry::new(config).map_err(|e| e.to_string())?;
    let report = scene.run(every).map_err(|e| e.to_string())?;
    if json {
        println!("{}", serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?);
        return Ok(());
    }
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
    let held = report.held_height > 0.15;
    let dropped = report.final_height < report.held_height - 0.1;
    println!(
        "outcome: {} and {}",
        if held { "held through lift and turn" } else { "NOT held" },
        if dropped { "fell when the hand opened" } else { "did NOT fall" }
    );
    if held && dropped { Ok(()) } else { Err("the demo's physical outcome was wrong".into()) }
}
