//! Objects carried on skin, not gripped: a plate on a flat, open hand
//! starts to slide at the friction angle, along the fingers or across them,
//! and a flat box resting on one still, straight finger under its centre
//! stays there.

use super::*;
use coulomb_hands::{Finger, FrictionState, InteractionConfig, ObjectDesc, Phalanx};

/// A tray-like material: skin on it holds to μ_st 0.52 (27.5°).
fn tray() -> Material {
    Material::custom("tray", 0.52, 0.37, 0.5)
}

/// Where the open hand's palm is, and its straight fingers' direction
/// (unit, horizontal) and top (the highest point of palm or finger, m).
fn open_hand(rig: &HandRig, centre: Vec3) -> (Vec3, f32) {
    let pose = rig.pose(centre, Quat::IDENTITY, [0.0; 5]);
    let middle = pose.fingers[Finger::Middle as usize][Phalanx::Distal as usize];
    let along = ((middle.b - centre) * Vec3::new(1.0, 0.0, 1.0)).normalize();
    let palm_top = pose.palm.to_world(Vec3::Y * pose.palm.half_extents.y).y;
    let fingers_top = pose.fingers[1..]
        .iter()
        .flatten()
        .map(|c| c.a.y.max(c.b.y) + c.radius)
        .fold(palm_top, f32::max);
    (along, fingers_top)
}

/// The tilt (°) at which a 17 × 0.8 × 19 cm plate of `mass` (kg) resting on
/// a flat, open hand, palm up and fingers straight, first slid 3 mm on it,
/// the hand tilted about `axis` (the fingers' direction, or across them)
/// after the plate settles: smoothly to 5° below atan μ_st, then on at
/// 1.2°/s. Also the tilt at which a contact first went dynamic, and how
/// many of the palm and the four fingers pressed on the plate at rest.
///
/// The plate is wide enough to cover the thumb's tip: 15 cm wide, its edge
/// lies at the tip, which catches it from the side or not as it settles.
fn slide_onset(config: InteractionConfig, mass: f32, across_fingers: bool) -> (f32, f32, usize) {
    let rig = HandRig::adult(Side::Right);
    let centre = Vec3::new(0.0, 0.4, 0.0);
    let (along, top) = open_hand(&rig, centre);
    let mut world = InteractionWorld::new(config).unwrap();
    // The plate's middle over the hand's middle, between the palm's centre
    // and the fingertips; its long side along the fingers.
    let middle = centre + along * 0.04;
    let size = Vec3::new(0.17, 0.008, 0.19);
    let turn = Quat::from_rotation_arc(Vec3::Z, along);
    let at = Vec3::new(middle.x, top + size.y / 2.0 + 0.0005, middle.z);
    let desc = ObjectDesc::cuboid("plate", size, mass, at).with_material(tray());
    let id = world.add_object(&ObjectDesc { rotation: turn, ..desc }).unwrap();
    let hand = world.add_hand(Side::Right);
    // Tilted so that the fingertips go down (across: the little finger's
    // side): the plate slides along the fingers, or across them.
    let axis = if across_fingers { along } else { Vec3::Y.cross(along) };
    let start = 0.52f32.atan().to_degrees() - 5.0;
    let settle = 1.0;
    let tilt = move |t: f32| {
        let s = ((t - settle) / 1.0).clamp(0.0, 1.0);
        start * s * s * (3.0 - 2.0 * s) + 1.2 * (t - settle - 1.0).max(0.0)
    };
    let rotation = move |t: f32| Quat::from_axis_angle(axis, tilt(t).to_radians());
    let (mut rest, mut dynamic, mut slid, mut pressing) = (None, None, None, 0);
    run(
        &mut world,
        hand,
        settle + 1.0 + 10.0 / 1.2,
        |t| rig.pose(centre, rotation(t), [0.0; 5]),
        |w, t| {
            let palm = rig.pose(centre, rotation(t), [0.0; 5]).palm;
            let local = palm.to_local(w.object_state(id).unwrap().position);
            if t >= settle && rest.is_none() {
                rest = Some(local);
                // The palm, and each finger but the thumb, that presses.
                let limbs: std::collections::BTreeSet<_> = w
                    .contacts_on(id)
                    .iter()
                    .filter(|c| c.normal_force > 0.0)
                    .filter_map(|c| match c.bone {
                        Bone::Palm => Some(None),
                        Bone::Finger(f, _) if f != Finger::Thumb => Some(Some(f as usize)),
                        Bone::Finger(..) => None,
                    })
                    .collect();
                pressing = limbs.len();
            }
            let Some(rest) = rest else { return };
            let moving = w.contacts_on(id).iter().any(|c| c.state == FrictionState::Dynamic);
            if dynamic.is_none() && moving {
                dynamic = Some(tilt(t));
            }
            if slid.is_none() && (local - rest).length() > 0.003 {
                slid = Some(tilt(t));
            }
        },
    );
    (slid.unwrap_or(f32::NAN), dynamic.unwrap_or(f32::NAN), pressing)
}

