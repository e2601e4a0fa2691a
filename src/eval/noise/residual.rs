//! One frame's tracking noise, and how it moves a hand.

use super::{JOINTS, SMOOTHING, WINDOW};
use crate::hand::HandPose;
use glam::{FloatExt, Quat, Vec3};

/// The most times longer, or shorter, a scaled residual lays a bone than
/// the pose has it: a tracker's stretch scaled past that would reach
/// across the hand, or shrink a bone to nothing, which the world refuses.
pub const MAX_STRETCH: f32 = 2.0;

/// One frame's noise: each joint's offset from its smoothed track (m),
/// the palm's turn from its smoothed turn (a rotation vector, rad), both
/// in the smoothed palm's frame, and each finger bone's stretch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Residual {
    /// Per joint, in the order of [`JOINTS`].
    pub joints: [Vec3; JOINTS],
    /// The palm's turn.
    pub turn: Vec3,
    /// Per finger (thumb first) and capsule (proximal first), how much
    /// longer the tracker made the bone than its mean length over the
    /// smoothing's neighbouring frames, as the log of their ratio (at most
    /// 0.014 in a Leap's recordings here; 0 where a recorded bone has no
    /// length); `None` for a tracker whose joints are each off
    /// on their own (white jitter), whose bones change length as its
    /// joints' offsets make them ([`Self::apply`]).
    pub stretch: Option<[[f32; 3]; 5]>,
}

impl Default for Residual {
    /// No noise.
    fn default() -> Self {
        Residual::ZERO
    }
}

impl Residual {
    pub(super) const ZERO: Residual =
        Residual { joints: [Vec3::ZERO; JOINTS], turn: Vec3::ZERO, stretch: None };

    pub(super) fn lerp(&self, other: &Residual, w: f32) -> Residual {
        Residual {
            joints: std::array::from_fn(|j| self.joints[j].lerp(other.joints[j], w)),
            turn: self.turn.lerp(other.turn, w),
            stretch: match (self.stretch, other.stretch) {
                (Some(a), Some(b)) => {
                    Some(std::array::from_fn(|f| std::array::from_fn(|p| a[f][p].lerp(b[f][p], w))))
                }
                _ => None,
            },
        }
    }

    /// This noise, `scale` times as strong.
    pub fn scaled(&self, scale: f32) -> Residual {
        Residual {
            joints: self.joints.map(|j| j * scale),
            turn: self.turn * scale,
            stretch: self.stretch.map(|s| s.map(|f| f.map(|l| l * scale))),
        }
    }

    /// `pose` with this noise: the palm's centre moved by its residual
    /// turned into the pose's palm frame, the palm turned by its residual
    /// turn, and each finger laid from its first joint, moved by that
    /// joint's residual, capsule by capsule: each pointed along the chord
    /// its joints' residuals give it, and as much longer or shorter than
    /// the pose has it as the tracker made it ([`Self::stretch`]).
    ///
    /// A recorded tracker's residual turns a bone, and a Leap's (any
    /// skeleton fitted to the hand) keeps its length. Scaled as offsets of
    /// its joints, a turn's chord would stretch the bone: a fingertip thrown
    /// 13 mm across its 25 mm bone, scaled 3.7 times (a Leap's fist
    /// recording at 2 mm rms), would make it 54 mm long. Without a stretch
    /// (white jitter), each joint is moved by its residual, as a tracker of
    /// independent joints moves it. A stretch is laid at most
    /// [`MAX_STRETCH`] times longer or shorter.
    pub fn apply(&self, pose: &HandPose) -> HandPose {
        let frame = pose.palm.rotation;
        let shift = |j: usize| frame * self.joints[j];
        let mut out = pose.clone();
        out.palm.center += shift(0);
        out.palm.rotation = (frame * Quat::from_scaled_axis(self.turn)).normalize();
        for (f, finger) in out.fingers.iter_mut().enumerate() {
            let Some(stretch) = self.stretch else {
                for (p, capsule) in finger.iter_mut().enumerate() {
                    capsule.a += shift(joint(f, p));
                    capsule.b += shift(joint(f, p + 1));
                }
                continue;
            };
            let ln_max = MAX_STRETCH.ln();
            // How far the joint before the capsule was moved.
            let mut moved = shift(joint(f, 0));
            for (p, capsule) in finger.iter_mut().enumerate() {
                let vector = capsule.b - capsule.a;
                let turned = vector + shift(joint(f, p + 1)) - shift(joint(f, p));
                let ratio = stretch[f][p].clamp(-ln_max, ln_max).exp();
                // A chord of no direction leaves the capsule's own.
                let along = turned.try_normalize().unwrap_or(vector.normalize_or_zero());
                let laid = along * vector.length() * ratio;
                capsule.a += moved;
                let end = capsule.a + laid;
                moved = end - capsule.b;
                capsule.b = end;
            }
        }
        out
    }
}

