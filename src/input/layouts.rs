//! Other trackers' joint layouts mapped onto the same hand model:
//! OpenXR `XR_EXT_hand_tracking` (26 joints with radii), WebXR Hand Input
//! (25 joints with radii) and MediaPipe Hands (21 world landmarks).
//!
//! Each maps to a [`TrackedHand`]; [`super::skeleton::hand_pose`] then builds
//! the 16 bones. The joint → bone mapping, per finger, is
//!
//! | our bone | OpenXR / WebXR joints | MediaPipe landmarks |
//! |---|---|---|
//! | thumb proximal | thumb metacarpal → thumb proximal | THUMB_CMC → THUMB_MCP |
//! | thumb intermediate | thumb proximal → thumb distal | THUMB_MCP → THUMB_IP |
//! | thumb distal | thumb distal → thumb tip | THUMB_IP → THUMB_TIP |
//! | finger proximal | proximal → intermediate | MCP → PIP |
//! | finger intermediate | intermediate → distal | PIP → DIP |
//! | finger distal | distal → tip | DIP → TIP |
//!
//! The thumb's first bone is its metacarpal, as in Leap Motion's model (whose
//! thumb has a zero-length metacarpal and calls that bone "proximal"). The
//! palm is OpenXR's palm joint; WebXR and MediaPipe have none, so it is the
//! midpoint of the wrist and the middle finger's knuckle, with its normal
//! from the knuckle line and the wrist. Finger widths are twice the joint
//! radius at the knuckle. OpenXR's and WebXR's index … little metacarpal
//! joints are the palm's back edge ([`TrackedHand::carps`]); MediaPipe has
//! none. MediaPipe has no radii, so it uses
//! [`super::leap::DEFAULT_WIDTHS_MM`] converted to metres.
//!
//! All three report metres in a right-handed, y-up frame (OpenXR, WebXR),
//! except MediaPipe world landmarks, whose y axis points down (image
//! convention): use [`mediapipe_to_y_up`] to convert them first.

use super::TrackedHand;
use super::convert::Conversion;
use super::skeleton::{SkeletonError, hand_pose};
use crate::hand::{HandPose, PoseError, Side};
use glam::{Quat, Vec3};

/// A tracked joint: position (m), orientation and radius (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joint {
    /// Joint position (m), in the tracker's frame.
    pub position: Vec3,
    /// The joint frame: −z along the bone towards the fingertip, +y out of
    /// the back of the hand (OpenXR and WebXR convention).
    pub orientation: Quat,
    /// Joint radius (m): half the finger's thickness there.
    pub radius: f32,
}

/// Why a joint set could not become a hand.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{layout} joint {joint}: {reason}")]
pub struct LayoutError {
    /// The layout: `openxr`, `webxr` or `mediapipe`.
    pub layout: &'static str,
    /// Index of the joint in the layout's order.
    pub joint: usize,
    /// What is wrong with it.
    pub reason: String,
}

/// A tracker's joint layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// OpenXR `XR_EXT_hand_tracking`: 26 joints, palm first, with radii.
    OpenXr,
    /// WebXR Hand Input: 25 joints, wrist first, with radii.
    WebXr,
    /// MediaPipe Hands: 21 world landmarks, wrist first, no radii.
    MediaPipe,
}

/// A layout name that is none of [`Layout`]'s.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("unknown layout \"{0}\" (known: {known})", known = Layout::KNOWN)]
pub struct UnknownLayout(pub String);

impl Layout {
    /// The layouts' names, for messages.
    pub const KNOWN: &str = "openxr, webxr, mediapipe";

