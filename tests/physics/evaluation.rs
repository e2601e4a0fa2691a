//! The positioning-accuracy study (thesis §5.2), reduced: every method and
//! strategy runs the same synthetic users' trials to the end; a user nudges
//! and slides the cube as a person does; and the grip holds the cube where
//! it closed on it until it lets go.

use coulomb_hands::eval::board::{self, CUBE_HALF, SQUARE, SQUARES};
use coulomb_hands::eval::noise::TrackingNoise;
use coulomb_hands::eval::perception::{EYE, Perception};
use coulomb_hands::eval::user::{Eyes, Sight, Strategy, User, UserParams};
use coulomb_hands::eval::{AccuracyOptions, Conditions, MethodResult, accuracy};
use coulomb_hands::run::drive::{Driver, StepView};
use coulomb_hands::{InteractionConfig, Method};
use glam::Vec3;

#[test]
fn every_method_completes_the_reduced_accuracy_study_with_errors_on_the_board() {
    let options = AccuracyOptions { users: 2, trials: 5, seed: 11, ..AccuracyOptions::default() };
    let report = accuracy(&options, &mut |_, _| {}).expect("the study runs");
    let board_diagonal_mm = (SQUARES as f64 * SQUARE as f64) * 2f64.sqrt() * 1e3;
    assert_eq!(report.methods.len(), 8, "four methods, each lifting and sliding");
    for m in &report.methods {
        let name = format!("{} ({:?})", m.method, m.strategy);
        assert_eq!(m.errors_mm.len() + m.failed, 10, "{name}: every trial counted");
        for e in &m.errors_mm {
            assert!(e.is_finite() && *e >= 0.0 && *e < board_diagonal_mm, "{name}: {e} mm");
        }
        // A method with no completed trial has no error: not a number,
        // not zero.
        let finite = m.mean_time_s.is_finite() && m.mean_mm.is_finite();
        assert_eq!(finite, !m.errors_mm.is_empty(), "{name}");
        // A grip that holds a 40 g cube completes nearly every trial; the
        // thesis's law as written, an undamped spring, may not (the book's
        // "Evaluation").
        if m.method != "thesis" {
            assert!(m.failed <= 2, "{name}: {} of 10 trials failed", m.failed);
        }
    }
}

/// The coulomb method's lifts by `users` users of `trials` trials each,
/// drawn from `seed`, under white jitter of `rms_mm` per joint and axis
/// from a tracker at `hz` frames a second.
fn lifts_under_white_jitter(
    (users, trials, seed): (usize, usize, u64),
    rms_mm: f32,
    hz: f32,
) -> MethodResult {
    let mut options = AccuracyOptions { users, trials, seed, ..Default::default() };
    options.methods = vec![Method::Coulomb];
    options.strategies = vec![Strategy::Lift];
    options.noise = rms_mm;
    options.conditions = Conditions {
        noise_white: Some(hz),
        noise_unit: coulomb_hands::eval::NoiseUnit::RmsMm,
        ..Conditions::default()
    };
    let report = accuracy(&options, &mut |_, _| {}).expect("the study runs");
    report.methods.into_iter().next().expect("one method")
}

#[test]
fn under_white_tracker_jitter_the_users_lift_and_place_the_cube_without_dropping_it() {
    // A tracker at 90 frames a second, every joint off by a fresh 2.4 mm
    // each frame: the grip closes in time for the users' lifts.
    let m = lifts_under_white_jitter((2, 4, 23), 2.4, 90.0);
    assert_eq!((m.failed, m.drops), (0, 0), "{m:?}");
    assert!(m.mean_mm < 4.0, "placed {:.1} mm off on average", m.mean_mm);
}

