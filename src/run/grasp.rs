//! Where and when a recorded hand grasps: computed from the recording
//! itself, so an object can be placed in the hand of any recording.

use crate::hand::HandSample;
use crate::input::playback::Playback;
use glam::{Mat3, Quat, Vec3};

/// The grasp of a recording.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct GraspSite {
    /// Where the thumb and the fingertips converge at the most closed
    /// instant (world, m).
    pub point: Vec3,
    /// How an object there is turned to sit in the grasp (`grasp_point`).
    pub rotation: Quat,
    /// The most closed instant (s).
    pub closed_at: f64,
    /// When the hand became three quarters closed (s).
    pub closing_at: f64,
    /// When it began to open: the last instant of the closing at which the
    /// aperture was within a fingertip's radius of its closest (s). Wider
    /// than that, the pads have left the faces they closed on.
    pub opening_at: f64,
    /// When it opened again past three quarters closed (s).
    pub open_at: f64,
    /// The hand's most open instant between the previous closing of its
    /// track opening (or the recording's start) and this closing (s): when
    /// an object can appear at the site with the fingers farthest from it.
    pub widest_before: f64,
    /// Thumb-to-nearest-fingertip distances at the widest and closest (m).
    pub aperture_range: (f32, f32),
    /// The track (hand) that grasps.
    pub track: usize,
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
/// * A power grasp (the tracker reports a grab strength of at least ½, a
///   fist): between the palm's face and the middle phalanges wrapped
///   around it, the space a fist encloses, turned with the palm.
/// * A precision grasp: the midpoint between the thumb tip and the mean of
///   the fingertips that have converged on it (no farther from the thumb
///   than the nearest one plus one finger width), turned so that its x
///   axis runs from the thumb to those fingertips and its y axis is as
///   near the palm's normal as that allows: a box is pinched on two
///   opposite faces, as a person turns what they pick up.
fn grasp_point(
    hand: &HandSample,
    tip: &[Vec3; 5],
    aperture: f32,
    finger_width: f32,
) -> (Vec3, Quat) {
    let pose = &hand.pose;
    let face = pose.palm_surface();
    let palm = pose.palm.rotation;
    if hand.grab.is_some_and(|g| g >= 0.5) {
        let middles = (1..5).map(|f| pose.fingers[f][1].centroid()).sum::<Vec3>() / 4.0;
        return (0.5 * (face + middles), palm);
    }
    let converged: Vec<Vec3> = tip[1..]
        .iter()
        .copied()
        .filter(|t| t.distance(tip[0]) <= aperture + finger_width)
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

/// How far a hand's aperture must shrink, as a fraction of its widest, for
/// it to close at all: a hand that never halves the distance from its
/// thumb tip to its nearest fingertip (a clap, a wave, a resting hand)
/// makes no grasp, however its aperture wavers.
pub const CLOSES_TO: f32 = 0.5;

/// How often a recording is sampled to find its closings (s): finer than
/// any tracker's frame interval, so no closing falls between samples.
pub const SAMPLE_STEP: f64 = 0.005;

/// Finds every grasp (closing of a hand) of a recording by sampling it
/// every `step` seconds ([`SAMPLE_STEP`] for the replays' closings).
///
/// A grasp is a stretch of time during which a hand is at least three
/// quarters of the way from its widest to its closest aperture (thumb tip
/// to nearest fingertip), on a track whose closest aperture is at most
/// [`CLOSES_TO`] of its widest. Its site is taken at its most closed
/// instant, by `grasp_point`. Grasps come in time order.
pub fn find_grasps(playback: &Playback, step: f64) -> Vec<GraspSite> {
    let samples = (playback.duration / step).floor() as usize + 1;
    let mut out = Vec::new();
    for track in 0..playback.tracks.len() {
        let series: Vec<Option<([Vec3; 5], f32, f32)>> = (0..samples)
            .map(|i| {
                playback.sample(track, i as f64 * step).map(|s| {
                    let tip = tips(&s.pose);
                    (tip, aperture(&tip), 2.0 * s.pose.fingers[1][2].radius)
                })
            })
            .collect();
        let apertures = series.iter().flatten().map(|s| s.1);
        let widest = apertures.clone().fold(0.0f32, f32::max);
        let closest = apertures.fold(f32::INFINITY, f32::min);
        if !closest.is_finite() || closest > CLOSES_TO * widest {
            continue;
        }
        let threshold = closest + 0.25 * (widest - closest);
        let mut last_open = 0;
        let mut i = 0;
        while i < samples {
            if !series[i].as_ref().is_some_and(|s| s.1 <= threshold) {
                i += 1;
                continue;
            }
            let start = i;
            while i < samples && series[i].as_ref().is_some_and(|s| s.1 <= threshold) {
                i += 1;
            }
            let most_closed = (start..i)
                .filter_map(|k| series[k].map(|s| (k, s)))
                .min_by(|x, y| x.1.1.total_cmp(&y.1.1));
            let Some((k, (tip, a, width))) = most_closed else { continue };
            let Some(hand) = playback.sample(track, k as f64 * step) else { continue };
            let (point, rotation) = grasp_point(&hand, &tip, a, width);
            let opening_at =
                (k..i).rfind(|&m| series[m].is_some_and(|s| s.1 <= a + 0.5 * width)).unwrap_or(k);
            let widest_before = (last_open..=start)
                .filter_map(|k| series[k].map(|s| (k, s.1)))
                .max_by(|x, y| x.1.total_cmp(&y.1))
                .map_or(start, |(k, _)| k);
            last_open = i.min(samples - 1);
            out.push(GraspSite {
                point,
                rotation,
                closed_at: k as f64 * step,
                closing_at: start as f64 * step,
                opening_at: opening_at as f64 * step,
                open_at: i as f64 * step,
                widest_before: widest_before as f64 * step,
                aperture_range: (widest, closest),
                track,
            });
        }
    }
    out.sort_by(|a, b| a.closing_at.total_cmp(&b.closing_at));
    out
}
