//! The skeletal hand model of thesis §3.5.1: a palm box plus three capsules
//! per finger (thumb included), 16 bones per hand.
//!
//! A [`HandPose`] is one tracking sample of every bone, in world metres.
//! Bones are never bodies in the physics engine: they only ever act on
//! objects through the friction contact forces of [`crate::friction`].
//!
//! * [`acting`]: the hand that acts, the tracked hand with the tracker's
//!   jitter taken out ([`one_euro`], the 1€ filter; [`jitter`], the
//!   tracker's jitter measured on the hand);
//! * [`rig`]: a parametric hand for scripts.

use glam::{Quat, Vec3};

pub mod acting;
mod curl;
pub mod jitter;
pub mod one_euro;
pub mod rig;

/// Handle of a hand in an [`crate::InteractionWorld`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
pub struct HandId(pub u32);

impl std::fmt::Display for HandId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "hand {}", self.0)
    }
}

/// Which hand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// The left hand.
    Left,
    /// The right hand.
    Right,
}

/// `left` or `right`, as files and the bindings spell a side.
impl std::str::FromStr for Side {
    type Err = UnknownSide;
    fn from_str(s: &str) -> Result<Side, UnknownSide> {
        match s {
            "left" => Ok(Side::Left),
            "right" => Ok(Side::Right),
            _ => Err(UnknownSide(s.to_string())),
        }
    }
}

/// A side that is neither `left` nor `right`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("expected \"left\" or \"right\", got {0:?}")]
pub struct UnknownSide(pub String);

/// A digit, thumb first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Finger {
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

impl Finger {
    /// All five digits, thumb first.
    pub const ALL: [Finger; 5] =
        [Finger::Thumb, Finger::Index, Finger::Middle, Finger::Ring, Finger::Pinky];
}

/// A phalanx, from the palm outwards.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Phalanx {
    /// The phalanx next to the palm (the thumb's metacarpal).
    Proximal,
    /// The middle phalanx (the thumb's proximal phalanx).
    Intermediate,
    /// The fingertip phalanx.
    Distal,
}

impl Phalanx {
    /// All three phalanges, from the palm outwards.
    pub const ALL: [Phalanx; 3] = [Phalanx::Proximal, Phalanx::Intermediate, Phalanx::Distal];
}

/// One of the 16 bones of a hand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Bone {
    /// The palm box.
    Palm,
    /// One phalanx capsule of one finger.
    Finger(Finger, Phalanx),
}

/// Number of bones in a hand.
pub const BONES_PER_HAND: usize = 16;

impl Bone {
    /// All bones, palm first, then each finger from proximal to distal.
    pub fn all() -> impl Iterator<Item = Bone> {
        (0..BONES_PER_HAND).map(Bone::from_index)
    }

    /// A dense index in `0..16`: 0 is the palm, then `1 + 3·finger + phalanx`.
    pub fn index(self) -> usize {
        match self {
            Bone::Palm => 0,
            Bone::Finger(f, p) => 1 + 3 * f as usize + p as usize,
        }
    }

    /// The inverse of [`Bone::index`]; indices ≥ 16 wrap.
    pub fn from_index(i: usize) -> Bone {
        let i = i % BONES_PER_HAND;
        if i == 0 {
            Bone::Palm
        } else {
            Bone::Finger(Finger::ALL[(i - 1) / 3], Phalanx::ALL[(i - 1) % 3])
        }
    }

    /// Thumb and palm contacts spread over a wider skin patch (§3.5.4).
    pub fn skin_class(self) -> SkinClass {
        match self {
            Bone::Palm => SkinClass::Palm,
            Bone::Finger(Finger::Thumb, _) => SkinClass::Thumb,
            Bone::Finger(..) => SkinClass::Finger,
        }
    }
}

impl std::fmt::Display for Bone {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Bone::Palm => write!(f, "palm"),
            Bone::Finger(finger, phalanx) => {
                write!(
                    f,
                    "{}-{}",
                    format!("{finger:?}").to_lowercase(),
                    format!("{phalanx:?}").to_lowercase()
                )
            }
        }
    }
}

/// Which skin patch size a bone uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SkinClass {
    /// A phalanx of index … pinky.
    Finger,
    /// A phalanx of the thumb.
    Thumb,
    /// The palm.
    Palm,
}