#[test]
fn a_plate_on_a_flat_hand_slides_off_only_past_the_friction_angle() {
    // Lying on the palm's face and along the straight fingers, the plate is
    // held by flat supports: it should slide when the slope passes
    // atan μ_st, along the fingers or across them, as on a flat palm alone,
    // whatever it weighs.
    let expected = 0.52f32.atan().to_degrees();
    for mass in [0.08, 0.15, 0.25] {
        for across in [false, true] {
            let (slid, dynamic, pressing) = slide_onset(InteractionConfig::default(), mass, across);
            let how = if across { "across the fingers" } else { "along the fingers" };
            assert!(pressing >= 4, "{mass} kg, {how}: {pressing} of palm and fingers pressed");
            assert!(
                (slid - expected).abs() <= 1.0,
                "{mass} kg, {how}: slid 3 mm at {slid:.2}° (atan μ_st {expected:.2}°; a \
                 contact slipped at {dynamic:.2}°)"
            );
        }
    }
}

#[test]
fn without_the_stribeck_fade_the_plate_slides_before_the_friction_angle() {
    // The control: each light contact that reaches its cone drops at once
    // to μ_dyn and hands its load on, and the plate goes early.
    let config = InteractionConfig { stribeck_speed: None, ..InteractionConfig::default() };
    let (slid, _, _) = slide_onset(config, 0.15, false);
    let expected = 0.52f32.atan().to_degrees();
    assert!(slid < expected - 1.0, "slid at {slid:.2}°, atan μ_st {expected:.2}°");
}

/// A flat, 45 g box, 7 × 1.2 × 4.5 cm, resting on one straight index
/// finger held level along its length, the finger `off` (m) across from
/// under the box's centre; every other bone parked away. Returns how far
/// the box's centre moved (m) and how far it turned (°) from 0.5 s to 4 s,
/// and its lowest height above the finger's axis (m).
fn box_on_one_finger(config: InteractionConfig, off: f32) -> (f32, f32, f32) {
    let mut world = InteractionWorld::new(config).unwrap();
    let rig = HandRig::adult(Side::Right);
    let radius = rig.radii[Finger::Index as usize];
    let axis_y = 0.35;
    let mut pose = parked_hand(Side::Right);
    let lengths = rig.lengths[Finger::Index as usize];
    let mut x = -0.5 * lengths.iter().sum::<f32>();
    for (phalanx, length) in
        [Phalanx::Proximal, Phalanx::Intermediate, Phalanx::Distal].into_iter().zip(lengths)
    {
        let a = Vec3::new(x, axis_y, 0.0);
        x += length;
        let capsule = Capsule { a, b: Vec3::new(x, axis_y, 0.0), radius };
        set_bone(&mut pose, Bone::Finger(Finger::Index, phalanx), capsule);
    }
    let size = Vec3::new(0.07, 0.012, 0.045);
    let at = Vec3::new(0.0, axis_y + radius + size.y / 2.0 + 0.0005, off);
    let desc = ObjectDesc::cuboid("box", size, 0.045, at).with_material(test_material(0.5));
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let (mut settled, mut moved, mut turned, mut lowest) = (None, 0.0f32, 0.0f32, f32::MAX);
    run(
        &mut world,
        hand,
        4.0,
        |_| pose.clone(),
        |w, t| {
            let state = w.object_state(id).unwrap();
            lowest = lowest.min(state.position.y - axis_y);
            if t < 0.5 {
                return;
            }
            let (p, r) = *settled.get_or_insert((state.position, state.rotation));
            moved = moved.max((state.position - p).length());
            turned = turned.max(state.rotation.angle_between(r).to_degrees());
        },
    );
    (moved, turned, lowest)
}

#[test]
fn a_box_resting_on_one_still_finger_under_its_centre_stays_there() {
    // The finger's three bones lie along the box's bottom face: line
    // contacts, each a flat support along the bone and the pad's width
    // across it, hold the box level.
    let (moved, turned, lowest) = box_on_one_finger(InteractionConfig::default(), 0.0);
    assert!(moved < 0.002 && turned < 2.0, "moved {moved} m and turned {turned}°");
    assert!(lowest > 0.0, "the box sank {lowest} m below the finger's axis");
    // The finger 2.6 cm across, past the box's 2.25 cm half-width: nothing
    // under its centre, and it tips off.
    let (moved, turned, _) = box_on_one_finger(InteractionConfig::default(), 0.026);
    assert!(moved > 0.01 && turned > 10.0, "off the finger it moved {moved} m, turned {turned}°");
}
