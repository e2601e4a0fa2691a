//! Why real tracking noise drops what a friction grip holds, measured
//! (the book's "Tracking noise"): a hand closes on the study's 4 cm, 40 g
//! cube, lifts it 5 cm and holds it still for 4.5 s, its tracked joints
//! shaken by the bundled recordings' residuals scaled to a given rms. For
//! each noise strength it prints how many of 40 holds dropped the cube,
//! and what the hand's contacts did while it was held: how often each
//! stuck, slipped or lifted off, and how often contacts began or ended.
//!
//! The raw tracked hand is compared with the hand that acts through the
//! tracking filter, and with three controls: no contact damper, only
//! the hand's rigid shake (every joint moved by the palm's residual), and
//! only its change of shape (every joint's residual less the palm's).
//!
//! `cargo run --release --example noise_mechanism`

use coulomb_hands::eval::board::{self, CUBE_HALF};
use coulomb_hands::eval::grip::grip;
use coulomb_hands::eval::noise::{Residual, TrackingNoise};
use coulomb_hands::friction::FrictionState;
use coulomb_hands::run::drive::{Driver, PoseFn, StepView};
use coulomb_hands::{Bone, InteractionConfig, RunError, Side};
use glam::{Quat, Vec3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Holds per condition.
const HOLDS: u64 = 40;
/// How deep the closed grip sinks each pad (m): the middle of the users'.
const SQUEEZE: f32 = 0.0045;
/// The hold is judged from this time (s), once lifted.
const HELD_FROM: f64 = 1.5;

/// Which part of the noise shakes the hand.
#[derive(Clone, Copy, PartialEq)]
enum Part {
    All,
    Rigid,
    Shape,
}

/// What a condition's holds did.
#[derive(Default)]
struct Tally {
    drops: u64,
    /// Contact-steps that stuck, slipped, and did not press.
    states: [u64; 3],
    /// The same, of each digit (thumb first) and of the palm.
    by_digit: [[u64; 3]; 6],
    contacts: u64,
    steps: u64,
    events: u64,
}

fn main() -> Result<(), RunError> {
    let noise = TrackingNoise::bundled()?;
    let raw = InteractionConfig { tracking: None, ..InteractionConfig::default() };
    let filtered = InteractionConfig::default();
    let undamped = InteractionConfig { damping_ratio: None, ..raw };
    println!("holds of the study's cube under the bundled recordings' noise, scaled by its rms");
    println!(
        "{:<26} {:>6} {:>8} {:>7} {:>7} {:>8} {:>9} {:>9}",
        "hand", "rms mm", "dropped", "stuck", "slipped", "off", "contacts", "events/s"
    );
    let conditions: [(&str, InteractionConfig, Part, &[f32]); 5] = [
        ("tracked, as it is", raw, Part::All, &[0.0, 0.5, 1.0, 1.5, 2.0, 3.0]),
        ("through the tracking filter", filtered, Part::All, &[1.0, 2.0, 3.0]),
        ("no contact damper", undamped, Part::All, &[1.0, 2.0]),
        ("only the rigid shake", raw, Part::Rigid, &[2.0, 3.0]),
        ("only the change of shape", raw, Part::Shape, &[2.0, 3.0]),
    ];
    let mut telling = None;
    for (k, (name, config, part, levels)) in conditions.into_iter().enumerate() {
        for &mm in levels {
            let scale = noise.scale_for_rms_mm(mm)?;
            let mut tally = Tally::default();
            for seed in 0..HOLDS {
                hold(config, &noise, scale, part, seed, &mut tally)?;
            }
            let share = |n: u64| 100.0 * n as f64 / tally.contacts.max(1) as f64;
            let seconds = tally.steps as f64 * f64::from(config.dt);
            println!(
                "{name:<26} {mm:>6.1} {:>5}/{HOLDS} {:>6.1}% {:>6.1}% {:>7.1}% {:>9.2} {:>9.2}",
                tally.drops,
                share(tally.states[0]),
                share(tally.states[1]),
                share(tally.states[2]),
                tally.contacts as f64 / tally.steps.max(1) as f64,
                tally.events as f64 / seconds.max(1e-9),
            );
            if k == 0 && mm == 2.0 {
                telling = Some(tally);
            }
        }
    }
    if let Some(tally) = telling {
        println!("the tracked hand at 2 mm, digit by digit: share of its contact-steps");
        let names = ["thumb", "index", "middle", "ring", "little", "palm"];
        for (name, [stuck, slipped, lifted]) in names.iter().zip(tally.by_digit) {
            let all = (stuck + slipped + lifted).max(1) as f64;
            let pct = |n: u64| 100.0 * n as f64 / all;
            println!(
                "  {name:<7} slipped {:>5.1}%  off {:>4.1}%  ({:.2} contacts a step)",
                pct(slipped),
                pct(lifted),
                all / tally.steps.max(1) as f64
            );
        }
    }
    Ok(())
}

/// One hold: closes, lifts and holds, the tracked hand shaken by `part`
/// of the noise at `scale`, drawn from `seed`.
fn hold(
    config: InteractionConfig,
    noise: &TrackingNoise,
    scale: f32,
    part: Part,
    seed: u64,
    tally: &mut Tally,
) -> Result<(), RunError> {
    let (mut world, cube) = board::world(config, (3, 3), 0.0)?;
    let at = board::square_center((3, 3)) + Vec3::Y * CUBE_HALF;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let stream = noise.stream(scale, &mut rng);
    let hand = PoseFn::new(Side::Right, move |t: f64| {
        let closure = ((t - 0.1) / 0.35).clamp(0.0, 1.0) as f32;
        let lift = ((t - 0.8) * 0.1).clamp(0.0, 0.05) as f32;
        let pose = grip(CUBE_HALF, closure, SQUEEZE);
        let pose = pose.transformed(Vec3::ZERO, Quat::IDENTITY, at + Vec3::Y * lift);
        let r = stream.residual(t);
        let shaken = match part {
            Part::All => r,
            Part::Rigid => Residual { joints: [r.joints[0]; 21], stretch: None, ..r },
            Part::Shape => {
                Residual { joints: r.joints.map(|j| j - r.joints[0]), turn: Vec3::ZERO, ..r }
            }
        };
        Some(shaken.apply(&pose))
    });
    let mut dropped = false;
    let mut watch = |step: &StepView| {
        if step.t < HELD_FROM {
            return Ok(());
        }
        for c in step.world.contacts() {
            let k = match c.state {
                FrictionState::Static => 0,
                FrictionState::Dynamic => 1,
                FrictionState::Separated => 2,
            };
            tally.states[k] += 1;
            let digit = match c.bone {
                Bone::Finger(finger, _) => finger as usize,
                Bone::Palm => 5,
            };
            tally.by_digit[digit][k] += 1;
        }
        tally.contacts += step.world.contacts().len() as u64;
        tally.events += step.world.events().len() as u64;
        tally.steps += 1;
        dropped |= step.world.object_state(cube)?.position.y < CUBE_HALF + 0.025;
        Ok(())
    };
    let mut driver = Driver::new(&mut world);
    driver.add_hand(hand);
    driver.run(6000, &mut [&mut watch])?;
    tally.drops += u64::from(dropped);
    Ok(())
}
