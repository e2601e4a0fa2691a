//! Rolling contacts: a ball or a cylinder rolls down a tilted palm as
//! rigid-body mechanics says, with its true depth at every step and no
//! kick; too steep, it slides and spins up as Coulomb's law says; between
//! a thumb and a finger moving apart, a ball turns as they set it. The
//! thesis's anchored C (rolling off, as `--method thesis` has it) is the
//! negative control.

use super::*;
use coulomb_hands::{Finger, InteractionConfig, Method, ObjectDesc, Palm, Phalanx, ShapeDesc};

const G: f32 = 9.81;

/// The default settings: rolling contacts are on.
fn rolling() -> InteractionConfig {
    let config = InteractionConfig::default();
    assert!(config.rolling, "rolling contacts are the default");
    config
}

/// What a run down the palm measured, over its middle stretch.
struct Roll {
    /// Acceleration down the slope (m/s²).
    accel: f32,
    /// ω·r over the speed down the slope, at the end of the stretch.
    ratio: f32,
    /// The largest step-to-step change of speed over its mean.
    kick: f32,
    /// The shallowest and deepest contact depth over the stretch (m).
    depth: (f32, f32),
    /// The spin about the rolling axis at the stretch's start and end
    /// (rad/s).
    spin: (f32, f32),
}

/// A body of radius `radius` set on a flat palm tilted `theta` (rad) down
/// +z, let go still, and watched for `seconds`: its motion from 0.1 s on.
/// The palm is a long flat box, so it rolls the whole time; the fingers are
/// parked away.
fn roll_down(
    config: InteractionConfig,
    theta: f32,
    radius: f32,
    desc: ObjectDesc,
    seconds: f32,
) -> Roll {
    let mut world = InteractionWorld::new(config).unwrap();
    let center = Vec3::new(0.0, 0.3, 0.0);
    let (pose, normal, down) = tilted_palm(theta, Vec3::new(0.06, 0.012, 0.25), center);
    // Resting 0.4 mm into the skin, a third of the way down.
    let start = center + normal * (0.012 + radius - 0.0004) - down * 0.15;
    let desc = ObjectDesc { position: start, ..desc };
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let axis = normal.cross(down);
    let (mut speeds, mut spins, mut depths) = (Vec::new(), Vec::new(), Vec::new());
    run(
        &mut world,
        hand,
        seconds,
        |_| pose.clone(),
        |w, _| {
            let s = w.object_state(id).unwrap();
            speeds.push(s.linvel.dot(down));
            spins.push(s.angvel.dot(axis));
            depths.push(w.contacts_on(id).iter().map(|c| c.depth).fold(f32::NAN, f32::max));
        },
    );
    let dt = config.dt;
    let (a, b) = ((0.1 / dt).round() as usize, speeds.len() - 1);
    let steps: Vec<f32> = speeds[a..=b].windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    let mean_step = steps.iter().sum::<f32>() / steps.len() as f32;
    let depth =
        depths[a..=b].iter().fold((f32::INFINITY, 0.0f32), |(lo, hi), &d| (lo.min(d), hi.max(d)));
    Roll {
        accel: (speeds[b] - speeds[a]) / ((b - a) as f32 * dt),
        ratio: spins[b] * radius / speeds[b],
        kick: steps.iter().fold(0.0f32, |m, &s| m.max(s)) / mean_step,
        depth,
        spin: (spins[a], spins[b]),
    }
}

/// A hand whose palm is a flat box of half extents `half` (m) centred at
/// `center`, tilted `theta` (rad) down +z, its fingers parked away; with the
/// palm's normal and the direction down its slope.
fn tilted_palm(theta: f32, half: Vec3, center: Vec3) -> (HandPose, Vec3, Vec3) {
    let normal = Vec3::new(0.0, theta.cos(), theta.sin());
    let down = Vec3::new(0.0, -theta.sin(), theta.cos());
    let mut pose = parked_hand(Side::Right);
    pose.palm = Palm::from_normal_direction(center, normal, down, half).unwrap();
    (pose, normal, down)
}

fn ball(radius: f32, mass: f32, material: Material) -> ObjectDesc {
    let mut desc = ObjectDesc::cuboid("ball", Vec3::splat(2.0 * radius), mass, Vec3::ZERO)
        .with_material(material);
    desc.shape = ShapeDesc::Sphere { radius };
    desc
}

/// Skin on a grippy surface: μ well above what rolling needs on these
/// slopes, so nothing slips.
fn grippy() -> Material {
    Material::custom("rubber", 0.8, 0.7, 0.6)
}

/// It rolls without slipping at `expected` (m/s²), within 5 %, and without
/// a kick: no step's change of speed above 3× the mean.
fn assert_rolls(roll: &Roll, expected: f32) {
    assert!((roll.accel / expected - 1.0).abs() < 0.05, "a {} vs {expected}", roll.accel);
    assert!((roll.ratio - 1.0).abs() < 0.05, "ω·r/v {}", roll.ratio);
    assert!(roll.kick < 3.0, "a step's speed change {:.1}× the mean", roll.kick);
}