/// Of [`JOINTS`], finger `f`'s joint `k` (0 its knuckle, 3 its tip);
/// 0 is the palm's centre.
fn joint(f: usize, k: usize) -> usize {
    1 + 4 * f + k
}

/// The joints of a pose, in the order of [`JOINTS`] (world, m).
pub(super) fn joints(pose: &HandPose) -> [Vec3; JOINTS] {
    let mut out = [pose.palm.center; JOINTS];
    for (f, finger) in pose.fingers.iter().enumerate() {
        out[joint(f, 0)] = finger[0].a;
        for p in 0..3 {
            out[joint(f, p + 1)] = finger[p].b;
        }
    }
    out
}

/// Frame `k`'s residual from the Gaussian-weighted mean of the frames
/// within 3σ of it, in that mean's palm frame; each bone's stretch from
/// the same weighted mean of its lengths.
pub(super) fn residual(
    times: &[f64],
    poses: &[&HandPose],
    points: &[[Vec3; JOINTS]],
    k: usize,
) -> Residual {
    let t = times[k];
    let (mut weight, mut mean, mut turn) =
        (0.0f32, [Vec3::ZERO; JOINTS], Quat::from_xyzw(0.0, 0.0, 0.0, 0.0));
    let mut lengths = [[0.0f32; 3]; 5];
    let here = poses[k].palm.rotation;
    let window =
        times.partition_point(|&s| s < t - WINDOW)..times.partition_point(|&s| s <= t + WINDOW);
    for m in window {
        let w = (-0.5 * ((times[m] - t) / SMOOTHING).powi(2)).exp() as f32;
        weight += w;
        for j in 0..JOINTS {
            mean[j] += w * points[m][j];
        }
        for (f, finger) in lengths.iter_mut().enumerate() {
            for (p, length) in finger.iter_mut().enumerate() {
                *length += w * bone_length(&points[m], f, p);
            }
        }
        let q = poses[m].palm.rotation;
        turn += q * (w * q.dot(here).signum());
    }
    let frame = turn.normalize().inverse();
    let joints = std::array::from_fn(|j| frame * (points[k][j] - mean[j] / weight));
    let stretch = std::array::from_fn(|f| {
        std::array::from_fn(|p| {
            let ratio = bone_length(&points[k], f, p) * weight / lengths[f][p];
            if ratio.is_normal() { ratio.ln() } else { 0.0 }
        })
    });
    Residual { joints, turn: (frame * here).to_scaled_axis(), stretch: Some(stretch) }
}

/// Finger `f`'s capsule `p`'s length in a pose's [`JOINTS`] (m).
fn bone_length(joints: &[Vec3; JOINTS], f: usize, p: usize) -> f32 {
    joints[joint(f, p)].distance(joints[joint(f, p + 1)])
}

#[cfg(test)]
mod tests {
    use super::super::residual_track;
    use super::*;

    /// A skeleton's glitch (a tracker that bends the index in a fist for
    /// 30 ms, as a Leap fits it: the bones keep their lengths), scaled 3.7
    /// times as the study scales a recording to 2 mm, turns the bones of
    /// another hand and keeps their lengths; moved as joint offsets, the
    /// same residual would stretch its distal bone by the turn's chord.
    #[test]
    fn a_skeletons_glitch_scaled_turns_bones_and_keeps_their_lengths() {
        use crate::hand::{Side, rig::HandRig};
        let rig = HandRig::adult(Side::Right);
        let times: Vec<f64> = (0..60).map(|k| k as f64 / 100.0).collect();
        let poses: Vec<HandPose> = times
            .iter()
            .map(|&t| {
                let index = if (0.25..0.28).contains(&t) { 1.0 } else { 0.2 };
                rig.pose(Vec3::new(0.1, 0.2, 0.0), Quat::IDENTITY, [0.3, index, 0.4, 0.4, 0.4])
            })
            .collect();
        let track = residual_track(&times, &poses.iter().collect::<Vec<_>>());
        let tip = joint(1, 3);
        let glitch = track
            .residuals
            .iter()
            .max_by(|a, b| a.joints[tip].length().total_cmp(&b.joints[tip].length()))
            .unwrap()
            .scaled(3.7);
        let pose = rig.pose(Vec3::new(-0.2, 0.3, 0.1), Quat::from_rotation_x(0.4), [0.5; 5]);
        let shaken = glitch.apply(&pose);
        let index = |p: &HandPose| p.fingers[1];
        let moved = index(&shaken)[2].b.distance(index(&pose)[2].b);
        assert!(moved > 0.02, "the fingertip moved {} mm", moved * 1e3);
        for (p, (was, now)) in index(&pose).iter().zip(index(&shaken)).enumerate() {
            let (was, now) = (was.a.distance(was.b), now.a.distance(now.b));
            assert!((now - was).abs() < 1e-5, "bone {p}: {} mm, was {}", now * 1e3, was * 1e3);
        }
        let frame = pose.palm.rotation;
        let distal = index(&pose)[2];
        // Pointed along the scaled residuals' chord.
        let chord = distal.b - distal.a + frame * (glitch.joints[tip] - glitch.joints[tip - 1]);
        let laid = index(&shaken)[2].b - index(&shaken)[2].a;
        assert!(laid.normalize().dot(chord.normalize()) > 0.999_99, "{laid} against {chord}");
        let offsets = (distal.b + frame * glitch.joints[tip])
            .distance(distal.a + frame * glitch.joints[tip - 1]);
        let length = distal.a.distance(distal.b);
        assert!(
            offsets > length + 0.005,
            "as offsets {} mm, {} mm long",
            offsets * 1e3,
            length * 1e3
        );
    }

