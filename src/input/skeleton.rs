//! Builds the 16-bone [`HandPose`] (§3.5.1) from a tracked hand.

use super::TrackedHand;
use super::convert::Conversion;
use crate::hand::{HandPose, Palm};
use glam::Vec3;

/// Why a tracked hand could not become a pose.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("hand {hand}: {reason}")]
pub struct SkeletonError {
    /// The tracker's id of the hand ([`TrackedHand::id`]).
    pub hand: i64,
    /// What is wrong with it.
    pub reason: String,
}

/// The hand pose in world coordinates.
///
/// * Capsule radius = half the tracked finger width.
/// * The distal capsule is shortened by its radius, so its rounded end
///   reaches the tracked fingertip instead of overshooting it.
/// * The palm box spans the knuckles: half width from the index–pinky
///   knuckle spread plus half a finger, half thickness half a finger width.
///   Lengthwise it runs from the knuckles back to the wrist ends of the
///   metacarpals when the tracker gives them ([`TrackedHand::carps`]), else
///   as far behind the palm centre as the knuckles are ahead of it. Its
///   grasping face lies in the plane of the tracked palm position.
pub fn hand_pose(hand: &TrackedHand, conversion: &Conversion) -> Result<HandPose, SkeletonError> {
    let fail = |reason: String| SkeletonError { hand: hand.id, reason };
    let joints: [[Vec3; 4]; 5] = hand.joints.map(|finger| finger.map(|j| conversion.point(j)));
    let radii: [f32; 5] = hand.widths.map(|w| 0.5 * conversion.length(w));
    let normal = conversion.direction(hand.palm_normal);
    let direction = conversion.direction(hand.direction);
    let palm_position = conversion.point(hand.palm_position);

    let knuckles = [1, 2, 3, 4].map(|f| joints[f][0]);
    let mean_radius = radii.iter().sum::<f32>() / 5.0;
    let knuckle_centre = knuckles.iter().copied().sum::<Vec3>() / 4.0;
    let half_width = 0.5 * (knuckles[0] - knuckles[3]).length() + mean_radius;
    // Lengthwise extent along `direction`, relative to the palm position.
    let front = (knuckle_centre - palm_position).dot(direction);
    let back = match hand.carps {
        Some(carps) => {
            let carp_centre = carps.iter().map(|&c| conversion.point(c)).sum::<Vec3>() / 4.0;
            (carp_centre - palm_position).dot(direction)
        }
        None => -front,
    };
    let half_length = (0.5 * (front - back)).max(mean_radius);
    let half_thickness = mean_radius;
    let palm = Palm::from_normal_direction(
        palm_position + direction * (0.5 * (front + back)) - normal * half_thickness,
        normal,
        direction,
        Vec3::new(half_width, half_thickness, half_length),
    )
    .ok_or_else(|| fail("palm normal and direction are parallel or zero".into()))?;

    let mut pose = HandPose::from_joints(palm, joints, radii);
    for (f, finger) in pose.fingers.iter_mut().enumerate() {
        let distal = &mut finger[2];
        let axis = distal.b - distal.a;
        let len = axis.length();
        if len > 2.0 * distal.radius {
            distal.b -= axis / len * distal.radius;
        } else if len > 0.0 {
            distal.b = distal.a + axis * 0.5;
        }
        if !radii[f].is_finite() {
            return Err(fail(format!("finger {f} width is not finite")));
        }
    }
    Ok(pose)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hand::Side;

    fn flat_hand() -> TrackedHand {
        let x = |f: usize| 20.0 * f as f32 - 40.0;
        TrackedHand {
            id: 1,
            side: Side::Right,
            palm_position: Vec3::new(0.0, 200.0, 0.0),
            palm_normal: -Vec3::Y,
            direction: -Vec3::Z,
            joints: std::array::from_fn(|f| {
                [-40.0, -80.0, -105.0, -125.0].map(|z| Vec3::new(x(f), 200.0, z))
            }),
            carps: None,
            widths: [18.0; 5],
            grab: None,
            pinch: None,
            confidence: None,
        }
    }

    #[test]
    fn builds_a_valid_pose_in_metres() {
        let pose = hand_pose(&flat_hand(), &Conversion::mm_to_m()).unwrap();
        pose.validate(0).unwrap();
        assert!((pose.fingers[1][0].radius - 0.009).abs() < 1e-6);
        // Distal shortened by its radius: its far end is 9 mm short of the tip.
        assert!((pose.fingers[1][2].b - Vec3::new(-0.02, 0.2, -0.116)).length() < 1e-5);
        // The palm's grasping face (−y here) is at the tracked palm position.
        let face = pose.palm.to_world(Vec3::new(0.0, pose.palm.half_extents.y, 0.0));
        assert!((face - Vec3::new(0.0, 0.2, 0.0)).length() < 1e-5);
        assert!((pose.palm.normal() + Vec3::Y).length() < 1e-5);
    }

    #[test]
    fn tracked_metacarpal_bases_set_the_palm_length() {
        // Knuckles 40 mm ahead of the palm centre (−z), carps 30 mm behind:
        // a 70 mm palm centred 5 mm ahead, instead of the 80 mm mirror.
        let mut h = flat_hand();
        let pose = hand_pose(&h, &Conversion::mm_to_m()).unwrap();
        assert!((pose.palm.half_extents.z - 0.040).abs() < 1e-6);
        h.carps = Some(std::array::from_fn(|f| Vec3::new(20.0 * f as f32 - 20.0, 200.0, 30.0)));
        let pose = hand_pose(&h, &Conversion::mm_to_m()).unwrap();
        assert!((pose.palm.half_extents.z - 0.035).abs() < 1e-6, "{:?}", pose.palm.half_extents);
        let face = pose.palm.to_world(Vec3::new(0.0, pose.palm.half_extents.y, 0.0));
        assert!((face - Vec3::new(0.0, 0.2, -0.005)).length() < 1e-5, "{face:?}");
    }

    #[test]
    fn parallel_palm_axes_are_an_error() {
        let mut h = flat_hand();
        h.direction = h.palm_normal;
        assert!(hand_pose(&h, &Conversion::mm_to_m()).is_err());
    }
}
