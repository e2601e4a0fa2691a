//! The synthetic users' hand: the demo's claw grip around a cube from
//! above, opening by spreading its fingers, so its curl falls as a real
//! hand's does (the heuristic baseline reads it).

use crate::hand::HandPose;
use crate::run::demo::claw;

/// A right hand gripping a cube of half size `h` (m) centred at the
/// origin, fingers along +x ([`claw`]): `closure` 1 sinks each pad
/// `squeeze` metres into its face; 0 leaves a 2 cm gap and spreads the
/// fingertips 3 cm further out.
pub fn grip(h: f32, closure: f32, squeeze: f32) -> HandPose {
    claw(h, closure, squeeze, 1.0)
}
