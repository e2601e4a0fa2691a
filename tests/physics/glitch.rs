//! Tracking glitches: a bone or a hand that jumps, vanishes, collapses or
//! floods the input must never fling an object, never put a NaN anywhere,
//! and its contacts must end and begin again as the bones really touch.

use super::*;
use coulomb_hands::{ContactEventKind, Finger, InteractionConfig, ObjectDesc, Phalanx, StaticDesc};

const INDEX_DISTAL: Bone = Bone::Finger(Finger::Index, Phalanx::Distal);

/// The top speed (m/s) of a `size` box of `mass` resting on the ground
/// when a fingertip lying against its −x face jumps `jump` (m) into it in
/// one frame, stays there for 0.6 s and is then tracked far away; checks
/// the contacts' events and that they all end.
fn jump_into_box(size: f32, mass: f32, jump: f32) -> f32 {
    jump_into_box_at(InteractionConfig::default().dt, size, mass, jump)
}

/// [`jump_into_box`] with the world stepping at `dt` (s).
fn jump_into_box_at(dt: f32, size: f32, mass: f32, jump: f32) -> f32 {
    let config = InteractionConfig { dt, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
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
    let (before, after, away) = (bone_at(touching), bone_at(touching + jump), bone_at(-1.0));
    let mut top = 0.0f32;
    let mut book = ContactBook::default();
    run(
        &mut world,
        hand,
        1.0,
        |t| match t {
            t if t < 0.2 => before.clone(),
            t if t < 0.8 => after.clone(),
            _ => away.clone(),
        },
        |w, t| {
            book.check(w, t);
            top = top.max(w.object_state(id).unwrap().linvel.length());
        },
    );
    assert!(book.began > 0 && world.contacts().is_empty(), "{mass} kg, {jump} m: {book:?}");
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
    let bad: Vec<_> = report.iter().filter(|r| r.2.is_nan() || r.2 > 2.0).collect();
    assert!(bad.is_empty(), "flung (mass kg, jump m, top speed m/s): {bad:?}\nall: {report:?}");
}

#[test]
fn at_a_host_engines_90_hz_a_fingertip_jumping_into_a_box_never_flings_it_either() {
    // The springs step by backward Euler there, the bone's speed into the
    // object limited as the explicit law limits it: a jump is not a push.
    let mut report = Vec::new();
    for mass in [0.008, 0.06, 0.5] {
        for jump in [0.03, 0.08] {
            let top = jump_into_box_at(1.0 / 90.0, jump + 0.04, mass, jump);
            report.push((mass, jump, top));
        }
    }
    let bad: Vec<_> = report.iter().filter(|r| r.2.is_nan() || r.2 > 2.0).collect();
    assert!(bad.is_empty(), "flung (mass kg, jump m, top speed m/s): {bad:?}\nall: {report:?}");
}

#[test]
fn a_hand_that_really_swings_fast_still_pushes_fast() {
    // The safeguard limits how fast a bone may sink into an object, not how
    // fast a hand may push one: a fingertip sweeping at 3 m/s through a
    // 30 g box on ice carries it along at its own speed.
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.0)).unwrap();
    let desc = ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.03, Vec3::new(0.0, 0.025, 0.0))
        .with_material(Material::custom("ice", 0.1, 0.1, 0.0));
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let start = -0.025 - 0.008 - 0.03;
    let bone_at = |t: f32| {
        let x = start + 3.0 * (t - 0.1).max(0.0);
        let mut p = parked_hand(Side::Right);
        let capsule =
            Capsule { a: Vec3::new(x, 0.02, -0.012), b: Vec3::new(x, 0.02, 0.012), radius: 0.008 };
        set_bone(&mut p, INDEX_DISTAL, capsule);
        p
    };
    let mut top = 0.0f32;
    run(&mut world, hand, 0.2, bone_at, |w, _| {
        top = top.max(w.object_state(id).unwrap().linvel.x);
    });
    assert!(top > 2.7, "a 3 m/s sweep pushed the box to only {top:.2} m/s");
}

