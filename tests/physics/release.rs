//! Release: a still hand that opens lets go of what it held. Its pads back
//! out together, the squeeze falls on both sides at once, and the box
//! drops straight; on a table it stays put. When one side leaves first,
//! the other's pads push as a fingertip would: giving back at most the
//! 19 % of their stored energy that a fingertip returns.

use super::grip::{BoxSpec, Grip, Layout, Pad, tip};
use super::*;
use coulomb_hands::friction::{FINGERTIP_DISSIPATION, grip};
use coulomb_hands::{Finger, InteractionConfig};

const AT: Vec3 = Vec3::new(0.0, 0.5, 0.0);
/// When the hand opens (s), after the weight is loaded over `LOAD`.
const OPEN: f32 = 0.7;
const LOAD: f32 = 0.4;

/// Thumb on −x against `fingers` on +x, 15 mm apart, on a box of half
/// width `h` centred at `at`.
fn thumb_against(fingers: &[Finger], at: Vec3, h: f32) -> Vec<Pad> {
    let n = fingers.len() as f32;
    let mut pads = vec![tip(0, Finger::Thumb, at - Vec3::X * h, Vec3::X)];
    for (i, &finger) in fingers.iter().enumerate() {
        let z = (i as f32 - (n - 1.0) / 2.0) * 0.015;
        pads.push(tip(0, finger, at + Vec3::new(h, 0.0, z), -Vec3::X));
    }
    pads
}

const THREE: [Finger; 3] = [Finger::Index, Finger::Middle, Finger::Ring];
const THUMB: Bone = Bone::Finger(Finger::Thumb, coulomb_hands::Phalanx::Distal);

/// How a dropped box fell: its fastest horizontal speed (m/s) and how far
/// it moved sideways (m) from the first pad's opening until it had fallen
/// 20 cm.
#[derive(Debug)]
struct Fall {
    speed: f32,
    sideways: f32,
}

fn drop(config: InteractionConfig, spec: BoxSpec, layout: Layout) -> Fall {
    let from = layout.pads.iter().filter_map(|p| p.opens_at).fold(OPEN, f32::min);
    let mut grip = Grip::new(config, &spec, layout, None);
    let cube = grip.cube;
    let (mut opened, mut fall) = (None::<Vec3>, Fall { speed: 0.0, sideways: 0.0 });
    grip.run(OPEN + 0.6, LOAD, |w, t| {
        let s = w.object_state(cube).unwrap();
        let flat = s.position * Vec3::new(1.0, 0.0, 1.0);
        match opened {
            None if t >= from => opened = Some(s.position),
            Some(at) if at.y - s.position.y <= 0.2 => {
                fall.speed = fall.speed.max((s.linvel * Vec3::new(1.0, 0.0, 1.0)).length());
                fall.sideways = fall.sideways.max(flat.distance(at * Vec3::new(1.0, 0.0, 1.0)));
            }
            _ => {}
        }
    });
    let end = position(&grip.world, cube);
    assert!(opened.unwrap().y - end.y > 0.2, "the box did not fall 20 cm: {end:?}");
    fall
}

fn box_at(size: f32, mass: f32, gamma: f32) -> BoxSpec {
    BoxSpec { size: Vec3::splat(size), mass, centre: AT, gamma }
}

#[test]
fn a_still_hand_that_opens_drops_its_box_straight() {
    for (speed, mass) in [(0.035, 0.07), (0.11, 0.07), (0.28, 0.045)] {
        let pads = thumb_against(&THREE, AT, 0.022);
        let layout = Layout { pads, depth: 0.0036, speed }.open_at(OPEN, 0.0, |_| false);
        let fall = drop(InteractionConfig::default(), box_at(0.044, mass, 400.0), layout);
        assert!(
            fall.speed <= 0.03 && fall.sideways <= 0.003,
            "opening at {speed} m/s: {:.3} m/s, {:.1} mm sideways",
            fall.speed,
            fall.sideways * 1e3
        );
    }
}

