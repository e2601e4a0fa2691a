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

impl ContactEventKind {
    /// Every kind, in the order of [`Self::code`]; the names bindings give
    /// them (Python's `EVENT_KINDS`).
    pub const NAMES: [&'static str; 2] = ["began", "ended"];

    /// The kind as a number, for arrays across a binding: its place in
    /// [`Self::NAMES`].
    pub fn code(self) -> u8 {
        match self {
            ContactEventKind::Began => 0,
            ContactEventKind::Ended => 1,
        }
    }
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
