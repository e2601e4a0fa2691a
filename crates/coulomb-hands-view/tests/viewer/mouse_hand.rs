//! The mouse-and-keyboard hand, driven by key presses as a person would,
//! in a headless app with the plugin: it pushes the desk scene's cube,
//! grasps and lifts it, and drops it, only through friction contacts.
//!
//! The "person" watches where the hand is (closed loop on the hand's pose),
//! as one does on screen, and holds keys for as long as that takes.

use super::keys::key;
use bevy::input::ButtonState;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::hand::Side;
use coulomb_hands::pipeline::Method;
use coulomb_hands::run::replay::is_squeezed;
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::headless_app;
use coulomb_hands_view::mouse_hand::MouseHand;
use coulomb_hands_view::sound::{ContactSound, SoundPlugin, loudness};
use coulomb_hands_view::source::{HandDriver, LoadOptions, Source};
use coulomb_hands_view::transport::Transport;
use std::time::Duration;

/// One frame (s): the app runs at 100 frames per second.
const FRAME: f32 = 0.01;
/// The desk's cube: 4 cm, centred 2 cm above the table at the origin.
const CUBE: ObjectId = ObjectId(0);
const CUBE_HALF: f32 = 0.02;

fn desk() -> App {
    app_of(Source::load(None, &LoadOptions::default()).expect("the desk scene"))
}

/// An app of `source` with the mouse hand, the transport and the taps, at
/// 100 frames per second.
pub fn app_of(source: Source) -> App {
    assert!(source.app_hands().contains(&(Side::Right, HandDriver::Mouse)), "a mouse hand");
    let mut app = headless_app(source, Method::Coulomb).expect("a world");
    // Silent, as with no audio device: the taps are worked out, not played.
    app.add_plugins(SoundPlugin { play: false })
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(FRAME)));
    app.update();
    app
}

/// Holds `keys` while `go` says so (at most `limit` s); returns the time held.
pub fn hold_while(
    app: &mut App,
    keys: &[KeyCode],
    limit: f32,
    mut go: impl FnMut(&App) -> bool,
) -> f32 {
    let mut held = 0.0;
    keys.iter().for_each(|k| key(app, *k, ButtonState::Pressed));
    // Frames are counted, not summed as floats, so 0.25 s is 25 frames.
    let frames = (limit / FRAME).round() as usize;
    for _ in 0..frames {
        if !go(app) {
            break;
        }
        app.update();
        held += FRAME;
    }
    keys.iter().for_each(|k| key(app, *k, ButtonState::Released));
    app.update();
    held
}

/// Holds `keys` for `seconds`.
pub fn hold(app: &mut App, keys: &[KeyCode], seconds: f32) {
    hold_while(app, keys, seconds, |_| true);
}

pub fn hand(app: &App) -> &MouseHand {
    app.world().resource::<MouseHand>()
}

pub fn cube(app: &App) -> glam::Vec3 {
    cube_state(app).position
}

/// The middle fingertip's end (world, m).
pub fn fingertip(app: &App) -> glam::Vec3 {
    tip(app, 2)
}

/// The end of finger `f`'s last bone (thumb 0; world, m).
pub fn tip(app: &App, f: usize) -> glam::Vec3 {
    hand(app).sample().pose.fingers[f][2].b
}

/// Finger `f`'s radius (m).
pub fn tip_radius(app: &App, f: usize) -> f32 {
    hand(app).sample().pose.fingers[f][2].radius
}

/// The hand moves at the speed its keys say: the palm's travel is the
/// speed times the time held, in the camera's (here the world's) axes.
#[test]
fn keys_move_turn_and_curl_the_hand_at_their_rates() {
    let mut app = desk();
    let start = hand(&app).palm;
    hold(&mut app, &[KeyCode::KeyW], 0.25);
    hold(&mut app, &[KeyCode::KeyE, KeyCode::ShiftLeft], 0.4);
    let moved = hand(&app).palm - start;
    assert!((moved.z - 0.03).abs() < 0.002, "0.12 m/s for 0.25 s forward: {moved}");
    assert!((moved.y - 0.012).abs() < 0.001, "0.03 m/s for 0.4 s up (fine): {moved}");
    let curl = hand(&app).curl;
    hold(&mut app, &[KeyCode::Digit2], 0.5);
    let after = hand(&app).curl;
    assert!((after[1] - curl[1] - 0.3).abs() < 0.02, "the index alone curls: {after:?}");
    assert_eq!((after[0], after[2]), (curl[0], curl[2]), "the others stay");
    hold(&mut app, &[KeyCode::KeyT], 0.5);
    assert!(hand(&app).opposition > 0.99, "T opposes the thumb within 0.5 s");
}

