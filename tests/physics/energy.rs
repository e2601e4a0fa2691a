//! Friction never adds energy: a bone held still can only take energy out
//! of an object that moves under it, whatever the material's μ pair.

use super::*;
use coulomb_hands::{Finger, InteractionConfig, ObjectDesc, Phalanx, StaticDesc};

const INDEX_DISTAL: Bone = Bone::Finger(Finger::Index, Phalanx::Distal);

/// A 7 × 2.4 × 7 cm, 120 g box on frictionless ground; a fingertip held
/// still presses 2.5 mm into the middle of its top face. After 0.3 s the
/// box is set spinning about the vertical at `spin` rad/s under the finger.
/// Returns the box's kinetic energy at the kick, the most it has at any
/// later step (J), the farthest it turned under the finger (degrees), and
/// the twist its patch holds before any sample slips (degrees): each
/// sample holds a stretch of μ_st·f_n/γ, the farthest from the patch's
/// centre, at the smallest angle.
fn spin_under_a_still_finger(static_mu: f32, dynamic_mu: f32, spin: f32) -> (f32, f32, f32, f32) {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.0)).unwrap();
    let (half, mass) = (Vec3::new(0.035, 0.012, 0.035), 0.12);
    let desc = ObjectDesc::cuboid("box", 2.0 * half, mass, Vec3::new(0.0, half.y, 0.0))
        .with_material(Material::custom("test", static_mu, dynamic_mu, 0.0));
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let mut pose = parked_hand(Side::Right);
    let (r, y) = (0.008, 2.0 * half.y + 0.008 - 0.0025);
    set_bone(
        &mut pose,
        INDEX_DISTAL,
        Capsule { a: Vec3::new(0.0, y, -0.01), b: Vec3::new(0.0, y, 0.01), radius: r },
    );
    run(&mut world, hand, 0.3, |_| pose.clone(), |_, _| {});
    let contact = &world.contacts()[0];
    let centre = contact.samples.iter().sum::<Vec3>() / contact.samples.len() as f32;
    let reach = contact.samples.iter().map(|q| (*q - centre).length()).fold(0.0, f32::max);
    let holds = (static_mu * contact.normal_force / (contact.stiffness * reach)).to_degrees();
    let body = world.object_body(id).unwrap();
    world.physics_mut().bodies[body].set_angvel(Vec3::new(0.0, spin, 0.0), true);
    let energy = |w: &InteractionWorld| w.physics().bodies[body].kinetic_energy();
    let kicked = energy(&world);
    let start = world.object_state(id).unwrap().rotation;
    let (mut most, mut turned) = (0.0f32, 0.0f32);
    run(
        &mut world,
        hand,
        1.5,
        |_| pose.clone(),
        |w, _| {
            most = most.max(energy(w));
            turned =
                turned.max(start.angle_between(w.object_state(id).unwrap().rotation).to_degrees());
        },
    );
    (kicked, most, turned, holds)
}

#[test]
fn a_still_finger_only_takes_energy_out_of_a_box_spinning_under_it() {
    // Aluminium's published pair, μ_dyn above μ_st, and wood's equal pair.
    for (static_mu, dynamic_mu) in [(0.38, 0.6), (0.46, 0.46)] {
        for spin in [0.6, 1.5, 4.0] {
            let (kicked, most, turned, holds) =
                spin_under_a_still_finger(static_mu, dynamic_mu, spin);
            let case = format!("μ {static_mu}/{dynamic_mu}, {spin} rad/s");
            assert!(
                most <= kicked * 1.001,
                "{case}: kinetic energy rose from {kicked:.3e} J to {most:.3e} J"
            );
            if spin == 4.0 {
                // The fingertip lies along the face, so its patch is its
                // pulp's ring laid flat (`contact/line.rs`), whose samples
                // hold 13–17° here: turning well past that means they
                // slipped.
                assert!(
                    turned > 1.5 * holds,
                    "{case}: the box only turned {turned:.1}° of the {holds:.1}° its patch holds"
                );
            }
        }
    }
}
