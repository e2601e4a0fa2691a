//! Grasp, lift and carry: the scripted demo scene, checked.

use coulomb_hands::InteractionConfig;
use coulomb_hands::run::demo::GraspLiftCarry;

#[test]
fn cube_follows_the_hand_through_lift_and_turn_then_rests_on_the_open_thumb() {
    let scene = GraspLiftCarry::new(InteractionConfig::default()).unwrap();
    let report = scene.run(0.5).unwrap();
    // Lifted with the hand: 20 cm up from its start at the origin.
    assert!(report.held_height > 0.19, "held at {:.3} m", report.held_height);
    // Its pose in the hand frame barely changes while carried and turned 90°.
    assert!(report.max_drift < 0.005, "drifted {:.1} mm in the hand", report.max_drift * 1e3);
    assert!(report.max_drift_deg < 5.0, "turned {:.1}° in the hand", report.max_drift_deg);
    assert!(
        report.contacts_held >= 5,
        "only {} contacts at the end of the carry",
        report.contacts_held
    );
    // The turn put the thumb under the cube, its distal bone lying along
    // the cube's face. Opening the hand, the fingers let go, and the cube
    // stays on the thumb's line contact, as on a rigid thumb of the same
    // capsules (`examples/demo_release.rs`): still over where it was held
    // (x 0), sunk only by the thumb's opening.
    assert_eq!(report.fingers_after_release, 0, "the fingers still press");
    assert_eq!(report.contacts_after_release, 2, "the thumb's two pad bones carry it");
    let rest = report.timeline.last().unwrap().cube;
    assert!(rest[0].abs() < 0.01, "it rolled {:.1} mm off the thumb", rest[0] * 1e3);
    let sunk = report.held_height - report.final_height;
    assert!(sunk > 0.0 && sunk < 0.03, "sunk {:.1} mm on the open thumb", sunk * 1e3);
}

#[test]
fn without_line_contacts_the_cube_rolls_off_the_open_thumb() {
    // The negative control: the thumb's pad rings alone let it roll off and
    // fall to the ground, 9 cm to the side (the book's "The demo").
    let config = InteractionConfig { line_contacts: false, ..InteractionConfig::default() };
    let report = GraspLiftCarry::new(config).unwrap().run(0.5).unwrap();
    assert!(report.held_height > 0.19, "held at {:.3} m", report.held_height);
    assert!(report.final_height < 0.01, "still at {:.3} m after opening", report.final_height);
    let rest = report.timeline.last().unwrap().cube;
    assert!(rest[0] > 0.05, "landed only {:.1} mm to the side", rest[0] * 1e3);
}

#[test]
fn replays_are_bit_for_bit_deterministic() {
    let run = || {
        let report = GraspLiftCarry::new(InteractionConfig::default()).unwrap().run(0.05).unwrap();
        report.timeline.iter().map(|r| r.cube).collect::<Vec<_>>()
    };
    let (a, b) = (run(), run());
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.map(f32::to_bits), y.map(f32::to_bits));
    }
}

/// Unlocks a fixture on `object` at the first step that starts at or after
/// `at` (s).
struct Unlock {
    object: coulomb_hands::ObjectId,
    at: f64,
}

impl coulomb_hands::run::drive::Observer for Unlock {
    fn before_step(
        &mut self,
        world: &mut coulomb_hands::InteractionWorld,
        t: f64,
    ) -> Result<(), coulomb_hands::RunError> {
        if t >= self.at && t < self.at + world.config().dt as f64 {
            world.set_object_locked(self.object, false)?;
        }
        Ok(())
    }
}

#[test]
fn a_recorded_session_replays_bit_for_bit_from_its_file() {
    use coulomb_hands::output::session::{Session, object_states};
    use coulomb_hands::run::drive::{Driver, PoseFn, StepView};

    use coulomb_hands::{InteractionWorld, ObjectDesc, Side, StaticDesc};
    use glam::Vec3;
    // Record the grasp-lift-carry script, including a fixture on the cube
    // until the grasp has closed.
    let script = GraspLiftCarry::new(InteractionConfig::default()).unwrap();
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    Session::start(&mut world);
    world.add_static(&StaticDesc::ground(-script.half, 0.5)).unwrap();
    let cube = world
        .add_object(&ObjectDesc::cuboid("cube", Vec3::splat(2.0 * script.half), 0.05, Vec3::ZERO))
        .unwrap();
    let hand = world.add_hand(Side::Right);
    world.set_object_locked(cube, true).unwrap();
    let dt = world.config().dt;
    let mut live = Vec::new();
    let mut fixture = Unlock { object: cube, at: GraspLiftCarry::CLOSE.1 as f64 };
    let mut states = |step: &StepView| {
        live.push(object_states(step.world));
        Ok(())
    };
    let mut driver = Driver::new(&mut world);
    let pose = |t: f64| Some(script.hand_pose(t as f32));
    driver.drive(hand, PoseFn::new(Side::Right, pose)).unwrap();
    let steps = (GraspLiftCarry::OPEN.0 / dt) as usize;
    driver.run(steps, &mut [&mut fixture, &mut states]).unwrap();
    assert!(
        world.object_state(cube).unwrap().position.y > 0.15,
        "the recorded run lifted the cube"
    );
    let session = Session::take(&mut world).unwrap();
    assert_eq!(session.steps(), live.len());

    let path =
        std::env::temp_dir().join(format!("coulomb-hands-session-{}.json", std::process::id()));
    session.save(&path).unwrap();
    let loaded = Session::load(&path).unwrap();
    std::fs::remove_file(&path).ok();
    assert_eq!(loaded, session, "the file round-trips exactly");

    let mut replayed = Vec::new();
    loaded.replay(|w| replayed.push(object_states(w))).unwrap();
    assert_eq!(replayed.len(), live.len());
    let bits = |s: &coulomb_hands::ObjectState| {
        (
            s.position.to_array().map(f32::to_bits),
            s.rotation.to_array().map(f32::to_bits),
            s.linvel.to_array().map(f32::to_bits),
        )
    };
    for (step, (a, b)) in live.iter().zip(&replayed).enumerate() {
        for (x, y) in a.iter().zip(b) {
            assert_eq!(bits(x), bits(y), "step {step} differs");
        }
    }
}
