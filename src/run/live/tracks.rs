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

/// How many frames in a row, each after the one before but all behind the
/// newest, show that the tracker's clock restarted (or that the newest
/// was a corrupt timestamp the stream never followed).
const RESTART_AFTER: usize = 5;

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
    /// Frames left out: behind the newest, or a jump ahead the next frame
    /// refuted; and hands that could not be posed or came twice for one
    /// side at one time.
    pub(super) dropped: usize,
    /// A frame that jumped ahead, with its time (s), until the next one
    /// confirms it.
    held: Option<(TrackingFrame, f64)>,
    /// The latest timestamp (µs) of the frames in a row behind the newest,
    /// and how many there were.
    behind: Option<(i64, usize)>,
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
            behind: None,
        }
    }

    /// Takes the stream's next frame.
    ///
    /// A frame more than [`JUMP_AHEAD`] ahead of the newest is held back
    /// until the next one: if that comes back below it, the jump was a
    /// corrupt timestamp and is dropped. Taken at its word, it would make
    /// every later frame look stale and stop the clock reading the stream.
    /// A frame behind the newest is stale and dropped, unless
    /// [`RESTART_AFTER`] come in a row running on among themselves: then
    /// the tracker's clock restarted, and its frames play on from the
    /// newest.
    pub(super) fn take(&mut self, frame: TrackingFrame) {
        let start = *self.start_us.get_or_insert(frame.timestamp_us);
        let mut time = seconds_since(start, frame.timestamp_us);
        if let Some((held, held_time)) = self.held.take() {
            if time < held_time {
                self.dropped += 1; // the held jump was the glitch
            } else {
                self.accept(&held, held_time);
            }
        }
        if time < self.newest {
            let run = match self.behind {
                Some((last, run)) if frame.timestamp_us > last => run + 1,
                _ => 1,
            };
            self.behind = Some((frame.timestamp_us, run));
            if run < RESTART_AFTER {
                self.dropped += 1;
                return;
            }
            // The new clock's zero, so that this frame is a microsecond
            // after the newest.
            let newest_us = ((self.newest * 1e6).round() as i64).saturating_add(1);
            let start = frame.timestamp_us.saturating_sub(newest_us);
            self.start_us = Some(start);
            time = seconds_since(start, frame.timestamp_us);
        }
        self.behind = None;
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
                    let sample = hand.sample(pose);
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

/// A timestamp (µs) on the clock whose zero is `start_us`, in s.
fn seconds_since(start_us: i64, timestamp_us: i64) -> f64 {
    timestamp_us.saturating_sub(start_us) as f64 * 1e-6
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tracks after frames with no hands at `stamps` (µs).
    fn after(stamps: &[i64]) -> Tracks {
        let mut tracks = Tracks::new(Conversion::identity());
        for &timestamp_us in stamps {
            tracks.take(TrackingFrame { timestamp_us, hands: vec![] });
        }
        tracks
    }

    #[test]
    fn a_jump_ahead_is_refuted_by_a_next_frame_that_goes_back_even_behind_the_newest() {
        // 4 s ahead, then a stale frame, then the stream on time.
        let tracks = after(&[500, 11_500, 22_500, 4_022_500, 17_500, 33_500]);
        assert!((tracks.newest - 0.033).abs() < 1e-12, "{}", tracks.newest);
        assert_eq!(tracks.dropped, 2);
    }

    #[test]
    fn a_corrupt_first_timestamp_is_left_behind_once_the_stream_runs_on_without_it() {
        let real: Vec<i64> = (0..9).map(|k| 3_000_000 + k * 13_900).collect();
        let tracks = after(&[[7_000_000_000].as_slice(), &real].concat());
        // Four frames behind, then the fifth plays on a microsecond after
        // the newest, and the rest from there.
        assert_eq!(tracks.dropped, 4);
        assert!((tracks.newest - (1e-6 + 4.0 * 0.0139)).abs() < 1e-9, "{}", tracks.newest);
    }

    #[test]
    fn a_restarted_tracker_clock_is_followed_but_stale_frames_are_not() {
        let mut stamps: Vec<i64> = (0..20).map(|k| 80_000_000 + k * 8_000).collect();
        // Stale frames, never five in a row that run on: four, then an
        // on-time frame; five that repeat one timestamp, then another.
        stamps.extend([70_000_000, 70_000_100, 70_000_200, 70_000_300, 80_160_000]);
        stamps.extend([10, 10, 10, 10, 10, 80_170_000]);
        let stale = after(&stamps);
        assert!((stale.newest - 0.17).abs() < 1e-9, "{}", stale.newest);
        assert_eq!(stale.dropped, 9);
        // The tracker restarts its clock near zero and runs on.
        stamps.extend((0..8).map(|k| 2_000 + k * 8_000));
        let restarted = after(&stamps);
        assert!((restarted.newest - (0.17 + 1e-6 + 3.0 * 0.008)).abs() < 1e-9);
        assert_eq!(restarted.dropped, 9 + 4);
    }
}
