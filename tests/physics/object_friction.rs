//! Object–object friction: a box sliding on the ground meets Coulomb's
//! μ·m·g, pulled at its centre or stopping from a speed, with no hand at all
//! (the pushed box is the `push-steady` scenario). μ is rapier's combined
//! coefficient, the average of the ground's and the box's.

use coulomb_hands::{
    InteractionConfig, InteractionWorld, Material, ObjectDesc, ObjectFriction, ObjectId, StaticDesc,
};
use glam::{Quat, Vec3};
use rapier3d::math::Vector;

const G: f32 = 9.81;

/// A box of `half_extents` (m) and `mass` (kg) at rest on the ground, turned
/// `yaw` (rad) about the vertical, with combined friction `mu` (ground
/// 0.1 less than μ, the box 0.1 more), in a world of `friction`.
fn box_on_ground(
    friction: ObjectFriction,
    half_extents: Vec3,
    yaw: f32,
    mass: f32,
    mu: f32,
) -> (InteractionWorld, ObjectId) {
    let config = InteractionConfig { object_friction: friction, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(0.0, mu - 0.1)).unwrap();
    let material = Material { surface_friction: mu + 0.1, ..Material::wood() };
    let desc = ObjectDesc {
        rotation: Quat::from_rotation_y(yaw),
        ..ObjectDesc::cuboid("box", 2.0 * half_extents, mass, Vec3::Y * half_extents.y)
    }
    .with_material(material);
    let id = world.add_object(&desc).unwrap();
    // Settle onto the ground.
    for _ in 0..300 {
        world.step();
    }
    (world, id)
}

/// The friction (N) on the box while a constant horizontal `pull` (N)
/// drags it along x at its centre of mass: `pull − m·a`, with `a` its mean
/// acceleration over 0.6 s once it slides.
fn friction_while_dragged(world: &mut InteractionWorld, id: ObjectId, mass: f32, pull: f32) -> f32 {
    let body = world.object_body(id).unwrap();
    let drag = |world: &mut InteractionWorld, steps: usize| {
        for _ in 0..steps {
            world.apply_hand_forces();
            let b = world.physics_mut().bodies.get_mut(body).unwrap();
            b.add_force(Vector::new(pull, 0.0, 0.0), true);
            world.step_physics();
        }
    };
    drag(world, 200);
    let (v0, t0) = (world.object_state(id).unwrap().linvel.x, world.time());
    drag(world, 600);
    let (v1, t1) = (world.object_state(id).unwrap().linvel.x, world.time());
    pull - mass * (v1 - v0) / (t1 - t0) as f32
}

/// How far the box slides (m) from speed `v` (m/s) along x until it stops.
fn stopping_distance(world: &mut InteractionWorld, id: ObjectId, v: f32) -> f32 {
    let body = world.object_body(id).unwrap();
    let x0 = world.object_state(id).unwrap().position.x;
    world.physics_mut().bodies.get_mut(body).unwrap().set_linvel(Vector::new(v, 0.0, 0.0), true);
    for _ in 0..3000 {
        world.step();
    }
    let s = world.object_state(id).unwrap();
    assert!(s.linvel.length() < 1e-3, "still sliding at {}", s.linvel);
    s.position.x - x0
}

/// Flat and squat boxes, turned on the ground, none of them able to tip
/// under the pull.
const BOXES: [(Vec3, f32, f32, f32); 3] = [
    // half extents (m), yaw (rad), mass (kg), μ
    (Vec3::new(0.035, 0.035, 0.035), 0.0, 0.32, 0.45),
    (Vec3::new(0.07, 0.012, 0.045), 0.4, 0.6, 0.28),
    (Vec3::new(0.03, 0.02, 0.055), 1.1, 0.18, 0.62),
];

#[test]
fn a_box_dragged_across_the_ground_meets_mu_m_g() {
    for (half, yaw, mass, mu) in BOXES {
        let (mut world, id) = box_on_ground(ObjectFriction::default(), half, yaw, mass, mu);
        let weight = mass * G;
        let friction = friction_while_dragged(&mut world, id, mass, 1.35 * mu * weight);
        let ratio = friction / (mu * weight);
        assert!((ratio - 1.0).abs() < 0.01, "{half} turned {yaw}: friction {ratio} × μmg");
    }
}

