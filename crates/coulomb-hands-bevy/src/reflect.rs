//! Reflection of the core's ids and kinds, which cannot derive Bevy's
//! `Reflect` themselves (the core has no Bevy): remote wrappers, so the
//! plugin's components show them in an inspector and scenes can store
//! them. A component field of a core type says `#[reflect(remote = …)]`.

use bevy::reflect::reflect_remote;
use coulomb_hands::friction::FrictionState;
use coulomb_hands::hand::{Bone, Finger, HandId, Phalanx, Side};
use coulomb_hands::scene::ObjectId;

/// [`Side`], reflected.
#[reflect_remote(Side)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SideReflect {
    /// The left hand.
    Left,
    /// The right hand.
    Right,
}

/// [`HandId`], reflected.
#[reflect_remote(HandId)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HandIdReflect(pub u32);

/// [`ObjectId`], reflected.
#[reflect_remote(ObjectId)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectIdReflect(pub u32);

/// [`Finger`], reflected.
#[reflect_remote(Finger)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FingerReflect {
    /// The thumb.
    Thumb,
    /// The index finger.
    Index,
    /// The middle finger.
    Middle,
    /// The ring finger.
    Ring,
    /// The little finger.
    Pinky,
}

/// [`Phalanx`], reflected.
#[reflect_remote(Phalanx)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PhalanxReflect {
    /// Next to the palm.
    Proximal,
    /// The middle one.
    Intermediate,
    /// The fingertip's.
    Distal,
}

/// [`Bone`], reflected.
#[reflect_remote(Bone)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BoneReflect {
    /// The palm box.
    Palm,
    /// One phalanx of one finger.
    Finger(#[reflect(remote = FingerReflect)] Finger, #[reflect(remote = PhalanxReflect)] Phalanx),
}

/// [`FrictionState`], reflected.
#[reflect_remote(FrictionState)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionStateReflect {
    /// Inside the friction cone.
    Static,
    /// Outside it: slipping.
    Dynamic,
    /// Not pressing.
    Separated,
}