/// A phalanx: a capsule around the segment `a → b` (world metres).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Capsule {
    /// The joint nearer the palm.
    pub a: Vec3,
    /// The joint nearer the fingertip.
    pub b: Vec3,
    /// Radius (m), half the tracked finger width.
    pub radius: f32,
}

impl Capsule {
    /// The point at axial parameter `s ∈ [0, 1]`.
    pub fn axis_point(&self, s: f32) -> Vec3 {
        self.a + s * (self.b - self.a)
    }

    /// The axial parameter of the axis point closest to `q`.
    pub fn closest_parameter(&self, q: Vec3) -> f32 {
        let ab = self.b - self.a;
        let len2 = ab.length_squared();
        if len2 <= 0.0 {
            return 0.5;
        }
        ((q - self.a).dot(ab) / len2).clamp(0.0, 1.0)
    }

    /// The phalanx centroid (the thesis's `p_j`).
    pub fn centroid(&self) -> Vec3 {
        0.5 * (self.a + self.b)
    }
}

/// The palm: an oriented box (world metres).
///
/// Its local frame: +y is the palm normal (out of the palm, the grasping
/// side), +z points from the wrist towards the fingers, x = y × z.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Palm {
    /// Centre of the box.
    pub center: Vec3,
    /// Orientation of the local frame (unit quaternion).
    pub rotation: Quat,
    /// Half width (x), half thickness (y) and half length (z), in m.
    pub half_extents: Vec3,
}

impl Palm {
    /// A palm from the tracker's palm normal and finger direction.
    /// Returns `None` if the two are parallel or not finite.
    pub fn from_normal_direction(
        center: Vec3,
        normal: Vec3,
        direction: Vec3,
        half_extents: Vec3,
    ) -> Option<Palm> {
        let y = normal.try_normalize()?;
        let z = (direction - direction.dot(y) * y).try_normalize()?;
        let x = y.cross(z);
        let rotation = Quat::from_mat3(&glam::Mat3::from_cols(x, y, z)).normalize();
        Some(Palm { center, rotation, half_extents })
    }

    /// The palm normal (world).
    pub fn normal(&self) -> Vec3 {
        self.rotation * Vec3::Y
    }

    /// Local point to world.
    pub fn to_world(&self, local: Vec3) -> Vec3 {
        self.center + self.rotation * local
    }

    /// World point to local.
    pub fn to_local(&self, world: Vec3) -> Vec3 {
        self.rotation.inverse() * (world - self.center)
    }
}

/// The shape of one bone at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BoneShape {
    /// The palm's box.
    Palm(Palm),
    /// A phalanx's capsule.
    Capsule(Capsule),
}

/// One tracking sample of a whole hand, in world metres.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct HandPose {
    /// The palm box.
    pub palm: Palm,
    /// `fingers[finger][phalanx]`, thumb first, proximal first.
    pub fingers: [[Capsule; 3]; 5],
}

/// A hand's state at one instant: its pose and the tracker's own grab and
/// pinch strengths (0 to 1), when it reports them.
#[derive(Debug, Clone, PartialEq)]
pub struct HandSample {
    /// The 16 bones (world, m).
    pub pose: HandPose,
    /// The tracker's grab strength, if any.
    pub grab: Option<f32>,
    /// The tracker's pinch strength, if any.
    pub pinch: Option<f32>,
    /// The tracker's confidence in the pose, in [0, 1], if it reports one.
    pub confidence: Option<f32>,
}

impl HandSample {
    /// A pose without tracker strengths (a scripted or synthetic hand).
    pub fn from_pose(pose: HandPose) -> HandSample {
        HandSample { pose, grab: None, pinch: None, confidence: None }
    }

    /// The sample `w` of the way from `self` to `other` (0 to 1): the pose
    /// by [`HandPose::lerp`], each strength and the confidence linearly
    /// where both have it, else the one that has it.
    pub fn lerp(&self, other: &HandSample, w: f32) -> HandSample {
        let mix = |a: Option<f32>, b: Option<f32>| match (a, b) {
            (Some(a), Some(b)) => Some(a + (b - a) * w),
            (a, b) => a.or(b),
        };
        HandSample {
            pose: self.pose.lerp(&other.pose, w),
            grab: mix(self.grab, other.grab),
            pinch: mix(self.pinch, other.pinch),
            confidence: mix(self.confidence, other.confidence),
        }
    }
}

/// Positions beyond this distance from the origin (m) are rejected as
/// absurd tracking data rather than handed to the physics engine.
pub const MAX_COORDINATE: f32 = 1.0e4;

