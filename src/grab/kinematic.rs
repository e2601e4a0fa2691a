//! The kinematic grasp of \[23\], as the thesis re-implemented it (§3.9):
//! once the hand's contacts qualify as a grasp, the object follows the
//! hand's global transform, `M_object = M_object^hand · M_hand`, and it is
//! let go when they no longer qualify.
//!
//! Thresholds:
//! * a grasp is the thumb touching the object plus at least one bone of
//!   another finger, or the palm, touching it from the opposite side: the
//!   two contact normals at more than 90° ([`OPPOSING_DOT`]);
//! * touching is being a contact: within the contact offset when it
//!   begins, kept until the release offset, so the grasp needs no
//!   penetration and its release has the offsets' hysteresis;
//! * the hand has opened when no such pair is left: the object is let go
//!   with the velocity it had while carried.

use super::{facing, is_thumb};
use crate::contact::Contact;

/// Two contacts oppose each other when their normals' dot product is below
/// this: more than 90° apart.
pub const OPPOSING_DOT: f32 = 0.0;

/// Whether one hand's `contacts` on one object qualify as \[23\]'s grasp:
/// the thumb plus an opposing finger or the palm.
pub fn is_grasp(contacts: &[&Contact]) -> bool {
    contacts
        .iter()
        .filter(|c| is_thumb(c))
        .any(|thumb| contacts.iter().any(|other| facing(thumb, other, OPPOSING_DOT)))
}
