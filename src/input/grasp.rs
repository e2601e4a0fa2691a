//! Where and when a recorded hand grasps: computed from the recording
//! itself, so an object can be placed in the hand of any recording.

use super::playback::Playback;
use glam::Vec3;

/// The grasp of a recording.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GraspSite {
    /// Where the thumb and the fingertips converge at the most closed
    /// instant (world, m).
    pub point: Vec3,
    /// The most closed instant (s).
    pub closed_at: f64,
    /// When the closing that ends in the most closed instant passed three
    /// quarters of the way from the widest to the closest aperture (s).
    pub closing_at: f64,
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

/// Finds the grasp by sampling the playback every `step` seconds. The site
/// is the midpoint between the thumb tip and the mean of the fingertips
/// that have converged on it: those no farther from the thumb than the
/// nearest one plus one finger width. `None` if no hand is ever tracked.
pub fn find_grasp(playback: &Playback, step: f64) -> Option<GraspSite> {
    let mut best: Option<(f32, f64, usize, [Vec3; 5], f32)> = None;
    let mut widest = 0.0f32;
    let samples = (playback.duration / step).floor() as usize + 1;
    for track in 0..playback.tracks.len() {
        for i in 0..samples {
            let t = i as f64 * step;
            let Some(s) = playback.sample(track, t) else { continue };
            let tip = tips(&s.pose);
            let a = aperture(&tip);
            widest = widest.max(a);
            if best.is_none_or(|b| a < b.0) {
                best = Some((a, t, track, tip, 2.0 * s.pose.fingers[1][2].radius));
            }
        }
    }
    let (closest, closed_at, track, tip, finger_width) = best?;
    let converged: Vec<Vec3> = tip[1..].iter().copied().filter(|t| t.distance(tip[0]) <= closest + finger_width).collect();
    let fingers = converged.iter().copied().sum::<Vec3>() / converged.len().max(1) as f32;
    let threshold = closest + 0.25 * (widest - closest);
    // Walk back from the most closed instant while the hand stays closed.
    let closed = |t: f64| playback.sample(track, t).is_some_and(|s| aperture(&tips(&s.pose)) <= threshold);
    let mut closing_at = closed_at;
    while closing_at - step >= 0.0 && closed(closing_at - step) {
        closing_at -= step;
    }
    Some(GraspSite {
        point: 0.5 * (tip[0] + fingers),
        closed_at,
        closing_at,
        aperture_range: (widest, closest),
        track,
    })
}
