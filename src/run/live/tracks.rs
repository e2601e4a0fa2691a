//! A live stream's frames as each hand's recent samples on the stream's own
//! clock: what both the blocking reader ([`super::LiveTracks`]) and the
//! threaded one ([`super::feed::LiveFeed`]) keep.

use crate::hand::{HandSample, Side};
use crate::input::TrackingFrame;
use crate::input::convert::Conversion;
use crate::input::skeleton::hand_pose;
use std::collections::BTreeSet;

/// How far ahead of the newest frame (s) a frame may jump before the next
/// one must confirm it.
const JUMP_AHEAD: f64 = 1.0;

/// Each hand's samples, timed from the stream's first frame (s).
pub(super) struct Tracks {
    conversion: Conversion,
    /// The first frame's timestamp (µs): the clock's zero.
    start_us: Option<i64>,
    /// The newest accepted frame's time (s), or −∞ before any.
    pub(super) newest: f64,
    /// Per side (left, right): `(time, hand)` samples, oldest first.
    pub(super) samples: [Vec<(f64, HandSample)>; 2],
    /// Tracker hand ids seen so far.
    pub(super) ids_seen: BTreeSet<i64>,
    /// Frames whose timestamp went backwards (or is too far from the first
    /// to subtract), and hands that could not be posed or came twice for
    /// one side at one time, left out.
    pub(super) dropped: usize,
    /// A frame that jumped ahead, with its time (s), until the next one
    /// confirms it.
    held: Option<(TrackingFrame, f64)>,
}

impl Tracks {
    pub(super) fn new(conversion: Conversion) -> Tracks {
        Tracks {
            conversion,
            start_us: None,
            newest: f64::NEG_INFINITY,
            samples: [Vec::new(), Vec::new()],
            ids_seen: BTreeSet::new(),
            dropped: 0,
            held: None,
        }
    }

    /// Takes the stream's next frame.
    ///
    /// A frame more than [`JUMP_AHEAD`] ahead of the newest is held back
    /// until the next one: if that comes back below it, the jump was a
    /// corrupt timestamp and is dropped. Taken at its word, it would make
    /// every later frame look stale and stop the clock reading the stream.
    pub(super) fn take(&mut self, frame: TrackingFrame) {
        let start = *self.start_us.get_or_insert(frame.timestamp_us);
        // A timestamp too far from the first to subtract is corrupt.
        let Some(elapsed) = frame.timestamp_us.checked_sub(start) else {
            self.dropped += 1;
            return;
        };
        let time = elapsed as f64 * 1e-6;
        if let Some((held, held_time)) = self.held.take() {
            if time < held_time && time >= self.newest {
                self.dropped += 1; // the held jump was the glitch
            } else {
                self.accept(&held, held_time);
            }
        }
        if time > self.newest.max(0.0) + JUMP_AHEAD {
            self.held = Some((frame, time));
            return;
        }
        self.accept(&frame, time);
    }

    /// The stream closed: a frame held back is all there is, so it counts.
    pub(super) fn close(&mut self) {
        if let Some((held, time)) = self.held.take() {
            self.accept(&held, time);
        }
    }

    /// Takes a frame's hands at `time` (s), unless it goes backwards.
    fn accept(&mut self, frame: &TrackingFrame, time: f64) {
        if time < self.newest {
            self.dropped += 1;
            return;
        }
        self.newest = time;
        for hand in &frame.hands {
            self.ids_seen.insert(hand.id);
            match hand_pose(hand, &self.conversion) {
                Ok(pose) if pose.validate(0).is_ok() => {
                    let sample = HandSample { pose, grab: hand.grab, pinch: hand.pinch };
                    let side = &mut self.samples[hand.side as usize];
                    // A second hand of the same side in one frame (or at
                    // one time) is a tracker's mistake: the first counts.
                    if side.last().is_none_or(|(last, _)| *last < time) {
                        side.push((time, sample));
                    } else {
                        self.dropped += 1;
                    }
                }
                _ => self.dropped += 1,
            }
        }
    }

    /// Forgets the `side` hand's samples that no time from `t` (s) on can
    /// need: all but the newest at or before `t`.
    pub(super) fn forget_before(&mut self, side: Side, t: f64) {
        let samples = &mut self.samples[side as usize];
        let before = samples.partition_point(|s| s.0 <= t);
        if before > 1 {
            samples.drain(..before - 1);
        }
    }
}
