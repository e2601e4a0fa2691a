//! The skeletal hand fitted to a captured hand: each capsule's surface and
//! the palm box's grasping face laid on the captured skin.
//!
//! The keypoints of [`super::rings`] lie on the bones' axes, except the
//! fingertips, which are points of the skin (as MediaPipe's and MANO's
//! are, and as the skeleton expects: its distal capsule ends one radius
//! short of the tip, so its cap reaches it). Two things are fitted:
//! - each capsule's radius, from the rings ([`super::rings::widths`]);
//! - the palm box's grasping face, on the palm's skin, which lies
//!   [`palm_depth`] in front of the knuckles' axes, not on those axes.
//!
//! And one check: the fingers curl towards the palm. A capture whose
//! frame is mirrored (a left-handed frame, or a hand mirrored on export)
//! turns a right hand's points into a left hand's shape; [`shape_side`]
//! finds the side the points have, which the skeleton is built as.

use super::rings;
use crate::hand::Side;
use crate::input::layouts::{LayoutError, from_mediapipe};
use glam::Vec3;

/// MediaPipe's index of finger `f`'s tip (thumb 0).
fn tip(f: usize) -> usize {
    4 + 4 * f
}

/// The side whose palm the fingers curl towards: `labelled`, or the other
/// side when the points have the other hand's shape. Over all frames, the
/// index … little fingertips' offset from their proximal phalanx's line,
/// along the palm normal `labelled` gives, is summed: a hand curls its
/// fingers palmwards, and bends them backwards by far less.
pub fn shape_side(labelled: Side, keypoints: &[[Vec3; 21]]) -> Result<Side, (usize, LayoutError)> {
    let mut curl = 0.0f64;
    for (i, keys) in keypoints.iter().enumerate() {
        let hand = from_mediapipe(0, labelled, keys).map_err(|e| (i, e))?;
        for f in 1..5 {
            let (knuckle, middle) = (keys[tip(f) - 3], keys[tip(f) - 2]);
            let line = (middle - knuckle).normalize_or_zero();
            let offset = (keys[tip(f)] - knuckle).reject_from_normalized(line);
            curl += f64::from(offset.dot(hand.palm_normal));
        }
    }
    Ok(match (curl < 0.0, labelled) {
        (false, side) => side,
        (true, Side::Left) => Side::Right,
        (true, Side::Right) => Side::Left,
    })
}

/// How far the palm's skin lies in front of the palm the keypoints give
/// (m, along its normal): the median, over frames, of the median normal
/// offset of the surface points in front of it within [`PALM_REACH`] of
/// its centre. In front of the palm's centre the hand has only its palm
/// skin, unless fingers curl over it; the median keeps to the skin.
pub fn palm_depth(
    side: Side,
    keypoints: &[[Vec3; 21]],
    points: &[Vec<Vec3>],
) -> Result<f32, (usize, LayoutError)> {
    let mut depths = Vec::new();
    for (i, (keys, points)) in keypoints.iter().zip(points).enumerate() {
        let hand = from_mediapipe(0, side, keys).map_err(|e| (i, e))?;
        let mut ahead: Vec<f32> = points
            .iter()
            .map(|p| *p - hand.palm_position)
            .filter(|d| d.reject_from_normalized(hand.palm_normal).length() < PALM_REACH)
            .map(|d| d.dot(hand.palm_normal))
            .filter(|&d| d > 0.0)
            .collect();
        if let Some(m) = median(&mut ahead) {
            depths.push(m);
        }
    }
    Ok(median(&mut depths).unwrap_or(0.0))
}

/// Points this near the palm's centre, across its normal, are its skin (m).
pub const PALM_REACH: f32 = 0.02;

/// The median of `values` (reordered), or `None` when there are none.
fn median(values: &mut [f32]) -> Option<f32> {
    values.sort_by(f32::total_cmp);
    values.get(values.len() / 2).copied()
}

/// The skeletal hand fitted to a captured hand.
#[derive(Debug, Clone, PartialEq)]
pub struct HandFit {
    /// 21 keypoints per frame (MediaPipe order).
    pub keypoints: Vec<[Vec3; 21]>,
    /// Finger widths (diameters), thumb first.
    pub widths: [f32; 5],
    /// The palm skin's offset in front of the keypoints' palm.
    pub palm_depth: f32,
    /// The side the points have the shape of ([`shape_side`]).
    pub shape: Side,
}

/// The hand fitted to every frame's surface points, labelled `side`.
pub fn from_surface(side: Side, points: &[Vec<Vec3>]) -> Result<HandFit, (usize, LayoutError)> {
    let keys: Vec<[Vec3; 21]> = points.iter().map(|p| rings::keypoints(p)).collect();
    let widths = rings::widths(points, &keys);
    let shape = shape_side(side, &keys)?;
    let palm_depth = palm_depth(shape, &keys, points)?;
    Ok(HandFit { keypoints: keys, widths, palm_depth, shape })
}

/// The hand from keypoints, labelled `side`, with the default widths and
/// no palm offset (keypoints say nothing of the skin).
pub fn from_keypoints(side: Side, keys: Vec<[Vec3; 21]>) -> Result<HandFit, (usize, LayoutError)> {
    let widths = crate::input::leap::DEFAULT_WIDTHS_MM.map(|w| w * 0.001);
    let shape = shape_side(side, &keys)?;
    Ok(HandFit { keypoints: keys, widths, palm_depth: 0.0, shape })
}
