//! Tracking input: recordings and trackers → tracked hands → [`crate::hand::HandPose`].
//!
//! The stage before [`crate::hand`]: a [`TrackingFrame`] holds hands in the
//! tracker's own units and axes; a [`convert::Conversion`] maps them into the
//! world (metres, y up); [`skeleton::hand_pose`] builds the 16-bone model.

pub mod capture;
pub mod convert;
pub mod joints;
pub mod layouts;
pub mod leap;
pub mod live;
pub mod mediapipe;
pub mod playback;
pub mod recording;
pub mod skeleton;

use crate::hand::Side;
use glam::Vec3;

/// One hand as a tracker reports it, in the tracker's units and axes.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackedHand {
    /// The tracker's id for this hand; stable while it stays tracked.
    pub id: i64,
    /// Which hand.
    pub side: Side,
    /// Centre of the palm surface.
    pub palm_position: Vec3,
    /// Unit normal out of the palm (the grasping side).
    pub palm_normal: Vec3,
    /// Unit direction from the wrist towards the fingers.
    pub direction: Vec3,
    /// `joints[finger]`: thumb first; base of the proximal phalanx, then
    /// the two interphalangeal joints, then the fingertip.
    pub joints: [[Vec3; 4]; 5],
    /// Wrist ends of the index … pinky metacarpals (Leap `carpPosition`,
    /// OpenXR/WebXR metacarpal joints), when the tracker reports them: the
    /// back edge of the palm.
    pub carps: Option<[Vec3; 4]>,
    /// Finger widths (diameters), thumb first.
    pub widths: [f32; 5],
    /// The tracker's grab strength in [0, 1], when it reports one.
    pub grab: Option<f32>,
    /// The tracker's pinch strength in [0, 1], when it reports one.
    pub pinch: Option<f32>,
    /// The tracker's confidence in this hand's pose, in [0, 1], when it
    /// reports one: a Leap Motion's per-hand `confidence`, or the least
    /// visibility of MediaPipe's landmarks.
    pub confidence: Option<f32>,
}

impl TrackedHand {
    /// `pose`, this hand's skeleton, with what the tracker says of it: its
    /// grab and pinch strengths and its confidence.
    pub fn sample(&self, pose: crate::hand::HandPose) -> crate::hand::HandSample {
        crate::hand::HandSample {
            pose,
            grab: self.grab,
            pinch: self.pinch,
            confidence: self.confidence,
        }
    }

    /// The same hand in another frame and unit (e.g. Leap millimetres to
    /// world metres).
    pub fn converted(&self, c: &convert::Conversion) -> TrackedHand {
        TrackedHand {
            palm_position: c.point(self.palm_position),
            palm_normal: c.direction(self.palm_normal),
            direction: c.direction(self.direction),
            joints: self.joints.map(|f| f.map(|j| c.point(j))),
            carps: self.carps.map(|carps| carps.map(|j| c.point(j))),
            widths: self.widths.map(|w| c.length(w)),
            ..self.clone()
        }
    }
}

/// All hands seen at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackingFrame {
    /// Tracker timestamp (µs).
    pub timestamp_us: i64,
    /// The hands tracked in this frame.
    pub hands: Vec<TrackedHand>,
}

/// A problem with tracking input, located as precisely as possible.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "{source_name}{}: {field}: {reason}",
    frame.map(|f| format!(": frame {f}")).unwrap_or_default()
)]
pub struct InputError {
    /// The file or stream the data came from.
    pub source_name: String,
    /// Index of the frame in the file, when the problem is in one frame.
    pub frame: Option<usize>,
    /// The field (a JSON path such as `hands[0].palmPosition`).
    pub field: String,
    /// What is wrong with it.
    pub reason: String,
}

/// A recording file's name (for messages) and text, read from `files`;
/// an unreadable or non-UTF-8 file is an error naming it.
fn read_text(
    path: &std::path::Path,
    files: &dyn crate::files::Files,
) -> Result<(String, String), InputError> {
    let name = path.display().to_string();
    let bytes = files.read(path).map_err(|e| file_error(&name, e.to_string()))?;
    let text = text_of(&name, bytes)?;
    Ok((name, text))
}

/// A recording file's bytes as text; not UTF-8 is an error naming `name`.
fn text_of(name: &str, bytes: Vec<u8>) -> Result<String, InputError> {
    String::from_utf8(bytes).map_err(|_| file_error(name, "not UTF-8 text".into()))
}

/// An error of the file `name` as a whole.
fn file_error(name: &str, reason: String) -> InputError {
    InputError { source_name: name.to_string(), frame: None, field: "file".into(), reason }
}
