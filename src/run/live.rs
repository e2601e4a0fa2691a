//! The live path: a Leap Motion service's WebSocket stream, as hand
//! sources for the driver. Frames are read as the physics clock needs
//! them, and poses are interpolated between them on the physics clock, with
//! short dropouts bridged as a replay does.

use super::RunError;
use super::drive::{self, Driver, HandSource, Observer};
use super::observe::{ObjectSummary, Summary};
use crate::hand::{HandSample, Side};
use crate::input::TrackingFrame;
use crate::input::convert::Conversion;
use crate::input::live::LiveLeap;
use crate::input::playback::interpolate;
use crate::input::skeleton::hand_pose;
use crate::pipeline::InteractionWorld;
use std::cell::RefCell;
use std::collections::BTreeSet;
use std::rc::Rc;

/// Frames from a live stream, turned into each hand's recent samples.
pub struct LiveTracks {
    stream: LiveLeap,
    conversion: Conversion,
    grace: f64,
    /// The first frame's timestamp (µs): the clock's zero.
    start_us: Option<i64>,
    /// The newest frame's time (s), or −∞ before any.
    newest: f64,
    /// Per side (left, right): `(time, hand)` samples, oldest first.
    samples: [Vec<(f64, HandSample)>; 2],
    closed: bool,
    /// Tracker hand ids seen so far.
    pub ids_seen: BTreeSet<i64>,
    /// Frames whose timestamp went backwards (or is too far from the
    /// first to subtract), and hands that could not be posed or came twice
    /// for one side at one time, left out.
    pub dropped: usize,
    /// A frame that jumped ahead, with its time (s), until the next one
    /// confirms it.
    held: Option<(TrackingFrame, f64)>,
}

/// How far ahead of the newest frame (s) a frame may jump before the next
/// one must confirm it.
const JUMP_AHEAD: f64 = 1.0;

impl LiveTracks {
    /// Tracks from `stream`, converted by `conversion`; gaps up to `grace`
    /// (s) are bridged.
    pub fn new(stream: LiveLeap, conversion: Conversion, grace: f64) -> Self {
        LiveTracks {
            stream,
            conversion,
            grace,
            start_us: None,
            newest: f64::NEG_INFINITY,
            samples: [Vec::new(), Vec::new()],
            closed: false,
            ids_seen: BTreeSet::new(),
            dropped: 0,
            held: None,
        }
    }

    /// The stream itself (its frame and skip counts).
    pub fn stream(&self) -> &LiveLeap {
        &self.stream
    }

    /// Reads frames until one is at or after `t` (s), or the stream closes.
    ///
    /// A frame more than [`JUMP_AHEAD`] ahead of the newest is held back
    /// until the next one: if that comes back below it, the jump was a
    /// corrupt timestamp and is dropped. Taken at its word, it would make
    /// every later frame look stale and stop the clock reading the stream.
    fn read_until(&mut self, t: f64) -> Result<(), RunError> {
        while !self.closed && self.newest < t {
            let Some(frame) = self.stream.next_frame()? else {
                self.closed = true;
                if let Some((held, time)) = self.held.take() {
                    self.accept(&held, time);
                }
                break;
            };
            let start = *self.start_us.get_or_insert(frame.timestamp_us);
            // A timestamp too far from the first to subtract is corrupt.
            let Some(elapsed) = frame.timestamp_us.checked_sub(start) else {
                self.dropped += 1;
                continue;
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
                continue;
            }
            self.accept(&frame, time);
        }
        Ok(())
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

    /// The `side` hand at `t` (s), reading frames as needed.
    fn sample(&mut self, side: Side, t: f64) -> Result<Option<HandSample>, RunError> {
        self.read_until(t)?;
        let samples = &mut self.samples[side as usize];
        // Keep only the samples the clock can still need.
        let before = samples.partition_point(|s| s.0 <= t);
        if before > 1 {
            samples.drain(..before - 1);
        }
        Ok(interpolate(samples, t, self.grace))
    }
}

/// One hand of a live stream: the stream is shared by both hands.
pub struct LiveHand {
    /// The shared stream.
    pub tracks: Rc<RefCell<LiveTracks>>,
    /// Which hand.
    pub side: Side,
}

impl HandSource for LiveHand {
    fn side(&self) -> Side {
        self.side
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        self.tracks.borrow_mut().sample(self.side, t)
    }

    fn finished(&self) -> bool {
        self.tracks.borrow().closed
    }
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
    /// Frames or hands left out (time going backwards, unusable poses, a
    /// second hand of a side at one time).
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
    let tracks = Rc::new(RefCell::new(LiveTracks::new(LiveLeap::connect(url)?, conversion, grace)));
    let mut summary = Summary::new(world)?;
    let steps = (seconds / world.config().dt as f64).ceil() as usize;
    let mut driver = Driver::new(world);
    for side in [Side::Left, Side::Right] {
        driver.add_hand(LiveHand { tracks: Rc::clone(&tracks), side });
    }
    driver.run(steps, &mut drive::observers(vec![&mut summary], observers))?;
    let tracks = tracks.borrow();
    Ok(LiveSummary {
        url: url.to_string(),
        frames: tracks.stream.frames,
        skipped: tracks.stream.skipped,
        dropped: tracks.dropped,
        hands_seen: tracks.ids_seen.len(),
        simulated: driver.world().time(),
        contacts_begun: summary.contacts_begun,
        objects: summary.objects(driver.world())?,
    })
}
