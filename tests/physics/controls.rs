//! Negative controls: each shipped scenario with the physics it shows
//! changed must fail the check that shows it. A control keeps the hands'
//! motion and removes the mechanism (friction, the squeeze, the floor's
//! friction), and its comment says why physics says it must fail.

use super::scenarios::{check, table, variant, variants};

/// Skin friction μ 0 (and wood's friction against other objects): hand
/// contacts can push but never drag.
const FRICTIONLESS: &str = r#"{"name": "frictionless", "surface_friction": 0.5, "source": "test",
                               "skin": {"static_mu": 0.0, "dynamic_mu": 0.0}}"#;

fn material(m: &str) -> String {
    format!(r#""material": {m}"#)
}

#[test]
fn without_the_physics_they_rely_on_the_scenarios_fail() {
    // A grippy floor: finger friction can no longer drag the box.
    let pull = variant("pull", r#""friction": 0.0"#, r#""friction": 1.0"#);
    assert!(!check(&pull, "pulled").passed, "{}", table(&pull));
    // A slippery floor under the wooden sculpture: it slides, not tips.
    let tilt = variant("tilt-wooden", r#""friction": 1.0"#, r#""friction": 0.0"#);
    assert!(!check(&tilt, "tipped").passed, "{}", table(&tilt));
    // A grippy floor under the slippery push: now it tips.
    let slide = variant("slide-slippery", r#""friction": 0.05}"#, r#""friction": 1.5}"#);
    assert!(!slide.passed, "{}", table(&slide));
    // A frictionless cube: the pinch's contacts on its vertical faces push
    // only horizontally, so nothing holds its weight; it stays on the floor.
    // (Ice, μ 0.05, would be a thin control: a squeeze of about 1.7 N a side
    // gives at most 0.17 N of friction against the cube's 0.2 N weight.)
    let grasp = variant("grasp-lift", r#""material": "wood""#, &material(FRICTIONLESS));
    assert!(!check(&grasp, "lifted").passed, "{}", table(&grasp));
    // Without the other hand's thumb there is nothing to balance against.
    let alone =
        variant("two-hand-balance", r#""curl": [0.5, 1, 1, 1, 1]"#, r#""curl": [0, 1, 1, 1, 1]"#);
    assert!(!check(&alone, "lifted").passed, "{}", table(&alone));
    // The spin needs the fingers' friction: to hold the cube up between them,
    // and to turn it, since the right finger's push on the face is along the
    // axis and has no moment about it. A frictionless cube is pushed off its
    // post and not spun. (Ice, μ 0.05, is no control: it still holds the
    // 5 g cube, and the finger's driving friction and the pivot's resisting
    // friction both scale with μ, so it may turn all the same.)
    let ice = variant("spin-two-hands", r#""material": "wood""#, &material(FRICTIONLESS));
    assert!(!check(&ice, "spun").passed, "{}", table(&ice));
    // The cross turns in one hand only because the fingertip pivots'
    // friction holds it against the middle finger's push. A slicker cross
    // (μ 0.1) is still lifted, and the first push still turns it, but the
    // pivots let it go under the pushes: it is dropped. (At μ 0.2 the
    // pivots hold: they slip, but stay under the fingertips.)
    let slick = r#"{"name": "slick", "skin": {"static_mu": 0.1, "dynamic_mu": 0.1},
                    "surface_friction": 0.5, "source": "test"}"#;
    let pushed_out =
        variant("spin-one-hand", r#""material": "wood""#, &format!(r#""material": {slick}"#));
    assert!(!check(&pushed_out, "lowest").passed, "{}", table(&pushed_out));
    // A loose wrap round the mallet's handle: it is not held.
    let loose = variant("tool-knock-tower", "0.9, 0.9, 0.9, 0.9", "0.6, 0.6, 0.6, 0.6");
    assert!(!loose.passed, "{}", table(&loose));
    // The same swing with the mallet elsewhere: the hand alone passes over
    // the tower, which stands. It is the mallet that knocks it down.
    let empty = variant(
        "tool-knock-tower",
        r#""position": [0.0, 0.02, 0.0]"#,
        r#""position": [1.0, 0.02, 0.0]"#,
    );
    assert!(!check(&empty, "tower fell: top").passed, "{}", table(&empty));
    // A hand too soft to hold the falling block: it falls through.
    let catch = variant(
        "catch",
        r#""duration": 2.0,"#,
        r#""duration": 2.0, "config": {"gamma": {"Fixed": 5.0}},"#,
    );
    assert!(!catch.passed, "{}", table(&catch));
}

#[test]
fn push_on_a_frictionless_floor_does_not_stop_when_the_hand_stops() {
    // The fingertips can push the box but not hold it back: only the floor's
    // friction stops it. They strike it at about 0.15 m/s; on a frictionless
    // floor (ground and box μ 0, the skin's friction unchanged) nothing slows
    // it, so it glides on ahead of the slowing hand and is still moving.
    let wood_on_ice = r#"{"name": "wood on ice", "surface_friction": 0.0, "source": "test",
                          "skin": {"static_mu": 0.46, "dynamic_mu": 0.46}}"#;
    let glide = variants(
        "push",
        &[
            (r#""friction": 0.3"#, r#""friction": 0.0"#),
            (r#""material": "wood""#, &material(wood_on_ice)),
        ],
    );
    assert!(!check(&glide, "at rest").passed, "{}", table(&glide));
}

#[test]
fn palmar_grasp_without_the_fingers_closing_does_not_lift() {
    // The palm only touches the bottle's side; the fingers wrapping round it
    // are what press it against the palm. Fingers that stay straight leave
    // the palm's slight push unopposed: there is no squeeze, so friction (at
    // most μ times the normal force) is all but nothing against the bottle's
    // 1 N weight. The lift leaves it standing, with at most the palm and
    // thumb pressing on it, not five contacts.
    let open = variant(
        "palmar-grasp",
        r#""curl": [0.2, 0.85, 0.85, 0.85, 0.65]"#,
        r#""curl": [0.2, 0.0, 0.0, 0.0, 0.0]"#,
    );
    assert!(!check(&open, "lifted").passed, "{}", table(&open));
    assert!(!check(&open, "hand contacts").passed, "{}", table(&open));
}

#[test]
fn motion_control_without_the_thumb_fails() {
    // The cube follows the hand's moves and turns only through the pinch's
    // squeeze. With the thumb swung back into the palm plane (opposition 0)
    // the fingertips on the cube's far face have nothing opposing them: they
    // press it only as hard as the floor's friction holds it back, at most
    // μ_floor m g, so their friction can lift at most μ μ_floor m g =
    // 0.46 × 0.5 m g, a quarter of its weight. It is pushed aside, never
    // lifted, and neither carried nor pitched with the hand.
    let thumbless = variant("motion-control", r#""opposition": 1"#, r#""opposition": 0"#);
    assert!(!check(&thumbless, "pitched towards").passed, "{}", table(&thumbless));
    assert!(!check(&thumbless, "still held").passed, "{}", table(&thumbless));
}

#[test]
fn handover_to_a_hand_that_does_not_close_drops_the_cube() {
    // The right hand must hold the cube by its own squeeze before the left
    // lets go. A right hand that comes to the cube but does not curl its
    // fingers onto the face opposite its thumb cannot squeeze: when the left
    // opens, nothing holds the cube's weight and it falls.
    let open = variant(
        "handover",
        r#""rotation_deg": [0, 90, 180], "curl": [0.3, 0.4, 0.4, 0.4, 0.4]"#,
        r#""rotation_deg": [0, 90, 180], "curl": 0.3"#,
    );
    assert!(!check(&open, "lowest").passed, "{}", table(&open));
    assert!(!check(&open, "carried away").passed, "{}", table(&open));
}

#[test]
fn flat_hand_lift_on_a_palm_tilted_past_the_friction_angle_loses_the_figurine() {
    // On a level palm the figurine's weight is normal to the skin and needs no
    // friction. On a palm tilted 35°, static friction must hold m g sin 35°
    // with a normal force m g cos 35°: tan 35° = 0.70 is more than wood's
    // μ_st 0.46, so the figurine cannot stand on the rising hand: it slides
    // down the palm and topples. Where it then ends depends on how it
    // topples: off the hand, or lying wedged between two fingers (as it does
    // with rapier's manifold-centred friction on the post). Either way it is
    // not carried standing the whole 16 cm.
    let slope = variant("flat-hand-lift", "0.0]}", r#"0.0], "rotation_deg": [35, 0, 0]}"#);
    assert!(!check(&slope, "lifted").passed, "{}", table(&slope));
    assert!(!check(&slope, "tilt at the end").passed, "{}", table(&slope));
}

#[test]
fn a_plate_carried_on_a_hand_tipped_past_the_friction_angle_slides_off() {
    // Tipped 12°, the plate's weight along the hand, m g sin 12°, is 0.21 of
    // the normal force, within skin on wood's μ_st 0.46. Tipped 35°, it is
    // tan 35° = 0.70 of it: no friction holds it, and it slides off the
    // fingertips, lying anywhere but tipped as the hand is.
    let steep = variant("plate-carry", "[12, 0, 0]", "[35, 0, 0]");
    assert!(!check(&steep, "moved on the hand").passed, "{}", table(&steep));
    assert!(!check(&steep, "tipped with the hand").passed, "{}", table(&steep));
    assert!(check(&steep, "lifted").passed, "{}", table(&steep));
}

#[test]
fn a_ball_pinned_to_the_palm_or_too_slick_to_roll_misses_rolling_s_law() {
    // Pinned (the thesis's anchored C, rolling contacts off): C turns away
    // with the ball, which sinks into the palm while the measured depth
    // falls, then slips, finds its depth again and kicks. Its acceleration
    // over the window is far from (5/7)·g·sin θ.
    let pinned = variant(
        "ball-roll",
        r#""duration": 1.0,"#,
        r#""duration": 1.0, "config": {"rolling": false},"#,
    );
    assert!(!check(&pinned, "acceleration").passed, "{}", table(&pinned));
    // Too slick to roll: μ 0.05, under the (2/7)·tan 14° = 0.071 rolling
    // needs. It slides at g (sin θ − μ cos θ) = 1.90 m/s², past the bound,
    // and friction spins it up at (5/2)·μ·g·cos θ / r = 59 rad/s², so it
    // turns 89° over the window, short of the 127° that rolling its
    // distance takes.
    let slick = r#"{"name": "slick", "skin": {"static_mu": 0.05, "dynamic_mu": 0.05},
                    "surface_friction": 0.9, "source": "test"}"#;
    let slides = variant("ball-roll", r#""material": "rubber""#, &material(slick));
    assert!(!check(&slides, "acceleration").passed, "{}", table(&slides));
    assert!(!check(&slides, "turned").passed, "{}", table(&slides));
    // Both still leave the hand: the checks fail on the law, not the set-up.
    for r in [&pinned, &slides] {
        assert!(check(r, "fell off").passed, "{}", table(r));
    }
}

#[test]
fn a_steady_push_on_grippier_ground_needs_more_than_the_scenario_s_mu_m_g() {
    // The push reads the ground's friction. Ground friction 0.6 instead of
    // 0.2 makes the combined μ 0.55, not 0.35: the same steady push needs
    // 0.55 m g, 57 % more than the check's bound.
    let grippy = variant("push-steady", r#""friction": 0.2}"#, r#""friction": 0.6}"#);
    assert!(!check(&grippy, "hand force along").passed, "{}", table(&grippy));
    assert!(check(&grippy, "moved in the steady").passed, "{}", table(&grippy));
}

#[test]
fn jenga_pulls_without_the_pinch_closing_leave_the_block_in() {
    // The push needs only the fingertip's normal force; the pull needs the
    // pinch's friction, and friction needs its squeeze. A pinch that keeps
    // the approach's curl (0.2) does not close on the block's end: the pull
    // slides off it, and the block stays 4.4 cm out, short of its 7.5 cm
    // length.
    for name in ["jenga-one-hand", "jenga-two-hands"] {
        let open = variant(name, "[0.3, 0.5, 0.5, 0.5, 0.5]", "[0.3, 0.2, 0.2, 0.2, 0.2]");
        assert!(!check(&open, "block pulled out").passed, "{name}:{}", table(&open));
    }
}
