//! Pinch hold threshold: Coulomb's law decides whether a squeezed box holds.

use super::*;
use coulomb_hands::contact::patch::PatchConfig;
use coulomb_hands::run::drive::Observer;
use coulomb_hands::{Finger, FrictionState, InteractionConfig, ObjectDesc, Phalanx, RunError};

const HALF: f32 = 0.02; // 4 cm box
const MASS: f32 = 0.05;
const RADIUS: f32 = 0.008;
const INDEX_DISTAL: Bone = Bone::Finger(Finger::Index, Phalanx::Distal);

struct Pinch {
    world: InteractionWorld,
    box_id: ObjectId,
    hands: [HandId; 2],
    poses: [HandPose; 2],
}

/// A box in mid-air squeezed by the index distal bones of two hands, one
/// on each x face, each sunk `depth` into the box; nothing else touches it.
fn pinch(config: InteractionConfig, depth: f32) -> Pinch {
    pinch_with(config, depth, test_material(0.5))
}

fn pinch_with(config: InteractionConfig, depth: f32, material: Material) -> Pinch {
    pinch_between(config, depth, material, [INDEX_DISTAL; 2])
}

/// [`pinch_with`] between `bones`, the left hand's and the right's.
fn pinch_between(
    config: InteractionConfig,
    depth: f32,
    material: Material,
    bones: [Bone; 2],
) -> Pinch {
    let mut world = InteractionWorld::new(config).unwrap();
    let desc = ObjectDesc::cuboid("box", Vec3::splat(2.0 * HALF), MASS, Vec3::new(0.0, 0.5, 0.0))
        .with_material(material);
    let box_id = world.add_object(&desc).unwrap();
    let mut poses = [parked_hand(Side::Left), parked_hand(Side::Right)];
    let mut hands = [HandId(0); 2];
    for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let s = if i == 0 { -1.0 } else { 1.0 };
        let x = s * (HALF + RADIUS - depth);
        let capsule =
            Capsule { a: Vec3::new(x, 0.5, -0.012), b: Vec3::new(x, 0.5, 0.012), radius: RADIUS };
        set_bone(&mut poses[i], bones[i], capsule);
        hands[i] = world.add_hand(side);
    }
    Pinch { world, box_id, hands, poses }
}

impl Pinch {
    /// Holds both hands still for `seconds`; returns the box's largest
    /// drop below its start (m).
    fn hold(&mut self, seconds: f32) -> f32 {
        self.hold_after(0.0, seconds)
    }

    /// Holds both hands still; returns the box's largest drop during the
    /// `seconds` that follow the first `settle` seconds (m).
    fn hold_after(&mut self, settle: f32, seconds: f32) -> f32 {
        let dt = self.world.config().dt;
        let settle_steps = (settle / dt).round() as usize;
        let box_id = self.box_id;
        let mut start = position(&self.world, box_id).y;
        let mut drop = 0.0f32;
        let mut watch = |step: &StepView| {
            let y = position(step.world, box_id).y;
            if step.index + 1 == settle_steps {
                start = y;
            }
            if step.index + 1 > settle_steps {
                drop = drop.max(start - y);
            }
            Ok(())
        };
        self.drive(((settle + seconds) / dt).round() as usize, &mut [&mut watch]);
        drop
    }

    /// Holds both hands still for `steps` steps, through the driver.
    fn drive(&mut self, steps: usize, observers: &mut [&mut dyn Observer]) {
        let mut driver = Driver::new(&mut self.world);
        for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
            let pose = &self.poses[i];
            driver.drive(self.hands[i], PoseFn::new(side, |_| Some(pose.clone()))).unwrap();
        }
        driver.run(steps, observers).unwrap();
    }
}

/// The squeeze depth at which `k` times the weight is the friction limit:
/// 2 μ_st γ δ = k m g.
fn depth_for(k: f32, gamma: f32) -> f32 {
    k * MASS * 9.81 / (2.0 * 0.5 * gamma)
}

