//! Host-engine mode (`pipeline::host`): the demo and every shipped scenario,
//! their hands' wrenches handed step by step to a second world that stands
//! for the host engine and steps rapier, follow the built-in world to the
//! bit. The world in host mode integrates nothing: what it knows of the
//! objects' motion, the host gives it.

use super::*;
use coulomb_hands::output::session::Session;
use coulomb_hands::run::demo::GraspLiftCarry;
use coulomb_hands::run::drive::Host;
use coulomb_hands::run::scenario::{Scenario, shipped};
use coulomb_hands::{
    Bone, Capsule, Finger, HandWrench, HostBody, InteractionConfig, ObjectDesc, ObjectState,
    Phalanx, RunError, StaticDesc,
};

/// A host engine: a world of the same scene, no hands, whose rapier steps
/// with the wrenches it is given.
struct RapierHost {
    world: InteractionWorld,
}

impl Host for RapierHost {
    fn give_states(&mut self, world: &mut InteractionWorld) -> Result<(), RunError> {
        for o in 0..self.world.object_count() {
            let id = ObjectId(o as u32);
            let body = &self.world.physics().bodies[self.world.object_body(id).unwrap()];
            world.set_host_body(id, &HostBody::of_rapier(body))?;
        }
        Ok(())
    }

    fn integrate(&mut self, wrenches: &[HandWrench]) -> Result<(), RunError> {
        Ok(self.world.integrate_wrenches(wrenches)?)
    }
}

/// Every object's state after every step.
#[derive(Default)]
struct States(Vec<Vec<ObjectState>>);

impl coulomb_hands::run::drive::Observer for States {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let w = step.world;
        let all = (0..w.object_count()).map(|o| w.object_state(ObjectId(o as u32)).unwrap());
        // The hand force total is the world's own record (Eq. 3.10), not
        // the host's: the motion is what must agree.
        self.0.push(all.map(|s| ObjectState { hand_force: Vec3::ZERO, ..s }).collect());
        Ok(())
    }
}

/// The first step and object at which two runs' states differ in any bit.
fn first_difference(built_in: &States, hosted: &States) -> Option<(usize, usize)> {
    assert_eq!(built_in.0.len(), hosted.0.len(), "the runs have as many steps");
    let bits = |s: &ObjectState| {
        let v = [s.position, s.linvel, s.angvel];
        (v.map(|v| v.to_array().map(f32::to_bits)), s.rotation.to_array().map(f32::to_bits))
    };
    built_in.0.iter().zip(&hosted.0).enumerate().find_map(|(step, (a, b))| {
        let object = a.iter().zip(b).position(|(a, b)| bits(a) != bits(b))?;
        Some((step, object))
    })
}

#[test]
fn every_scenario_in_host_mode_moves_its_objects_as_the_built_in_world_to_the_bit() {
    for (name, _) in shipped() {
        let scenario = Scenario::find(name).unwrap();
        let mut built_in = States::default();
        let report = scenario.run(&mut [&mut built_in]).unwrap();
        let mut host = InteractionWorld::new(scenario.config).unwrap();
        host.add_scene(&scenario.scene).unwrap();
        let mut hosted = States::default();
        let host = Box::new(RapierHost { world: host });
        let hosted_report = scenario.run_hosted(host, &mut [&mut hosted]).unwrap();
        assert!(!built_in.0.is_empty());
        assert_eq!(first_difference(&built_in, &hosted), None, "{name}: (step, object)");
        assert_eq!(report, hosted_report, "{name}: the same checks and values");
    }
}

