//! Live XR hands without a runtime: the test writes each frame's 26 joints
//! into bevy_mod_xr's hand-bone entities, as bevy_mod_openxr does from
//! `xrLocateHandJointsEXT` (bone `b` gets joint `b` of XrHandJointEXT's
//! order, under the tracking root), and the viewer's system poses the
//! interaction's hands from them. The hands are real: a Leap recording's
//! right hand, turned into OpenXR joints.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_mod_xr::hands::{
    HandBone, HandSide, RightHand, XrHandBoneEntities, XrHandBoneRadius, spawn_hand_bones,
};
use bevy_mod_xr::session::XrTrackingRoot;
use bevy_mod_xr::spaces::XrSpaceLocationFlags;
use coulomb_hands::hand::HandId;
use coulomb_hands::hand::{HandPose, Side};
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::layouts::{Joint, from_openxr, openxr, to_openxr};
use coulomb_hands::input::skeleton::hand_pose;
use coulomb_hands::input::{TrackedHand, recording};
use coulomb_hands::pipeline::Method;
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::convert::{to_bevy_quat, to_bevy_vec3};
use coulomb_hands_bevy::physics::HandPhysics;
use coulomb_hands_view::headless_app;
use coulomb_hands_view::sound::SoundPlugin;
use coulomb_hands_view::source::{LoadOptions, Source};
use coulomb_hands_view::xr_hands::{RoomPlacement, XrHands, XrHandsPlugin};
use std::path::Path;
use std::time::Duration;

/// One XR frame (s): a 90 Hz headset.
const FRAME: f32 = 1.0 / 90.0;
/// Where the test puts the scene in the room: not the default, so the
/// placement is what is tested.
const ORIGIN: Vec3 = Vec3::new(0.21, 0.93, -0.47);
/// The desk's cube.
const CUBE: ObjectId = ObjectId(0);
/// The interaction's hands: left, then right.
const RIGHT: HandId = HandId(1);

/// A headless viewer app of the desk with live XR hands, and the right
/// hand's bone entities (no left hand is tracked).
fn desk() -> (App, [Entity; openxr::COUNT]) {
    let source = Source::load(None, &LoadOptions::default()).and_then(Source::live_xr);
    let source = source.expect("the desk scene");
    let mut app = headless_app(source, Method::Coulomb).expect("a world");
    app.add_plugins((XrHandsPlugin, SoundPlugin { play: false }))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(FRAME)))
        .insert_resource(RoomPlacement { origin: ORIGIN });
    // What bevy_mod_xr's session plugin and bevy_mod_openxr's hand
    // tracking spawn: the tracking root, and a tracker with its bones.
    let world = app.world_mut();
    let root = world.spawn(XrTrackingRoot).id();
    let bones = {
        let mut commands = world.commands();
        let bones = spawn_hand_bones(&mut commands, |_| RightHand);
        commands.spawn((XrHandBoneEntities(bones), HandSide::Right, RightHand));
        commands.entity(root).add_children(&bones);
        bones
    };
    world.flush();
    app.update();
    (app, bones)
}

/// Writes `joints` (room space, m) into the bones as the runtime would:
/// each bone entity takes the joint of its own [`HandBone`] number.
fn locate(app: &mut App, bones: &[Entity; openxr::COUNT], joints: &[Joint; openxr::COUNT]) {
    for entity in bones {
        let mut bone = app.world_mut().entity_mut(*entity);
        let joint = joints[*bone.get::<HandBone>().expect("a hand bone") as usize];
        *bone.get_mut::<Transform>().expect("a transform") = Transform {
            translation: to_bevy_vec3(joint.position),
            rotation: to_bevy_quat(joint.orientation),
            ..default()
        };
        bone.get_mut::<XrHandBoneRadius>().expect("a radius").0 = joint.radius;
        *bone.get_mut::<XrSpaceLocationFlags>().expect("flags") =
            XrSpaceLocationFlags { position_tracked: true, rotation_tracked: true };
    }
}