#[test]
fn holds_with_a_25_percent_margin_over_coulombs_threshold() {
    let mut p = pinch(InteractionConfig::default(), depth_for(1.25, 400.0));
    p.hold(0.1);
    // A static contact's C is fixed on the box: record it in the box frame.
    let in_box = |p: &Pinch| {
        let s = p.world.object_state(p.box_id).unwrap();
        p.world
            .contacts()
            .iter()
            .map(|c| s.rotation.inverse() * (c.point - s.position))
            .collect::<Vec<_>>()
    };
    let anchored = in_box(&p);
    let drop = p.hold(2.0);
    // Measured from the release, so the elastic sag m g / 2γ ≈ 0.6 mm counts too.
    assert!(drop < 0.002, "box drifted {:.2} mm in 2 s", drop * 1e3);
    for (a, b) in anchored.iter().zip(in_box(&p)) {
        assert!(a.distance(b) < 1e-5, "C moved on the box from {a:?} to {b:?}");
    }
    // The hold really was at the intended normal force (no hidden margin).
    let contacts = p.world.contacts();
    assert_eq!(contacts.len(), 2, "{contacts:?}");
    for c in contacts {
        assert_eq!(c.state, FrictionState::Static);
        assert_eq!(c.stiffness, 400.0, "the stability limit must not soften this pinch");
        let expected = 1.25 * MASS * 9.81 / (2.0 * 0.5);
        assert!(
            (c.normal_force - expected).abs() / expected < 0.05,
            "f_n {} vs {expected}",
            c.normal_force
        );
    }
}

#[test]
fn slips_when_the_squeeze_is_25_percent_below_the_threshold() {
    let mut p = pinch(InteractionConfig::default(), depth_for(0.75, 400.0));
    let drop = p.hold(2.0);
    assert!(drop > 0.01, "box only dropped {:.2} mm", drop * 1e3);
}

#[test]
fn a_material_whose_sliding_mu_exceeds_its_static_mu_still_slips() {
    // Aluminium's published pair: μ_st 0.38 (pinch), μ_dyn 0.6 (sliding).
    // 25 % under the static threshold the box must slip down, not climb.
    let alu = Material::named("aluminium").unwrap();
    let depth = 0.75 * MASS * 9.81 / (2.0 * alu.skin.static_mu * 400.0);
    let mut p = pinch_with(InteractionConfig::default(), depth, alu);
    let start = position(&p.world, p.box_id).y;
    let drop = p.hold(2.0);
    let end = position(&p.world, p.box_id).y;
    assert!(
        drop > 0.01 && end < start,
        "dropped {:.2} mm, ended {:+.2} mm",
        drop * 1e3,
        (end - start) * 1e3
    );
}

#[test]
fn the_threshold_is_coulombs_for_another_stiffness_too() {
    // Auto-γ gives this box a different stiffness; the force threshold must not move.
    let config =
        InteractionConfig { gamma: coulomb_hands::GammaMode::Auto, ..InteractionConfig::default() };
    let gamma = pinch(config, 0.0).world.object_gamma(ObjectId(0)).unwrap();
    assert!((gamma - 400.0).abs() > 50.0, "auto γ {gamma} should differ from 400");
    // This softer γ sags m g / 2γ ≈ 3.5 mm before it holds: let that settle
    // for 0.5 s, then the hold must not creep.
    let held = pinch(config, depth_for(1.25, gamma)).hold_after(0.5, 2.0);
    assert!(held < 0.002, "held box crept {:.2} mm", held * 1e3);
    let slipped = pinch(config, depth_for(0.75, gamma)).hold_after(0.5, 2.0);
    assert!(slipped > 0.01, "box only dropped {:.2} mm", slipped * 1e3);
}

#[test]
fn one_or_nine_samples_give_the_same_total_force() {
    let total = |samples: usize| {
        let config = InteractionConfig {
            patch: PatchConfig { samples, ..PatchConfig::default() },
            ..InteractionConfig::default()
        };
        // One step from the same state: both see the same contacts.
        let mut p = pinch(config, depth_for(1.25, 400.0));
        p.hold(0.01);
        let total = p.world.object_state(p.box_id).unwrap().hand_force;
        let forces: Vec<Vec3> = p.world.contacts().iter().map(|c| c.force).collect();
        let sum: Vec3 = forces.iter().copied().sum();
        assert!(
            (total - sum).length() < 1e-6,
            "the samples' forces add up to the contacts' forces"
        );
        forces
    };
    let (one, nine) = (total(1), total(9));
    assert_eq!(one.len(), 2);
    for (a, b) in one.iter().zip(&nine) {
        assert!(a.length() > 0.1, "each bone pushes: {a:?}");
        assert!((*a - *b).length() < 1e-3 * a.length(), "1 sample {a:?} vs 9 samples {b:?}");
    }
}

/// Twists the box about x with 2 mN·m from outside, between the hand
/// forces and rapier's step, and adds up the angle it turns (rad).
struct Twister {
    object: ObjectId,
    turned: f32,
}

