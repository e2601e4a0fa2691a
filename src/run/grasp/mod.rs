//! Where and when a recorded hand grasps: computed from the recording
//! itself (the tracker's grab and pinch strengths where it reports them,
//! the fingers' curl and the thumb-to-fingertip aperture from the joints),
//! so an object can be placed in the hand of any recording.

pub mod spans;

use crate::hand::HandSample;
use crate::input::playback::Playback;
use glam::{Mat3, Quat, Vec3};
use spans::{CLOSES_TO, Signal, Signals, Span};

/// The grasp of a recording: one closing of one hand.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct GraspSite {
    /// Where the thumb and the fingertips converge at the most closed
    /// instant (world, m).
    pub point: Vec3,
    /// How an object there is turned to sit in the grasp (`grasp_point`).
    pub rotation: Quat,
    /// When the hand was closed ([`spans::hold`]): from `closing_at` until
    /// `opening_at`, the last instant before it opened by the tracker's
    /// strengths or the curl, whichever came first (by the aperture only
    /// when neither closed it) (s).
    pub closing_at: f64,
    /// See `closing_at` (s).
    pub opening_at: f64,
    /// The most closed instant of the hold (the narrowest aperture), where
    /// the object's site is taken (s).
    pub closed_at: f64,
    /// When every signal had let the hand go: the closing's end (s).
    pub open_at: f64,
    /// The hand's most open instant between the previous closing of its
    /// track (or the recording's start) and this one (s): when an object
    /// can appear at the site with the fingers farthest from it.
    pub widest_before: f64,
    /// The signals that found the closing.
    pub signals: Signals,
    /// Whether some signal kept the hand closed for [`MIN_HOLD`]; if not,
    /// the closing is a twitch or a flicker, too short to judge, and
    /// `closing_at`–`opening_at` is its longest firm part.
    pub sustained: bool,
    /// The track (hand) that grasps.
    pub track: usize,
}

impl GraspSite {
    /// How long the hand held (s).
    pub fn hold(&self) -> f64 {
        self.opening_at - self.closing_at
    }
}

/// A closing shorter than this (s) gets no verdict: it is a twitch or a
/// tracker's flicker. A grip takes about this long to load an object
/// before it holds it (the loading phase of a precision lift, Johansson &
/// Westling 1984).
pub const MIN_HOLD: f64 = 0.15;

/// How often a recording is sampled to find its closings (s): finer than
/// any tracker's frame interval, so no closing falls between samples.
pub const SAMPLE_STEP: f64 = 0.005;

/// How long a tracker's grab or pinch strength must stay at or above
/// [`spans::STRENGTH_CLOSED`] for the tracker itself to report a hold (s):
/// longer than [`MIN_HOLD`], so every such hold is long enough to judge.
pub const TRACKER_HOLD: f64 = 0.2;

/// The holds the tracker itself reports for `track`'s hand: each span (s)
/// in which its grab or pinch strength stays at or above
/// [`spans::STRENGTH_CLOSED`] for at least [`TRACKER_HOLD`], sampled every
/// [`SAMPLE_STEP`]. None for a tracker that reports no strengths.
pub fn tracker_holds(playback: &Playback, track: usize) -> Vec<(f64, f64)> {
    let samples = (playback.duration / SAMPLE_STEP).floor() as usize + 1;
    let closed = |k: usize| {
        let hand = playback.sample(track, k as f64 * SAMPLE_STEP);
        let strength = hand.map(|h| h.grab.unwrap_or(0.0).max(h.pinch.unwrap_or(0.0)));
        strength.is_some_and(|s| s >= spans::STRENGTH_CLOSED)
    };
    let mut out = Vec::new();
    let mut from = None;
    for k in 0..=samples {
        match (from, k < samples && closed(k)) {
            (None, true) => from = Some(k),
            (Some(first), false) => {
                let (a, b) = (first as f64 * SAMPLE_STEP, (k - 1) as f64 * SAMPLE_STEP);
                if b - a >= TRACKER_HOLD - 0.5 * SAMPLE_STEP {
                    out.push((a, b));
                }
                from = None;
            }
            _ => {}
        }
    }
    out
}

/// Whether a hand is closed in a power grasp (a fist) rather than a
/// precision one: the tracker's grab strength is at least ½, or, where it
/// reports none, the fingers' curl is.
pub fn is_power_grasp(hand: &HandSample) -> bool {
    hand.grab.unwrap_or_else(|| hand.pose.curl()) >= 0.5
}

/// The thumb tip and the four other fingertips of a pose (world, m).
fn tips(pose: &crate::hand::HandPose) -> [Vec3; 5] {
    pose.fingers.map(|f| f[2].b)
}

/// Thumb tip to nearest other fingertip (m).
fn aperture(tips: &[Vec3; 5]) -> f32 {
    tips[1..].iter().map(|t| t.distance(tips[0])).fold(f32::INFINITY, f32::min)
}

