//! A grab helper like Ultraleap's Physical Hands: `GrabHelperObject.cs`
//! in ultraleap/UnityPlugin (`Packages/Tracking/Physical Hands`, 7.x,
//! Apache-2.0). Its rules, with its constants:
//!
//! * **Grab** (`IsHandGrabbable`, `GrabbingCheck`,
//!   `CheckForBonesFacingEachOther`): the thumb or the palm touches the
//!   object, and so does a finger's middle or end phalanx (the pinky's end
//!   phalanx only); the touching fingers are curled at least
//!   [`MIN_CURL`] (`MINIMUM_STRENGTH`, `MINIMUM_THUMB_STRENGTH`); and
//!   either two touching bones of different digits face each other
//!   (contact normals' dot below [`FACING_DOT`],
//!   `GRABBABLE_DIRECTIONS_DOT`) or the thumb's tip is within
//!   [`PINCH_DISTANCE`] of a touching finger's tip
//!   (`REQUIRED_PINCH_DISTANCE`).
//! * **Held** (`UpdateHandPositions`, `PhysicsMovement`): gravity is off,
//!   and each step the object's velocity is set to reach its grab-time
//!   pose relative to the palm, capped at [`MAX_SPEED`]
//!   (`MAX_VELOCITY_SQUARED` = 100).
//! * **Let go** (`UpdateGrabbingValues`): when fewer than two digits keep
//!   their curl above [`MIN_CURL`] and above their grab-time curl less
//!   [`EXIT_CURL`] ([`THUMB_EXIT_CURL`] for the thumb)
//!   (`REQUIRED_EXIT_STRENGTH`, `REQUIRED_THUMB_EXIT_STRENGTH`), and the
//!   grab conditions no longer hold.
//! * **Throw** (`ThrowingOnRelease`): the velocity averaged over the last
//!   [`THROW_WINDOW`] s (`VELOCITY_HISTORY_LENGTH`); above
//!   [`THROW_SPEED`] it is the object's velocity and the object cannot be
//!   grabbed again for [`REGRAB_COOLDOWN`] s (`THOWN_GRAB_COOLDOWNTIME`);
//!   otherwise the object stops dead.
//!
//! Left out: the plugin's mass override while held (the object collides
//! with its own mass here), its short collision-ignore after a throw, and
//! its 15 % stickier strength for tiny pinches.

use super::{curl, digit, facing, is_thumb, is_tip};
use crate::contact::Contact;
use crate::hand::{Bone, Finger, HandPose, Phalanx};
use glam::Vec3;
use std::collections::VecDeque;

/// Least curl of a touching digit that can grab (`MINIMUM_STRENGTH`).
pub const MIN_CURL: f32 = 0.1;
/// A finger lets go when its curl falls this fraction below its grab-time
/// curl (`REQUIRED_EXIT_STRENGTH`).
pub const EXIT_CURL: f32 = 0.05;
/// The same for the thumb (`REQUIRED_THUMB_EXIT_STRENGTH`).
pub const THUMB_EXIT_CURL: f32 = 0.08;
/// Thumb-tip to finger-tip distance of a pinch (m)
/// (`REQUIRED_PINCH_DISTANCE`).
pub const PINCH_DISTANCE: f32 = 0.01;
/// Two bones face each other below this normals' dot product
/// (`GRABBABLE_DIRECTIONS_DOT`).
pub const FACING_DOT: f32 = -0.2;
/// Cap on the held object's speed (m/s) (`MAX_VELOCITY_SQUARED` = 100).
pub const MAX_SPEED: f32 = 10.0;
/// Throw velocity history (s) (`VELOCITY_HISTORY_LENGTH`).
pub const THROW_WINDOW: f64 = 0.045;
/// Above this averaged speed (m/s), a release is a throw.
pub const THROW_SPEED: f32 = 0.5;
/// No grab for this long after a throw (s) (`THOWN_GRAB_COOLDOWNTIME`).
pub const REGRAB_COOLDOWN: f64 = 0.5;