impl Observer for Twister {
    fn after_hand_forces(&mut self, world: &mut InteractionWorld) -> Result<(), RunError> {
        let body = world.object_body(self.object).unwrap();
        world.physics_mut().bodies[body].add_torque(Vec3::new(0.002, 0.0, 0.0), true);
        Ok(())
    }

    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let dt = step.world.config().dt;
        self.turned += step.world.object_state(self.object).unwrap().angvel.x * dt;
        Ok(())
    }
}

/// The pinch by `bone` twisted about its axis (x) with no gravity, its
/// patches of `samples`, with or without line contacts: the angle it
/// turned (degrees), and the patches' twist stiffness about x (N·m/rad),
/// each sample a spring of γ/N at its distance from the axis through its
/// patch's centre.
fn twist(samples: usize, line_contacts: bool, bone: Bone) -> (f32, f32) {
    let config = InteractionConfig {
        gravity: Vec3::ZERO,
        patch: PatchConfig { samples, ..PatchConfig::default() },
        line_contacts,
        ..InteractionConfig::default()
    };
    let mut p = pinch_between(config, 0.003, test_material(0.5), [bone; 2]);
    let dt = p.world.config().dt;
    // The turned angle, accumulated so full turns count.
    let mut twister = Twister { object: p.box_id, turned: 0.0 };
    p.drive((0.5 / dt) as usize, &mut [&mut twister]);
    let stiffness = p
        .world
        .contacts()
        .iter()
        .map(|c| {
            let n = c.samples.len() as f32;
            let centre = c.samples.iter().sum::<Vec3>() / n;
            let arm = |q: &Vec3| (*q - centre).with_x(0.0).length_squared();
            c.stiffness / n * c.samples.iter().map(arm).sum::<f32>()
        })
        .sum();
    (twister.turned.to_degrees(), stiffness)
}

#[test]
fn nine_samples_resist_twisting_that_one_sample_does_not() {
    let (one, _) = twist(1, true, INDEX_DISTAL);
    // The torque is below the patches' torsional friction (for the rings,
    // 2 · μ_st · f_n · ρ · 8/9 ≈ 0.0043 N·m), so the box settles at the
    // elastic angle τ/k of the patches' springs: the pads' rings of 4 mm,
    // also where the fingertips lie along the faces (their pulp touches,
    // not their bone), or the lines along the 2.4 cm middle phalanges that
    // lie along the faces, about 4 times as stiff.
    let middle = Bone::Finger(Finger::Index, Phalanx::Intermediate);
    let mut stiffnesses = Vec::new();
    for (line_contacts, bone) in [(false, INDEX_DISTAL), (true, INDEX_DISTAL), (true, middle)] {
        let (nine, stiffness) = twist(9, line_contacts, bone);
        let elastic = (0.002 / stiffness).to_degrees();
        assert!(
            (nine - elastic).abs() < 0.25 * elastic,
            "9 samples, lines {line_contacts}, {bone}: turned {nine:.1}°, elastic {elastic:.1}°"
        );
        stiffnesses.push(stiffness);
    }
    let rho = PatchConfig::default().finger_radius;
    let ring = 2.0 * 8.0 * (400.0 / 9.0) * rho * rho;
    for pad in &stiffnesses[..2] {
        assert!((pad - ring).abs() < 0.05 * ring, "{stiffnesses:?} vs a ring's {ring}");
    }
    assert!(stiffnesses[2] > 3.0 * ring, "the lines' {stiffnesses:?} vs a ring's {ring}");
    assert!(one > 45.0, "1 sample: turned only {one:.1}°");
}

/// Twists the box about x with a torque that grows by `rate` N·m/s, and
/// notes the torque and the pinch's squeeze ΣN when it spins free.
struct Ramp {
    object: ObjectId,
    rate: f32,
    torque: f32,
    /// The torque (N·m) and ΣN (N) since the box turns at over 1 rad/s, and
    /// for how long (s).
    spinning: Option<(f32, f32, f32)>,
    /// Those when it had kept turning so for 50 ms: a pad's brief slip,
    /// after which the pinch sticks again, is not yet free.
    free: Option<(f32, f32)>,
}

