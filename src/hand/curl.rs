//! How far a hand is curled, from its bones alone: the closing signal of a
//! hand whose tracker reports no grab strength.

use super::rig::FIST_FLEXION_DEG;
use super::{Capsule, HandPose, Palm};
use glam::Vec3;

/// One finger's flexion (rad): at the knuckle, the angle from the palm's
/// forward direction to the first phalanx, towards the palm's normal
/// (negative when bent back), plus the angles between consecutive
/// phalanges. Summed joint by joint, it keeps growing past 180° as a fist
/// folds the fingertip back towards the wrist. A phalanx too short to have a
/// direction adds nothing.
fn flexion(palm: &Palm, bones: &[Capsule; 3]) -> f32 {
    let (forward, normal) = (palm.rotation * Vec3::Z, palm.normal());
    let [d0, d1, d2] = bones.map(|c| (c.b - c.a).try_normalize());
    let knuckle = d0.map_or(0.0, |d| d.dot(normal).atan2(d.dot(forward)));
    let joint = |a: Option<Vec3>, b: Option<Vec3>| match (a, b) {
        (Some(a), Some(b)) => a.dot(b).clamp(-1.0, 1.0).acos(),
        _ => 0.0,
    };
    knuckle + joint(d0, d1) + joint(d1, d2)
}

impl HandPose {
    /// The mean flexion of index … little finger, as a fraction of a fist's
    /// ([`FIST_FLEXION_DEG`]): 0 for a flat hand, 1 for a fist, a little
    /// more for a tight one. The thumb is left out, as in trackers' grab
    /// strength: it opposes in a pinch and in a fist alike.
    pub fn curl(&self) -> f32 {
        let fist: f32 = FIST_FLEXION_DEG.iter().sum::<f32>().to_radians();
        let sum: f32 = self.fingers[1..].iter().map(|f| flexion(&self.palm, f)).sum();
        sum / (4.0 * fist)
    }
}

#[cfg(test)]
mod tests {
    use crate::hand::Side;
    use crate::hand::rig::{Articulation, HandRig};
    use glam::{Quat, Vec3};

    #[test]
    fn the_rigs_curl_reads_back_whatever_the_hands_size_and_turn() {
        let turned = Quat::from_euler(glam::EulerRot::XYZ, 0.7, -1.9, 0.4);
        for (k, rotation) in [(1.0, Quat::IDENTITY), (0.8, turned), (1.15, turned)] {
            let rig = HandRig::adult(Side::Left).scaled(k);
            for c in [0.0, 0.23, 0.61, 1.0] {
                let pose = rig.pose(Vec3::new(0.1, 0.3, -0.2), rotation, [0.4, c, c, c, c]);
                assert!((pose.curl() - c).abs() < 1e-4, "curl {c}: read {}", pose.curl());
            }
        }
    }

    #[test]
    fn each_joint_counts_by_its_angle_and_the_thumb_not_at_all() {
        let rig = HandRig::adult(Side::Right);
        let pose = |flex| {
            let joints = Articulation { flex, ..Articulation::default() };
            rig.pose_articulated(Vec3::ZERO, Quat::IDENTITY, &joints).curl()
        };
        let mut flex = [[0.0; 3]; 5];
        flex[0] = [1.0; 3];
        assert!(pose(flex).abs() < 1e-4, "the thumb alone: {}", pose(flex));
        // The middle finger bent at its knuckle only, halfway: 35° of the
        // four fingers' 920°.
        flex[2][0] = 0.5;
        assert!((pose(flex) - 35.0 / 920.0).abs() < 1e-4, "{}", pose(flex));
        // And its end joint fully: 65° more.
        flex[2][2] = 1.0;
        assert!((pose(flex) - 100.0 / 920.0).abs() < 1e-4, "{}", pose(flex));
    }
}