#[test]
fn a_hand_opening_on_a_cube_tipped_against_its_palm_lets_it_go() {
    // A user's first lift under 1 mm of white jitter at 100 Hz, the one
    // that failed before the palm's point under C was mended: as the hand
    // opened on the cube it had set down, the index tipped the cube's edge
    // 2.3 mm into the palm, the contact's normal that of the cube's side
    // face, along the palm. A ray along it ran under the palm's face to
    // the palm's far end and read 6 cm of depth, so the palm pinned the
    // cube against the thumb, and the withdrawing hand carried it off until
    // the trial timed out. The palm's face is 2.3 mm away, and the hand
    // lets go.
    let m = lifts_under_white_jitter((1, 1, 6), 1.0, 100.0);
    assert_eq!((m.failed, m.drops), (0, 0), "{m:?}");
    assert!(m.errors_mm[0] < 5.0, "placed {:.1} mm off", m.errors_mm[0]);
}

#[test]
fn trials_run_in_turn_on_one_thread_end_as_they_do_on_several() {
    // One thread (and wasm32, which has none) runs the trials on the caller's.
    let study = |threads| {
        let mut options = AccuracyOptions { users: 1, trials: 3, seed: 5, ..Default::default() };
        options.methods = vec![Method::Coulomb];
        options.strategies = vec![Strategy::Lift];
        options.conditions = Conditions { threads, ..Conditions::default() };
        let mut calls = 0;
        let report = accuracy(&options, &mut |_, _| calls += 1).expect("the study runs");
        (serde_json::to_string(&report).expect("JSON"), calls)
    };
    assert_eq!(study(1), study(2));
}

/// A user with no noise of its own who accepts 3 mm.
const STEADY: UserParams =
    UserParams { latency: 0.03, speed: 0.3, gain: 5.0, tolerance: 0.003, squeeze: 0.004 };

/// Runs one user on the board with `method` from the square (2, 5), the
/// cube turned 0.1 rad, to `target` (relative to the cube's start), with
/// exact sight and no tracking noise; returns the user, the cube's end and
/// its highest centre (m).
fn one_user(
    method: Method,
    user: impl FnOnce(Sight, Vec3, Vec3) -> User<'static>,
    to: Vec3,
) -> (User<'static>, Vec3, f32) {
    let (mut world, cube) =
        board::world(method.config(InteractionConfig::default()), (2, 5), 0.1).unwrap();
    let start = world.object_state(cube).unwrap().position;
    let sight = Sight::default();
    let mut user = user(sight.clone(), start + to, start + Vec3::new(-0.1, 0.15, 0.0));
    let mut eyes = Eyes { cube, sight };
    let mut highest = 0.0f32;
    let mut each = |s: &StepView| {
        highest = highest.max(s.world.object_state(cube)?.position.y);
        Ok(())
    };
    {
        let mut driver = Driver::new(&mut world);
        driver.add_hand(&mut user);
        driver.run(30_000, &mut [&mut eyes, &mut each]).unwrap();
    }
    (user, world.object_state(cube).unwrap().position - start, highest)
}

fn exact(sight: Sight) -> (Sight, Perception) {
    (sight, Perception::new(EYE, 0.0))
}

#[test]
fn a_nudge_pushes_a_cube_that_is_nearly_in_place_along_the_board() {
    // A cube 13 mm from where it should be, diagonally: the user pushes
    // it there with its thumb.
    let to = Vec3::new(0.009, 0.0, -0.0094);
    for method in [Method::Coulomb, Method::Kinematic] {
        let (user, moved, highest) = one_user(
            method,
            |sight, target, hand| {
                User::new(STEADY, Strategy::Lift, target, hand, exact(sight), None, 5).nudging()
            },
            to,
        );
        let error = ((moved - to) * Vec3::new(1.0, 0.0, 1.0)).length();
        assert!(user.done_at.is_some(), "{method:?}: the nudge never ended");
        // Within the user's tolerance plus how far the cube slides while
        // the user sees it (30 ms late) at the push's speed near the end.
        assert!(error < 0.005, "{method:?}: {:.1} mm from the target", error * 1e3);
        assert!(highest < CUBE_HALF + 0.002, "{method:?}: lifted to {highest} m, not pushed");
    }
}

