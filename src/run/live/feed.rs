//! A live stream read on a thread of its own, for a host whose physics
//! clock runs on the wall clock and must never wait for the network: a
//! Bevy app's fixed loop, a viewer that pauses and seeks.
//!
//! The host's clock and the stream's are tied at the first sample: the
//! hand is played [`PLAYOUT_DELAY`] behind the newest frame, so each
//! physics step finds a frame on each side of it to interpolate between.
//! When the two clocks part (the host paused, the stream jumped or fell
//! behind), the tie is made again.

use super::tracks::Tracks;
use crate::hand::{HandSample, Side};
use crate::input::InputError;
use crate::input::convert::Conversion;
use crate::input::live::LiveLeap;
use crate::input::playback::interpolate;
use crate::run::RunError;
use crate::run::drive::HandSource;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

/// How far behind the newest frame a live hand is played (s): two frame
/// intervals at 60 Hz, the slowest rate a Leap service streams at in its
/// usual modes, so there is a frame after the played time.
pub const PLAYOUT_DELAY: f64 = 2.0 / 60.0;

/// How far (s) the played time may fall behind its delay before it jumps
/// to the newest frames: past this, the host paused or the stream jumped.
const RESYNC: f64 = 0.25;

/// Samples further than this behind the newest frame (s) are forgotten
/// even when no hand asks for them, so a paused host keeps a bounded
/// buffer.
const KEEP: f64 = 1.0;

/// What the reader thread and the hands share.
struct Shared {
    tracks: Tracks,
    frames: usize,
    skipped: usize,
    closed: bool,
    /// Why the stream failed, if it did.
    error: Option<InputError>,
}

/// Sets the reader thread's stop flag when the last handle goes.
struct StopOnDrop(Arc<AtomicBool>);

impl Drop for StopOnDrop {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

/// A live Leap Motion stream read on its own thread: [`LiveFeed::hand`]
/// gives its hands as sources that never block. The thread ends when the
/// stream closes or fails, or when the feed and all its hands are dropped.
#[derive(Clone)]
pub struct LiveFeed {
    shared: Arc<Mutex<Shared>>,
    /// Held only to be dropped with the last handle.
    _stop: Arc<StopOnDrop>,
    grace: f64,
}

/// What a live feed has received so far.
#[derive(Debug, Clone, PartialEq)]
pub struct LiveStats {
    /// Frames received and parsed.
    pub frames: usize,
    /// Messages skipped as malformed.
    pub skipped: usize,
    /// Frames or hands left out (see [`super::LiveSummary::dropped`]).
    pub dropped: usize,
    /// Distinct tracker hand ids seen.
    pub hands_seen: usize,
    /// The newest frame's time from the stream's first (s), if any came.
    pub newest: Option<f64>,
    /// Whether the stream has ended.
    pub closed: bool,
    /// Why it failed, if it did.
    pub error: Option<InputError>,
}

impl std::fmt::Debug for LiveFeed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LiveFeed").field("stats", &self.stats()).finish()
    }
}

impl LiveFeed {
    /// Connects to the service at `url` (an error here is the caller's to
    /// show, before anything runs) and starts reading on a new thread.
    /// Poses are converted by `conversion`; gaps up to `grace` (s) are
    /// bridged.
    pub fn connect(url: &str, conversion: Conversion, grace: f64) -> Result<LiveFeed, InputError> {
        let stream = LiveLeap::connect(url)?;
        let feed = LiveFeed::unread(conversion, grace);
        let reader = (Arc::clone(&feed.shared), Arc::clone(&feed._stop.0));
        std::thread::Builder::new()
            .name("coulomb-hands live feed".into())
            .spawn(move || read(stream, &reader.0, &reader.1))
            .map_err(|e| InputError {
                source_name: url.to_string(),
                frame: None,
                field: "reader thread".into(),
                reason: e.to_string(),
            })?;
        Ok(feed)
    }