/// The right hand of the bundled `grab` recording's first frame that has
/// one, in metres, with its palm centre at `palm`, its palm facing
/// `normal` and its fingers pointing along `direction` (room space).
fn real_hand(palm: glam::Vec3, normal: glam::Vec3, direction: glam::Vec3) -> TrackedHand {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/leap/grab.json.lz");
    let recording = recording::load(&path).expect("the bundled recording");
    let hand = recording.frames.iter().flat_map(|f| &f.hands).find(|h| h.side == Side::Right);
    let hand = hand.expect("a right hand").converted(&recording.conversion(glam::Vec3::ZERO));
    let basis = |n: glam::Vec3, d: glam::Vec3| {
        let d = d.reject_from(n).normalize();
        glam::Mat3::from_cols(n.normalize(), d, n.normalize().cross(d))
    };
    let turn = glam::Quat::from_mat3(
        &(basis(normal, direction) * basis(hand.palm_normal, hand.direction).transpose()),
    );
    let placed = Conversion::head_pose(turn, palm - turn * hand.palm_position);
    hand.converted(&placed)
}

fn right_pose(app: &App) -> Option<HandPose> {
    app.world().resource::<HandPhysics>().world().hand_pose(RIGHT).cloned()
}

fn cube(app: &App) -> glam::Vec3 {
    let interaction = app.world().resource::<HandPhysics>();
    interaction.world().object_state(CUBE).expect("the cube").position
}

/// A real hand's joints, read as a headset's, pose the interaction's right
/// hand as the core reads those joints, shifted by the room placement:
/// every finger bone's ends within 1 mm of the tracked hand's own, and the
/// palm as the core's OpenXR layout makes it. The left hand, never
/// located, is untracked.
#[test]
fn xr_joints_pose_the_hand_where_it_was_tracked() {
    let (mut app, bones) = desk();
    let room = glam::Vec3::new(0.25, 1.06, -0.52);
    let hand = real_hand(room, glam::Vec3::NEG_Y, glam::Vec3::NEG_Z);
    let joints = to_openxr(&hand);
    locate(&mut app, &bones, &joints);
    app.update();
    let got = right_pose(&app).expect("the right hand is tracked");
    let shift = Conversion::translation(-coulomb_hands_bevy::convert::to_core_vec3(ORIGIN));
    let tracked = hand_pose(&hand.converted(&shift), &Conversion::identity()).expect("a pose");
    let err = |a: glam::Vec3, b: glam::Vec3| a.distance(b);
    for (f, (gf, wf)) in got.fingers.iter().zip(&tracked.fingers).enumerate() {
        for (p, (g, w)) in gf.iter().zip(wf).enumerate() {
            let (ea, eb) = (err(g.a, w.a), err(g.b, w.b));
            assert!(ea < 1e-3 && eb < 1e-3, "finger {f} bone {p}: {ea} m, {eb} m off");
            assert!((g.radius - w.radius).abs() < 1e-4, "finger {f} bone {p}'s radius");
        }
    }
    let shifted = joints.map(|j| Joint { position: shift.point(j.position), ..j });
    let read = from_openxr(1, Side::Right, &shifted).expect("the core reads the joints");
    let read = hand_pose(&read, &Conversion::identity()).expect("a pose");
    assert!(err(got.palm.center, read.palm.center) < 1e-3, "{:?} {:?}", got.palm, read.palm);
    assert!((got.palm.half_extents - read.palm.half_extents).length() < 1e-3);
    // 1.06 m in the room is 13 cm above the desk.
    assert!((0.1..0.16).contains(&got.palm.center.y), "{}", got.palm.center);
    let world = app.world().resource::<HandPhysics>();
    assert!(world.world().hand_pose(HandId(0)).is_none(), "the left hand was never located");
    assert_eq!(app.world().resource::<XrHands>().tracked, [false, true]);
}

