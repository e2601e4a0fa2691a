//! The hand that acts: the tracked hand as the contacts see it.
//!
//! A tracker reports every joint with an error that changes from frame to
//! frame, a few millimetres for many trackers. A real hand does not
//! shake so: the jitter is the tracker's. Given to the contacts as it is,
//! it stretches each pad's friction spring past its cone and lifts pads
//! off for a few milliseconds, and each slip lets the held object down a
//! little, until it falls out of the grip (the book's "Tracking noise").
//! So the hand that acts is the tracked hand with the jitter taken out,
//! as far as that can be done without lagging the hand: every point goes
//! through a 1€ filter ([`super::one_euro`]) whose speed is counted in the
//! tracker's own jitter, measured on the hand as it is tracked
//! ([`super::jitter`]), less the hand's own tremor. A clean tracker's hand
//! acts exactly where it is tracked; a noisy tracker's is smoothed as
//! much as its jitter asks.
//!
//! The hand's gross motion and its shape are filtered apart. The gross
//! motion is the mean of the palm's centre and the four knuckles, points
//! that the fingers' articulation does not move; the shape is every point
//! less that mean, and the palm's turn. A hand that carries an object
//! moves fast while its grip keeps still: the gross filter follows the
//! carry, and the shape filter, whose point is then still, keeps the
//! grip's jitter out. A finger that moves, moves its shape points, and
//! they are followed as closely as their speed stands out of the jitter.
//! The shape's points share one smoothing, set by their rms speed, so the
//! two sides of a grip open together: a thumb that opened ahead of a
//! finger would push the object out instead of letting it go.
//!
//! A tracker whose every frame is off alike (white jitter, a webcam's
//! landmarks) is smoothed no slower than a white cutoff: what a faster
//! filter passes of it is small and alike every frame. A tracker whose
//! error is its rare glitches (a Leap's, fingers hidden in a fist) is
//! not: what a faster filter passes of a glitch is a finger thrown
//! centimetres. The jitter meter's whiteness tells one from the other
//! ([`super::jitter`], [`super::one_euro::WHITENESS_POWER`]).
//!
//! A point that keeps still acts exactly where it is tracked: the filters
//! keep lags, not positions.

use super::HandPose;
use super::jitter::{JitterMeter, tracker_jitter};
use super::one_euro::{EuroPoint, EuroStep, EuroTurn, OneEuro};
use glam::Vec3;

/// The points of a hand that are filtered: the palm's centre, then each
/// finger's capsules' two ends, thumb first, proximal first.
pub const POINTS: usize = 31;
/// Of [`POINTS`], the palm's centre and the four knuckles (the bases of
/// the index to little fingers): their mean is the hand's gross position.
const REFERENCE: [usize; 5] = [0, 7, 13, 19, 25];

/// How the hand that acts follows the tracked hand.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TrackingFilter {
    /// The hand's gross motion: the mean of its palm's centre and knuckles.
    /// Followed closely: 15 ms behind a hand that moves 20 cm/s under a
    /// jitter of 0.5 mm.
    pub gross: OneEuro,
    /// Its shape: each point less that mean, and the palm's turn. Smoothed
    /// harder, since a grip that holds keeps its shape.
    pub shape: OneEuro,
    /// How long the tracker's jitter is measured over (s): its median over
    /// this window ([`super::jitter`]).
    pub jitter_window: f32,
}

impl Default for TrackingFilter {
    fn default() -> Self {
        TrackingFilter {
            gross: OneEuro {
                min_cutoff: 1.0,
                beta: 0.025,
                derivative_cutoff: 1.0,
                least_cutoff: 0.0,
                white_cutoff: 10.0,
            },
            shape: OneEuro {
                min_cutoff: 1.0,
                beta: 0.0025,
                derivative_cutoff: 1.0,
                least_cutoff: 2.0,
                white_cutoff: 4.5,
            },
            jitter_window: 2.0,
        }
    }
}

/// The longest jitter window (s): a minute at 100 samples a second.
const MAX_JITTER_WINDOW: f32 = 60.0;

