//! Plays tracking frames back on the physics clock: hand poses are
//! interpolated between frames, short dropouts are bridged, and a hand that
//! stays lost longer than the grace period is reported as untracked.

use super::convert::Conversion;
use super::skeleton::hand_pose;
use super::{InputError, TrackingFrame};
use crate::hand::{HandSample, Side};

/// One hand's tracked samples, in time order.
#[derive(Debug, Clone)]
pub struct Track {
    /// The tracker's hand id.
    pub id: i64,
    /// Which hand.
    pub side: Side,
    /// `(time since the first frame in s, the hand then)`.
    samples: Vec<(f64, HandSample)>,
}

/// Frames converted to world poses, ready to be sampled at any time.
#[derive(Debug, Clone)]
pub struct Playback {
    /// One per tracker hand id, in order of first appearance.
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
    pub fn new(
        source: &str,
        frames: &[TrackingFrame],
        conversion: &Conversion,
        grace: f64,
    ) -> Result<Self, InputError> {
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
                let why = format!("goes backwards ({} after {last})", frame.timestamp_us);
                return Err(fail(i, "timestamp".into(), why));
            }
            last = frame.timestamp_us;
            let Some(elapsed) = frame.timestamp_us.checked_sub(start) else {
                let why = format!("{} µs after {start} µs overflows", frame.timestamp_us);
                return Err(fail(i, "timestamp".into(), why));
            };
            let t = elapsed as f64 * 1e-6;
            for (h, hand) in frame.hands.iter().enumerate() {
                let bad = |e: String| fail(i, format!("hands[{h}]"), e);
                let pose = hand_pose(hand, conversion).map_err(|e| bad(e.to_string()))?;
                pose.validate(0).map_err(|e| bad(e.to_string()))?;
                let k = tracks.iter().position(|tr| tr.id == hand.id).unwrap_or_else(|| {
                    tracks.push(Track { id: hand.id, side: hand.side, samples: Vec::new() });
                    tracks.len() - 1
                });
                let sample = HandSample { pose, grab: hand.grab, pinch: hand.pinch };
                tracks[k].samples.push((t, sample));
            }
        }
        // `last - start` is the last frame's checked `elapsed`.
        let duration = last.wrapping_sub(start) as f64 * 1e-6;
        Ok(Playback { tracks, duration, frames: frames.len(), grace })
    }

    /// The state of track `index` at time `t` (s), or `None` while untracked.
    pub fn sample(&self, index: usize, t: f64) -> Option<HandSample> {
        interpolate(&self.tracks.get(index)?.samples, t, self.grace)
    }
}

/// A hand at time `t` (s) from its samples `(time, hand)` in time order:
/// interpolated between the two around `t` if they are at most `grace`
/// apart, else `None` (the hand was lost). Past the last sample the hand is
/// held only for an instant.
pub fn interpolate(samples: &[(f64, HandSample)], t: f64, grace: f64) -> Option<HandSample> {
    let after = samples.partition_point(|s| s.0 <= t);
    let before = after.checked_sub(1)?;
    let (t0, s0) = &samples[before];
    let Some((t1, s1)) = samples.get(after) else {
        return (t - t0 <= 1e-9).then(|| s0.clone());
    };
    if t1 - t0 > grace {
        return None;
    }
    let w = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0) as f32;
    let mix = |a: Option<f32>, b: Option<f32>| match (a, b) {
        (Some(a), Some(b)) => Some(a + (b - a) * w),
        (a, b) => a.or(b),
    };
    Some(HandSample {
        pose: s0.pose.lerp(&s1.pose, w),
        grab: mix(s0.grab, s1.grab),
        pinch: mix(s0.pinch, s1.pinch),
    })
}