    /// Its name in files and options: `openxr`, `webxr` or `mediapipe`.
    pub fn name(self) -> &'static str {
        match self {
            Layout::OpenXr => "openxr",
            Layout::WebXr => "webxr",
            Layout::MediaPipe => "mediapipe",
        }
    }

    /// How many joints it has.
    pub fn count(self) -> usize {
        match self {
            Layout::OpenXr => openxr::COUNT,
            Layout::WebXr => webxr::COUNT,
            Layout::MediaPipe => mediapipe::COUNT,
        }
    }

    /// Each joint's radius (m) when a tracker gives none: an average
    /// adult's finger widths ([`super::leap::DEFAULT_WIDTHS_MM`]), 0 for the
    /// joints that are not on a finger (OpenXR's palm and wrist, WebXR's
    /// wrist).
    pub fn default_radii(self) -> Vec<f32> {
        let count = self.count();
        let first_finger_joint = count - 24;
        let radius = |j: usize| match j.checked_sub(first_finger_joint) {
            None => 0.0,
            Some(k) => 0.0005 * super::leap::DEFAULT_WIDTHS_MM[(k + 1) / 5],
        };
        (0..count).map(radius).collect()
    }
}

impl std::str::FromStr for Layout {
    type Err = UnknownLayout;
    fn from_str(s: &str) -> Result<Layout, UnknownLayout> {
        [Layout::OpenXr, Layout::WebXr, Layout::MediaPipe]
            .into_iter()
            .find(|l| l.name() == s)
            .ok_or_else(|| UnknownLayout(s.to_string()))
    }
}

/// A hand from joint positions (m, y up) in `layout`'s order, with each
/// joint's radius (m) and orientation when the tracker gives them (OpenXR
/// and WebXR; MediaPipe has neither). Without radii, [`Layout::default_radii`];
/// without orientations, OpenXR's palm frame comes from the wrist and the
/// knuckles ([`palm_orientation`]). A joint recording's hands and the
/// Python package's `set_hand_joints` both come through here.
pub fn from_layout(
    layout: Layout,
    id: i64,
    side: Side,
    positions: &[Vec3],
    radii: Option<&[f32]>,
    orientations: Option<&[Quat]>,
) -> Result<TrackedHand, LayoutError> {
    let (name, count) = (layout.name(), layout.count());
    let fail = |joint: usize, reason: String| LayoutError { layout: name, joint, reason };
    for (what, n) in [("joints", Some(positions.len())), ("radii", radii.map(<[f32]>::len))]
        .into_iter()
        .chain([("orientations", orientations.map(<[Quat]>::len))])
    {
        if let Some(n) = n.filter(|&n| n != count) {
            return Err(fail(n.min(count), format!("{n} {what}, but {name} has {count}")));
        }
    }
    if layout == Layout::MediaPipe {
        if radii.is_some() || orientations.is_some() {
            let why = "mediapipe landmarks have no radii or orientations; leave them out";
            return Err(fail(0, why.into()));
        }
        return from_mediapipe(id, side, &std::array::from_fn(|j| positions[j]));
    }
    let default_radii;
    let radii = match radii {
        Some(r) => r,
        None => {
            default_radii = layout.default_radii();
            &default_radii
        }
    };
    let joint = |j: usize| Joint {
        position: positions[j],
        orientation: orientations.map_or(Quat::IDENTITY, |q| q[j]),
        radius: radii[j],
    };
    if layout == Layout::WebXr {
        return from_webxr(id, side, &std::array::from_fn(joint));
    }
    let mut joints: [Joint; openxr::COUNT] = std::array::from_fn(joint);
    if orientations.is_none() {
        joints[openxr::PALM].orientation = palm_orientation(side, positions);
    }
    from_openxr(id, side, &joints)
}