/// Why a hand pose was rejected. Each names the hand and the bone.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PoseError {
    /// A number of the bone is NaN or infinite.
    #[error("hand {hand}: bone {bone}: {field} is not finite")]
    NonFinite {
        /// The hand ([`HandId`] number).
        hand: u32,
        /// The bone.
        bone: Bone,
        /// The bone's field, e.g. `center`, `a` or `radius`.
        field: &'static str,
    },
    /// A point of the bone lies beyond [`MAX_COORDINATE`].
    #[error(
        "hand {hand}: bone {bone}: {field} is {value} m from the origin (limit {MAX_COORDINATE} m)"
    )]
    OutOfRange {
        /// The hand ([`HandId`] number).
        hand: u32,
        /// The bone.
        bone: Bone,
        /// The point's field: `center`, `a` or `b`.
        field: &'static str,
        /// The point's largest absolute coordinate (m).
        value: f32,
    },
    /// A capsule radius is zero or negative, or larger than
    /// [`MAX_COORDINATE`].
    #[error(
        "hand {hand}: bone {bone}: radius {radius} m must be positive and at most \
         {MAX_COORDINATE} m"
    )]
    BadRadius {
        /// The hand ([`HandId`] number).
        hand: u32,
        /// The bone.
        bone: Bone,
        /// The capsule radius (m).
        radius: f32,
    },
    /// A capsule shorter than [`MIN_BONE_LENGTH`].
    #[error("hand {hand}: bone {bone}: zero-length bone (joints coincide at {at:?})")]
    ZeroLength {
        /// The hand ([`HandId`] number).
        hand: u32,
        /// The bone.
        bone: Bone,
        /// Where its joints coincide: the joint nearer the palm (world, m).
        at: Vec3,
    },
    /// A palm half extent is zero or negative, or larger than
    /// [`MAX_COORDINATE`].
    #[error(
        "hand {hand}: bone palm: half extents {half_extents:?} must all be positive and at most \
         {MAX_COORDINATE} m"
    )]
    BadPalmExtents {
        /// The hand ([`HandId`] number).
        hand: u32,
        /// The palm's half extents (m).
        half_extents: Vec3,
    },
    /// The palm rotation is not a unit quaternion.
    #[error("hand {hand}: bone palm: rotation {rotation:?} is not a unit quaternion")]
    BadPalmRotation {
        /// The hand ([`HandId`] number).
        hand: u32,
        /// The palm rotation.
        rotation: Quat,
    },
}

/// Shorter bones than this (m) are treated as zero-length.
pub const MIN_BONE_LENGTH: f32 = 1.0e-5;

impl HandPose {
    /// Builds a pose from joint chains: `joints[finger]` holds the four
    /// joints base → tip of that finger, `radii[finger]` its capsule radius.
    pub fn from_joints(palm: Palm, joints: [[Vec3; 4]; 5], radii: [f32; 5]) -> HandPose {
        let fingers = std::array::from_fn(|f| {
            std::array::from_fn(|p| Capsule {
                a: joints[f][p],
                b: joints[f][p + 1],
                radius: radii[f],
            })
        });
        HandPose { palm, fingers }
    }

    /// The shape of one bone.
    #[inline]
    pub fn bone(&self, bone: Bone) -> BoneShape {
        match bone {
            Bone::Palm => BoneShape::Palm(self.palm),
            Bone::Finger(f, p) => BoneShape::Capsule(self.fingers[f as usize][p as usize]),
        }
    }

    /// The centre of the palm's grasping face (world, m): where trackers put
    /// the palm position.
    pub fn palm_surface(&self) -> Vec3 {
        self.palm.to_world(Vec3::Y * self.palm.half_extents.y)
    }

    /// The pose `t` of the way from `self` to `other` (0 to 1), joint by
    /// joint; the palm rotation by normalised spherical interpolation.
    pub fn lerp(&self, other: &HandPose, t: f32) -> HandPose {
        let mut out = self.clone();
        out.palm.center = self.palm.center.lerp(other.palm.center, t);
        out.palm.half_extents = self.palm.half_extents.lerp(other.palm.half_extents, t);
        out.palm.rotation = self.palm.rotation.slerp(other.palm.rotation, t).normalize();
        for (f, finger) in out.fingers.iter_mut().enumerate() {
            for (p, bone) in finger.iter_mut().enumerate() {
                let (x, y) = (&self.fingers[f][p], &other.fingers[f][p]);
                let radius = x.radius + (y.radius - x.radius) * t;
                *bone = Capsule { a: x.a.lerp(y.a, t), b: x.b.lerp(y.b, t), radius };
            }
        }
        out
    }

