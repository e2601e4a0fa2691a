//! The synthetic users' hand: a claw grip around a cube from above, which
//! opens by spreading its fingers (so its curl falls as a real hand's
//! does, which the heuristic baseline reads).

use crate::hand::{HandPose, Palm};
use glam::{Quat, Vec3};

/// A right hand gripping a cube of half size `h` (m) centred at the
/// origin, fingers along +x: the thumb's pad on the −x face, four finger
/// pads on the +x face (closer together on a cube under 5 cm), the palm
/// above. `closure` 1 sinks each pad
/// `squeeze` metres into its face; 0 leaves a 2 cm gap and spreads the
/// fingertips 3 cm further out.
pub fn grip(h: f32, closure: f32, squeeze: f32) -> HandPose {
    let closure = closure.clamp(0.0, 1.0);
    let open = 1.0 - closure;
    let offset = |r: f32| h + r - squeeze * closure + 0.02 * open;
    let half_extents = Vec3::new(0.045, 0.01, 0.04);
    let center = Vec3::new(0.0, h + 0.025, 0.0);
    let palm = Palm::from_normal_direction(center, -Vec3::Y, Vec3::X, half_extents)
        .unwrap_or(Palm { center, rotation: Quat::IDENTITY, half_extents });
    let radii = [0.0095, 0.0085, 0.0085, 0.008, 0.007];
    // Fingers 15 mm apart on a 5 cm cube, closer on smaller ones, so each
    // pad presses the face and none its edge.
    let finger_z = [0.0, -0.0225, -0.0075, 0.0075, 0.0225].map(|z| z * (h / 0.025).min(1.0));
    let joints = std::array::from_fn(|f| {
        let x = offset(radii[f]);
        let z = finger_z[f];
        // The thumb (f = 0) mirrors the fingers onto the −x face.
        let s = if f == 0 { -1.0 } else { 1.0 };
        [
            Vec3::new(s * 0.035, h + 0.02, z),
            Vec3::new(s * (x + 0.02), h + 0.008, z),
            Vec3::new(s * (x + 0.01 * open), h - 0.013, z),
            Vec3::new(s * (x + 0.03 * open), h - 0.035 + 0.01 * open, z),
        ]
    });
    HandPose::from_joints(palm, joints, radii)
}
