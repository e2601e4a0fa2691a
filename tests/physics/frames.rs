//! A hand posed once per display frame (a web page's WebXR hand, an app's
//! `step(n)` per frame) while the world steps at 1 kHz: the frame's steps
//! take it from where it was to its new pose (`run::sampled`), so what it
//! pushes moves at the hand's speed, not in a kick per frame.

use super::*;
use coulomb_hands::run::sampled::FrameHands;
use coulomb_hands::{HandSample, InteractionConfig, ObjectDesc, StaticDesc};

const HALF: f32 = 0.02;
/// The hand's speed along +x (m/s).
const SPEED: f32 = 0.12;
/// A headset's display rate (Hz): 1000/72 steps a frame, 13 or 14.
const FRAME_HZ: f64 = 72.0;

/// How a frame's pose reaches the world.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Posing {
    /// Set before every step, at the step's time: the reference.
    EveryStep,
    /// Set once a frame and held for its steps (the page until now).
    Held,
    /// Set once a frame, reached at the frame's last step.
    Ramped,
}

/// A pointing hand's index tip pushes a 4 cm, 60 g box along slippery
/// ground at [`SPEED`] for 0.8 s; returns the box's speed along the push
/// at each step of the last 0.4 s (m/s).
fn box_speeds(posing: Posing) -> Vec<f32> {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.1)).unwrap();
    let start = Vec3::new(0.3, HALF, 0.0);
    let desc = ObjectDesc::cuboid("box", Vec3::splat(2.0 * HALF), 0.06, start)
        .with_material(Material { surface_friction: 0.1, ..Material::wood() });
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let (pointing, tip) = pointing_hand();
    // The tip starts 1 cm before the box's face, at its mid-height.
    let offset = Vec3::new(start.x - HALF - 0.01, HALF, 0.0) - tip;
    let at = |t: f64| {
        let advance = Vec3::X * SPEED * t as f32;
        pointing.transformed(Vec3::ZERO, Quat::IDENTITY, offset + advance)
    };
    let dt = f64::from(world.config().dt);
    let mut hands = FrameHands::default();
    let mut speeds = Vec::new();
    let mut record = |world: &InteractionWorld| {
        if world.time() > 0.4 {
            speeds.push(world.object_state(id).unwrap().linvel.x);
        }
    };
    let mut frame = 0;
    while world.time() < 0.8 {
        // The steps that fit up to the frame's display time.
        frame += 1;
        let shown = frame as f64 / FRAME_HZ;
        let steps = ((shown - world.time()) / dt).round().max(0.0) as usize;
        let last = world.time() + (steps.max(1) - 1) as f64 * dt;
        match posing {
            Posing::EveryStep => {
                for _ in 0..steps {
                    world.set_hand_pose(hand, &at(world.time())).unwrap();
                    world.step();
                    record(&world);
                }
            }
            Posing::Held => {
                world.set_hand_pose(hand, &at(last)).unwrap();
                for _ in 0..steps {
                    world.step();
                    record(&world);
                }
            }
            Posing::Ramped => {
                hands.set(&mut world, hand, Some(HandSample::from_pose(at(last)))).unwrap();
                hands.begin(&world, steps);
                for _ in 0..steps {
                    hands.pose(&mut world).unwrap();
                    world.step();
                    record(&world);
                }
            }
        }
    }
    speeds
}

/// The mean and the largest departure from it of `speeds`.
fn spread(speeds: &[f32]) -> (f32, f32) {
    let mean = speeds.iter().sum::<f32>() / speeds.len() as f32;
    (mean, speeds.iter().map(|v| (v - mean).abs()).fold(0.0, f32::max))
}

#[test]
fn a_hand_posed_once_a_frame_pushes_a_box_as_smoothly_as_one_posed_every_step() {
    let [every, held, ramped] =
        [Posing::EveryStep, Posing::Held, Posing::Ramped].map(|p| spread(&box_speeds(p)));
    for (name, (mean, _)) in [("every step", every), ("held", held), ("ramped", ramped)] {
        assert!((mean - SPEED).abs() < 0.1 * SPEED, "{name}: pushed at {mean} m/s");
    }
    // Held for a frame's 13 or 14 steps, the tip jumps 1.7 mm in one: the
    // box is kicked each frame (its speed swings by about 30 %). Ramped, it
    // moves as if posed every step (both within 0.01 %).
    assert!(held.1 > 0.1 * SPEED, "held: the box's speed swings by {} m/s", held.1);
    let smooth = 0.01 * SPEED;
    assert!(every.1 < smooth, "every step: the box's speed swings by {} m/s", every.1);
    assert!(ramped.1 < smooth, "ramped: the box's speed swings by {} m/s", ramped.1);
}