impl TrackingFilter {
    /// Checks every field; the error names the first bad one as
    /// [`crate::InteractionConfig`] names it (`tracking.gross.beta`).
    pub fn validate(&self) -> Result<(), (&'static str, String)> {
        self.gross.validate([
            "tracking.gross.min_cutoff",
            "tracking.gross.beta",
            "tracking.gross.derivative_cutoff",
            "tracking.gross.least_cutoff",
            "tracking.gross.white_cutoff",
        ])?;
        self.shape.validate([
            "tracking.shape.min_cutoff",
            "tracking.shape.beta",
            "tracking.shape.derivative_cutoff",
            "tracking.shape.least_cutoff",
            "tracking.shape.white_cutoff",
        ])?;
        let w = self.jitter_window;
        if !(w.is_finite() && w > 0.0 && w <= MAX_JITTER_WINDOW) {
            let why = format!("must be in (0, {MAX_JITTER_WINDOW}] s, got {w}");
            return Err(("tracking.jitter_window", why));
        }
        Ok(())
    }
}

/// Of [`POINTS`], the base of finger `f`'s capsule `p`; its end is the
/// next.
fn base_index(f: usize, p: usize) -> usize {
    1 + 6 * f + 2 * p
}

/// A pose's [`POINTS`] (world, m).
fn points(pose: &HandPose) -> [Vec3; POINTS] {
    let mut out = [pose.palm.center; POINTS];
    for (f, finger) in pose.fingers.iter().enumerate() {
        for (p, bone) in finger.iter().enumerate() {
            out[base_index(f, p)] = bone.a;
            out[base_index(f, p) + 1] = bone.b;
        }
    }
    out
}

/// The hand's gross position: the mean of its [`REFERENCE`] points (m).
fn gross_position(points: &[Vec3; POINTS]) -> Vec3 {
    REFERENCE.iter().map(|&k| points[k]).sum::<Vec3>() / REFERENCE.len() as f32
}

/// One hand's filters and jitter meters.
#[derive(Debug, Clone)]
pub struct ActingHand {
    filter: TrackingFilter,
    gross: EuroPoint,
    shape: [EuroPoint; POINTS],
    turn: EuroTurn,
    gross_jitter: JitterMeter<1>,
    shape_jitter: JitterMeter<POINTS>,
    /// Every filter still and without lag: the hand acts exactly where it
    /// is tracked, and a pose that does not change changes nothing.
    at_rest: bool,
}

impl ActingHand {
    /// A hand not yet tracked, followed by `filter`.
    pub fn new(filter: TrackingFilter) -> ActingHand {
        ActingHand {
            filter,
            gross: EuroPoint::default(),
            shape: [EuroPoint::default(); POINTS],
            turn: EuroTurn::new(glam::Quat::IDENTITY),
            gross_jitter: JitterMeter::new(filter.jitter_window),
            shape_jitter: JitterMeter::new(filter.jitter_window),
            at_rest: true,
        }
    }

    /// The tracker's jitter as measured on this hand's shape (m, rms per
    /// axis as white noise would give it; [`super::jitter`]).
    pub fn jitter(&self) -> f32 {
        self.shape_jitter.jitter()
    }

    /// Follows a hand that was not tracked: it acts where it is tracked.
    /// The jitter measured so far is kept, as the tracker's.
    pub fn begin(&mut self, tracked: &HandPose) {
        let raw = points(tracked);
        let gross = gross_position(&raw);
        self.gross = EuroPoint::new(gross);
        self.shape = raw.map(|x| EuroPoint::new(x - gross));
        self.turn = EuroTurn::new(tracked.palm.rotation);
        self.at_rest = true;
        self.gross_jitter.break_path();
        self.shape_jitter.break_path();
        self.observe(gross, &raw.map(|x| x - gross), 0.0);
    }

    fn observe(&mut self, gross: Vec3, shape: &[Vec3; POINTS], dt: f32) {
        self.gross_jitter.observe(&[gross], dt);
        self.shape_jitter.observe(shape, dt);
    }

