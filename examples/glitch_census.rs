//! Where a tracker's noise glitches: for each recording given (any format
//! `replay` reads; the bundled Leap Motion recordings if none), its noise's
//! rms as recorded, and its glitches (a joint's residual past 5 mm, or
//! `--threshold MM`): how many a second, which joints, how far and for how
//! long. The book's chapter on tracking noise quotes it.
//!
//! `cargo run --release --example glitch_census -- [--threshold MM] [FILE...]`

use coulomb_hands::RunError;
use coulomb_hands::eval::glitch::{Glitch, GlitchCensus, quantile};
use coulomb_hands::eval::noise::TrackingNoise;

/// The joints of each part of the hand, in the noise's order.
const PARTS: [(&str, std::ops::Range<usize>); 6] = [
    ("palm", 0..1),
    ("thumb", 1..5),
    ("index", 5..9),
    ("middle", 9..13),
    ("ring", 13..17),
    ("little", 17..21),
];

fn main() -> Result<(), RunError> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut threshold_mm = 5.0;
    if let Some(i) = args.iter().position(|a| a == "--threshold") {
        let value = args.get(i + 1).and_then(|v| v.parse().ok());
        let Some(value) = value else {
            eprintln!("--threshold takes a length in mm");
            std::process::exit(2);
        };
        threshold_mm = value;
        args.drain(i..i + 2);
    }
    let sets: Vec<Vec<String>> = if args.is_empty() {
        vec![Vec::new()]
    } else {
        args.iter().map(|a| vec![a.clone()]).collect()
    };
    println!(
        "{:<36} {:>6} {:>7} {:>8} {:>20} {:>20}   by part (palm thumb index middle ring little)",
        "noise from",
        "rms mm",
        "seconds",
        "glitch/s",
        "peak mm: med p90 max",
        "duration ms: med p90"
    );
    for set in sets {
        let noise = TrackingNoise::load(&set)?;
        let census = GlitchCensus::of(&noise, threshold_mm * 1e-3)?;
        let name = set.first().map_or("the bundled recordings", |s| {
            std::path::Path::new(s).file_name().and_then(|n| n.to_str()).unwrap_or(s)
        });
        let shown =
            |v: f64, digits| if v.is_nan() { "—".into() } else { format!("{v:.digits$}") };
        let peaks =
            |p| shown(quantile(census.glitches.iter().map(|g| f64::from(g.peak) * 1e3), p), 1);
        let durations =
            |p| shown(quantile(census.glitches.iter().map(|g: &Glitch| g.duration * 1e3), p), 0);
        let parts: Vec<String> = PARTS
            .iter()
            .map(|(_, joints)| census.of_joints(joints.clone()).count().to_string())
            .collect();
        println!(
            "{:<36} {:>6.2} {:>7.1} {:>8.2} {:>8}{:>6}{:>6} {:>14}{:>6}   {}",
            name,
            noise.rms * 1e3,
            census.seconds,
            census.rate(),
            peaks(0.5),
            peaks(0.9),
            peaks(1.0),
            durations(0.5),
            durations(0.9),
            parts.join(" ")
        );
    }
    println!(
        "(a glitch: a joint's residual past {threshold_mm} mm, from its smoothed track, as recorded)"
    );
    Ok(())
}