#[test]
fn a_solid_ball_rolls_down_a_tilted_palm_at_five_sevenths_of_g_sin_theta_without_a_kick() {
    let (theta, r) = (11f32.to_radians(), 0.023);
    let roll = roll_down(rolling(), theta, r, ball(r, 0.06, grippy()), 0.45);
    let expected = 5.0 / 7.0 * G * theta.sin();
    assert_rolls(&roll, expected);
    // The true depth every step: it neither sinks nor lifts off.
    assert!(roll.depth.0 > 0.0 && roll.depth.1 < 0.003, "depth {:?}", roll.depth);
}

#[test]
fn pinned_to_the_ball_the_contact_sinks_and_kicks() {
    // The negative control: the thesis's C, anchored on the ball while it
    // sticks, turns away with it; the depth it measures falls while the
    // ball sinks, and the contact kicks when it lets go.
    let (theta, r) = (11f32.to_radians(), 0.023);
    let config = InteractionConfig { rolling: false, ..rolling() };
    let roll = roll_down(config, theta, r, ball(r, 0.06, grippy()), 0.45);
    let expected = 5.0 / 7.0 * G * theta.sin();
    let off = (roll.accel / expected - 1.0).abs() > 0.05;
    assert!(off || roll.kick > 3.0, "a {} vs {expected}, kick {:.1}", roll.accel, roll.kick);
    assert!(!Method::Thesis.config(InteractionConfig::default()).rolling);
}

#[test]
fn a_hollow_ball_rolls_at_three_fifths_of_g_sin_theta() {
    let (theta, r, m) = (9f32.to_radians(), 0.026, 0.045);
    let desc = ball(r, m, grippy()).with_inertia(Vec3::splat(2.0 / 3.0 * m * r * r));
    let roll = roll_down(rolling(), theta, r, desc, 0.45);
    let expected = 3.0 / 5.0 * G * theta.sin();
    assert_rolls(&roll, expected);
}

#[test]
fn a_cylinder_lying_across_the_palm_rolls_at_two_thirds_of_g_sin_theta() {
    let (theta, r) = (10f32.to_radians(), 0.015);
    let mut desc = ball(r, 0.07, grippy());
    desc.shape = ShapeDesc::Cylinder { half_height: 0.04, radius: r };
    // Its axis across the slope (x): a 4 cm-long log lying on its side.
    desc.rotation = Quat::from_rotation_z(std::f32::consts::FRAC_PI_2);
    let roll = roll_down(rolling(), theta, r, desc, 0.45);
    let expected = 2.0 / 3.0 * G * theta.sin();
    assert_rolls(&roll, expected);
}

#[test]
fn too_steep_to_roll_a_ball_slides_and_spins_up_as_kinetic_friction_says() {
    // μ_st 0.12 < (2/7)·tan 27° = 0.146: it cannot roll without slipping.
    let (theta, r) = (27f32.to_radians(), 0.02);
    let (mu_st, mu_dyn) = (0.12, 0.1);
    let desc = ball(r, 0.05, Material::custom("ice", mu_st, mu_dyn, 0.1));
    let seconds = 0.3;
    // One sample: the friction acts where the ball presses. The palm's
    // ring spreads it over samples up to 30° round so small a ball, which
    // shortens its lever (the book's "Rolling contacts").
    let mut point = rolling();
    point.patch.samples = 1;
    let roll = roll_down(point, theta, r, desc.clone(), seconds);
    let expected = G * (theta.sin() - mu_dyn * theta.cos());
    assert!((roll.accel / expected - 1.0).abs() < 0.05, "a {} vs {expected}", roll.accel);
    let spin_rate = (roll.spin.1 - roll.spin.0) / (seconds - 0.1);
    let expected = 2.5 * mu_dyn * G * theta.cos() / r;
    assert!((spin_rate / expected - 1.0).abs() < 0.1, "ω̇ {spin_rate} vs {expected}");
    assert!(roll.ratio < 0.9, "slipping: ω·r/v {}", roll.ratio);
    // With the ring, the sliding patch follows the ball round and does not
    // brake its spin: it spins up the whole way (it stalled at 3 rad/s
    // when the patch's dampers saw the spin).
    let ring = roll_down(rolling(), theta, r, desc, seconds);
    let spin_rate = (ring.spin.1 - ring.spin.0) / (seconds - 0.1);
    assert!(spin_rate > 0.7 * expected, "ω̇ {spin_rate} vs {expected}");
}

