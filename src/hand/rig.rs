//! A parametric adult hand for scripted motion: palm pose plus per-finger
//! flexion gives a full [`HandPose`]. Scenes, the demo and benchmarks use it
//! where no tracker is attached.

use super::{Finger, HandPose, Palm, Side};
use glam::{Quat, Vec3};

/// Bone lengths and radii of a hand, in metres.
#[derive(Debug, Clone, PartialEq)]
pub struct HandRig {
    pub side: Side,
    /// Palm box half extents: half width, half thickness, half length.
    pub palm_half_extents: Vec3,
    /// Lengths of proximal, intermediate and distal phalanx per finger.
    pub lengths: [[f32; 3]; 5],
    /// Capsule radius per finger.
    pub radii: [f32; 5],
    /// Joint angles (rad) of a fully curled finger, per phalanx.
    pub full_curl: [f32; 3],
}

impl HandRig {
    /// An average adult hand (lengths after anthropometric means, rounded).
    pub fn adult(side: Side) -> HandRig {
        HandRig {
            side,
            palm_half_extents: Vec3::new(0.04, 0.01, 0.045),
            lengths: [
                [0.040, 0.032, 0.026],
                [0.040, 0.025, 0.020],
                [0.045, 0.028, 0.022],
                [0.042, 0.026, 0.021],
                [0.033, 0.020, 0.018],
            ],
            radii: [0.0095, 0.0085, 0.0085, 0.008, 0.007],
            full_curl: [70f32.to_radians(), 95f32.to_radians(), 65f32.to_radians()],
        }
    }

    /// Mirror factor for the local x axis: the thumb is at −x on a right hand.
    fn mirror(&self) -> f32 {
        match self.side {
            Side::Right => 1.0,
            Side::Left => -1.0,
        }
    }

    /// The base joint of a finger and its rest direction, in palm-local
    /// coordinates (see [`Palm`] for the frame).
    pub fn finger_base(&self, finger: Finger) -> (Vec3, Vec3) {
        let m = self.mirror();
        let h = self.palm_half_extents;
        match finger {
            Finger::Thumb => (
                Vec3::new(-m * h.x * 0.9, 0.0, -h.z * 0.2),
                Vec3::new(-m * 0.6, 0.0, 0.8).normalize(),
            ),
            f => {
                let slot = f as usize as f32 - 1.0; // 0..3 from index to pinky
                (Vec3::new(m * h.x * (-0.675 + 0.45 * slot), 0.0, h.z), Vec3::Z)
            }
        }
    }

    /// The hand with its palm at `palm_center`, oriented by `rotation`
    /// (local frame of [`Palm`]), and each finger curled by `curl[f] ∈ [0, 1]`
    /// (0 straight, 1 a fist). Fingers bend towards the palm normal.
    pub fn pose(&self, palm_center: Vec3, rotation: Quat, curl: [f32; 5]) -> HandPose {
        let palm = Palm { center: palm_center, rotation, half_extents: self.palm_half_extents };
        let joints = std::array::from_fn(|f| {
            let finger = Finger::ALL[f];
            let (base, dir) = self.finger_base(finger);
            let c = curl[f].clamp(0.0, 1.0);
            // The thumb bends across the palm; the others about local x.
            let axis = if finger == Finger::Thumb {
                dir.cross(Vec3::Y).normalize() * -1.0
            } else {
                -Vec3::X
            };
            let mut chain = [base; 4];
            let mut angle = 0.0;
            for p in 0..3 {
                angle += c * self.full_curl[p];
                let d = Quat::from_axis_angle(axis, angle) * dir;
                chain[p + 1] = chain[p] + self.lengths[f][p] * d;
            }
            chain.map(|q| palm.to_world(q))
        });
        HandPose::from_joints(palm, joints, self.radii)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_hand_is_valid_and_curl_moves_tips_towards_the_palm_side() {
        let rig = HandRig::adult(Side::Right);
        let flat = rig.pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        flat.validate(0).unwrap();
        let fist = rig.pose(Vec3::ZERO, Quat::IDENTITY, [1.0; 5]);
        fist.validate(0).unwrap();
        let tip = |p: &HandPose| p.fingers[1][2].b;
        // Flat index tip lies in front of the palm in its plane...
        assert!(tip(&flat).z > 0.1 && tip(&flat).y.abs() < 1e-6);
        // ...and curling moves it to the palm-normal side (+y).
        assert!(tip(&fist).y > 0.02);
        // The right thumb sits at local −x.
        assert!(flat.fingers[0][0].a.x < 0.0);
        let left = HandRig::adult(Side::Left).pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        assert!(left.fingers[0][0].a.x > 0.0);
    }
}