#[test]
fn from_speed_v_a_box_stops_in_v_squared_over_two_mu_g() {
    for ((half, yaw, mass, mu), v) in BOXES.into_iter().zip([0.9, 0.55, 1.3]) {
        let (mut world, id) = box_on_ground(ObjectFriction::default(), half, yaw, mass, mu);
        let ratio = stopping_distance(&mut world, id, v) / (v * v / (2.0 * mu * G));
        assert!((ratio - 1.0).abs() < 0.02, "{half} turned {yaw}: slid {ratio} × v²/2μg");
    }
}

#[test]
fn rapier_s_cone_per_point_falls_short_of_coulomb_at_a_cube_s_corners() {
    // The control (ObjectFriction's docs): one cone per contact point caps
    // each corner's impulse along K⁻¹·v, not against the slip v. For a
    // cube's corner K ∝ [[4, −1.5], [−1.5, 4]], so the friction along the
    // slip is 4/√18.25 = 0.936 of μ·N; and the cube slides 1/0.936 as far.
    let (half, yaw, mass, mu) = BOXES[0];
    let (mut world, id) = box_on_ground(ObjectFriction::Coulomb, half, yaw, mass, mu);
    let weight = mass * G;
    let ratio = friction_while_dragged(&mut world, id, mass, 1.35 * mu * weight) / (mu * weight);
    let predicted = 4.0 / 18.25f32.sqrt();
    assert!((ratio - predicted).abs() < 0.005, "friction {ratio} × μmg, predicted {predicted}");
    let (mut world, id) = box_on_ground(ObjectFriction::Coulomb, half, yaw, mass, mu);
    let v = 0.9;
    let slid = stopping_distance(&mut world, id, v) / (v * v / (2.0 * mu * G));
    assert!((slid * predicted - 1.0).abs() < 0.01, "slid {slid} × v²/2μg");
}

/// The acceleration (m/s²) down a ramp tilted `slope` (rad), with combined
/// friction 0.55, of a 3 cm, 80 g ball with principal moments `inertia`
/// (kg·m², `None` for a solid ball's), measured from 0.1 s to 0.5 s after
/// it is let go, and its rolling ratio ω·r/v at the end.
fn down_a_ramp(slope: f32, inertia: Option<Vec3>) -> (f32, f32) {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let tilt = Quat::from_rotation_z(slope);
    let half = Vec3::new(1.0, 0.05, 0.3);
    let ramp = StaticDesc {
        name: "ramp".into(),
        shape: coulomb_hands::ShapeDesc::Box { half_extents: half },
        position: Vec3::ZERO,
        rotation: tilt,
        friction: 0.5,
    };
    world.add_static(&ramp).unwrap();
    let (r, mass) = (0.015, 0.08);
    let up = tilt * Vec3::Y;
    let mut desc = ObjectDesc {
        shape: coulomb_hands::ShapeDesc::Sphere { radius: r },
        ..ObjectDesc::cuboid("ball", Vec3::ZERO, mass, up * (half.y + r) + tilt * Vec3::X * 0.5)
    }
    .with_material(Material { surface_friction: 0.6, ..Material::wood() });
    desc.inertia = inertia;
    let id = world.add_object(&desc).unwrap();
    let down = tilt * -Vec3::X;
    let speed = |world: &mut InteractionWorld, steps: usize| {
        for _ in 0..steps {
            world.step();
        }
        world.object_state(id).unwrap()
    };
    let v0 = speed(&mut world, 100).linvel.dot(down);
    let end = speed(&mut world, 400);
    let v1 = end.linvel.dot(down);
    let spin = end.angvel.dot(up.cross(down)) * r;
    ((v1 - v0) / 0.4, spin / v1)
}

#[test]
fn a_hollow_ball_rolls_down_a_ramp_at_three_fifths_of_g_sin_theta() {
    // Rolling without slipping: a = g·sinθ / (1 + I/(m r²)): 5/7 for a
    // solid ball (I = 2/5 m r²), 3/5 for a hollow one (I = 2/3 m r²), as
    // long as μ > tanθ / (1 + m r²/I): 0.29 and 0.40 of tan 20° here.
    let slope = 20f32.to_radians();
    let g_sin = G * slope.sin();
    let (r, mass) = (0.015f32, 0.08f32);
    let hollow = Vec3::splat(2.0 / 3.0 * mass * r * r);
    for (inertia, fraction) in [(None, 5.0 / 7.0), (Some(hollow), 3.0 / 5.0)] {
        let (a, rolling) = down_a_ramp(slope, inertia);
        assert!((a / (fraction * g_sin) - 1.0).abs() < 0.02, "{inertia:?}: a = {a} m/s²");
        assert!((rolling - 1.0).abs() < 0.02, "{inertia:?}: ω·r/v = {rolling}");
    }
}