#[test]
fn a_ball_rolled_past_the_palm_s_edge_leaves_the_palm() {
    // A 2.8 cm ball let go 1 cm above the lower edge of a 6 cm-long palm
    // tipped 8° rolls over the edge: past it, no palm is under the ball,
    // which falls. (A rolling contact's p once slid along the face's plane
    // past the palm, and held the ball up on a palm that was not there.)
    let (theta, r, half) = (8f32.to_radians(), 0.014, Vec3::new(0.05, 0.011, 0.03));
    let mut world = InteractionWorld::new(rolling()).unwrap();
    let center = Vec3::new(0.0, 0.5, 0.0);
    let (pose, normal, down) = tilted_palm(theta, half, center);
    let start = center + normal * (half.y + r - 0.0004) + down * (half.z - 0.01);
    let id = world.add_object(&ObjectDesc { position: start, ..ball(r, 0.03, grippy()) }).unwrap();
    let hand = world.add_hand(Side::Right);
    let mut rolled = 0.0f32;
    run(
        &mut world,
        hand,
        0.5,
        |_| pose.clone(),
        |w, _| {
            rolled = rolled.max((position(w, id) - center).dot(down));
        },
    );
    // It rolled to the edge on the palm, then fell: nothing touches it,
    // and its centre is below the palm's face.
    assert!(rolled > half.z, "it reached {rolled} m down the palm");
    assert!(world.contacts_on(id).is_empty(), "{} contacts", world.contacts_on(id).len());
    let height = (position(&world, id) - center).dot(normal);
    assert!(height < 0.0, "its centre {height} m above the palm's middle");
}

/// A 3 cm ball pinched from above by the index's middle phalanx and from
/// below by the thumb's, each sunk 2 mm; the index moves +x and the thumb
/// −x at 1 cm/s for half a second, 5 mm each. Returns how far the ball
/// turned about z (rad) each step, and how far its centre moved (m).
fn roll_between_fingers(config: InteractionConfig) -> (Vec<f32>, Vec3) {
    let (r, bone_r, sink, v) = (0.015, 0.008, 0.002, 0.01);
    let mut world = InteractionWorld::new(config).unwrap();
    let at = Vec3::new(0.0, 0.4, 0.0);
    let id = world.add_object(&ObjectDesc { position: at, ..ball(r, 0.02, grippy()) }).unwrap();
    let hand = world.add_hand(Side::Right);
    let index = Bone::Finger(Finger::Index, Phalanx::Intermediate);
    let thumb = Bone::Finger(Finger::Thumb, Phalanx::Intermediate);
    let gap = r + bone_r - sink;
    let bone = |y: f32, x: f32| Capsule {
        a: Vec3::new(x, y, -0.02),
        b: Vec3::new(x, y, 0.02),
        radius: bone_r,
    };
    let pose = |t: f32| {
        let mut pose = parked_hand(Side::Right);
        set_bone(&mut pose, index, bone(at.y + gap, v * t));
        set_bone(&mut pose, thumb, bone(at.y - gap, -v * t));
        pose
    };
    let mut turns = Vec::new();
    let mut last = Quat::IDENTITY;
    run(&mut world, hand, 0.5, pose, |w, _| {
        let q = w.object_state(id).unwrap().rotation;
        turns.push((last.inverse() * q).to_scaled_axis().z);
        last = q;
    });
    (turns, world.object_state(id).unwrap().position - at)
}

#[test]
fn a_ball_between_a_thumb_and_a_finger_moving_apart_turns_as_they_set_it() {
    // Rolling on both, the ball's surface keeps up with each finger: it
    // turns (v + v)/2r about z, clockwise seen from +z, while its centre
    // stays where the two motions cancel.
    let expected = -2.0 * 0.01 * 0.5 / (2.0 * 0.015);
    let (turns, moved) = roll_between_fingers(rolling());
    let turned: f32 = turns.iter().sum();
    assert!((turned / expected - 1.0).abs() < 0.1, "turned {turned} rad vs {expected}");
    // Steadily, one way: no step turns back, nor by more than 3× the mean
    // (it once spun up to 20 rad/s within 25 ms and swung both ways).
    let mean = turned / turns.len() as f32;
    let kick = turns.iter().map(|t| t / mean).fold(f32::INFINITY, f32::min);
    assert!(kick >= 0.0, "a step turned back, {kick:.1}× the mean");
    let kick = turns.iter().map(|t| t / mean).fold(0.0f32, f32::max);
    assert!(kick < 3.0, "a step turned {kick:.1}× the mean");
    // Along the fingers' motions, which cancel, the centre moves less than
    // a third of either finger's 5 mm.
    assert!(moved.x.abs() < 0.3 * 0.005, "its centre moved {moved:?}");
    // Pinned, each C turns away with the ball and the fingers lose their
    // hold on its surface: it turns a third less than they set.
    let config = InteractionConfig { rolling: false, ..rolling() };
    let pinned: f32 = roll_between_fingers(config).0.iter().sum();
    assert!((pinned / expected - 1.0).abs() > 0.2, "pinned, turned {pinned} rad vs {expected}");
}
