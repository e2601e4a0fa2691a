//! Grab baselines: the two methods the thesis compares its friction hands
//! against (§3.9, Table 5.2). Each turns a qualifying set of contacts into
//! a grab that moves the object with the hand, instead of friction.
//!
//! * [`kinematic`]: the re-implemented kinematic grasp of \[23\] (§3.9);
//! * [`heuristic`]: a grab helper like Ultraleap's Physical Hands;
//!
//! Both are pure decisions over the step's contacts and the hand's pose.
//! The pipeline's grab stage (`pipeline/step/grab.rs`) carries them out on
//! rapier's bodies. Outside a grab, a baseline's hand pushes with the
//! contact law's normal force only (no skin friction): the study then
//! compares friction against grabbing, not the same friction plus a grab.

pub mod heuristic;
pub mod kinematic;

use crate::contact::Contact;
use crate::hand::{Bone, Finger, HandPose, Phalanx};
use glam::Vec3;

/// Which grab baseline a world uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum GrabMethod {
    /// \[23\]'s kinematic grasp ([`kinematic`]).
    Kinematic,
    /// The grab helper of Ultraleap's Physical Hands ([`heuristic`]).
    Heuristic,
}

/// The digit a bone belongs to, the palm as a sixth (index 5), as
/// Ultraleap's grab helper counts them.
pub fn digit(bone: Bone) -> usize {
    match bone {
        Bone::Palm => 5,
        Bone::Finger(f, _) => f as usize,
    }
}

/// How curled a finger is, in [0, 1]: the angle between the direction its
/// base phalanx leaves the palm and its distal phalanx, over 180° (a
/// finger folded back on itself is 1). This is the role of Leap's finger
/// strength; for the thumb the base is its metacarpal.
pub fn curl(pose: &HandPose, finger: Finger) -> f32 {
    let bones = &pose.fingers[finger as usize];
    let base = match finger {
        Finger::Thumb => bones[0].b - bones[0].a,
        _ => pose.palm.rotation * Vec3::Z,
    };
    let tip = bones[2].b - bones[2].a;
    match (base.try_normalize(), tip.try_normalize()) {
        (Some(a), Some(b)) => a.angle_between(b) / std::f32::consts::PI,
        _ => 0.0,
    }
}

/// Whether two contacts of different digits face each other across the
/// object: their normals' dot product is below `dot` (−1 for directly
/// opposite sides).
pub fn facing(a: &Contact, b: &Contact, dot: f32) -> bool {
    digit(a.bone) != digit(b.bone) && a.normal.dot(b.normal) < dot
}

/// The thumb's bones among `contacts`.
fn is_thumb(c: &Contact) -> bool {
    matches!(c.bone, Bone::Finger(Finger::Thumb, _))
}

/// Whether a bone is a fingertip phalanx (for pinches).
fn is_tip(bone: Bone) -> bool {
    matches!(bone, Bone::Finger(_, Phalanx::Distal))
}
