//! The live path: a Leap Motion service's WebSocket stream, as hand
//! sources for the driver, and poses interpolated between its frames on the
//! physics clock, with short dropouts bridged as a replay does.
//!
//! Two readers: [`LiveHand`] reads frames as the physics clock needs them,
//! so a headless run (`run_live`) steps exactly through the stream;
//! [`LiveFeedHand`] reads them on a thread of its own and never waits, for
//! an app whose physics clock runs on the wall clock (a Bevy app's fixed
//! loop, a viewer that may pause).

use super::RunError;
use super::drive::{self, Driver, HandSource, Observer};
use super::observe::{ObjectSummary, Summary};
use crate::hand::{HandSample, Side};
use crate::input::convert::Conversion;
use crate::input::live::LiveLeap;
use crate::input::playback::interpolate;
use crate::pipeline::InteractionWorld;
use std::collections::BTreeSet;
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};
use tracks::Tracks;

mod feed;
mod tracks;

pub use feed::{LiveFeed, LiveFeedHand, LiveStats, PLAYOUT_DELAY};

/// Frames from a live stream, turned into each hand's recent samples. It
/// reads the stream when the physics clock needs a frame, so it suits a
/// clock that waits for the stream (`run_live`); an app whose clock runs on
/// its own takes a [`LiveFeed`] instead.
pub struct LiveTracks {
    stream: LiveLeap,
    tracks: Tracks,
    grace: f64,
    closed: bool,
}

impl LiveTracks {
    /// Tracks from `stream`, converted by `conversion`; gaps up to `grace`
    /// (s) are bridged.
    pub fn new(stream: LiveLeap, conversion: Conversion, grace: f64) -> Self {
        LiveTracks { stream, tracks: Tracks::new(conversion), grace, closed: false }
    }

    /// The stream itself (its frame and skip counts).
    pub fn stream(&self) -> &LiveLeap {
        &self.stream
    }

    /// Tracker hand ids seen so far.
    pub fn ids_seen(&self) -> &BTreeSet<i64> {
        &self.tracks.ids_seen
    }

    /// Frames and hands left out (see [`LiveSummary::dropped`]).
    pub fn dropped(&self) -> usize {
        self.tracks.dropped
    }

    /// Reads frames until one is at or after `t` (s), or the stream closes.
    fn read_until(&mut self, t: f64) -> Result<(), RunError> {
        while !self.closed && self.tracks.newest < t {
            match self.stream.next_frame()? {
                Some(frame) => self.tracks.take(frame),
                None => {
                    self.closed = true;
                    self.tracks.close();
                }
            }
        }
        Ok(())
    }

    /// The `side` hand at `t` (s), reading frames as needed.
    fn sample(&mut self, side: Side, t: f64) -> Result<Option<HandSample>, RunError> {
        self.read_until(t)?;
        // Keep only the samples the clock can still need.
        self.tracks.forget_before(side, t);
        Ok(interpolate(&self.tracks.samples[side as usize], t, self.grace))
    }
}

/// One hand of a live stream: the stream is shared by both hands.
pub struct LiveHand {
    /// The shared stream.
    pub tracks: Arc<Mutex<LiveTracks>>,
    /// Which hand.
    pub side: Side,
}

impl HandSource for LiveHand {
    fn side(&self) -> Side {
        self.side
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        lock(&self.tracks).sample(self.side, t)
    }

    fn finished(&self) -> bool {
        lock(&self.tracks).closed
    }
}

/// The stream both hands share. Sampling returns errors rather than
/// panicking, so a poisoned lock is taken as it is, not panicked on again.
fn lock(tracks: &Mutex<LiveTracks>) -> MutexGuard<'_, LiveTracks> {
    tracks.lock().unwrap_or_else(PoisonError::into_inner)
}

/// What a live run did.
#[derive(Debug, Clone, serde::Serialize)]
pub struct LiveSummary {
    /// The stream's URL.
    pub url: String,
    /// Frames received and parsed.
    pub frames: usize,
    /// Messages skipped as malformed.
    pub skipped: usize,
    /// Frames or hands left out (stale frames, a jump ahead the next frame
    /// refuted, unusable poses, a second hand of a side at one time).
    pub dropped: usize,
    /// Distinct tracker hand ids seen.
    pub hands_seen: usize,
    /// Simulated time (s).
    pub simulated: f64,
    /// Contacts begun.
    pub contacts_begun: usize,
    /// What each object did.
    pub objects: Vec<ObjectSummary>,
}

/// Runs `world` on the live stream at `url` for `seconds` of tracking time,
/// or until the stream closes, with a left and a right hand; shows every
/// step to `observers`.
pub fn run_live(
    url: &str,
    world: &mut InteractionWorld,
    conversion: Conversion,
    grace: f64,
    seconds: f64,
    observers: &mut [&mut dyn Observer],
) -> Result<LiveSummary, RunError> {
    let tracks = Arc::new(Mutex::new(LiveTracks::new(LiveLeap::connect(url)?, conversion, grace)));
    let mut summary = Summary::new(world)?;
    let steps = (seconds / world.config().dt as f64).ceil() as usize;
    let mut driver = Driver::new(world);
    for side in [Side::Left, Side::Right] {
        driver.add_hand(LiveHand { tracks: Arc::clone(&tracks), side });
    }
    driver.run(steps, &mut drive::observers(vec![&mut summary], observers))?;
    let tracks = lock(&tracks);
    Ok(LiveSummary {
        url: url.to_string(),
        frames: tracks.stream.frames,
        skipped: tracks.stream.skipped,
        dropped: tracks.dropped(),
        hands_seen: tracks.ids_seen().len(),
        simulated: driver.world().time(),
        contacts_begun: summary.contacts_begun,
        objects: summary.objects(driver.world())?,
    })
}