/// The right hand, held edge-on (palm facing +x, thumb up), sweeps
/// across the desk at 0.2 m/s, low enough for its lower fingers to meet the
/// cube's side: the cube is pushed along +x, by friction contacts alone.
/// It starts clear of the desk's block (centred at x = −0.13), which would
/// otherwise be pushed ahead of the hand into the cube.
/// Then one joint goes untracked: the hand is lost, its contacts end, and
/// the cube stops though the joints sweep on through it.
#[test]
fn a_swept_xr_hand_pushes_the_cube_and_a_lost_one_lets_go() {
    let (mut app, bones) = desk();
    let start = cube(&app);
    let speed = 0.2;
    let mut x = -0.08;
    let pose_at = |x: f32| {
        let room = coulomb_hands_bevy::convert::to_core_vec3(ORIGIN);
        let palm = room + glam::Vec3::new(x, 0.045, 0.0);
        to_openxr(&real_hand(palm, glam::Vec3::X, glam::Vec3::Z))
    };
    let mut touched = false;
    while x < 0.02 {
        locate(&mut app, &bones, &pose_at(x));
        app.update();
        touched |= !app.world().resource::<HandPhysics>().world().contacts_on(CUBE).is_empty();
        x += speed * FRAME;
    }
    let pushed = cube(&app) - start;
    assert!(touched, "the hand's bones touched the cube");
    // The palm meets the cube 12 mm off its centre, so the cube turns
    // and slides aside as well as ahead.
    let across = glam::Vec2::new(pushed.x, pushed.z).length();
    assert!(pushed.x > 0.01 && across > 0.02, "the sweep pushed the cube along: {pushed}");
    assert!(pushed.y.abs() < 0.01, "it stayed on the desk: {pushed}");
    // The index fingertip goes untracked; the other joints sweep on.
    let tip = bones[HandBone::IndexTip as usize];
    for _ in 0..45 {
        locate(&mut app, &bones, &pose_at(x));
        let mut flags = app.world_mut().entity_mut(tip);
        *flags.get_mut::<XrSpaceLocationFlags>().expect("flags") = XrSpaceLocationFlags::default();
        app.update();
        x += speed * FRAME;
    }
    assert!(right_pose(&app).is_none(), "a hand with an untracked joint is lost");
    let world = app.world().resource::<HandPhysics>();
    assert!(world.world().contacts_on(CUBE).is_empty(), "a lost hand holds no contact");
    let after = cube(&app) - start;
    assert!(after.x - pushed.x < 0.01, "the cube stopped: {pushed} then {after}");
    assert_eq!(app.world().resource::<XrHands>().tracked, [false, false]);
}

/// `--openxr` that cannot work is a clear error before any window (no
/// `DISPLAY` is set), not a panic. Built without the feature, the viewer
/// says how to build it with. Built with it, and no runtime (none is
/// installed here, and `XR_RUNTIME_JSON` names no file), it says there is
/// no OpenXR runtime, or no loader where none is installed.
#[test]
fn openxr_without_a_runtime_is_a_clear_error() {
    let run = |args: &[&str]| {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_coulomb-hands-view"));
        command.args(args).env_remove("DISPLAY").env_remove("WAYLAND_DISPLAY");
        command.env("XR_RUNTIME_JSON", "/nonexistent/openxr_runtime.json");
        let out = command.output().expect("the viewer runs");
        let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_eq!(out.status.code(), Some(1), "{args:?} fails: {stderr}");
        assert!(!stderr.contains("panicked"), "an error, not a panic: {stderr}");
        stderr
    };
    let stderr = run(&["--openxr"]);
    let last = stderr.lines().last().unwrap_or_default();
    if cfg!(feature = "openxr") {
        let no_runtime = last.starts_with("error: --openxr: no OpenXR runtime is running");
        let no_loader = last.starts_with("error: --openxr: no OpenXR loader");
        assert!(no_runtime || no_loader, "{stderr}");
        let stderr = run(&["grasp-lift", "--openxr"]);
        assert!(stderr.ends_with("grasp-lift: --openxr takes a scene file, or none\n"), "{stderr}");
    } else {
        assert_eq!(stderr, format!("error: {}\n", coulomb_hands_view::NO_OPENXR));
    }
}
