//! Grasp, lift and carry: the scripted demo scene, checked.

use coulomb_hands::InteractionConfig;
use coulomb_hands::scenes::GraspLiftCarry;

#[test]
fn cube_follows_the_hand_through_lift_and_turn_then_falls_when_opened() {
    let scene = GraspLiftCarry::new(InteractionConfig::default()).unwrap();
    let report = scene.run(0.5).unwrap();
    // Lifted with the hand: 20 cm up from its start at the origin.
    assert!(report.held_height > 0.19, "held at {:.3} m", report.held_height);
    // Its pose in the hand frame barely changes while carried and turned 90°.
    assert!(report.max_drift < 0.005, "drifted {:.1} mm in the hand", report.max_drift * 1e3);
    assert!(report.max_drift_deg < 5.0, "turned {:.1}° in the hand", report.max_drift_deg);
    assert!(report.contacts_held >= 5, "only {} contacts at the end of the carry", report.contacts_held);
    // Opening the hand drops it back to the ground (its centre rests at 0).
    assert!(report.final_height < 0.01, "still at {:.3} m after opening", report.final_height);
    assert_eq!(report.contacts_after_release, 0);
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