/// Whether a touching bone can take part in a grab
/// (`IsFingerGrabbable`): the thumb and palm anywhere, the index, middle
/// and ring fingers by their middle or end phalanx, the pinky by its tip.
fn can_grab_with(bone: Bone) -> bool {
    match bone {
        Bone::Palm | Bone::Finger(Finger::Thumb, _) => true,
        Bone::Finger(Finger::Pinky, p) => p == Phalanx::Distal,
        Bone::Finger(_, p) => p != Phalanx::Proximal,
    }
}

/// The digits' curls (thumb first), and the palm's as 1: the palm always
/// counts as curled.
pub fn curls(pose: &HandPose) -> [f32; 6] {
    let mut out = [1.0; 6];
    for f in Finger::ALL {
        out[f as usize] = curl(pose, f);
    }
    out
}

/// Whether one hand's `contacts` on one object meet the grab conditions.
pub fn grabs(contacts: &[&Contact], pose: &HandPose) -> bool {
    let curls = curls(pose);
    let eligible: Vec<&Contact> = contacts
        .iter()
        .copied()
        .filter(|c| can_grab_with(c.bone) && curls[digit(c.bone)] >= MIN_CURL)
        .collect();
    let thumb_or_palm = eligible.iter().any(|c| is_thumb(c) || c.bone == Bone::Palm);
    let finger = eligible.iter().any(|c| !is_thumb(c) && c.bone != Bone::Palm);
    if !(thumb_or_palm && finger) {
        return false;
    }
    let faces = eligible.iter().any(|a| eligible.iter().any(|b| facing(a, b, FACING_DOT)));
    faces || pinches(&eligible, pose)
}

/// Whether the thumb's tip is within [`PINCH_DISTANCE`] of the tip of a
/// finger among `contacts`.
fn pinches(contacts: &[&Contact], pose: &HandPose) -> bool {
    let thumb_tip = pose.fingers[0][2].b;
    contacts.iter().filter(|c| is_tip(c.bone) && !is_thumb(c)).any(|c| {
        let Bone::Finger(f, _) = c.bone else { return false };
        pose.fingers[f as usize][2].b.distance(thumb_tip) <= PINCH_DISTANCE
    })
}

/// Whether a hand that grabbed with `at_grab` curls still holds: at least
/// two digits keep their curl (the palm always does, if it grabbed).
pub fn keeps_hold(at_grab: &[f32; 6], pose: &HandPose) -> bool {
    let now = curls(pose);
    let kept = (0..6)
        .filter(|&d| at_grab[d] >= MIN_CURL)
        .filter(|&d| {
            let exit = if d == 0 { THUMB_EXIT_CURL } else { EXIT_CURL };
            now[d] >= MIN_CURL && now[d] > at_grab[d] * (1.0 - exit)
        })
        .count();
    kept >= 2
}

/// The held object's velocities over the last [`THROW_WINDOW`].
#[derive(Debug, Clone, Default)]
pub struct ThrowHistory {
    samples: VecDeque<(f64, Vec3)>,
}

impl ThrowHistory {
    /// Records the velocity set at time `t` (s), forgetting older ones.
    pub fn push(&mut self, t: f64, velocity: Vec3) {
        self.samples.push_back((t, velocity));
        while self.samples.front().is_some_and(|(t0, _)| t - t0 > THROW_WINDOW) {
            self.samples.pop_front();
        }
    }

    /// The release velocity: the average, if faster than [`THROW_SPEED`]
    /// (a throw), else `None` (the object stops).
    pub fn throw(&self) -> Option<Vec3> {
        let n = self.samples.len();
        if n == 0 {
            return None;
        }
        let mean = self.samples.iter().map(|s| s.1).sum::<Vec3>() / n as f32;
        (mean.length() > THROW_SPEED).then_some(mean)
    }
}

/// The velocity that takes a point from `from` to `to` in `dt`, capped at
/// [`MAX_SPEED`] (`PhysicsMovement`).
pub fn chase_velocity(from: Vec3, to: Vec3, dt: f32) -> Vec3 {
    ((to - from) / dt).clamp_length_max(MAX_SPEED)
}