/// Lowered behind the cube with the fingers almost straight, the hand is
/// moved forward 12 cm: its fingertips push the cube along the table
/// without lifting it, and leave it just ahead of them.
///
/// The middle fingertip reaches the cube first, 9 mm off its centre, so the
/// cube turns (about 20°) and slides in fits and starts as the fingers
/// catch it. Where its centre ends depends on that turn, so the test asks
/// where the cube ends against the fingertips, from the geometry.
#[test]
fn the_hand_pushes_the_cube_along_the_table() {
    let mut app = desk();
    let before = cube(&app);
    // Back until the fingertips are 3 cm behind the cube's back face.
    let behind = before.z - CUBE_HALF - 0.03;
    hold_while(&mut app, &[KeyCode::KeyS], 2.0, |a| fingertip(a).z > behind);
    // Down until the palm is 3 cm above the table.
    hold_while(&mut app, &[KeyCode::KeyQ], 2.0, |a| hand(a).palm.y > 0.03);
    let gap = skin_gap(&app);
    assert!(gap > 0.0, "the fingertips start behind the cube: {gap}");
    let start = fingertip(&app);
    // Forward for a second, then still for half a second, watching how fast the cube goes.
    let mut fastest = 0.0_f32;
    let mut watch = |a: &App| {
        fastest = fastest.max(cube_state(a).linvel.length());
        true
    };
    hold_while(&mut app, &[KeyCode::KeyW], 1.0, &mut watch);
    hold_while(&mut app, &[], 0.5, &mut watch);
    let pushed = cube(&app) - before;
    assert!(pushed.y.abs() < 0.003, "it slid, not lifted: {pushed}");
    // It went with the tips, past the gap, to within a centimetre: turned by
    // θ, a cube's centre is up to h·(1 − cos θ + sin θ) nearer the face's
    // pushed point, about 9 mm at 23°.
    let travel = fingertip(&app).z - start.z;
    assert!(
        pushed.z > travel - gap - 0.01,
        "pushed {pushed} by tips {travel} m past a {gap} m gap"
    );
    assert!(cube(&app).z > fingertip(&app).z, "ahead of the fingertips, not under them");
    // It ends against the fingertips, pressed in by at most the springs'
    // lag (μ·m·g/γ, 0.6 mm; plus a millimetre), or ahead of them by at most
    // how far its fastest speed coasts on the table (v²/2μg, μ = 0.5).
    let lag = 0.5 * 0.05 * 9.81 / 400.0;
    let coast = fastest * fastest / (2.0 * 0.5 * 9.81);
    let ahead = skin_gap(&app);
    let range = -lag - 0.001..coast + 0.001;
    assert!(range.contains(&ahead), "{ahead} m ahead, fastest {fastest} m/s: {range:?}");
}

/// The cube's pose and velocities.
fn cube_state(app: &App) -> coulomb_hands::pipeline::ObjectState {
    let world = app.world().resource::<HandPhysics>();
    world.world().object_state(CUBE).expect("the cube")
}

/// The signed gap from the nearest fingertip's skin (of the four fingers) to the
/// cube's surface (m; negative when pressed in), from its pose.
fn skin_gap(app: &App) -> f32 {
    use rapier3d::math::Pose;
    use rapier3d::parry::query;
    use rapier3d::parry::shape::{Cuboid, Segment};
    let state = cube_state(app);
    let pose = Pose::from_parts(state.position, state.rotation);
    let shape = Cuboid::new(glam::Vec3::splat(CUBE_HALF));
    let gap = |f: usize| {
        let bone = hand(app).sample().pose.fingers[f][2];
        let axis = Segment::new(bone.a, bone.b);
        let hit = query::contact(&Pose::identity(), &axis, &pose, &shape, 1.0);
        hit.expect("a segment and a box").expect("within a metre").dist - bone.radius
    };
    (1..5).map(gap).fold(f32::INFINITY, f32::min)
}