#[test]
fn the_demo_in_host_mode_grasps_lifts_and_turns_the_cube_as_the_built_in_world() {
    let config = InteractionConfig::default();
    let run = |hosted: bool| {
        let GraspLiftCarry { mut world, hand, half, cube } = GraspLiftCarry::new(config).unwrap();
        if hosted {
            // The same world, recorded from its first call.
            world = InteractionWorld::new(config).unwrap();
            Session::start(&mut world);
            world.add_static(&StaticDesc::ground(-half, 0.5)).unwrap();
            let desc = ObjectDesc::cuboid("cube", Vec3::splat(2.0 * half), 0.05, Vec3::ZERO);
            assert_eq!(world.add_object(&desc).unwrap(), cube);
            assert_eq!(world.add_hand(Side::Right), hand);
        }
        let host = GraspLiftCarry::new(config).unwrap().world;
        let mut states = States::default();
        let mut driver = Driver::new(&mut world);
        let pose = move |t: f64| Some(GraspLiftCarry::pose_at(half, t as f32));
        driver.drive(hand, PoseFn::new(Side::Right, pose)).unwrap();
        if hosted {
            driver.set_host(Box::new(RapierHost { world: host })).unwrap();
        }
        let steps = GraspLiftCarry::steps(config.dt);
        driver.run(steps, &mut [&mut states]).unwrap();
        (states, Session::take(&mut world), world.contacts().to_vec())
    };
    let ((built_in, _, _), (hosted, session, contacts)) = (run(false), run(true));
    // A host-mode session (the host's states, the steps) replays to the
    // same contacts.
    let session = session.expect("recorded");
    assert_eq!(session.steps(), built_in.0.len());
    let mut last = Vec::new();
    let replayed = session.replay(|w| last = w.contacts().to_vec()).unwrap();
    assert!((replayed.time() - f64::from(GraspLiftCarry::END)).abs() < 1e-6);
    assert!(!last.is_empty(), "the hand still touches the cube at the end");
    let bits = |cs: &[coulomb_hands::Contact]| -> Vec<_> {
        cs.iter().map(|c| (c.bone, c.force.to_array().map(f32::to_bits))).collect()
    };
    assert_eq!(bits(&last), bits(&contacts), "the replayed session's last contacts");
    // The cube was lifted and turned, so the runs agree on a motion.
    let start = built_in.0[0][0].position.y;
    let rise = built_in.0.iter().map(|s| s[0].position.y - start).fold(0.0, f32::max);
    assert!(rise > 0.75 * GraspLiftCarry::LIFT_HEIGHT, "the cube rose {rise} m");
    assert_eq!(first_difference(&built_in, &hosted), None, "(step, object)");
}

#[test]
fn a_host_turning_an_object_about_a_far_origin_brings_it_to_a_finger_that_touches_it() {
    // A 2 cm block 1 m from its object's origin, which the host turns
    // about y at 5 rad/s: the block sweeps 5 mm a step along its arc, to a
    // fingertip held still on the arc 0.333 rad ahead. The contact search
    // keeps its answers while nothing can have moved 5 mm: the block's
    // sweep must say so, not the turn times the block's own size (with
    // that, the block passed through the finger untouched).
    use coulomb_hands::scene::{Part, ShapeDesc};
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let part = Part {
        position: Vec3::new(1.0, 0.0, 0.0),
        rotation: Quat::IDENTITY,
        shape: ShapeDesc::Box { half_extents: Vec3::splat(0.01) },
    };
    let desc = ObjectDesc {
        shape: ShapeDesc::Compound(vec![part]),
        ..ObjectDesc::cuboid("arm", Vec3::ONE, 0.1, Vec3::new(0.0, 0.5, 0.0))
    };
    let arm = world.add_object(&desc).unwrap();
    let body = &world.physics().bodies[world.object_body(arm).unwrap()];
    let rest = HostBody::of_rapier(body);
    let hand = world.add_hand(Side::Right);
    let ahead = Quat::from_rotation_y(-0.333) * Vec3::new(1.0, 0.0, 0.0) + rest.position;
    let mut pose = parked_hand(Side::Right);
    let tip = Bone::Finger(coulomb_hands::Finger::Index, coulomb_hands::Phalanx::Distal);
    let capsule = Capsule { a: ahead - Vec3::Y * 0.03, b: ahead - Vec3::Y * 0.012, radius: 0.008 };
    set_bone(&mut pose, tip, capsule);
    let dt = world.config().dt;
    let mut touched_at = None;
    for step in 0..120 {
        let angle = 5.0 * step as f32 * dt;
        let state = HostBody {
            rotation: Quat::from_rotation_y(-angle),
            angvel: Vec3::new(0.0, -5.0, 0.0),
            ..rest
        };
        world.set_host_body(arm, &state).unwrap();
        world.set_hand_pose(hand, &pose).unwrap();
        world.host_step().unwrap();
        if touched_at.is_none() && !world.contacts().is_empty() {
            touched_at = Some(angle);
        }
    }
    // The fingertip's cap reaches 6 mm up into the block's height; the
    // block's leading face meets it at 0.333 rad less the block's
    // half-width and the finger's radius over 1 m (0.018 rad), less the
    // 5 mm contact offset's worth: at about 0.31 rad, to a step (5 mrad).
    let angle = touched_at.expect("the block reached the finger");
    assert!((0.3..0.325).contains(&angle), "touched at {angle} rad");
}