    /// A feed that nothing has read into yet.
    fn unread(conversion: Conversion, grace: f64) -> LiveFeed {
        let shared = Shared {
            tracks: Tracks::new(conversion),
            frames: 0,
            skipped: 0,
            closed: false,
            error: None,
        };
        let stop = StopOnDrop(Arc::new(AtomicBool::new(false)));
        LiveFeed { shared: Arc::new(Mutex::new(shared)), _stop: Arc::new(stop), grace }
    }

    /// The `side` hand alone, tied to the clock of whoever samples it
    /// first.
    pub fn hand(&self, side: Side) -> LiveFeedHand {
        self.hand_tied(side, Arc::default())
    }

    /// Both hands (left, right) on one tie to the host's clock, so that a
    /// frame arriving between their samples cannot set them a frame apart:
    /// what a two-handed grasp needs.
    pub fn hands(&self) -> [LiveFeedHand; 2] {
        let playout = Arc::default();
        [Side::Left, Side::Right].map(|side| self.hand_tied(side, Arc::clone(&playout)))
    }

    fn hand_tied(&self, side: Side, playout: Arc<Mutex<Playout>>) -> LiveFeedHand {
        LiveFeedHand { feed: self.clone(), side, playout }
    }

    /// What has been received so far.
    pub fn stats(&self) -> LiveStats {
        let shared = self.lock();
        LiveStats {
            frames: shared.frames,
            skipped: shared.skipped,
            dropped: shared.tracks.dropped,
            hands_seen: shared.tracks.ids_seen.len(),
            newest: shared.tracks.newest.is_finite().then_some(shared.tracks.newest),
            closed: shared.closed,
            error: shared.error.clone(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, Shared> {
        self.shared.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// The reader thread: frames into the shared tracks until the stream ends
/// or fails, or `stop` is set.
fn read(mut stream: LiveLeap, shared: &Mutex<Shared>, stop: &AtomicBool) {
    loop {
        let next = stream.next_frame_unless(stop);
        let mut shared = shared.lock().unwrap_or_else(PoisonError::into_inner);
        (shared.frames, shared.skipped) = (stream.frames, stream.skipped);
        match next {
            Ok(Some(frame)) => {
                shared.tracks.take(frame);
                let old = shared.tracks.newest - KEEP;
                for side in [Side::Left, Side::Right] {
                    shared.tracks.forget_before(side, old);
                }
            }
            Ok(None) => {
                shared.tracks.close();
                shared.closed = true;
                return;
            }
            Err(e) => {
                shared.error = Some(e);
                shared.closed = true;
                return;
            }
        }
    }
}

/// One hand of a [`LiveFeed`], for the driver. Sampling reads what the
/// thread has received and never waits; with no frame yet the hand is
/// untracked.
pub struct LiveFeedHand {
    feed: LiveFeed,
    side: Side,
    /// The tie to the host's clock, shared by the hands of one
    /// [`LiveFeed::hands`].
    playout: Arc<Mutex<Playout>>,
}

/// The tie between the host's clock and the stream's.
#[derive(Debug)]
struct Playout {
    /// Stream time minus host time (s), once tied.
    offset: Option<f64>,
    /// The newest frame's time at the last call (s); 0 before any.
    newest_seen: f64,
    /// The stream time last played (s), never past the newest frame; −∞
    /// before any.
    played: f64,
}

impl Default for Playout {
    fn default() -> Self {
        Playout { offset: None, newest_seen: 0.0, played: f64::NEG_INFINITY }
    }
}

impl Playout {
    /// The stream time (s) that host time `t` plays, given the newest
    /// frame's: `t` plus the tie, made again when the clocks have parted.
    fn at(&mut self, t: f64, newest: f64) -> f64 {
        let target = newest - PLAYOUT_DELAY;
        let arrived = newest > self.newest_seen;
        self.newest_seen = newest;
        if let Some(offset) = self.offset {
            let s = t + offset;
            // Behind: the host paused, or the stream jumped ahead. Ahead
            // although a frame just came: the host's clock ran faster, or
            // a stall ended.
            let behind = s < target - RESYNC;
            let ahead = arrived && s > newest + PLAYOUT_DELAY;
            if !behind && !ahead {
                return s;
            }
        }
        // Never back before what was played: the samples before it are
        // forgotten, and a hand played backwards would move against its
        // own motion.
        let tie = target.max(self.played);
        self.offset = Some(tie - t);
        tie
    }

    /// The `side` hand of `tracks` at host time `t` (s), forgetting the
    /// samples no later call can need. Past the newest frame (the stream
    /// is late), that frame is held for `grace` (s), as a gap between
    /// frames is bridged.
    fn sample(
        &mut self,
        tracks: &mut Tracks,
        side: Side,
        t: f64,
        grace: f64,
    ) -> Option<HandSample> {
        let newest = tracks.newest;
        if !newest.is_finite() {
            return None;
        }
        let s = self.at(t, newest);
        self.played = s.min(newest);
        if s - newest > grace {
            return None;
        }
        tracks.forget_before(side, self.played);
        interpolate(&tracks.samples[side as usize], self.played, grace)
    }
}

impl HandSource for LiveFeedHand {
    fn side(&self) -> Side {
        self.side
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        let mut shared = self.feed.lock();
        if let Some(e) = &shared.error {
            return Err(e.clone().into());
        }
        let mut playout = self.playout.lock().unwrap_or_else(PoisonError::into_inner);
        Ok(playout.sample(&mut shared.tracks, self.side, t, self.feed.grace))
    }

    /// The stream has closed and every frame has been played.
    fn finished(&self) -> bool {
        let shared = self.feed.lock();
        let played = self.playout.lock().unwrap_or_else(PoisonError::into_inner).played;
        shared.closed && shared.error.is_none() && played >= shared.tracks.newest
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{TrackedHand, TrackingFrame};
    use glam::Vec3;

    /// Plays `playout` at host times `t0 + k·dt` while frames come at
    /// `newest(k)`; returns the stream times played.
    fn play(playout: &mut Playout, ticks: &[(f64, f64)]) -> Vec<f64> {
        ticks.iter().map(|&(t, newest)| playout.at(t, newest)).collect()
    }

    #[test]
    fn a_steady_stream_is_played_at_its_delay_on_the_hosts_clock() {
        // The host at 1 kHz from 3.7 s, frames every 9 ms from 12.0 s.
        let mut playout = Playout::default();
        let ticks: Vec<(f64, f64)> =
            (0..300).map(|k| (3.7 + k as f64 * 1e-3, 12.0 + (k / 9 * 9) as f64 * 1e-3)).collect();
        let played = play(&mut playout, &ticks);
        for (k, s) in played.iter().enumerate() {
            let want = 12.0 - PLAYOUT_DELAY + k as f64 * 1e-3;
            assert!((s - want).abs() < 1e-9, "tick {k}: {s} for {want}");
        }
    }

    #[test]
    fn a_paused_host_jumps_to_the_newest_frames_and_a_stall_does_not() {
        let mut playout = Playout::default();
        assert!((playout.at(1.0, 5.0) - (5.0 - PLAYOUT_DELAY)).abs() < 1e-12);
        // The host's clock held for 0.6 s while frames kept coming.
        let s = playout.at(1.001, 5.6);
        assert!((s - (5.6 - PLAYOUT_DELAY)).abs() < 1e-12, "{s}");
        // No frame for 0.2 s is not a pause: the clock runs on.
        let s = playout.at(1.201, 5.6);
        assert!((s - (5.6 - PLAYOUT_DELAY + 0.2)).abs() < 1e-12, "{s}");
        // The stream stalls for 0.4 s more: the played time runs past it
        // (the hand is held, then lost), with no tie made again.
        let s = playout.at(1.601, 5.6);
        assert!((s - (5.6 - PLAYOUT_DELAY + 0.6)).abs() < 1e-12, "{s}");
    }

    #[test]
    fn a_host_clock_running_ahead_of_the_stream_is_tied_again_when_a_frame_comes() {
        let mut playout = Playout::default();
        playout.at(0.0, 2.0);
        // The host ran 50 ms further than the stream: a frame comes at
        // 2.05 s, while the played time is 2.1 − delay, past it by more than
        // the delay only if the host is 2·delay ahead, so not yet.
        let s = playout.at(0.1, 2.05);
        assert!((s - (2.1 - PLAYOUT_DELAY)).abs() < 1e-12, "{s}");
        // 0.2 s ahead: tied again to the new frame.
        let s = playout.at(0.3, 2.1);
        assert!((s - (2.1 - PLAYOUT_DELAY)).abs() < 1e-12, "{s}");
    }

    /// The first right hand of the bundled pinch recording.
    fn right_hand() -> TrackedHand {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/leap/pinch.json.lz");
        let recording = crate::input::leap::load(&path).unwrap();
        let mut hands = recording.frames.into_iter().flat_map(|f| f.hands);
        hands.find(|h| h.side == Side::Right).unwrap()
    }

    /// Frame `k` of a 120 Hz stream of `hand`.
    fn frame(hand: &TrackedHand, k: i64) -> TrackingFrame {
        TrackingFrame { timestamp_us: k * 8_333, hands: vec![hand.clone()] }
    }

    #[test]
    fn a_hand_held_through_a_stall_stays_tracked_when_the_backlog_comes() {
        // The host samples at 1 kHz from 7.3 s. The service goes quiet from
        // 150 ms to 240 ms (less than the 0.1 s grace), then sends its
        // backlog a frame per millisecond until it is on time again.
        let hand = right_hand();
        let mut tracks = Tracks::new(Conversion::leap_desktop(Vec3::ZERO));
        let mut playout = Playout::default();
        let (mut sent, mut last) = (0, f64::NEG_INFINITY);
        for ms in 0..400 {
            let due = (ms as f64 / 8.333) as i64 + 1; // frames stamped by now
            let quiet = (150..240).contains(&ms);
            while !quiet && sent < due {
                tracks.take(frame(&hand, sent));
                sent += 1;
                if ms >= 240 {
                    break; // the backlog: a frame per millisecond
                }
            }
            let sample = playout.sample(&mut tracks, Side::Right, 7.3 + ms as f64 * 1e-3, 0.1);
            // Tracked once the first frame lies a play-out delay behind.
            if ms as f64 * 1e-3 > PLAYOUT_DELAY {
                assert!(sample.is_some(), "lost at {ms} ms (played {})", playout.played);
            }
            assert!(playout.played >= last, "played backwards at {ms} ms");
            last = playout.played;
        }
        assert_eq!(sent, 48, "the backlog was sent");
    }

    #[test]
    fn the_hands_of_one_feed_share_one_tie_to_the_clock() {
        let hand = right_hand();
        let feed = LiveFeed::unread(Conversion::leap_desktop(Vec3::ZERO), 0.1);
        let take = |k: i64| feed.lock().tracks.take(frame(&hand, k));
        let played = |hand: &LiveFeedHand| hand.playout.lock().unwrap().played;
        (0..6).for_each(take);
        // A frame arrives between the left hand's sample and the right's.
        let [mut left, mut right] = feed.hands();
        left.sample(4.2).unwrap();
        take(6);
        assert!(right.sample(4.2).unwrap().is_some());
        assert_eq!(played(&left), played(&right));
        // Hands taken one by one are tied a frame apart.
        let (mut left, mut right) = (feed.hand(Side::Left), feed.hand(Side::Right));
        left.sample(9.1).unwrap();
        take(7);
        right.sample(9.1).unwrap();
        assert!((played(&right) - played(&left) - 8.333e-3).abs() < 1e-9);
    }
}
