//! Contact begin/end events: what a step tells visuals and sound.

use crate::hand::{Bone, HandId};
use crate::scene::ObjectId;
use glam::Vec3;

/// Whether a contact began or ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum ContactEventKind {
    /// A bone came within the contact offset of an object.
    Began,
    /// A bone left the release offset, its hand lost tracking, or its
    /// object's contacts were re-seated.
    Ended,
}

/// A contact began or ended during a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    /// Began or ended.
    pub kind: ContactEventKind,
    /// The contact's hand.
    pub hand: HandId,
    /// The contact's bone.
    pub bone: Bone,
    /// The object touched.
    pub object: ObjectId,
    /// The contact point C at that moment (world, m).
    pub point: Vec3,
    /// Simulation time of the step (s).
    pub time: f64,
}