/// The thesis's precision grasp by hand: the palm over the cube, the thumb
/// opposed behind it, the fingers curled until they squeeze it from
/// opposite sides; then up 6 cm, and open. The cube rises with the hand,
/// and falls back to the table when the hand opens.
#[test]
fn the_hand_grasps_lifts_and_drops_the_cube() {
    let mut app = desk();
    // Thumb opposed, fingers bent a third of the way, as for a pinch.
    hold(&mut app, &[KeyCode::KeyT], 0.4);
    hold_while(&mut app, &[KeyCode::KeyG], 1.0, |a| hand(a).curl[1] < 0.3);
    // Forward until the thumb's tip is just behind the cube's back face,
    // sideways until thumb and index tips straddle its centre, the fingers
    // opened until their tips are in front of the cube, then down until
    // the lowest tip is at the cube's mid-height.
    let back = -CUBE_HALF - 0.005;
    hold_while(&mut app, &[KeyCode::KeyW], 2.0, |a| tip(a, 0).z + tip_radius(a, 0) < back);
    let straddle = |a: &App| (tip(a, 0).x + tip(a, 1).x) / 2.0;
    let side = if straddle(&app) > 0.0 { KeyCode::KeyD } else { KeyCode::KeyA };
    let sign = straddle(&app).signum();
    hold_while(&mut app, &[side], 2.0, |a| straddle(a) * sign > 0.0);
    // A person lowering a pinch round the cube sees to it that the index
    // and middle fingertips clear its front face, opening the fingers a
    // little until they do: lowered onto its top, they would press it
    // into the table, not against the thumb.
    let clear = |a: &App, f: usize| {
        let bone = hand(a).sample().pose.fingers[f][2];
        bone.a.z.min(bone.b.z) - bone.radius > CUBE_HALF + 0.003
    };
    let front = |a: &App| (1..3).all(|f| clear(a, f));
    let mut opened = 0.0;
    while !front(&app) && opened < 1.0 {
        hold(&mut app, &[KeyCode::KeyH], 0.01);
        opened += 0.01;
    }
    let lowest = |a: &App| (0..3).map(|f| tip(a, f).y).fold(f32::INFINITY, f32::min);
    hold_while(&mut app, &[KeyCode::KeyQ], 2.0, |a| lowest(a) > CUBE_HALF);
    let bumped = cube(&app) - glam::Vec3::new(0.0, CUBE_HALF, 0.0);
    assert!(bumped.length() < 0.01, "still in place, give or take a bump: {bumped}");
    // Curl the index and middle fingers until the cube is squeezed against
    // the thumb, and a little more for a firm grip.
    let squeezed = |a: &App| {
        let i = a.world().resource::<HandPhysics>();
        is_squeezed(i.world(), CUBE)
    };
    let pinch = [KeyCode::Digit2, KeyCode::Digit3];
    let curling = hold_while(&mut app, &pinch, 1.5, |a| !squeezed(a));
    assert!(squeezed(&app), "curled for {curling} s without squeezing the cube");
    hold(&mut app, &pinch, 0.1);
    let gripped = cube(&app);
    hold(&mut app, &[KeyCode::KeyE], 0.5);
    hold(&mut app, &[], 0.5);
    let lifted = cube(&app) - gripped;
    // Held: it rose with the hand's 6 cm, give or take what the replay
    // verdicts allow a held object to drift in the hand (a finger's width).
    let finger = 2.0 * hand(&app).sample().pose.fingers[1][2].radius;
    assert!(lifted.y > 0.06 - finger, "the cube rose with the hand's 6 cm: {lifted}");
    // Open the hand, the fingers straight and the thumb brought back from
    // opposition: the cube falls back onto the table. (Half open, the hand
    // may still hold it: wedged in a finger's claw, or between the opposed
    // thumb and a finger's base.)
    let bent = |a: &App| hand(a).curl[1..3].iter().any(|&c| c > 0.0) || hand(a).opposition > 0.0;
    hold(&mut app, &[KeyCode::KeyT], 0.02);
    hold_while(&mut app, &[KeyCode::KeyH], 2.0, bent);
    hold(&mut app, &[], 0.5);
    let dropped = cube(&app);
    assert!((dropped.y - CUBE_HALF).abs() < 0.005, "back on the table: {dropped}");
}

fn taps(app: &App) -> &[f32] {
    &app.world().resource::<ContactSound>().taps
}

/// A touch taps, louder the faster the fingertips close on the cube: from 3
/// cm behind it, the hand moves forward at the fine rate (0.03 m/s), then in
/// a second run at the normal one (0.12 m/s). Each first tap's volume is
/// that of its speed. Paused, it taps no more.
#[test]
fn a_faster_touch_taps_louder() {
    let mut first = Vec::new();
    for (keys, speed) in
        [(&[KeyCode::KeyW, KeyCode::ShiftLeft][..], 0.03), (&[KeyCode::KeyW], 0.12)]
    {
        let mut app = desk();
        let behind = cube(&app).z - CUBE_HALF - 0.03;
        hold_while(&mut app, &[KeyCode::KeyS], 2.0, |a| fingertip(a).z > behind);
        hold_while(&mut app, &[KeyCode::KeyQ], 2.0, |a| hand(a).palm.y > 0.03);
        let before = taps(&app).len();
        // One physics step a frame from here, so the frame that taps is the step
        // whose contact began; paused right then, the physics holds and that
        // contact's begin is not heard again.
        let one_step = Duration::from_millis(1);
        app.insert_resource(TimeUpdateStrategy::ManualDuration(one_step));
        keys.iter().for_each(|k| key(&mut app, *k, ButtonState::Pressed));
        for _ in 0..3000 {
            app.update();
            if taps(&app).len() > before {
                break;
            }
        }
        let tap = *taps(&app).get(before).expect("the touch taps");
        assert!(
            (tap - loudness(speed)).abs() < 0.01,
            "at {speed} m/s: {tap}, not {}",
            loudness(speed)
        );
        app.world_mut().resource_mut::<Transport>().paused = true;
        let heard = taps(&app).len();
        hold(&mut app, &[], 0.5);
        assert_eq!(taps(&app).len(), heard, "no new taps while paused");
        first.push(tap);
    }
    assert!(first[1] > first[0] + 0.04, "the faster touch is louder: {first:?}");
}