/// Why one frame of a tracker's joints made no hand pose.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JointsError {
    /// A joint is missing, not finite, or has a negative radius.
    #[error(transparent)]
    Layout(#[from] LayoutError),
    /// The joints made no skeleton (fingers of zero length, say).
    #[error(transparent)]
    Skeleton(#[from] SkeletonError),
    /// The skeleton made a pose the world would refuse.
    #[error(transparent)]
    Pose(#[from] PoseError),
}

/// One frame of `layout`'s joints (m, y up; radii and orientations as for
/// [`from_layout`]) as the 16 bones of the hand model, checked as the world
/// checks a pose, so that a pose held for later (an app's input) fails now
/// and says why. The one way from joints to a pose: the Python package's
/// `set_hand_joints`, the web page's WebXR hands and the Bevy plugin's
/// OpenXR hands all come through here. `id` is the hand's, for messages.
pub fn hand_pose_from_joints(
    layout: Layout,
    id: u32,
    side: Side,
    positions: &[Vec3],
    radii: Option<&[f32]>,
    orientations: Option<&[Quat]>,
) -> Result<HandPose, JointsError> {
    let tracked = from_layout(layout, i64::from(id), side, positions, radii, orientations)?;
    let pose = hand_pose(&tracked, &Conversion::identity())?;
    pose.validate(id)?;
    Ok(pose)
}

/// OpenXR `XrHandJointEXT` indices.
pub mod openxr {
    /// The palm joint (`XR_HAND_JOINT_PALM_EXT`).
    pub const PALM: usize = 0;
    /// The wrist joint.
    pub const WRIST: usize = 1;
    /// First joint of each finger (thumb: metacarpal; others: metacarpal).
    pub const THUMB_METACARPAL: usize = 2;
    /// The index finger's metacarpal; each later finger's starts 5 further on.
    pub const INDEX_METACARPAL: usize = 6;
    /// Number of joints.
    pub const COUNT: usize = 26;
}

/// WebXR `XRHandJoint` order (no palm joint).
pub mod webxr {
    /// The wrist joint.
    pub const WRIST: usize = 0;
    /// The thumb's metacarpal joint, its first of four.
    pub const THUMB_METACARPAL: usize = 1;
    /// The index finger's metacarpal; each later finger's starts 5 further on.
    pub const INDEX_METACARPAL: usize = 5;
    /// Number of joints.
    pub const COUNT: usize = 25;
}

/// MediaPipe Hands landmark indices.
pub mod mediapipe {
    /// The wrist landmark.
    pub const WRIST: usize = 0;
    /// The thumb's carpometacarpal joint, its first of four landmarks.
    pub const THUMB_CMC: usize = 1;
    /// The index finger's knuckle; each later finger's starts 4 further on.
    pub const INDEX_MCP: usize = 5;
    /// Number of landmarks.
    pub const COUNT: usize = 21;
}

fn check(
    layout: &'static str,
    joints: impl Iterator<Item = (Vec3, f32)>,
) -> Result<(), LayoutError> {
    for (i, (p, r)) in joints.enumerate() {
        if !p.is_finite() {
            return Err(LayoutError {
                layout,
                joint: i,
                reason: format!("position {p:?} is not finite"),
            });
        }
        if !(r.is_finite() && r >= 0.0) {
            return Err(LayoutError {
                layout,
                joint: i,
                reason: format!("radius {r} is not a finite non-negative number"),
            });
        }
    }
    Ok(())
}

/// The four joints base → tip of each finger, thumb first, given the index
/// of the thumb's first used joint and of the index finger's metacarpal in
/// a layout with 4 thumb joints and 5 joints per other finger.
fn finger_joints(
    position: impl Fn(usize) -> Vec3,
    thumb: usize,
    index_metacarpal: usize,
) -> [[Vec3; 4]; 5] {
    std::array::from_fn(|f| {
        // The thumb uses all four of its joints; other fingers skip their
        // metacarpal joint (inside the palm).
        let first = if f == 0 { thumb } else { index_metacarpal + 5 * (f - 1) + 1 };
        std::array::from_fn(|j| position(first + j))
    })
}

/// The metacarpal joints of index … pinky in a layout with 5 joints per
/// finger.
fn metacarpals(position: impl Fn(usize) -> Vec3, index_metacarpal: usize) -> [Vec3; 4] {
    std::array::from_fn(|f| position(index_metacarpal + 5 * f))
}

/// A palm from the wrist and the knuckles, for layouts without a palm joint.
/// The normal is oriented to the palm side for the given hand.
fn palm_from_knuckles(side: Side, wrist: Vec3, joints: &[[Vec3; 4]; 5]) -> (Vec3, Vec3, Vec3) {
    let knuckle_centre = (joints[1][0] + joints[4][0]) * 0.5;
    let direction = (joints[2][0] - wrist).normalize_or_zero();
    let across = joints[4][0] - joints[1][0]; // index → pinky
    // For a right hand, index→pinky × wrist→fingers points out of the back;
    // the palm normal is the opposite. Mirrored for a left hand.
    let back = across.cross(direction).normalize_or_zero();
    let normal = match side {
        Side::Right => -back,
        Side::Left => back,
    };
    (0.5 * (wrist + knuckle_centre), normal, direction)
}

fn tracked(
    id: i64,
    side: Side,
    palm: (Vec3, Vec3, Vec3),
    joints: [[Vec3; 4]; 5],
    carps: Option<[Vec3; 4]>,
    widths: [f32; 5],
) -> TrackedHand {
    TrackedHand {
        id,
        side,
        palm_position: palm.0,
        palm_normal: palm.1,
        direction: palm.2,
        joints,
        carps,
        widths,
        grab: None,
        pinch: None,
        confidence: None,
    }
}

/// A joint's or an object's rotation given as four numbers, x, y, z, w,
/// made a unit quaternion: how every binding and file reader takes one. A
/// zero-length or non-finite one is `None`, which the caller names.
pub fn rotation(xyzw: [f32; 4]) -> Option<Quat> {
    glam::Vec4::from_array(xyzw).try_normalize().map(Quat::from_vec4)
}

/// Each joint's orientation given as four numbers (x, y, z, w) in
/// `layout`'s order, made unit quaternions ([`rotation`]); a zero-length or
/// non-finite one is an error naming its joint. The Python package and the
/// C ABI take a tracker's orientations through here.
pub fn orientations(layout: Layout, xyzw: &[[f32; 4]]) -> Result<Vec<Quat>, LayoutError> {
    let one = |(joint, q): (usize, &[f32; 4])| {
        rotation(*q).ok_or_else(|| LayoutError {
            layout: layout.name(),
            joint,
            reason: "zero-length or non-finite orientation".into(),
        })
    };
    xyzw.iter().enumerate().map(one).collect()
}

/// The palm joint's orientation for OpenXR joint positions (all 26, in
/// `XrHandJointEXT` order) given without orientations: from the wrist and
/// the knuckles, as for WebXR.
pub fn palm_orientation(side: Side, positions: &[Vec3]) -> Quat {
    let position = |i: usize| positions.get(i).copied().unwrap_or(Vec3::ZERO);
    let fingers = finger_joints(position, openxr::THUMB_METACARPAL, openxr::INDEX_METACARPAL);
    let (_, normal, direction) = palm_from_knuckles(side, position(openxr::WRIST), &fingers);
    frame(normal, direction)
}

/// OpenXR `XR_EXT_hand_tracking` joints (all 26, in `XrHandJointEXT`
/// order) to a tracked hand in metres.
pub fn from_openxr(
    id: i64,
    side: Side,
    joints: &[Joint; openxr::COUNT],
) -> Result<TrackedHand, LayoutError> {
    check("openxr", joints.iter().map(|j| (j.position, j.radius)))?;
    let palm = joints[openxr::PALM];
    let fingers =
        finger_joints(|i| joints[i].position, openxr::THUMB_METACARPAL, openxr::INDEX_METACARPAL);
    let widths = std::array::from_fn(|f| {
        let knuckle = if f == 0 {
            openxr::THUMB_METACARPAL + 1
        } else {
            openxr::INDEX_METACARPAL + 5 * (f - 1) + 1
        };
        2.0 * joints[knuckle].radius
    });
    let normal = (palm.orientation * -Vec3::Y).normalize_or_zero();
    let direction = (palm.orientation * -Vec3::Z).normalize_or_zero();
    let carps = metacarpals(|i| joints[i].position, openxr::INDEX_METACARPAL);
    Ok(tracked(id, side, (palm.position, normal, direction), fingers, Some(carps), widths))
}

/// WebXR Hand Input joints (all 25, in `XRHandJoint` order) to a tracked
/// hand in metres.
pub fn from_webxr(
    id: i64,
    side: Side,
    joints: &[Joint; webxr::COUNT],
) -> Result<TrackedHand, LayoutError> {
    check("webxr", joints.iter().map(|j| (j.position, j.radius)))?;
    let fingers =
        finger_joints(|i| joints[i].position, webxr::THUMB_METACARPAL, webxr::INDEX_METACARPAL);
    let widths = std::array::from_fn(|f| {
        let knuckle = if f == 0 {
            webxr::THUMB_METACARPAL + 1
        } else {
            webxr::INDEX_METACARPAL + 5 * (f - 1) + 1
        };
        2.0 * joints[knuckle].radius
    });
    let palm = palm_from_knuckles(side, joints[webxr::WRIST].position, &fingers);
    let carps = metacarpals(|i| joints[i].position, webxr::INDEX_METACARPAL);
    Ok(tracked(id, side, palm, fingers, Some(carps), widths))
}

/// MediaPipe Hands world landmarks (21, metres, already y-up) to a tracked
/// hand in metres.
pub fn from_mediapipe(
    id: i64,
    side: Side,
    landmarks: &[Vec3; mediapipe::COUNT],
) -> Result<TrackedHand, LayoutError> {
    check("mediapipe", landmarks.iter().map(|p| (*p, 0.0)))?;
    // MediaPipe numbers each finger's 4 landmarks consecutively.
    let fingers = std::array::from_fn(|f| {
        std::array::from_fn(|j| landmarks[mediapipe::THUMB_CMC + 4 * f + j])
    });
    let widths = super::leap::DEFAULT_WIDTHS_MM.map(|w| w * 0.001);
    let palm = palm_from_knuckles(side, landmarks[mediapipe::WRIST], &fingers);
    Ok(tracked(id, side, palm, fingers, None, widths))
}

/// MediaPipe's world landmarks have y pointing down: flip y and z (a
/// rotation by 180° about x) to get right-handed, y-up metres.
pub fn mediapipe_to_y_up() -> Conversion {
    Conversion::mount_rotation(std::f32::consts::PI, 0.0, 0.0)
}

/// The joints a tracker in `layout` would report for `hand` (metres),
/// for tests and for exporting. Joint frames are built from the bones.
pub fn to_openxr(hand: &TrackedHand) -> [Joint; openxr::COUNT] {
    let mut out =
        [Joint { position: Vec3::ZERO, orientation: Quat::IDENTITY, radius: 0.0 }; openxr::COUNT];
    let palm_rot = frame(hand.palm_normal, hand.direction);
    out[openxr::PALM] = Joint { position: hand.palm_position, orientation: palm_rot, radius: 0.0 };
    out[openxr::WRIST] = Joint {
        position: hand.palm_position - hand.direction * 0.05,
        orientation: palm_rot,
        radius: 0.0,
    };
    fill_fingers(hand, &mut out, openxr::THUMB_METACARPAL, openxr::INDEX_METACARPAL, palm_rot);
    out
}

/// As [`to_openxr`], in WebXR order (no palm joint).
pub fn to_webxr(hand: &TrackedHand, wrist: Vec3) -> [Joint; webxr::COUNT] {
    let mut out =
        [Joint { position: Vec3::ZERO, orientation: Quat::IDENTITY, radius: 0.0 }; webxr::COUNT];
    let palm_rot = frame(hand.palm_normal, hand.direction);
    out[webxr::WRIST] = Joint { position: wrist, orientation: palm_rot, radius: 0.0 };
    fill_fingers(hand, &mut out, webxr::THUMB_METACARPAL, webxr::INDEX_METACARPAL, palm_rot);
    out
}

/// As [`to_openxr`], as MediaPipe's 21 landmarks (y up).
pub fn to_mediapipe(hand: &TrackedHand, wrist: Vec3) -> [Vec3; mediapipe::COUNT] {
    let mut out = [Vec3::ZERO; mediapipe::COUNT];
    out[mediapipe::WRIST] = wrist;
    for f in 0..5 {
        for j in 0..4 {
            out[mediapipe::THUMB_CMC + 4 * f + j] = hand.joints[f][j];
        }
    }
    out
}

/// A joint frame with −z along `forward` and +y along `-palm_normal`.
fn frame(palm_normal: Vec3, forward: Vec3) -> Quat {
    let y = -palm_normal.normalize_or_zero();
    let z = -(forward - forward.dot(y) * y).normalize_or_zero();
    let x = y.cross(z);
    Quat::from_mat3(&glam::Mat3::from_cols(x, y, z)).normalize()
}

fn fill_fingers(
    hand: &TrackedHand,
    out: &mut [Joint],
    thumb: usize,
    index_metacarpal: usize,
    palm_rot: Quat,
) {
    for f in 0..5 {
        let radius = 0.5 * hand.widths[f];
        let first = if f == 0 { thumb } else { index_metacarpal + 5 * (f - 1) + 1 };
        if f > 0 {
            // The metacarpal joint, inside the palm: the tracked one, or
            // else halfway from the palm.
            let position =
                hand.carps.map_or(0.5 * (hand.palm_position + hand.joints[f][0]), |c| c[f - 1]);
            out[first - 1] = Joint { position, orientation: palm_rot, radius };
        }
        for j in 0..4 {
            let towards = if j < 3 {
                hand.joints[f][j + 1] - hand.joints[f][j]
            } else {
                hand.joints[f][3] - hand.joints[f][2]
            };
            out[first + j] = Joint {
                position: hand.joints[f][j],
                orientation: frame(hand.palm_normal, towards),
                radius,
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_arithmetic_matches_the_published_orders() {
        // OpenXR: INDEX_PROXIMAL = 7, MIDDLE_PROXIMAL = 12, LITTLE_TIP = 25.
        let f = finger_joints(
            |i| Vec3::splat(i as f32),
            openxr::THUMB_METACARPAL,
            openxr::INDEX_METACARPAL,
        );
        assert_eq!(f[0], [2.0, 3.0, 4.0, 5.0].map(Vec3::splat));
        assert_eq!(f[1][0], Vec3::splat(7.0));
        assert_eq!(f[2][0], Vec3::splat(12.0));
        assert_eq!(f[4][3], Vec3::splat(25.0));
        // WebXR: thumb 1..=4, index-finger-phalanx-proximal = 6, pinky tip = 24.
        let w = finger_joints(
            |i| Vec3::splat(i as f32),
            webxr::THUMB_METACARPAL,
            webxr::INDEX_METACARPAL,
        );
        assert_eq!(w[0][0], Vec3::splat(1.0));
        assert_eq!(w[1][0], Vec3::splat(6.0));
        assert_eq!(w[4][3], Vec3::splat(24.0));
    }

    #[test]
    fn mediapipe_flip_is_a_rotation() {
        let c = mediapipe_to_y_up();
        assert!((c.point(Vec3::new(0.1, -0.2, 0.3)) - Vec3::new(0.1, 0.2, -0.3)).length() < 1e-6);
        assert!(!c.mirrors());
    }

    #[test]
    fn bad_joints_name_the_layout_and_joint() {
        let mut j = [Joint { position: Vec3::ZERO, orientation: Quat::IDENTITY, radius: 0.01 };
            openxr::COUNT];
        j[9].position.x = f32::NAN;
        let e = from_openxr(0, Side::Right, &j).unwrap_err();
        assert_eq!((e.layout, e.joint), ("openxr", 9));
    }
}