    /// The hand that acts `dt` (s) after the last call, for the hand
    /// `tracked` now, written into `acting` (the last one). Returns whether
    /// it changed.
    ///
    /// A hand at rest whose tracked pose has not changed is left as it is:
    /// its filters would compute what they hold, and a repeated report (a
    /// tracker holding its last frame) tells nothing new of the jitter.
    pub fn advance(&mut self, tracked: &HandPose, acting: &mut HandPose, dt: f32) -> bool {
        if self.at_rest && tracked == acting {
            return false;
        }
        let raw = points(tracked);
        let gross = gross_position(&raw);
        let shape = raw.map(|x| x - gross);
        self.observe(gross, &shape, dt);
        let gross_step = self.filter.gross.step(
            tracker_jitter(self.gross_jitter.jitter()),
            self.gross_jitter.whiteness(),
            dt,
        );
        let shape_step = self.filter.shape.step(
            tracker_jitter(self.jitter()),
            self.shape_jitter.whiteness(),
            dt,
        );
        let behind = self.gross.advance(gross, &gross_step);
        let lags = self.advance_shape(&shape, behind, &shape_step);
        let palm_extents = tracked.palm.half_extents;
        let rotation =
            self.turn.advance(tracked.palm.rotation, &shape_step, palm_extents.max_element());
        self.at_rest = self.gross.at_rest()
            && self.shape.iter().all(EuroPoint::at_rest)
            && self.turn.at_rest();
        let mut changed = false;
        let mut set = |to: &mut Vec3, at: Vec3| {
            changed |= *to != at;
            *to = at;
        };
        set(&mut acting.palm.center, raw[0] + lags[0]);
        for (f, finger) in acting.fingers.iter_mut().enumerate() {
            for (p, bone) in finger.iter_mut().enumerate() {
                let a = base_index(f, p);
                set(&mut bone.a, raw[a] + lags[a]);
                set(&mut bone.b, raw[a + 1] + lags[a + 1]);
            }
        }
        changed |= acting.palm.rotation != rotation || acting.palm.half_extents != palm_extents;
        acting.palm.rotation = rotation;
        acting.palm.half_extents = palm_extents;
        for (finger, tracked) in acting.fingers.iter_mut().zip(&tracked.fingers) {
            for (bone, tracked) in finger.iter_mut().zip(tracked) {
                changed |= bone.radius != tracked.radius;
                bone.radius = tracked.radius;
            }
        }
        changed
    }

    /// Each shape point's lag behind the tracked point, with the gross
    /// motion's lag `behind` (m). The shape's points share one smoothing
    /// factor, from the rms of their speeds: the hand's shape moves as one,
    /// and the two sides of a grip that opens let go together, as a still
    /// hand's pads do ([`crate::friction::grip`]). A capsule's base is the
    /// end of the one before it in a tracker's hand: where they are the
    /// same point, with the same filter state, the one result serves both.
    fn advance_shape(
        &mut self,
        shape: &[Vec3; POINTS],
        behind: Vec3,
        step: &EuroStep,
    ) -> [Vec3; POINTS] {
        let mut twins = [false; POINTS];
        let mut squares = 0.0;
        let mut twin = (Vec3::NAN, EuroPoint::default());
        for k in 0..POINTS {
            let before = self.shape[k];
            twins[k] = is_joined_base(k) && twin == (shape[k], before);
            let speed = if twins[k] {
                self.shape[k] = self.shape[k - 1];
                self.shape[k].speed()
            } else {
                self.shape[k].track(shape[k], step)
            };
            squares += speed * speed;
            twin = (shape[k], before);
        }
        let alpha = step.alpha((squares / POINTS as f32).sqrt());
        let mut lags = [Vec3::ZERO; POINTS];
        for k in 0..POINTS {
            lags[k] = if twins[k] {
                self.shape[k] = self.shape[k - 1];
                lags[k - 1]
            } else {
                behind + self.shape[k].follow(shape[k], alpha)
            };
        }
        lags
    }
}

/// Whether point `k` of [`POINTS`] is the base of a finger's second or
/// third capsule, which a tracker's hand joins to the end of the capsule
/// before it (point `k − 1`).
fn is_joined_base(k: usize) -> bool {
    k > 0 && (k - 1) % 6 >= 2 && (k - 1).is_multiple_of(2)
}
