//! How white a tracker's noise reads to the jitter meter
//! (`hand::jitter`), whose whiteness sets how fast the hand that acts may
//! follow a still grip ([`coulomb_hands::hand::one_euro::WHITENESS_POWER`]).
//! For each recording given (any format `replay` reads; the bundled Leap
//! Motion recordings if none) and for white jitter at each `--white HZ`,
//! the noise scaled to 3 mm rms (`--rms MM`) is laid on a still hand,
//! drawn between its frames as a replay draws them, and metered by the
//! jitter meter the hand that acts has, on the hand's 21 joints: on its
//! shape (the joints less their mean) and on its gross position (that
//! mean). (The hand that acts meters 31 points of its capsules, and the
//! mean of its palm's centre and knuckles.) It prints each one's whiteness,
//! the mean over 8 noise streams of 20 s (after the first 3 s) and the
//! largest stream's. The book's chapter on tracking noise quotes it.
//!
//! `cargo run --release --example whiteness -- [--rms MM] [--white HZ]... [FILE...]`

use coulomb_hands::RunError;
use coulomb_hands::eval::noise::TrackingNoise;
use coulomb_hands::hand::jitter::JitterMeter;
use glam::Vec3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Noise streams per source, and each one's length and settling time (s).
const STREAMS: u64 = 8;
const SECONDS: f64 = 20.0;
const SETTLE: f64 = 3.0;
/// The physics step the meters are fed at (s).
const DT: f64 = 0.001;

const USAGE: &str = "usage: whiteness [--rms MM] [--white HZ]... [FILE...]";

fn main() {
    if let Err(e) = run() {
        eprintln!("whiteness: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), RunError> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut rms_mm = 3.0;
    let mut sources: Vec<(String, TrackingNoise)> = Vec::new();
    let mut files = Vec::new();
    while let Some(arg) = args.first().cloned() {
        args.remove(0);
        let value = |args: &mut Vec<String>| -> f32 {
            let parsed = (!args.is_empty()).then(|| args.remove(0)).and_then(|v| v.parse().ok());
            parsed.unwrap_or_else(|| {
                eprintln!("{arg} takes a number\n{USAGE}");
                std::process::exit(2);
            })
        };
        match arg.as_str() {
            "--help" | "-h" => {
                println!("{USAGE}");
                return Ok(());
            }
            "--rms" => {
                rms_mm = value(&mut args);
                if !(rms_mm.is_finite() && rms_mm > 0.0) {
                    eprintln!("--rms takes a positive length in mm, got {rms_mm}\n{USAGE}");
                    std::process::exit(2);
                }
            }
            "--white" => {
                let hz = value(&mut args);
                sources.push((format!("white, {hz} fps"), TrackingNoise::white(hz)?));
            }
            _ if arg.starts_with('-') => {
                eprintln!("unknown option {arg}\n{USAGE}");
                std::process::exit(2);
            }
            _ => files.push(arg),
        }
    }
    if files.is_empty() && sources.is_empty() {
        sources.push(("the bundled recordings".into(), TrackingNoise::bundled()?));
    }
    for file in files {
        let name = std::path::Path::new(&file).file_name().and_then(|n| n.to_str());
        let name = name.unwrap_or(&file).to_owned();
        sources.push((name, TrackingNoise::load(&[&file])?));
    }
    println!("{:<36} {:>20} {:>20}", "noise from", "shape: mean (max)", "gross: mean (max)");
    for (name, noise) in &sources {
        let scale = noise.scale_for_rms_mm(rms_mm)?;
        let (mut shape, mut gross) = ((0.0, 0.0f32), (0.0, 0.0f32));
        for seed in 0..STREAMS {
            let (s, g) = metered(noise, scale, seed);
            shape = (shape.0 + s / STREAMS as f32, shape.1.max(s));
            gross = (gross.0 + g / STREAMS as f32, gross.1.max(g));
        }
        let shown = |(mean, max): (f32, f32)| format!("{mean:.2} ({max:.2})");
        println!("{name:<36} {:>20} {:>20}", shown(shape), shown(gross));
    }
    Ok(())
}

/// One stream's mean whiteness, of the shape and of the gross position.
fn metered(noise: &TrackingNoise, scale: f32, seed: u64) -> (f32, f32) {
    let stream = noise.stream(scale, &mut ChaCha8Rng::seed_from_u64(seed));
    let mut shape = JitterMeter::<21>::new(2.0);
    let mut gross = JitterMeter::<1>::new(2.0);
    let (mut sums, mut reads) = ((0.0, 0.0), 0);
    let steps = (SECONDS / DT).round() as usize;
    for k in 0..steps {
        let t = k as f64 * DT;
        let joints = stream.residual(t).joints;
        let mean = joints.iter().sum::<Vec3>() / joints.len() as f32;
        shape.observe(&joints.map(|j| j - mean), DT as f32);
        gross.observe(&[mean], DT as f32);
        if t >= SETTLE && k % 10 == 0 {
            sums = (sums.0 + shape.whiteness(), sums.1 + gross.whiteness());
            reads += 1;
        }
    }
    (sums.0 / reads as f32, sums.1 / reads as f32)
}