    /// The same pose moved rigidly: `rotation` about `pivot`, then `translation`.
    pub fn transformed(&self, pivot: Vec3, rotation: Quat, translation: Vec3) -> HandPose {
        let map = |q: Vec3| pivot + rotation * (q - pivot) + translation;
        let mut out = self.clone();
        out.palm.center = map(self.palm.center);
        out.palm.rotation = (rotation * self.palm.rotation).normalize();
        for finger in out.fingers.iter_mut() {
            for bone in finger.iter_mut() {
                bone.a = map(bone.a);
                bone.b = map(bone.b);
            }
        }
        out
    }

    /// Checks that every number is usable by the physics: finite, within
    /// [`MAX_COORDINATE`], radii and extents positive and at most that,
    /// non-degenerate bones.
    pub fn validate(&self, hand: u32) -> Result<(), PoseError> {
        let point = |bone: Bone, field: &'static str, v: Vec3| -> Result<(), PoseError> {
            if !v.is_finite() {
                return Err(PoseError::NonFinite { hand, bone, field });
            }
            let m = v.abs().max_element();
            if m > MAX_COORDINATE {
                return Err(PoseError::OutOfRange { hand, bone, field, value: m });
            }
            Ok(())
        };
        let palm = &self.palm;
        point(Bone::Palm, "center", palm.center)?;
        if !palm.half_extents.is_finite() {
            return Err(PoseError::NonFinite { hand, bone: Bone::Palm, field: "half_extents" });
        }
        // A bone larger than the world's extent only makes the contact
        // queries fail (parry's EPA panics on a 1e20 m palm).
        if palm.half_extents.min_element() <= 0.0
            || palm.half_extents.max_element() > MAX_COORDINATE
        {
            return Err(PoseError::BadPalmExtents { hand, half_extents: palm.half_extents });
        }
        if !palm.rotation.is_finite() {
            return Err(PoseError::NonFinite { hand, bone: Bone::Palm, field: "rotation" });
        }
        if (palm.rotation.length() - 1.0).abs() > 1.0e-3 {
            return Err(PoseError::BadPalmRotation { hand, rotation: palm.rotation });
        }
        for bone in Bone::all().skip(1) {
            let BoneShape::Capsule(c) = self.bone(bone) else { continue };
            point(bone, "a", c.a)?;
            point(bone, "b", c.b)?;
            if !c.radius.is_finite() {
                return Err(PoseError::NonFinite { hand, bone, field: "radius" });
            }
            if c.radius <= 0.0 || c.radius > MAX_COORDINATE {
                return Err(PoseError::BadRadius { hand, bone, radius: c.radius });
            }
            if (c.b - c.a).length() < MIN_BONE_LENGTH {
                return Err(PoseError::ZeroLength { hand, bone, at: c.a });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bone_index_round_trips() {
        for (i, b) in Bone::all().enumerate() {
            assert_eq!(b.index(), i);
            assert_eq!(Bone::from_index(i), b);
        }
        assert_eq!(Bone::from_index(16), Bone::Palm);
        assert_eq!(Bone::Finger(Finger::Pinky, Phalanx::Distal).index(), 15);
        assert_eq!(Bone::Finger(Finger::Thumb, Phalanx::Distal).to_string(), "thumb-distal");
    }

    #[test]
    fn a_side_is_spelled_left_or_right() {
        assert_eq!("left".parse::<Side>(), Ok(Side::Left));
        assert_eq!("right".parse::<Side>(), Ok(Side::Right));
        let e = "Right".parse::<Side>().unwrap_err().to_string();
        assert_eq!(e, r#"expected "left" or "right", got "Right""#);
    }

    #[test]
    fn palm_frame_follows_normal_and_direction() {
        let palm = Palm::from_normal_direction(Vec3::ZERO, -Vec3::Y, -Vec3::Z, Vec3::ONE).unwrap();
        assert!((palm.normal() + Vec3::Y).length() < 1e-6);
        assert!((palm.rotation * Vec3::Z + Vec3::Z).length() < 1e-6);
        assert!(Palm::from_normal_direction(Vec3::ZERO, Vec3::Y, Vec3::Y, Vec3::ONE).is_none());
    }
}
