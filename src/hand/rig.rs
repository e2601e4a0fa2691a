//! A parametric adult hand for scripted motion: palm pose plus per-finger
//! flexion gives a full [`HandPose`]. Scenes, the demo and benchmarks use it
//! where no tracker is attached.

use super::{Finger, HandPose, Palm, Side};
use glam::{Quat, Vec3};

/// A finger's flexion in a fist (°) at its knuckle, middle and end joint:
/// within each joint's active range (about 90°, 100–110° and 80–90°,
/// American Academy of Orthopaedic Surgeons 1965), short of it as a relaxed
/// fist is. [`HandPose::curl`] calls this flexion 1.
pub const FIST_FLEXION_DEG: [f32; 3] = [70.0, 95.0, 65.0];

/// Bone lengths and radii of a hand, in metres.
#[derive(Debug, Clone, PartialEq)]
pub struct HandRig {
    /// Which hand.
    pub side: Side,
    /// Palm box half extents: half width, half thickness, half length.
    pub palm_half_extents: Vec3,
    /// Lengths of proximal, intermediate and distal phalanx per finger.
    pub lengths: [[f32; 3]; 5],
    /// Capsule radius per finger.
    pub radii: [f32; 5],
    /// Joint angles (rad) of a fully curled finger, per phalanx.
    pub full_curl: [f32; 3],
    /// The same for the thumb (metacarpal, proximal, distal), which flexes
    /// less.
    pub thumb_full_curl: [f32; 3],
}