impl Observer for Ramp {
    fn after_hand_forces(&mut self, world: &mut InteractionWorld) -> Result<(), RunError> {
        self.torque += self.rate * world.config().dt;
        let body = world.object_body(self.object).unwrap();
        world.physics_mut().bodies[body].add_torque(Vec3::new(self.torque, 0.0, 0.0), true);
        Ok(())
    }

    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let spin = step.world.object_state(self.object).unwrap().angvel.x;
        if self.free.is_some() {
            return Ok(());
        }
        self.spinning = match (spin > 1.0, self.spinning) {
            (false, _) => None,
            (true, Some((torque, squeeze, time))) => {
                Some((torque, squeeze, time + step.world.config().dt))
            }
            (true, None) => {
                let squeeze = step.world.contacts().iter().map(|c| c.normal_force).sum();
                Some((self.torque, squeeze, 0.0))
            }
        };
        if let Some((torque, squeeze, time)) = self.spinning
            && time >= 0.05
        {
            self.free = Some((torque, squeeze));
        }
        Ok(())
    }
}

/// The torsional capacity τ/(μ_st·ΣN) (m) of a pinch between `bones`
/// sunk 2.5 mm into the box, with no gravity: the torque about the pinch's
/// axis, growing slowly, at which the box spins free.
fn torsional_capacity(bones: [Bone; 2]) -> f32 {
    let config = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
    let skin = Material::custom("grippy", 0.7, 0.55, 0.5);
    let mut p = pinch_between(config, 0.0025, skin, bones);
    let dt = p.world.config().dt;
    let mut ramp = Ramp { object: p.box_id, rate: 0.0015, torque: 0.0, spinning: None, free: None };
    p.drive((12.0 / dt) as usize, &mut [&mut ramp]);
    let (torque, squeeze) = ramp.free.expect("the box spun free");
    torque / (0.7 * squeeze)
}

#[test]
fn a_fingertip_pinch_twists_free_at_a_fingertips_torsional_friction() {
    // A fingertip's contact patch of radius a, 4–7 mm, holds a twist of
    // μ·N·(2/3)·a. Laid along the faces, the fingertips touch with their
    // pulp, so a pinch holds what the pads' rings hold, 8/9 of their mean
    // radius (thumb 6 mm, fingers 4), where lines along the whole distal
    // bones held twice that. The middle phalanges, whose pads lie flat
    // along them, still touch along their length, the control.
    let patch = PatchConfig::default();
    let thumb = Bone::Finger(Finger::Thumb, Phalanx::Distal);
    let pairs = [
        ([INDEX_DISTAL; 2], patch.finger_radius),
        ([INDEX_DISTAL, thumb], 0.5 * (patch.finger_radius + patch.thumb_radius)),
    ];
    for (bones, radius) in pairs {
        let tip = torsional_capacity(bones);
        let ring = 8.0 / 9.0 * radius;
        assert!(
            (2.0 / 3.0 * 0.004..=2.0 / 3.0 * 0.007).contains(&tip),
            "{bones:?}: τ/(μ_st ΣN) = {:.2} mm",
            tip * 1e3
        );
        assert!((tip - ring).abs() < 0.1 * ring, "{bones:?}: {tip} vs the rings' {ring}");
    }
    let middle = Bone::Finger(Finger::Index, Phalanx::Intermediate);
    let lines = torsional_capacity([middle; 2]);
    assert!(lines > 1.5 * 2.0 / 3.0 * 0.007, "middle phalanges: {:.2} mm", lines * 1e3);
}

#[test]
fn the_pinch_threshold_is_coulombs_within_3_percent() {
    // Squeezed at 1.4 times Coulomb's threshold by a skin of μ_st 0.63,
    // then opened slowly (the squeeze falls 20 % a second): the box must
    // start to slip when μ_st·Σf_n has fallen to its weight m g.
    let (t, ratio) = slip_as_the_squeeze_falls(InteractionConfig::default(), 0.63);
    assert!(t > 1.0, "slipped at {t} s, before the squeeze fell below 1.4× the threshold");
    assert!((ratio - 1.0).abs() < 0.03, "slipped when m g = {ratio:.4} μ_st Σf_n");
}

#[test]
fn at_a_host_engines_90_hz_the_pinch_threshold_is_still_coulombs_within_3_percent() {
    // The same opening pinch, a skin of μ_st 0.48, at a step 11 times the
    // haptic one: 50 g between two fingertips is too light for explicit
    // springs there (dt²·Σγw ≈ 3), so they step by backward Euler.
    let config = InteractionConfig { dt: 1.0 / 90.0, ..InteractionConfig::default() };
    let (t, ratio) = slip_as_the_squeeze_falls(config, 0.48);
    assert!(t > 1.0, "slipped at {t} s, before the squeeze fell below 1.4× the threshold");
    assert!((ratio - 1.0).abs() < 0.03, "slipped when m g = {ratio:.4} μ_st Σf_n at 90 Hz");
}

