//! Tracking glitches: a bone or a hand that jumps, vanishes, collapses or
//! floods the input must never fling an object, never put a NaN anywhere,
//! and its contacts must end and begin again as the bones really touch.

use super::*;
use coulomb_hands::{ContactEventKind, Finger, InteractionConfig, ObjectDesc, Phalanx, StaticDesc};

const INDEX_DISTAL: Bone = Bone::Finger(Finger::Index, Phalanx::Distal);

/// The top speed (m/s) of a `size` box of `mass` resting on the ground
/// when a fingertip lying against its −x face jumps `jump` (m) into it in
/// one frame and stays there.
fn jump_into_box(size: f32, mass: f32, jump: f32) -> f32 {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.6)).unwrap();
    let h = size / 2.0;
    let desc = ObjectDesc::cuboid("box", Vec3::splat(size), mass, Vec3::new(0.0, h, 0.0));
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let bone_at = |x: f32| {
        let mut p = parked_hand(Side::Right);
        let (y, r) = (h.min(0.02), 0.007);
        set_bone(
            &mut p,
            INDEX_DISTAL,
            Capsule { a: Vec3::new(x, y, -0.01), b: Vec3::new(x, y, 0.01), radius: r },
        );
        p
    };
    let touching = -h - 0.007 - 0.001;
    let (before, after) = (bone_at(touching), bone_at(touching + jump));
    let mut top = 0.0f32;
    run(
        &mut world,
        hand,
        1.0,
        |t| if t < 0.2 { before.clone() } else { after.clone() },
        |w, _| top = top.max(w.object_state(id).unwrap().linvel.length()),
    );
    top
}

#[test]
fn a_fingertip_jumping_up_to_10_cm_into_a_box_never_flings_it() {
    let mut report = Vec::new();
    for mass in [0.005, 0.013, 0.045, 0.32] {
        for jump in [0.025, 0.06, 0.1] {
            // The box is big enough for the bone to land inside it.
            let top = jump_into_box(jump + 0.04, mass, jump);
            report.push((mass, jump, top));
        }
    }
    let bad: Vec<_> = report.iter().filter(|r| !(r.2 <= 2.0)).collect();
    assert!(bad.is_empty(), "flung (mass kg, jump m, top speed m/s): {bad:?}\nall: {report:?}");
}