#[test]
fn a_sliding_user_moves_the_cube_over_the_board_without_lifting_it() {
    // Three squares along, one across: gripped and slid, never lifted.
    let to = Vec3::new(0.15, 0.0, 0.05);
    for method in [Method::Coulomb, Method::Heuristic] {
        let (user, moved, highest) = one_user(
            method,
            |sight, target, hand| {
                User::new(STEADY, Strategy::Slide, target, hand, exact(sight), None, 9)
            },
            to,
        );
        assert!(user.done_at.is_some(), "{method:?}: the slide never ended");
        assert_eq!(user.drops, 0, "{method:?}");
        let error = ((moved - to) * Vec3::new(1.0, 0.0, 1.0)).length();
        assert!(error < 0.006, "{method:?}: {:.1} mm from the target", error * 1e3);
        assert!(highest < CUBE_HALF + 0.003, "{method:?}: lifted to {highest} m, not slid");
    }
}

#[test]
fn the_grip_holds_the_cube_where_it_closed_on_it_and_one_gamma_per_contact_does_not() {
    // The users' grip: a thumb against four fingers, each sunk `squeeze`.
    // Held and carried, then set down: where the cube sits across the
    // grip as the hand opens on it. With one γ per contact, four springs
    // against one push it (4 − 1)/(4 + 1) of the squeeze towards the
    // thumb, the offset that springs back across the hand as it opens.
    let squeeze = 0.0052;
    let params = UserParams { squeeze, ..STEADY };
    let held = |config: InteractionConfig| {
        let (mut world, cube) = board::world(config, (3, 3), 0.0).unwrap();
        let start = world.object_state(cube).unwrap().position;
        let sight = Sight::default();
        let begin = start + Vec3::new(-0.1, 0.15, 0.0);
        let mut user = User::new(
            params,
            Strategy::Lift,
            start + Vec3::Z * 0.1,
            begin,
            exact(sight.clone()),
            None,
            2,
        );
        let mut eyes = Eyes { cube, sight };
        let mut driver = Driver::new(&mut world);
        driver.add_hand(&mut user);
        driver.run(20_000, &mut [&mut eyes]).unwrap();
        drop(driver);
        user.held_at.expect("the user set the cube down").x
    };
    let balanced = held(InteractionConfig::default());
    assert!(balanced.abs() < 0.0003, "held {:.2} mm off centre", balanced * 1e3);
    let config = InteractionConfig { virtual_fingers: false, ..InteractionConfig::default() };
    let offset = held(config);
    let expected = -0.6 * squeeze;
    assert!((offset - expected).abs() < 0.25 * squeeze, "{:.2} mm", offset * 1e3);
}

#[test]
fn real_tracking_noise_moves_each_finger_on_its_own() {
    use rand::SeedableRng;
    let noise = TrackingNoise::bundled().unwrap();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(4);
    let mut stream = noise.stream(1.0, &mut rng);
    let pose = coulomb_hands::eval::grip::grip(CUBE_HALF, 1.0, 0.004);
    // The thumb's tip and the index's tip move apart by different amounts
    // over a second: the aperture flickers.
    let mut apertures = Vec::new();
    for i in 0..200 {
        if let coulomb_hands::eval::noise::Tracked::Hand(r) = stream.at(i as f64 * 0.005, &mut rng)
        {
            let p = r.apply(&pose);
            apertures.push(p.fingers[0][2].b.distance(p.fingers[1][2].b));
        }
    }
    let mean = apertures.iter().sum::<f32>() / apertures.len() as f32;
    let sd =
        (apertures.iter().map(|a| (a - mean).powi(2)).sum::<f32>() / apertures.len() as f32).sqrt();
    assert!(sd > 1e-4 && sd < 5e-3, "aperture flickers by {:.3} mm", sd * 1e3);
    // At scale 0 there is none.
    let mut still = noise.stream(0.0, &mut rng);
    for i in 0..50 {
        let r = still.at(i as f64 * 0.01, &mut rng);
        assert_eq!(r, coulomb_hands::eval::noise::Tracked::Hand(Default::default()));
    }
}