    /// A tracker that changes a bone's length has that change scaled: 4 %
    /// longer than its smoothed track, scaled 3 times, is 12.5 % longer
    /// (1.04³), and at most twice as long; white jitter's joints are moved
    /// as they are.
    #[test]
    fn a_trackers_own_stretch_is_scaled_to_a_bound_and_white_joints_move_as_offsets() {
        use crate::hand::{Side, rig::HandRig};
        let pose = HandRig::adult(Side::Left).pose(Vec3::ZERO, Quat::IDENTITY, [0.2; 5]);
        let mut stretch = [[0.0f32; 3]; 5];
        stretch[3][1] = 1.04f32.ln();
        let longer = Residual { stretch: Some(stretch), ..Residual::ZERO }.scaled(3.0).apply(&pose);
        let length =
            |p: &HandPose, f: usize, b: usize| p.fingers[f][b].a.distance(p.fingers[f][b].b);
        let ratio = length(&longer, 3, 1) / length(&pose, 3, 1);
        assert!((ratio - 1.04f32.powi(3)).abs() < 1e-5, "{ratio}");
        assert!((length(&longer, 3, 2) - length(&pose, 3, 2)).abs() < 1e-7);
        // 1.5 times as long, scaled 4 times, would be 5 times: laid twice.
        stretch[3][1] = 1.5f32.ln();
        let most = Residual { stretch: Some(stretch), ..Residual::ZERO }.scaled(4.0).apply(&pose);
        let ratio = length(&most, 3, 1) / length(&pose, 3, 1);
        assert!((ratio - MAX_STRETCH).abs() < 1e-5, "{ratio}");
        stretch[3][1] = -(1.5f32.ln());
        let least = Residual { stretch: Some(stretch), ..Residual::ZERO }.scaled(4.0).apply(&pose);
        let ratio = length(&least, 3, 1) / length(&pose, 3, 1);
        assert!((ratio - 1.0 / MAX_STRETCH).abs() < 1e-5, "{ratio}");
        let mut joints = [Vec3::ZERO; JOINTS];
        joints[joint(2, 3)] = Vec3::new(0.0, 0.013, 0.0);
        let white = Residual { joints, ..Residual::ZERO }.scaled(3.7).apply(&pose);
        let tip = pose.fingers[2][2].b + pose.palm.rotation * Vec3::new(0.0, 0.0481, 0.0);
        assert!(white.fingers[2][2].b.distance(tip) < 1e-6);
    }

    /// A tracker that draws one frame's index fingertip 20 % further from
    /// its last joint (a landmark tracker's misfit) gives that bone a
    /// stretch, and no other bone any.
    #[test]
    fn a_trackers_stretched_bone_is_measured_as_its_stretch() {
        use crate::hand::{Side, rig::HandRig};
        let rig = HandRig::adult(Side::Right);
        let times: Vec<f64> = (0..60).map(|k| k as f64 / 100.0).collect();
        let mut poses: Vec<HandPose> =
            times.iter().map(|_| rig.pose(Vec3::ZERO, Quat::IDENTITY, [0.3; 5])).collect();
        let distal = &mut poses[30].fingers[1][2];
        distal.b = distal.a + (distal.b - distal.a) * 1.2;
        let points: Vec<[Vec3; JOINTS]> = poses.iter().map(joints).collect();
        let stretch =
            residual(&times, &poses.iter().collect::<Vec<_>>(), &points, 30).stretch.unwrap();
        // Against the weighted mean of its lengths, which the frame itself
        // lengthens a little: ln 1.2 less that.
        assert!(stretch[1][2] > 0.1 && stretch[1][2] < 1.2f32.ln(), "{}", stretch[1][2]);
        let others = stretch.iter().flatten().filter(|s| s.abs() > 1e-6).count();
        assert_eq!(others, 1, "{stretch:?}");
    }
}
