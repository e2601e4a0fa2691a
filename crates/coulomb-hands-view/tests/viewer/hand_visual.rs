//! The drawn hand of §3.6 on a real run (grasp-lift, stepped headless): it
//! freezes when a contact first presses, moves exactly as the object
//! moves, takes a finger's new pose when that finger begins to press, and
//! lets go when the object is no longer touched.

use coulomb_hands::contact::Contact;
use coulomb_hands::hand::HandId;
use coulomb_hands::pipeline::Method;
use coulomb_hands_view::hand_visual::{Grip, drawn_pose, next_grip};
use coulomb_hands_view::source::{LoadOptions, Source};

#[test]
fn the_drawn_hand_freezes_at_the_first_press_and_rides_with_the_object() {
    let scenario = Source::load(Some("grasp-lift"), &LoadOptions::default()).expect("shipped");
    let mut interaction = scenario.build(Method::Coulomb).expect("a world");
    let mut grip: Option<Grip> = None;
    let (mut frozen_at, mut refined) = (None, 0);
    // 4.3 s of grasp, lift and hold, one frame per physics step.
    for _ in 0..4300 {
        assert!(interaction.step());
        let world = interaction.world();
        let tracked = world.hand_pose(HandId(0)).expect("tracked throughout").clone();
        let contacts: Vec<&Contact> = world.contacts().iter().collect();
        let pressing = contacts.iter().any(|c| c.normal_force > 0.0);
        let before = grip.clone();
        grip = next_grip(grip, &tracked, &contacts, world);
        // A grip begins with a press and lasts while its object is touched.
        assert!(grip.is_some() || !pressing, "a pressing hand is frozen");
        let Some(g) = &grip else { continue };
        assert!(before.is_some() || pressing, "a grip begins only with a press");
        assert!(contacts.iter().any(|c| c.object == g.object), "a grip needs a touch");
        let drawn = drawn_pose(g, world).expect("the object exists");
        let state = world.object_state(g.object).expect("the cube");
        match &before {
            None => {
                // The first press: drawn where tracked.
                assert!((drawn.palm.center - tracked.palm.center).length() < 1e-5);
                frozen_at = Some((drawn.clone(), state));
            }
            Some(b) if b.parts != g.parts => {
                // A part began to press: its bones are tracked ones now.
                let newly = (0..6).find(|p| g.parts[*p] && !b.parts[*p]).expect("a new part");
                if newly > 0 {
                    let f = newly - 1;
                    assert!((drawn.fingers[f][2].b - tracked.fingers[f][2].b).length() < 1e-5);
                }
                refined += 1;
            }
            Some(_) => {}
        }
        // The palm rides with the object: the rigid motion since the freeze.
        let (pose0, state0) = frozen_at.as_ref().expect("frozen");
        let motion = state.rotation * state0.rotation.inverse();
        let expected = state.position + motion * (pose0.palm.center - state0.position);
        assert!((drawn.palm.center - expected).length() < 1e-4, "palm rides with the cube");
    }
    let lifted = interaction.world().object_state(coulomb_hands::scene::ObjectId(0)).unwrap();
    assert!(lifted.position.y > 0.15, "the cube was lifted: {}", lifted.position);
    assert!(grip.is_some(), "still holding at the end");
    assert!(refined >= 1, "the thumb and the fingers press at different moments");
}