/// How a [`HandRig`]'s joints are set, beyond the palm pose.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Articulation {
    /// Flexion of each finger (thumb first) at its base, middle and end
    /// joint, each in [0, 1] of that joint's full flexion
    /// ([`HandRig::full_curl`], the thumb's [`HandRig::thumb_full_curl`]).
    /// Equal thirds curl a finger as one; the base (knuckle) joint alone
    /// gives a straight finger bent at the knuckle, and knuckle and finger
    /// joints together draw the fingertip along a line, e.g. stroking a
    /// surface it presses on.
    pub flex: [[f32; 3]; 5],
    /// Thumb opposition in [0, 1] ([`HandRig::thumb_direction`]).
    pub opposition: f32,
    /// Abduction of index … pinky in the palm plane about their knuckles
    /// (degrees, positive towards the thumb).
    pub spread_deg: [f32; 4],
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
            full_curl: FIST_FLEXION_DEG.map(f32::to_radians),
            thumb_full_curl: [40f32.to_radians(), 50f32.to_radians(), 70f32.to_radians()],
        }
    }

    /// The same hand scaled by `k` (lengths, radii and palm): hands come in
    /// many sizes, e.g. 0.8 for slim fingers that fit a 15 mm slot.
    pub fn scaled(mut self, k: f32) -> HandRig {
        self.palm_half_extents *= k;
        self.lengths = self.lengths.map(|f| f.map(|l| l * k));
        self.radii = self.radii.map(|r| r * k);
        self
    }

    /// Mirror factor for the local x axis: the thumb is at −x on a right hand.
    fn mirror(&self) -> f32 {
        match self.side {
            Side::Right => 1.0,
            Side::Left => -1.0,
        }
    }

    /// The base joint of a finger and its rest direction, in palm-local
    /// coordinates (see [`Palm`] for the frame). The thumb's direction is
    /// that of an abducted thumb, in the palm plane; see [`Self::thumb_direction`].
    pub fn finger_base(&self, finger: Finger) -> (Vec3, Vec3) {
        let m = self.mirror();
        let h = self.palm_half_extents;
        match finger {
            Finger::Thumb => {
                (Vec3::new(-m * h.x * 0.9, 0.0, -h.z * 0.6), self.thumb_direction(0.0))
            }
            f => {
                let slot = f as usize as f32 - 1.0; // 0..3 from index to pinky
                (Vec3::new(m * h.x * (-0.675 + 0.45 * slot), 0.0, h.z), Vec3::Z)
            }
        }
    }

    /// The thumb's rest direction (palm-local) for `opposition ∈ [0, 1]`:
    /// 0 abducted in the palm plane, pointing out and forward; 1 swung in
    /// front of the palm (towards the palm normal and across it), so that
    /// flexing brings its tip to the fingertips, as in a pinch.
    pub fn thumb_direction(&self, opposition: f32) -> Vec3 {
        let m = self.mirror();
        let abducted = Vec3::new(-m * 0.6, 0.0, 0.8);
        let opposed = Vec3::new(m * -0.25, 0.35, 0.9).normalize();
        abducted.lerp(opposed, opposition.clamp(0.0, 1.0)).normalize()
    }

    /// The hand with its palm at `palm_center`, oriented by `rotation`
    /// (local frame of [`Palm`]), and each finger curled by `curl[f] ∈ [0, 1]`
    /// (0 straight, 1 a fist). Fingers bend towards the palm normal; the
    /// thumb is abducted (see [`Self::pose_opposed`]).
    pub fn pose(&self, palm_center: Vec3, rotation: Quat, curl: [f32; 5]) -> HandPose {
        self.pose_opposed(palm_center, rotation, curl, 0.0)
    }

    /// As [`Self::pose`], with the thumb swung by `opposition ∈ [0, 1]`
    /// ([`Self::thumb_direction`]). The abducted thumb flexes towards the
    /// palm normal; the opposed one across the palm, towards the fingers.
    pub fn pose_opposed(
        &self,
        palm_center: Vec3,
        rotation: Quat,
        curl: [f32; 5],
        opposition: f32,
    ) -> HandPose {
        let joints = Articulation { flex: curl.map(|c| [c; 3]), opposition, spread_deg: [0.0; 4] };
        self.pose_articulated(palm_center, rotation, &joints)
    }

    /// The general pose: the palm at `palm_center` turned by `rotation`, and
    /// every joint set by `joints` ([`Articulation`]).
    pub fn pose_articulated(
        &self,
        palm_center: Vec3,
        rotation: Quat,
        joints: &Articulation,
    ) -> HandPose {
        let Articulation { flex, opposition, spread_deg } = *joints;
        let palm = Palm { center: palm_center, rotation, half_extents: self.palm_half_extents };
        let m = self.mirror();
        let joints = std::array::from_fn(|f| {
            let finger = Finger::ALL[f];
            let (base, mut dir) = self.finger_base(finger);
            if f > 0 {
                // Towards the thumb is −x on a right hand: a rotation about
                // the palm normal (+y) by −m·angle.
                dir = Quat::from_rotation_y(-m * spread_deg[f - 1].to_radians()) * dir;
            }
            // Each finger bends its direction towards `towards`.
            let towards = if finger == Finger::Thumb {
                dir = self.thumb_direction(opposition);
                Vec3::Y.lerp((Vec3::X * m + Vec3::Y).normalize(), opposition.clamp(0.0, 1.0))
            } else {
                Vec3::Y
            };
            let axis = dir.cross(towards).normalize_or(Vec3::X * -1.0);
            let mut chain = [base; 4];
            let mut angle = 0.0;
            let full = if finger == Finger::Thumb { self.thumb_full_curl } else { self.full_curl };
            for p in 0..3 {
                angle += flex[f][p].clamp(0.0, 1.0) * full[p];
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
        // The right thumb sits at local −x, and flexes to the palm side too.
        assert!(flat.fingers[0][0].a.x < 0.0);
        assert!(fist.fingers[0][2].b.y > 0.02, "thumb tip {:?}", fist.fingers[0][2].b);
        // Opposed and a little flexed, the thumb tip meets the curled
        // index tip (their radii add to 18 mm) in front of the palm.
        let pinch = rig.pose_opposed(Vec3::ZERO, Quat::IDENTITY, [0.3, 0.6, 0.6, 0.6, 0.6], 1.0);
        pinch.validate(0).unwrap();
        let gap = pinch.fingers[0][2].b.distance(pinch.fingers[1][2].b);
        // Spread swings the index towards the thumb in the palm plane.
        let joints = Articulation { spread_deg: [20.0, 0.0, 0.0, 0.0], ..Articulation::default() };
        let spread = rig.pose_articulated(Vec3::ZERO, Quat::IDENTITY, &joints);
        spread.validate(0).unwrap();
        let (tip, straight) = (spread.fingers[1][2].b, flat.fingers[1][2].b);
        assert!(
            tip.x < straight.x - 0.02 && tip.y.abs() < 1e-6,
            "index tip {tip:?} vs {straight:?}"
        );
        assert!(
            gap < 0.022 && pinch.fingers[0][2].b.y > 0.03,
            "thumb–index gap {gap}, thumb tip {:?}",
            pinch.fingers[0][2].b
        );
        let left = HandRig::adult(Side::Left).pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        assert!(left.fingers[0][0].a.x > 0.0);
    }

    #[test]
    fn knuckle_flexion_bends_a_straight_finger_and_joint_pairs_move_the_tip_along_a_line() {
        let rig = HandRig::adult(Side::Right);
        let mut joints = Articulation::default();
        // The index bent 0.5 at the knuckle only: its phalanges stay in line,
        // pointing 35° (half of 70°) towards the palm normal.
        joints.flex[1] = [0.5, 0.0, 0.0];
        let pose = rig.pose_articulated(Vec3::ZERO, Quat::IDENTITY, &joints);
        pose.validate(0).unwrap();
        let index = pose.fingers[1];
        let dir = (index[2].b - index[0].a).normalize();
        let want = Vec3::new(0.0, 35f32.to_radians().sin(), 35f32.to_radians().cos());
        assert!(dir.distance(want) < 1e-5, "{dir:?}");
        assert!(
            (index[2].b.distance(index[0].a) - 0.085).abs() < 1e-5,
            "a straight finger spans its bone lengths"
        );
        // Knuckle flexion with the finger joints opening keeps the middle
        // fingertip in the plane z ≈ const while it moves 2 cm along y: a
        // stroke across a surface facing the fingers.
        let tip = |k: f32, c: f32| {
            let mut j = Articulation::default();
            j.flex[2] = [k, c, c];
            rig.pose_articulated(Vec3::ZERO, Quat::IDENTITY, &j).fingers[2][2].b
        };
        let (a, b) = (tip(0.22, 0.56), tip(0.6, 0.25));
        assert!(b.y - a.y > 0.015 && (b.z - a.z).abs() < 0.004, "{a:?} → {b:?}");
        // Equal thirds are the plain curl.
        joints.flex = [[0.4; 3]; 5];
        assert_eq!(
            rig.pose_articulated(Vec3::ZERO, Quat::IDENTITY, &joints),
            rig.pose(Vec3::ZERO, Quat::IDENTITY, [0.4; 5])
        );
    }
}
