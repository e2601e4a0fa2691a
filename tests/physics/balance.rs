//! Balance: the squeeze of a grip balances inside the hand. With every pad
//! sunk equally, a held box stays where the pads first touched it, however
//! many digits press each side ([`coulomb_hands::friction::grip`]).

use super::grip::{BoxSpec, Grip, Layout, Pad, palm, tip};
use super::*;
use coulomb_hands::{Finger, InteractionConfig};

/// The box starts here, where every grip below first touches it (m).
const AT: Vec3 = Vec3::new(0.0, 0.6, 0.0);
/// The weight is loaded over this long (s), then held until `HOLD`.
const LOAD: f32 = 0.6;
const HOLD: f32 = 1.5;

/// The box's largest offset from where the pads first touched it along
/// `axes` (m), and its vertical sag at the end (m).
fn offsets(config: InteractionConfig, spec: BoxSpec, pads: Vec<Pad>, depth: f32) -> (Vec3, f32) {
    let layout = Layout { pads, depth, speed: 0.0 };
    let mut grip = Grip::new(config, &spec, layout, None);
    let cube = grip.cube;
    let mut worst = Vec3::ZERO;
    grip.run(HOLD, LOAD, |w, _| worst = worst.max((position(w, cube) - spec.centre).abs()));
    let sag = spec.centre.y - position(&grip.world, cube).y;
    (worst, sag)
}

/// Fingers on the +x face of a box of half width `h`, `gap` apart across
/// it, against the thumb on −x, opposite their centre as people place it
/// (Baud-Bovy & Soechting 2001: the thumb points midway between fingers).
fn thumb_against(fingers: &[Finger], h: f32, gap: f32) -> Vec<Pad> {
    let n = fingers.len() as f32;
    let mut pads = vec![tip(0, Finger::Thumb, AT - Vec3::X * h, Vec3::X)];
    for (i, &finger) in fingers.iter().enumerate() {
        let z = (i as f32 - (n - 1.0) / 2.0) * gap;
        pads.push(tip(0, finger, AT + Vec3::new(h, 0.0, z), -Vec3::X));
    }
    pads
}

fn spec(size: f32, mass: f32, gamma: f32) -> BoxSpec {
    BoxSpec { size: Vec3::splat(size), mass, centre: AT, gamma }
}

fn assert_across_x(name: &str, (worst, sag): (Vec3, f32)) {
    assert!(
        worst.x < 0.0002 && worst.z < 0.0002,
        "{name}: the box moved {:.3} mm across the grip and {:.3} mm along it (sag {:.2} mm)",
        worst.x * 1e3,
        worst.z * 1e3,
        sag * 1e3,
    );
}

#[test]
fn a_thumb_balances_one_finger() {
    let pads = thumb_against(&[Finger::Middle], 0.018, 0.0);
    assert_across_x(
        "1 finger",
        offsets(InteractionConfig::default(), spec(0.036, 0.01, 400.0), pads, 0.005),
    );
}

#[test]
fn a_thumb_balances_two_fingers() {
    let pads = thumb_against(&[Finger::Index, Finger::Middle], 0.027, 0.017);
    let held = offsets(InteractionConfig::default(), spec(0.054, 0.23, 900.0), pads, 0.0046);
    assert_across_x("2 fingers", held);
}

#[test]
fn a_thumb_balances_four_fingers_and_without_virtual_fingers_it_does_not() {
    let fingers = [Finger::Index, Finger::Middle, Finger::Ring, Finger::Pinky];
    let pads = thumb_against(&fingers, 0.03, 0.016);
    let held = offsets(InteractionConfig::default(), spec(0.06, 0.12, 650.0), pads.clone(), 0.0031);
    assert_across_x("4 fingers", held);
    // One γ per contact: four springs against one, and only the box can
    // give, so it sits (n − 1)/(n + 1) of the depth towards the thumb.
    let config = InteractionConfig { virtual_fingers: false, ..InteractionConfig::default() };
    let (worst, _) = offsets(config, spec(0.06, 0.12, 650.0), pads, 0.0031);
    let expected = 3.0 / 5.0 * 0.0031;
    assert!((worst.x - expected).abs() < 0.2 * expected, "{:.3} mm", worst.x * 1e3);
}

#[test]
fn a_palm_balances_four_fingers() {
    let h = 0.032;
    let mut pads = vec![palm(0, AT - Vec3::X * h, Vec3::X)];
    let fingers = [Finger::Index, Finger::Middle, Finger::Ring, Finger::Pinky];
    for (i, &finger) in fingers.iter().enumerate() {
        let z = (i as f32 - 1.5) * 0.014;
        pads.push(tip(0, finger, AT + Vec3::new(h, 0.0, z), -Vec3::X));
    }
    let held = offsets(InteractionConfig::default(), spec(2.0 * h, 0.06, 500.0), pads, 0.0038);
    assert_across_x("palm against 4 fingers", held);
}

#[test]
fn two_hands_gripping_across_each_other_balance() {
    // The right hand's thumb and two fingers along x, the left hand's
    // thumb and three fingers along z: 300 g on pads 2 mm deep.
    let h = 0.025;
    let mut pads = vec![tip(0, Finger::Thumb, AT - Vec3::X * h, Vec3::X)];
    for (finger, y) in [(Finger::Index, 0.008), (Finger::Middle, -0.008)] {
        pads.push(tip(0, finger, AT + Vec3::new(h, y, 0.0), -Vec3::X));
    }
    pads.push(tip(1, Finger::Thumb, AT + Vec3::Z * h, -Vec3::Z));
    for (finger, x) in [(Finger::Index, -0.016), (Finger::Middle, 0.0), (Finger::Ring, 0.016)] {
        pads.push(tip(1, finger, AT + Vec3::new(x, 0.0, -h), Vec3::Z));
    }
    let (worst, sag) =
        offsets(InteractionConfig::default(), spec(2.0 * h, 0.3, 1400.0), pads, 0.002);
    assert!(
        worst.x < 0.0002 && worst.z < 0.0002,
        "two hands: {:.3} mm along x, {:.3} mm along z (sag {:.2} mm)",
        worst.x * 1e3,
        worst.z * 1e3,
        sag * 1e3
    );
}