/// Squeezes the box at 1.4 times Coulomb's threshold for a skin of
/// `mu_st`, then opens the fingers slowly (the squeeze falls 20 % a
/// second); returns when its contacts first slipped (s) and the weight
/// over μ_st·Σf_n then (1 at Coulomb's threshold).
fn slip_as_the_squeeze_falls(config: InteractionConfig, mu_st: f32) -> (f64, f32) {
    let grippy = Material::custom("grippy", mu_st, 0.52, 0.5);
    let start_depth = 1.4 * MASS * 9.81 / (2.0 * mu_st * 400.0);
    let mut p = pinch_with(config, start_depth, grippy);
    let depth_at = |t: f64| start_depth * (1.0 - 0.2 * (t as f32 - 0.5).max(0.0));
    let poses = p.poses.clone();
    let pose_at = |i: usize, t: f64| {
        let mut pose = poses[i].clone();
        let s = if i == 0 { -1.0 } else { 1.0 };
        let x = s * (HALF + RADIUS - depth_at(t));
        let capsule =
            Capsule { a: Vec3::new(x, 0.5, -0.012), b: Vec3::new(x, 0.5, 0.012), radius: RADIUS };
        set_bone(&mut pose, INDEX_DISTAL, capsule);
        pose
    };
    let mut squeeze_at_slip = None;
    let mut watch = |step: &StepView| {
        let contacts = step.world.contacts();
        if squeeze_at_slip.is_none() && contacts.iter().any(|c| c.state == FrictionState::Dynamic) {
            let squeeze: f32 = contacts.iter().map(|c| c.normal_force).sum();
            squeeze_at_slip = Some((step.t, squeeze));
        }
        Ok(())
    };
    let mut driver = Driver::new(&mut p.world);
    for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let pose = &pose_at;
        driver.drive(p.hands[i], PoseFn::new(side, move |t| Some(pose(i, t)))).unwrap();
    }
    driver.run((3.0 / config.dt).round() as usize, &mut [&mut watch]).unwrap();
    let (t, squeeze) = squeeze_at_slip.expect("the box slipped as the fingers opened");
    (t, MASS * 9.81 / (mu_st * squeeze))
}

#[test]
fn releasing_a_two_handed_hold_one_hand_then_the_other_flings_nothing() {
    // Ultraleap's UnityPlugin #846: let go with one hand of a two-handed
    // hold, then quickly with the other, and a kinematic grab flings the
    // object. Here the box is squeezed at 2.5 times Coulomb's threshold by
    // two still hands; the left finger snaps 3 cm away in 10 ms, the right
    // one 40 ms later. The right finger's spring, no longer opposed, may
    // push the box sideways only with what it stored: ½γδ² for δ = 15 mm
    // is 0.6 m/s at most on 50 g, and its damper takes some of that.
    let depth = depth_for(2.5, 400.0);
    let mut p = pinch(InteractionConfig::default(), depth);
    let poses = p.poses.clone();
    let away = |i: usize, t: f64, from: f64| {
        let mut pose = poses[i].clone();
        let s = if i == 0 { -1.0 } else { 1.0 };
        let open = 0.03 * ((t - from) / 0.01).clamp(0.0, 1.0) as f32;
        let x = s * (HALF + RADIUS - depth + open);
        let capsule =
            Capsule { a: Vec3::new(x, 0.5, -0.012), b: Vec3::new(x, 0.5, 0.012), radius: RADIUS };
        set_bone(&mut pose, INDEX_DISTAL, capsule);
        pose
    };
    let (box_id, mut sideways, mut held_until) = (p.box_id, 0.0f32, 0.0);
    let mut watch = |step: &StepView| {
        let v = step.world.object_state(box_id).unwrap().linvel;
        sideways = sideways.max(Vec3::new(v.x, 0.0, v.z).length());
        if step.world.contacts().len() == 2 {
            held_until = step.t;
        }
        Ok(())
    };
    let mut driver = Driver::new(&mut p.world);
    let release = [0.5, 0.54];
    for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let away = &away;
        driver.drive(p.hands[i], PoseFn::new(side, move |t| Some(away(i, t, release[i])))).unwrap();
    }
    driver.run(1000, &mut [&mut watch]).unwrap();
    assert!(held_until >= 0.5, "the box was held by both hands until the release");
    assert!(sideways < 1.0, "the release flung the box sideways at {sideways:.2} m/s");
    assert!(p.world.contacts().is_empty(), "both fingers let go");
}
