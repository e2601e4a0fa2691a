//! Plays tracking frames back on the physics clock: hand poses are
//! interpolated between frames, short dropouts are bridged, and a hand that
//! stays lost longer than the grace period is reported as untracked.

use super::convert::Conversion;
use super::skeleton::{blend, hand_pose};
use super::{InputError, TrackingFrame};
use crate::hand::{HandPose, Side};

/// One hand's tracked samples, in time order.
#[derive(Debug, Clone)]
pub struct Track {
    /// The tracker's hand id.
    pub id: i64,
    pub side: Side,
    /// `(time since the first frame in s, pose, grab, pinch)`.
    samples: Vec<(f64, HandPose, Option<f32>, Option<f32>)>,
}

/// A hand's state at one instant of playback.
#[derive(Debug, Clone, PartialEq)]
pub struct HandSample {
    pub pose: HandPose,
    pub grab: Option<f32>,
    pub pinch: Option<f32>,
}

/// Frames converted to world poses, ready to be sampled at any time.
#[derive(Debug, Clone)]
pub struct Playback {
    pub tracks: Vec<Track>,
    /// Time from the first to the last frame (s).
    pub duration: f64,
    /// Number of frames.
    pub frames: usize,
    /// A gap between two samples of a hand up to this long (s) is bridged
    /// by interpolation; a longer one means the hand was lost.
    pub grace: f64,
}

/// The default grace period for tracking dropouts (s).
pub const DEFAULT_GRACE: f64 = 0.1;

impl Playback {
    /// Converts every hand of every frame; any bad frame is an error naming
    /// the frame. Timestamps must not go backwards.
    pub fn new(source: &str, frames: &[TrackingFrame], conversion: &Conversion, grace: f64) -> Result<Self, InputError> {
        let fail = |frame: usize, field: String, reason: String| InputError {
            source_name: source.to_string(),
            frame: Some(frame),
            field,
            reason,
        };
        let start = frames.first().map_or(0, |f| f.timestamp_us);
        let mut tracks: Vec<Track> = Vec::new();
        let mut last = start;
        for (i, frame) in frames.iter().enumerate() {
            if frame.timestamp_us < last {
                return Err(fail(i, "timestamp".into(), format!("goes backwards ({} after {last})", frame.timestamp_us)));
            }
            last = frame.timestamp_us;
            let t = (frame.timestamp_us - start) as f64 * 1e-6;
            for (h, hand) in frame.hands.iter().enumerate() {
                let pose = hand_pose(hand, conversion).map_err(|e| fail(i, format!("hands[{h}]"), e.to_string()))?;
                pose.validate(0).map_err(|e| fail(i, format!("hands[{h}]"), e.to_string()))?;
                let k = tracks.iter().position(|tr| tr.id == hand.id).unwrap_or_else(|| {
                    tracks.push(Track { id: hand.id, side: hand.side, samples: Vec::new() });
                    tracks.len() - 1
                });
                tracks[k].samples.push((t, pose, hand.grab, hand.pinch));
            }
        }
        Ok(Playback { tracks, duration: (last - start) as f64 * 1e-6, frames: frames.len(), grace })
    }

    /// The state of track `index` at time `t` (s), or `None` while untracked.
    pub fn sample(&self, index: usize, t: f64) -> Option<HandSample> {
        let samples = &self.tracks.get(index)?.samples;
        let after = samples.partition_point(|s| s.0 <= t);
        let before = after.checked_sub(1)?;
        let (t0, p0, g0, n0) = &samples[before];
        let Some((t1, p1, g1, n1)) = samples.get(after) else {
            // Past the hand's last sample: hold it only for an instant.
            return (t - t0 <= 1e-9).then(|| HandSample { pose: p0.clone(), grab: *g0, pinch: *n0 });
        };
        if t1 - t0 > self.grace {
            return None;
        }
        let w = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0) as f32;
        let mix = |a: Option<f32>, b: Option<f32>| match (a, b) {
            (Some(a), Some(b)) => Some(a + (b - a) * w),
            (a, b) => a.or(b),
        };
        Some(HandSample { pose: blend(p0, p1, w), grab: mix(*g0, *g1), pinch: mix(*n0, *n1) })
    }
}
