//! Plays tracking frames back on the physics clock: hand poses are
//! interpolated between frames, short dropouts are bridged, and a hand that
//! stays lost longer than the grace period is reported as untracked.
//!
//! Trackers glitch, and one glitch must not cost the whole recording. What
//! playback leaves out, it lists in [`Playback::skipped`]:
//! * a frame whose timestamp goes backwards (a stale frame), or jumps
//!   ahead of the next frames (a corrupt one);
//! * a second hand with the same id and side in one frame;
//! * a hand with a collapsed bone (its joints coincide): its neighbours are
//!   interpolated across it, as across a dropout.
//!
//! A hand whose id keeps but whose side flips starts a new track (the
//! tracker's left and right are separate hands). Everything else that is
//! wrong (a number that is not finite, a joint out of range) is an error
//! naming the frame and the field.

use super::convert::Conversion;
use super::skeleton::hand_pose;
use super::{InputError, TrackingFrame};
use crate::hand::{HandSample, PoseError, Side};

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

impl Track {
    /// `(time since the first frame in s, the hand then)`, frame by frame.
    pub fn samples(&self) -> &[(f64, HandSample)] {
        &self.samples
    }
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
    /// What was left out, in frame order.
    pub skipped: Vec<Skipped>,
}

/// A frame, or one hand of a frame, that playback left out.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Skipped {
    /// The frame's index in the recording.
    pub frame: usize,
    /// The hand's index in the frame, or `None` for the whole frame.
    pub hand: Option<usize>,
    /// Why.
    pub reason: String,
}

impl std::fmt::Display for Skipped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.hand {
            Some(h) => write!(f, "frame {} hands[{h}]: {}", self.frame, self.reason),
            None => write!(f, "frame {}: {}", self.frame, self.reason),
        }
    }
}

/// The default grace period for tracking dropouts (s).
pub const DEFAULT_GRACE: f64 = 0.1;

/// The longest recording replayed (s): one hour. Later timestamps are
/// taken for corrupt data, as a replay of them would not end.
pub const MAX_DURATION: f64 = 3600.0;

impl Playback {
    /// The physics steps of `dt` (s) a replay of it runs: its whole
    /// duration and one step more, so its last frame is reached.
    pub fn steps(&self, dt: f32) -> usize {
        (self.duration / f64::from(dt)).floor() as usize + 1
    }

    /// Converts every hand of every frame, leaving out and listing the
    /// glitches of the module doc; any other bad frame is an error naming
    /// the frame. Timestamps must not run past [`MAX_DURATION`] from the
    /// first.
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
        if !(grace.is_finite() && grace >= 0.0) {
            let why = format!("must be a finite number ≥ 0 s, got {grace}");
            return Err(InputError { frame: None, ..fail(0, "grace".into(), why) });
        }
        let start = frames.first().map_or(0, |f| f.timestamp_us);
        let mut tracks: Vec<Track> = Vec::new();
        let mut skipped = Vec::new();
        let mut last = start;
        for (i, frame) in frames.iter().enumerate() {
            if frame.timestamp_us < last {
                let reason =
                    format!("timestamp goes backwards ({} after {last})", frame.timestamp_us);
                skipped.push(Skipped { frame: i, hand: None, reason });
                continue;
            }
            if let Some(next) = contradicted(frames, i, last, grace) {
                let reason = format!(
                    "timestamp jumps ahead ({} after {last}), and frame {next} comes back",
                    frame.timestamp_us
                );
                skipped.push(Skipped { frame: i, hand: None, reason });
                continue;
            }
            last = frame.timestamp_us;
            let t =
                frame.timestamp_us.checked_sub(start).map_or(f64::INFINITY, |d| d as f64 * 1e-6);
            if t > MAX_DURATION {
                let why = format!(
                    "{} µs is more than {MAX_DURATION} s (the longest recording replayed) \
                     after the first frame's {start} µs",
                    frame.timestamp_us
                );
                return Err(fail(i, "timestamp".into(), why));
            }
            let mut seen: Vec<(i64, Side)> = Vec::with_capacity(frame.hands.len());
            for (h, hand) in frame.hands.iter().enumerate() {
                if seen.contains(&(hand.id, hand.side)) {
                    let reason = format!("another {:?} hand with id {}", hand.side, hand.id);
                    skipped.push(Skipped { frame: i, hand: Some(h), reason });
                    continue;
                }
                let bad = |e: String| fail(i, format!("hands[{h}]"), e);
                let pose = hand_pose(hand, conversion).map_err(|e| bad(e.to_string()))?;
                match pose.validate(h as u32) {
                    Err(e @ PoseError::ZeroLength { .. }) => {
                        skipped.push(Skipped { frame: i, hand: Some(h), reason: e.to_string() });
                        continue;
                    }
                    result => result.map_err(|e| bad(e.to_string()))?,
                }
                seen.push((hand.id, hand.side));
                let key = |tr: &Track| tr.id == hand.id && tr.side == hand.side;
                let k = tracks.iter().position(key).unwrap_or_else(|| {
                    tracks.push(Track { id: hand.id, side: hand.side, samples: Vec::new() });
                    tracks.len() - 1
                });
                let sample = hand.sample(pose);
                tracks[k].samples.push((t, sample));
            }
        }
        let duration = (last - start) as f64 * 1e-6;
        Ok(Playback { tracks, duration, frames: frames.len(), grace, skipped })
    }

    /// The state of track `index` at time `t` (s), or `None` while untracked.
    pub fn sample(&self, index: usize, t: f64) -> Option<HandSample> {
        interpolate(&self.tracks.get(index)?.samples, t, self.grace)
    }
}

/// How many later frames may contradict a frame's timestamp.
const LOOK_AHEAD: usize = 3;

/// For a frame `i` more than `grace` (s) ahead of `last` (the last kept),
/// the index of a frame among the next [`LOOK_AHEAD`] whose timestamp falls
/// back between the two: then frame `i` is the glitch, a jump ahead that
/// the stream does not follow. Left in, it would make every later frame
/// look stale. (A smaller step back is the later frame's: it is stale.)
fn contradicted(frames: &[TrackingFrame], i: usize, last: i64, grace: f64) -> Option<usize> {
    let t = frames[i].timestamp_us;
    if (t.saturating_sub(last) as f64) * 1e-6 <= grace {
        return None;
    }
    (i + 1..frames.len().min(i + 1 + LOOK_AHEAD))
        .find(|&j| (last..t).contains(&frames[j].timestamp_us))
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
    Some(s0.lerp(s1, w))
}
