//! A stand-in for an XR runtime's hand tracking, so the example runs
//! anywhere: the right hand of a real Leap Motion recording (the bundled
//! `grab.json.lz`), held edge-on (palm facing +x, fingers along +z) and
//! swept across the table at 0.2 m/s, low enough for its lower fingers to
//! meet the cube's side. Its joints are given as OpenXR's 26.

use bevy::prelude::*;
use coulomb_hands::Side;
use coulomb_hands::input::TrackedHand;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::layouts::{Joint, openxr, to_openxr};
use std::sync::OnceLock;

/// Where the cube sits: 4 cm, on the table at the origin (m).
pub const CUBE: Vec3 = Vec3::new(0.0, 0.02, 0.0);
/// The sweep: from 13 cm left of the cube, at 0.2 m/s, for 1 s (m, m/s, s).
const START_X: f32 = -0.13;
const SPEED: f32 = 0.2;
const DURATION: f32 = 1.0;

/// The recorded hand, turned edge-on with its palm at the origin.
fn hand() -> &'static TrackedHand {
    static HAND: OnceLock<TrackedHand> = OnceLock::new();
    HAND.get_or_init(|| {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/leap/grab.json.lz");
        let recording = coulomb_hands::input::recording::load(std::path::Path::new(path))
            .expect("the bundled recording");
        let hand = recording.frames.iter().flat_map(|f| &f.hands).find(|h| h.side == Side::Right);
        let hand = hand.expect("a right hand").converted(&recording.conversion(glam::Vec3::ZERO));
        let basis = |n: glam::Vec3, d: glam::Vec3| {
            let d = d.reject_from(n).normalize();
            glam::Mat3::from_cols(n.normalize(), d, n.normalize().cross(d))
        };
        let edge_on = basis(glam::Vec3::X, glam::Vec3::Z);
        let turn =
            glam::Quat::from_mat3(&(edge_on * basis(hand.palm_normal, hand.direction).transpose()));
        hand.converted(&Conversion::head_pose(turn, -(turn * hand.palm_position)))
    })
}

/// The right hand's joints at `t` seconds (world, m).
pub fn openxr_joints(t: f32) -> [Joint; openxr::COUNT] {
    let x = START_X + SPEED * t.min(DURATION);
    to_openxr(&hand().converted(&Conversion::translation(glam::Vec3::new(x, 0.045, 0.0))))
}

/// Quits once the sweep is over.
pub fn exit_when_done(time: Res<Time>, mut exit: MessageWriter<AppExit>) {
    if time.elapsed_secs() > DURATION + 0.2 {
        exit.write(AppExit::Success);
    }
}