#[test]
fn a_whole_hand_teleporting_30_cm_into_a_crate_neither_flings_it_nor_sticks() {
    // A 2 kg, 40 cm crate and a 60 g, 40 cm foam block: the hand jumps from
    // beside each, its fingertips touching, to 30 cm inside it, stays for
    // 0.4 s, and is then tracked 1 m away. The glitch may shove the crate
    // (each bone pushes out through the face nearest to it), but never
    // faster than 2 m/s, and every contact ends once the hand is gone.
    for mass in [2.0, 0.06] {
        let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
        world.add_static(&StaticDesc::ground(0.0, 0.6)).unwrap();
        let desc = ObjectDesc::cuboid("crate", Vec3::splat(0.4), mass, Vec3::new(0.0, 0.2, 0.0));
        let id = world.add_object(&desc).unwrap();
        let hand = world.add_hand(Side::Right);
        let rig = coulomb_hands::hand::rig::HandRig::adult(Side::Right);
        // Palm down, fingers along +x, fingertips just short of the −x face.
        let outside = rig.pose(Vec3::new(-0.31, 0.2, 0.0), Quat::IDENTITY, [0.0; 5]);
        let reach = outside.fingers[2][2].b.x + outside.fingers[2][2].radius;
        let outside =
            rig.pose(Vec3::new(-0.31 - reach - 0.2 - 0.002, 0.2, 0.0), Quat::IDENTITY, [0.0; 5]);
        let inside =
            rig.pose(Vec3::new(-0.31 - reach - 0.2 + 0.3, 0.2, 0.0), Quat::IDENTITY, [0.0; 5]);
        let away = rig.pose(Vec3::new(-1.5, 0.2, 0.0), Quat::IDENTITY, [0.0; 5]);
        let mut book = ContactBook::default();
        let mut top = 0.0f32;
        run(
            &mut world,
            hand,
            2.5,
            |t| match t {
                t if t < 0.2 => outside.clone(),
                t if t < 0.6 => inside.clone(),
                _ => away.clone(),
            },
            |w, t| {
                book.check(w, t);
                top = top.max(w.object_state(id).unwrap().linvel.length());
            },
        );
        assert!(top <= 2.0, "{mass} kg: flung at {top:.2} m/s");
        assert!(book.began > 0, "{mass} kg: the hand never touched the crate");
        assert!(world.contacts().is_empty(), "{mass} kg: contacts outlived the hand leaving");
        let speed = world.object_state(id).unwrap().linvel.length();
        assert!(speed < 0.01, "{mass} kg: still moving at {speed} m/s after the hand left");
    }
}

/// Checks, step by step, that contacts begin and end only with their
/// events, and that the world stays finite.
#[derive(Debug, Default)]
pub struct ContactBook {
    before: Vec<(u32, Bone, u32)>,
    pub began: usize,
    pub ended: usize,
}

impl ContactBook {
    pub fn check(&mut self, world: &InteractionWorld, t: f32) {
        if let Some(bad) = world.first_non_finite() {
            panic!("{bad} is not finite at t = {t}");
        }
        let now: Vec<_> = world.contacts().iter().map(|c| (c.hand.0, c.bone, c.object.0)).collect();
        let key = |e: &coulomb_hands::ContactEvent| (e.hand.0, e.bone, e.object.0);
        let of = |kind| world.events().iter().filter(move |e| e.kind == kind).map(key);
        let began: Vec<_> = of(ContactEventKind::Began).collect();
        let ended: Vec<_> = of(ContactEventKind::Ended).collect();
        for c in &now {
            assert!(self.before.contains(c) || began.contains(c), "t {t}: {c:?} began silently");
        }
        for c in &self.before {
            assert!(now.contains(c) || ended.contains(c), "t {t}: {c:?} ended silently");
        }
        self.began += began.len();
        self.ended += ended.len();
        self.before = now;
    }
}