/// A 3.5 cm, 35 g box squeezed mid-air between two fingertips pressed in
/// twice Coulomb's threshold (2 μ_st γ depth = 2 m g), its host a plain
/// semi-implicit Euler integrator stepping at `dt`, held 1.5 s and then let
/// go. Returns the largest drop while held (m), whether any hand still
/// touches it 0.3 s after the fingers opened, and its velocity then (m/s).
fn pinch_with_an_euler_host(dt: f32) -> (f32, bool, Vec3) {
    use coulomb_hands::run::euler_host::EulerHost;
    let (half, mass, radius, mu) = (0.0175f32, 0.035f32, 0.0085f32, 0.45f32);
    let at = Vec3::new(0.1, 0.8, -0.2);
    let depth = 2.0 * mass * 9.81 / (2.0 * mu * 400.0);
    let config = InteractionConfig { dt, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    let material = Material::custom("skin", mu, 0.4, 0.5);
    let desc = ObjectDesc::cuboid("box", Vec3::splat(2.0 * half), mass, at).with_material(material);
    let id = world.add_object(&desc).unwrap();
    let hands = [world.add_hand(Side::Left), world.add_hand(Side::Right)];
    let inertia = mass * (2.0 * half).powi(2) / 6.0;
    let body = HostBody {
        position: at,
        rotation: Quat::IDENTITY,
        linvel: Vec3::ZERO,
        angvel: Vec3::ZERO,
        mass,
        center_of_mass: Vec3::ZERO,
        principal_inertia: Vec3::splat(inertia),
        inertia_rotation: Quat::IDENTITY,
    };
    let host = EulerHost { bodies: vec![body], gravity: config.gravity, dt };
    let (hold, open) = (1.5, 0.3);
    let fingertip = move |side: Side, t: f64| {
        let s = if side == Side::Left { -1.0 } else { 1.0 };
        let pressed = if t < hold { depth } else { -0.03 };
        let x = at.x + s * (half + radius - pressed);
        let (a, b) = (Vec3::new(x, at.y, at.z - 0.01), Vec3::new(x, at.y, at.z + 0.01));
        let mut pose = parked_hand(side);
        set_bone(&mut pose, Bone::Finger(Finger::Index, Phalanx::Distal), Capsule { a, b, radius });
        Some(pose)
    };
    let mut sag = 0.0f32;
    let mut watch = |step: &StepView| {
        if step.t <= hold {
            sag = sag.max(at.y - position(step.world, id).y);
        }
        Ok(())
    };
    let mut driver = Driver::new(&mut world);
    driver.set_host(Box::new(host)).unwrap();
    for (hand, side) in hands.into_iter().zip([Side::Left, Side::Right]) {
        driver.drive(hand, PoseFn::new(side, move |t| fingertip(side, t))).unwrap();
    }
    driver.run(((hold + open) / f64::from(dt)).round() as usize, &mut [&mut watch]).unwrap();
    let touched = !world.contacts_on(id).is_empty();
    (sag, touched, world.object_state(id).unwrap().linvel)
}

#[test]
fn a_host_stepping_at_1_ms_to_a_60th_of_a_second_holds_a_pinch_and_lets_it_go() {
    for dt in [1e-3, 1.0 / 240.0, 1.0 / 120.0, 1.0 / 90.0, 1.0 / 72.0, 1.0 / 60.0] {
        let (sag, touched, velocity) = pinch_with_an_euler_host(dt);
        let hz = 1.0 / dt;
        // Held: only the springs' elastic sag, m g / 2γ = 0.4 mm, and a
        // little; let go: untouched, falling freely since the fingers
        // opened (the last step's fall may be the step's own), not flung.
        assert!(sag < 0.0015, "{hz:.0} Hz: sagged {:.2} mm while held", sag * 1e3);
        assert!(!touched, "{hz:.0} Hz: still touched after the fingers opened");
        let sideways = Vec3::new(velocity.x, 0.0, velocity.z).length();
        assert!(sideways < 0.005, "{hz:.0} Hz: flung sideways at {sideways:.3} m/s");
        assert!(
            (velocity.y + 9.81 * 0.3).abs() < 9.81 * dt * 2.0 + 0.05,
            "{hz:.0} Hz: falling at {:.2} m/s, not freely",
            velocity.y
        );
    }
}
