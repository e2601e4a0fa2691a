//! Push: a fingertip pushes a box along the ground. Slippery ground: it
//! slides; grippy ground with a push above the centre: it tips over
//! (thesis Ch. 4, the sculpture path).

use super::*;
use coulomb_hands::run::bench::keep_awake;
use coulomb_hands::{Finger, InteractionConfig, ObjectDesc, StaticDesc};

const HALF: f32 = 0.025;

struct Outcome {
    /// Box displacement along the push (m).
    travel: f32,
    /// Box rotation from upright (degrees).
    tilt: f32,
    /// Bones other than the index finger that touched the box.
    other_bones: usize,
}

/// A pointing right hand (index straight, other fingers curled) moves its
/// index tip along +x at 0.1 m/s for 1.2 s at height `tip_height`, into a
/// 5 cm, 100 g box, then lifts 5 cm straight up and waits. Ground and box share the
/// object–object friction `ground_mu`.
fn push(tip_height: f32, ground_mu: f32) -> Outcome {
    push_with(InteractionConfig::default(), tip_height, ground_mu, false)
}

/// [`push`] in a world of `config`; with `aside`, a second box rests 30 cm
/// to the side, never asleep, as a body the hand does not push.
fn push_with(config: InteractionConfig, tip_height: f32, ground_mu: f32, aside: bool) -> Outcome {
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(0.0, ground_mu)).unwrap();
    let start = Vec3::new(0.2, HALF, 0.0);
    let desc = ObjectDesc::cuboid("box", Vec3::splat(2.0 * HALF), 0.1, start)
        .with_material(Material { surface_friction: ground_mu, ..Material::wood() });
    let id = world.add_object(&desc).unwrap();
    if aside {
        let other = ObjectDesc { position: start + Vec3::Z * 0.3, ..desc.clone() };
        world.add_object(&other).unwrap();
        keep_awake(&mut world);
    }
    let hand = world.add_hand(Side::Right);
    let (pointing, tip) = pointing_hand();
    // Shift the hand so the index tip starts 2 cm before the box's face.
    let offset = Vec3::new(start.x - HALF - 0.02, tip_height, 0.0) - tip;
    let mut other_bones = 0;
    run(
        &mut world,
        hand,
        2.5,
        |t| {
            let advance = Vec3::X * 0.1 * t.min(1.2);
            let lift = Vec3::Y * 0.1 * (t - 1.2).clamp(0.0, 0.5);
            pointing.transformed(Vec3::ZERO, Quat::IDENTITY, offset + advance + lift)
        },
        |w, _| {
            other_bones += w
                .contacts()
                .iter()
                .filter(|c| !matches!(c.bone, Bone::Finger(Finger::Index, _)))
                .count();
        },
    );
    let state = world.object_state(id).unwrap();
    Outcome {
        travel: state.position.x - start.x,
        tilt: state.rotation.angle_between(Quat::IDENTITY).to_degrees(),
        other_bones,
    }
}

#[test]
fn on_slippery_ground_the_box_slides() {
    let o = push(HALF, 0.05);
    assert_eq!(o.other_bones, 0, "only the index finger may touch the box");
    assert!(o.travel > 0.08, "slid only {:.1} cm", o.travel * 100.0);
    assert!(o.tilt < 10.0, "tilted {:.1}°", o.tilt);
}

#[test]
fn on_grippy_ground_a_high_push_tips_it_over() {
    let o = push(0.045, 1.0);
    assert_eq!(o.other_bones, 0, "only the index finger may touch the box");
    assert!(o.tilt > 60.0, "tilted only {:.1}°", o.tilt);
}

/// The box the finger pushes runs rapier's 4 substeps whatever the engine
/// runs for the bodies it does not push (`engine_substeps`), here a box
/// kept awake beside it: the push is the same, to a micrometre and a tenth
/// of a degree. (Were the pushed box to run the engine's 2 as well, it
/// would slide 14 µm differently: a push is not what the substeps change
/// most; letting go is, as `recordings.rs`'s grab fist shows.)
#[test]
fn the_engines_substeps_leave_a_push_as_it_was() {
    let with = |engine_substeps| {
        let config = InteractionConfig { engine_substeps, ..InteractionConfig::default() };
        push_with(config, 0.6 * HALF, 0.4, true)
    };
    let four = with(4);
    assert!(four.travel > 0.09, "slid {:.1} cm", four.travel * 100.0);
    for engine in [2, 1] {
        let o = with(engine);
        let apart = (o.travel - four.travel).abs();
        assert!(apart < 1e-6, "engine {engine}: {:.3} µm from 4's", apart * 1e6);
        assert!((o.tilt - four.tilt).abs() < 0.1, "engine {engine}: {:.2}°", o.tilt);
    }
}