#[test]
fn without_virtual_fingers_the_opening_grip_throws_the_box_sideways() {
    // The control: one γ per contact leaves the box off-centre, and the
    // grip's opening pushes it back across the hand as it falls.
    let config = InteractionConfig { virtual_fingers: false, ..InteractionConfig::default() };
    let pads = thumb_against(&THREE, AT, 0.022);
    let layout = Layout { pads, depth: 0.0036, speed: 0.11 }.open_at(OPEN, 0.0, |_| false);
    let fall = drop(config, box_at(0.044, 0.07, 400.0), layout);
    assert!(fall.sideways > 0.003, "only {:.1} mm sideways", fall.sideways * 1e3);
}

#[test]
fn a_box_let_go_on_a_table_stays_put() {
    for (fingers, size, speed) in [(&THREE[..], 0.046, 0.06), (&THREE[..2], 0.038, 0.17)] {
        let half = size / 2.0;
        let at = Vec3::new(0.1, half, -0.05);
        let pads = thumb_against(fingers, at, half);
        let layout = Layout { pads, depth: 0.0041, speed }.open_at(0.8, 0.0, |_| false);
        let spec = BoxSpec { size: Vec3::splat(size), mass: 0.09, centre: at, gamma: 450.0 };
        let mut grip = Grip::new(InteractionConfig::default(), &spec, layout, Some(0.0));
        let cube = grip.cube;
        let mut moved = 0.0f32;
        grip.run(1.6, 0.0, |w, _| {
            let p = position(w, cube);
            moved = moved.max(((p - at) * Vec3::new(1.0, 0.0, 1.0)).length());
        });
        assert!(
            moved <= 0.0003,
            "{} fingers at {speed} m/s: the box moved {:.3} mm",
            fingers.len(),
            moved * 1e3
        );
    }
}

/// The fastest a box of `mass` can leave a side of pads of stiffness γ
/// sunk `depth` if they give back what a fingertip does: 19 % of the work
/// that loaded them, `½γ·depth²` (Jindrich et al. 2003: 81 % dissipated),
/// so `½mv² ≤ 0.19·½γ·depth²`. A real pad, stiffer than γ at the same
/// force, stores less and pushes slower. Times 1.05 for the explicit step,
/// which overshoots the exact release by 2.5 % at a 1 ms step (0.3 % at
/// 0.25 ms).
fn fingertip_bound(gamma: f32, mass: f32, depth: f32) -> f32 {
    1.05 * ((1.0 - FINGERTIP_DISSIPATION) * gamma / mass).sqrt() * depth
}

#[test]
fn a_side_that_lets_go_first_leaves_the_other_to_push_as_a_fingertip_would() {
    assert!(
        (grip::released_energy_fraction(InteractionConfig::default().damping_ratio.unwrap())
            - (1.0 - FINGERTIP_DISSIPATION))
            .abs()
            < 1e-3
    );
    // (what, how long the first side leads (s), how fast the pads open
    // (m/s), the box's mass (kg), the pads' depth (m), the thumb first?)
    let cases = [
        ("thumb 50 ms early", 0.05, 0.25, 0.04, 0.003, true),
        ("fingers 20 ms early", 0.02, 0.09, 0.15, 0.0042, false),
        ("thumb 35 ms early, slowly", 0.035, 0.04, 0.025, 0.0033, true),
        ("fingers 50 ms early, fast", 0.05, 0.3, 0.06, 0.0025, false),
    ];
    for (name, lead, speed, mass, depth, thumb_first) in cases {
        let first = |p: &Pad| (p.bone == THUMB) == thumb_first;
        let gamma = 400.0;
        // Either side of a thumb against three fingers presses like 1.5 pads.
        let side = gamma * grip::side_count(3.0, 1.0);
        let pads = thumb_against(&THREE, AT, 0.022);
        let layout = Layout { pads, depth, speed }.open_at(OPEN, lead, first);
        let fall = drop(InteractionConfig::default(), box_at(0.044, mass, gamma), layout);
        let bound = fingertip_bound(side, mass, depth);
        assert!(fall.speed <= bound, "{name}: {:.3} m/s, bound {bound:.3} m/s", fall.speed);
    }
}