/// Where the object goes in a closed hand, and how it is turned.
///
/// * A power grasp ([`is_power_grasp`], a fist): between the palm's face
///   and the middle phalanges wrapped around it, the space a fist
///   encloses, turned with the palm.
/// * A precision grasp: the midpoint between the thumb tip and the mean of
///   the fingertips that have converged on it (no farther from the thumb
///   than the nearest one plus one finger width), turned so that its x
///   axis runs from the thumb to those fingertips and its y axis is as
///   near the palm's normal as that allows: a box is pinched on two
///   opposite faces, as a person turns what they pick up.
fn grasp_point(hand: &HandSample, reading: &Reading) -> (Vec3, Quat) {
    let pose = &hand.pose;
    let face = pose.palm_surface();
    let palm = pose.palm.rotation;
    if is_power_grasp(hand) {
        let middles = (1..5).map(|f| pose.fingers[f][1].centroid()).sum::<Vec3>() / 4.0;
        return (0.5 * (face + middles), palm);
    }
    let tip = &reading.tips;
    let converged: Vec<Vec3> = tip[1..]
        .iter()
        .copied()
        .filter(|t| t.distance(tip[0]) <= reading.aperture + reading.finger_width)
        .collect();
    let fingers = converged.iter().copied().sum::<Vec3>() / converged.len().max(1) as f32;
    let point = 0.5 * (tip[0] + fingers);
    let turned = (fingers - tip[0]).try_normalize().and_then(|x| {
        let normal = palm * Vec3::Y;
        let y = (normal - normal.dot(x) * x).try_normalize()?;
        Some(Quat::from_mat3(&Mat3::from_cols(x, y, x.cross(y))).normalize())
    });
    (point, turned.unwrap_or(palm))
}

/// The site the grasp point takes for `track`'s hand at `t`, and the
/// hand's aperture then (m): `None` where the hand is not tracked.
pub fn site_at(playback: &Playback, track: usize, t: f64) -> Option<(Vec3, Quat, f32)> {
    let hand = playback.sample(track, t)?;
    let reading = Reading::of(&hand);
    let (point, rotation) = grasp_point(&hand, &reading);
    Some((point, rotation, reading.aperture))
}

/// A hand at one sample: its fingertips and what each signal reads.
#[derive(Debug, Clone, Copy)]
struct Reading {
    tips: [Vec3; 5],
    /// Thumb tip to nearest fingertip (m).
    aperture: f32,
    /// The index fingertip's width (m).
    finger_width: f32,
    curl: f32,
    grab: Option<f32>,
    pinch: Option<f32>,
}

impl Reading {
    fn of(hand: &HandSample) -> Reading {
        let tips = tips(&hand.pose);
        Reading {
            tips,
            aperture: aperture(&tips),
            finger_width: 2.0 * hand.pose.fingers[1][2].radius,
            curl: hand.pose.curl(),
            grab: hand.grab,
            pinch: hand.pinch,
        }
    }
}

/// Every signal's spans of one track ([`spans`]): the tracker's grab and
/// pinch strengths where it reports them, the curl and the aperture
/// always.
fn signal_spans(series: &[Option<Reading>]) -> Vec<Span> {
    let of = |f: fn(&Reading) -> Option<f32>| -> Vec<Option<f32>> {
        series.iter().map(|r| r.as_ref().and_then(f)).collect()
    };
    let mut out = spans::strength_spans(Signal::Grab, &of(|r| r.grab));
    out.extend(spans::strength_spans(Signal::Pinch, &of(|r| r.pinch)));
    out.extend(spans::excursion_spans(Signal::Curl, &of(|r| Some(r.curl)), spans::curl_rise));
    // The aperture negated is a closedness: halving from `open` is a rise
    // of half its width.
    let closedness = of(|r| Some(-r.aperture));
    out.extend(spans::excursion_spans(Signal::Aperture, &closedness, |open| -CLOSES_TO * open));
    out
}

/// Finds every grasp (closing of a hand) of a recording by sampling it
/// every `step` seconds ([`SAMPLE_STEP`] for the replays' closings).
///
/// Each signal the recording has finds its own closings ([`spans`]); those
/// of one hand that overlap, or that are less than the playback's grace
/// apart (the gap it bridges as one continuous track), are one closing,
/// found by all of them. Its site is taken at its most closed instant, by
/// `grasp_point`. Grasps come in time order.
pub fn find_grasps(playback: &Playback, step: f64) -> Vec<GraspSite> {
    let samples = (playback.duration / step).floor() as usize + 1;
    let bridge = (playback.grace / step).round() as usize;
    let min_len = (MIN_HOLD / step).round() as usize;
    let mut out = Vec::new();
    for track in 0..playback.tracks.len() {
        let series: Vec<Option<Reading>> = (0..samples)
            .map(|i| playback.sample(track, i as f64 * step).map(|s| Reading::of(&s)))
            .collect();
        let mut last_open = 0;
        for group in spans::union(signal_spans(&series), bridge) {
            let enter = group.iter().map(|s| s.enter).min().unwrap_or(0);
            let leave = group.iter().map(|s| s.leave).max().unwrap_or(enter);
            let held = spans::hold(&group, min_len);
            let longest = group.iter().max_by_key(|s| s.firm_len()).map(|s| s.firm);
            let Some((first, last)) = held.or(longest) else { continue };
            let narrowest = (first..=last)
                .filter_map(|k| series[k].map(|r| (k, r)))
                .min_by(|x, y| x.1.aperture.total_cmp(&y.1.aperture));
            let Some((k, reading)) = narrowest else { continue };
            let Some(hand) = playback.sample(track, k as f64 * step) else { continue };
            let (point, rotation) = grasp_point(&hand, &reading);
            let widest_before = (last_open..=enter.min(samples - 1))
                .filter_map(|k| series[k].map(|r| (k, r.aperture)))
                .max_by(|x, y| x.1.total_cmp(&y.1))
                .map_or(enter, |(k, _)| k);
            last_open = leave.min(samples - 1);
            out.push(GraspSite {
                point,
                rotation,
                closing_at: first as f64 * step,
                opening_at: last as f64 * step,
                closed_at: k as f64 * step,
                open_at: leave as f64 * step,
                widest_before: widest_before as f64 * step,
                signals: spans::signals(&group),
                sustained: held.is_some(),
                track,
            });
        }
    }
    out.sort_by(|a, b| a.closing_at.total_cmp(&b.closing_at));
    out
}
