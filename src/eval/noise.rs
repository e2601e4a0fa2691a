//! Tracking noise from real tracking, for the synthetic users.
//!
//! A tracker reports each joint of a hand with an error of its own, from
//! frame to frame: the grip's depth and its aperture flicker, which one
//! rigid shake of the whole hand would not do. So the noise is taken from
//! real recordings: each joint's position less its smoothed track, in the
//! palm's frame (and the palm's turn less its smoothed turn), frame by
//! frame. A synthetic user's tracked hand replays those residuals from a
//! stretch of one recorded hand, scaled, each finger laid from its knuckle
//! so that a scaled residual turns a bone as a tracker's skeleton does,
//! rather than stretching it ([`Residual::apply`]); and loses tracking as
//! often, and for as long, as the recordings' hands did.
//!
//! The smoothing is a Gaussian of σ = 30 ms, a cut-off near 5 Hz: voluntary
//! hand motion lies below it (Brooks 1990, "Telerobotic response
//! requirements": most of its energy under 5 Hz), tracker jitter above.
//! What a recording moves slower than that is the hand, not noise.
//!
//! Or the noise is white ([`TrackingNoise::white`]): every joint off by a
//! fresh Gaussian error each frame, the jitter of a tracker that fits each
//! frame anew (a webcam's landmarks), where a Leap's residuals are mostly
//! small with rare glitches of centimetres. The two load a grip
//! differently, and a filter must hold under both.

use crate::file_error::FileError;
use crate::hand::HandPose;
use crate::input::playback::DEFAULT_GRACE;
use crate::input::recording::{self, Recording};
use crate::run::RunError;
use glam::Vec3;
use rand::Rng;
use std::path::Path;

mod residual;
pub use residual::{MAX_STRETCH, Residual};
use residual::{joints, residual};

/// The Gaussian smoothing's σ (s): see the module doc.
pub const SMOOTHING: f64 = 0.03;
/// How far either side of a frame its smoothing window reaches (s): 3σ.
const WINDOW: f64 = 3.0 * SMOOTHING;
/// The shortest stretch of one tracked hand the noise is taken from (s).
pub const MIN_TRACK: f64 = 1.0;
/// A gap between two frames of a hand longer than this many times its
/// median frame interval is a dropout.
const DROPOUT_FACTOR: f64 = 2.5;
/// Residuals with less rms than this (m) are a recording's float rounding,
/// not a tracker's jitter: a micrometre, a hundredth of the best tracker's.
pub const JITTERLESS: f32 = 1.0e-6;
/// Joints per hand: the palm's centre, then four per digit, thumb first,
/// from the base of the proximal bone to the tip.
pub const JOINTS: usize = 21;

/// White noise: its rms per joint and axis at scale 1 (m).
const WHITE_RMS: f32 = 0.001;
/// White noise: the lever (m) over which a tracker reads the palm's turn
/// from its joints, so the turn's error per axis is the joints' over it.
const WHITE_LEVER: f32 = 0.1;
/// White noise: the residual tracks drawn, and their length (s). Longer
/// than a trial, and looped like a recording's.
const WHITE_TRACKS: usize = 4;
const WHITE_SECONDS: f64 = 30.0;
/// White noise: the tracker frame rates it can be drawn at (Hz).
pub const WHITE_RATES: std::ops::RangeInclusive<f32> = 10.0..=1000.0;

/// The bundled Leap Motion recordings (`data/leap`), built in, so the
/// study needs no files.
const BUNDLED: [(&str, &str); 4] = [
    ("data/leap/grab.json.lz", include_str!("../../data/leap/grab.json.lz")),
    ("data/leap/pinch.json.lz", include_str!("../../data/leap/pinch.json.lz")),
    ("data/leap/pinch-57fps.json.lz", include_str!("../../data/leap/pinch-57fps.json.lz")),
    ("data/leap/three-claps.json.lz", include_str!("../../data/leap/three-claps.json.lz")),
];

/// The residuals of one recorded hand, frame by frame.
#[derive(Debug, Clone)]
struct ResidualTrack {
    /// Frame times from the track's first (s).
    times: Vec<f64>,
    residuals: Vec<Residual>,
}

impl ResidualTrack {
    fn duration(&self) -> f64 {
        self.times.last().copied().unwrap_or(0.0)
    }

    /// The residual at `t` (s) from the track's start, interpolated, the
    /// track replayed in a loop.
    fn at(&self, t: f64) -> Residual {
        let t = t.rem_euclid(self.duration().max(1e-9));
        let after = self.times.partition_point(|&s| s <= t).min(self.times.len() - 1);
        let before = after.saturating_sub(1);
        let (t0, t1) = (self.times[before], self.times[after]);
        let w = if t1 > t0 { ((t - t0) / (t1 - t0)).clamp(0.0, 1.0) as f32 } else { 0.0 };
        self.residuals[before].lerp(&self.residuals[after], w)
    }
}

/// Real tracking noise: residual tracks and the recordings' dropouts.
#[derive(Debug, Clone)]
pub struct TrackingNoise {
    tracks: Vec<ResidualTrack>,
    /// Dropouts per second of tracked hand.
    pub dropout_rate: f64,
    /// The length of each dropout seen (s).
    pub dropout_lengths: Vec<f64>,
    /// The recordings it was taken from.
    pub sources: Vec<String>,
    /// The residuals' rms over every joint, axis and frame (m).
    pub rms: f32,
}

impl TrackingNoise {
    /// The noise of the bundled Leap Motion recordings.
    pub fn bundled() -> Result<TrackingNoise, RunError> {
        let recordings = BUNDLED
            .iter()
            .map(|(name, text)| recording::parse(name, text, false))
            .collect::<Result<Vec<_>, _>>()?;
        TrackingNoise::from_recordings(&recordings)
    }

    /// The noise of the recordings at `paths` (any format `replay`
    /// reads), or of the bundled ones if there are none.
    pub fn load(paths: &[impl AsRef<Path>]) -> Result<TrackingNoise, RunError> {
        if paths.is_empty() {
            return TrackingNoise::bundled();
        }
        let recordings =
            paths.iter().map(|p| recording::load(p.as_ref())).collect::<Result<Vec<_>, _>>()?;
        TrackingNoise::from_recordings(&recordings)
    }

    /// The noise a study asks for: white at `white_hz` frames a second
    /// ([`Self::white`]), or else that of the recordings at `paths` (the
    /// bundled ones if there are none). An error if it asks for both.
    pub fn choose(paths: &[impl AsRef<Path>], white_hz: Option<f32>) -> Result<Self, RunError> {
        match white_hz {
            None => TrackingNoise::load(paths),
            Some(_) if !paths.is_empty() => Err(RunError::Study {
                field: "noise-white",
                reason: "white noise is drawn, not taken from recordings: give one or the other"
                    .into(),
            }),
            Some(rate) => TrackingNoise::white(rate),
        }
    }

    /// The noise of `recordings`: every hand tracked for at least
    /// [`MIN_TRACK`] gives a residual track. An error names a recording
    /// none of whose hands does, or the first bad frame.
    pub fn from_recordings(recordings: &[Recording]) -> Result<TrackingNoise, RunError> {
        let mut noise = TrackingNoise {
            tracks: Vec::new(),
            dropout_rate: 0.0,
            dropout_lengths: Vec::new(),
            sources: Vec::new(),
            rms: 0.0,
        };
        let mut tracked = 0.0;
        for rec in recordings {
            let playback = rec.playback(Vec3::ZERO, DEFAULT_GRACE)?;
            let before = noise.tracks.len();
            for track in &playback.tracks {
                let samples = track.samples();
                let times: Vec<f64> = samples.iter().map(|s| s.0).collect();
                let duration = times.last().unwrap_or(&0.0) - times.first().unwrap_or(&0.0);
                if duration < MIN_TRACK {
                    continue;
                }
                tracked += duration;
                noise.dropout_lengths.extend(dropouts(&times));
                let poses: Vec<&HandPose> = samples.iter().map(|s| &s.1.pose).collect();
                let residuals = residual_track(&times, &poses);
                if residuals.times.len() > 1 {
                    noise.tracks.push(residuals);
                }
            }
            if noise.tracks.len() == before {
                let reason = format!(
                    "no hand is tracked for {MIN_TRACK} s or more, so it has no noise to take"
                );
                return Err(FileError::new(&rec.source_name, reason).into());
            }
            noise.sources.push(rec.source_name.clone());
        }
        noise.dropout_rate = noise.dropout_lengths.len() as f64 / tracked.max(1e-9);
        noise.rms = rms(&noise.tracks);
        Ok(noise)
    }

    /// White tracking noise: a tracker at `rate_hz` frames a second whose
    /// every joint is off by a fresh Gaussian error each frame, 1 mm rms
    /// per axis at scale 1, independent joint to joint and frame to frame;
    /// the palm turned by the joints' error over a 10 cm lever; no
    /// dropouts. The same draw every time. An error names the rate if it is
    /// outside [`WHITE_RATES`].
    pub fn white(rate_hz: f32) -> Result<TrackingNoise, RunError> {
        use rand::SeedableRng;
        use rand_distr::{Distribution, StandardNormal};
        if !WHITE_RATES.contains(&rate_hz) {
            let (low, high) = (WHITE_RATES.start(), WHITE_RATES.end());
            let reason = format!("a tracker's frame rate in {low}–{high} Hz, got {rate_hz}");
            return Err(RunError::Study { field: "noise-white", reason });
        }
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x00c0_ffee);
        let mut gauss = |rms: f32| -> Vec3 {
            let mut one =
                || -> f32 { rms * Distribution::<f32>::sample(&StandardNormal, &mut rng) };
            Vec3::new(one(), one(), one())
        };
        let frames = (WHITE_SECONDS * f64::from(rate_hz)).round() as usize;
        let times: Vec<f64> = (0..frames).map(|k| k as f64 / f64::from(rate_hz)).collect();
        let tracks = (0..WHITE_TRACKS)
            .map(|_| ResidualTrack {
                times: times.clone(),
                residuals: (0..frames)
                    .map(|_| Residual {
                        joints: std::array::from_fn(|_| gauss(WHITE_RMS)),
                        turn: gauss(WHITE_RMS / WHITE_LEVER),
                        stretch: None,
                    })
                    .collect(),
            })
            .collect::<Vec<_>>();
        let rms = rms(&tracks);
        Ok(TrackingNoise {
            tracks,
            dropout_rate: 0.0,
            dropout_lengths: Vec::new(),
            sources: vec![format!("white jitter at {rate_hz} Hz")],
            rms,
        })
    }

    /// Each recorded hand's residuals: its frame times (s, from its first)
    /// and its frames' residuals.
    pub fn tracks(&self) -> impl Iterator<Item = (&[f64], &[Residual])> {
        self.tracks.iter().map(|t| (t.times.as_slice(), t.residuals.as_slice()))
    }

    /// These residuals' rms per joint and axis when scaled by `scale` (mm).
    pub fn rms_mm(&self, scale: f32) -> f64 {
        f64::from(scale) * f64::from(self.rms) * 1e3
    }

    /// The scale that gives these residuals an rms of `mm` per joint and
    /// axis. An error if they have none to scale: less than
    /// [`JITTERLESS`], float rounding rather than a tracker's error.
    pub fn scale_for_rms_mm(&self, mm: f32) -> Result<f32, RunError> {
        if mm == 0.0 {
            return Ok(0.0);
        }
        if self.rms >= JITTERLESS {
            return Ok(mm / (self.rms * 1e3));
        }
        let reason = format!("the recordings have no jitter to scale to {mm} mm");
        Err(RunError::Study { field: "noise-mm", reason })
    }

    /// A fresh stream of this noise for one trial, from a random stretch
    /// of a random recorded hand, `scale` times as strong and its dropouts
    /// `scale` times as frequent.
    pub fn stream(&self, scale: f32, rng: &mut impl Rng) -> NoiseStream<'_> {
        let track = rng.random_range(0..self.tracks.len().max(1));
        let offset = self.tracks.get(track).map_or(0.0, |t| rng.random_range(0.0..t.duration()));
        NoiseStream { noise: self, track, offset, scale, dropout: None, next_drop: None }
    }
}

/// The gaps of a track's frame times that are dropouts, each as the time
/// lost beyond one frame interval (s).
fn dropouts(times: &[f64]) -> Vec<f64> {
    let median = median_interval(times);
    let gaps = times.windows(2).map(|w| w[1] - w[0]);
    gaps.filter(|&g| g > DROPOUT_FACTOR * median).map(|g| g - median).collect()
}

/// Each frame's residual from its Gaussian-smoothed neighbours, where they
/// lie on both sides of it.
///
/// A frame within 3σ of where the hand came into view, left it, or was
/// lost for a while (a [dropout](dropouts)) has a one-sided window: its
/// smoothed track is pulled towards where the hand was on the side it has,
/// and the hand's own motion reads as its noise. Entering the view, a hand
/// moves fast, so that bias reached 104 mm on one recorded hand whose
/// residuals elsewhere stay under 21 mm, and the track's loop replayed it
/// every period. Those frames are cut out, and the stretches either side of
/// a cut are joined one frame interval apart: the noise of a hand being
/// tracked, whose dropouts [`NoiseStream::at`] draws apart. An empty track
/// if no frame has a whole window.
fn residual_track(times: &[f64], poses: &[&HandPose]) -> ResidualTrack {
    let points: Vec<[Vec3; JOINTS]> = poses.iter().map(|p| joints(p)).collect();
    let frame = median_interval(times);
    let mut track = ResidualTrack { times: Vec::new(), residuals: Vec::new() };
    for stretch in stretches(times, frame) {
        let (first, end) = (times[stretch.start], times[stretch.end - 1]);
        let whole: Vec<usize> =
            stretch.filter(|&k| times[k] - first >= WINDOW && end - times[k] >= WINDOW).collect();
        for (n, &k) in whole.iter().enumerate() {
            let step = if n == 0 { frame } else { times[k] - times[k - 1] };
            let at = track.times.last().map_or(0.0, |&s| s + step);
            track.times.push(at);
            track.residuals.push(residual(times, poses, &points, k));
        }
    }
    track
}

/// The runs of frames between dropouts, as index ranges into `times`,
/// whose median frame interval is `frame` (s).
fn stretches(times: &[f64], frame: f64) -> Vec<std::ops::Range<usize>> {
    let limit = DROPOUT_FACTOR * frame;
    let mut out = Vec::new();
    let mut start = 0;
    for k in 1..=times.len() {
        if k == times.len() || times[k] - times[k - 1] > limit {
            out.push(start..k);
            start = k;
        }
    }
    out
}

/// The median of a track's frame intervals (s); 0 for fewer than two frames.
fn median_interval(times: &[f64]) -> f64 {
    let mut intervals: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    intervals.sort_by(f64::total_cmp);
    intervals.get(intervals.len() / 2).copied().unwrap_or(0.0)
}

/// The rms of every residual coordinate (m).
fn rms(tracks: &[ResidualTrack]) -> f32 {
    let (sum, n) = tracks.iter().flat_map(|t| &t.residuals).fold((0.0f64, 0usize), |(s, n), r| {
        (s + r.joints.iter().map(|j| f64::from(j.length_squared())).sum::<f64>(), n + 3 * JOINTS)
    });
    if n == 0 { 0.0 } else { (sum / n as f64).sqrt() as f32 }
}

/// One trial's tracking noise, sampled on the physics clock.
#[derive(Debug, Clone)]
pub struct NoiseStream<'a> {
    noise: &'a TrackingNoise,
    track: usize,
    offset: f64,
    scale: f32,
    /// The dropout under way: when it began and ends (s).
    dropout: Option<(f64, f64)>,
    /// When the next dropout begins (s), once drawn.
    next_drop: Option<f64>,
}

/// What the tracker reports at one instant.
// Returned by value once a physics step: a box would allocate each step.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tracked {
    /// A hand, with this noise on it.
    Hand(Residual),
    /// No new frame: the last report is held (a dropout within the
    /// grace period, as a live feed holds a hand).
    Held,
    /// The hand is lost (a dropout past the grace period).
    Lost,
}

impl NoiseStream<'_> {
    /// The noise at `t` (s), without dropouts: the stream's residual,
    /// scaled.
    pub fn residual(&self, t: f64) -> Residual {
        match self.noise.tracks.get(self.track) {
            Some(track) if self.scale > 0.0 => track.at(self.offset + t).scaled(self.scale),
            _ => Residual::ZERO,
        }
    }

    /// The tracker's report at `t` (s), drawing dropouts from `rng`: they
    /// begin at the recordings' rate (times the scale) and last as long as
    /// one of theirs, drawn at random.
    pub fn at(&mut self, t: f64, rng: &mut impl Rng) -> Tracked {
        let rate = self.noise.dropout_rate * f64::from(self.scale);
        if self.next_drop.is_none() && rate > 0.0 && self.dropout.is_none() {
            let wait = -(1.0 - rng.random::<f64>()).ln() / rate;
            self.next_drop = Some(t + wait);
        }
        if let Some(start) = self.next_drop.filter(|&s| s <= t) {
            let lengths = &self.noise.dropout_lengths;
            let length = lengths[rng.random_range(0..lengths.len())];
            self.dropout = Some((start, start + length));
            self.next_drop = None;
        }
        if let Some((start, end)) = self.dropout {
            if t < end {
                return if t - start <= DEFAULT_GRACE { Tracked::Held } else { Tracked::Lost };
            }
            self.dropout = None;
        }
        Tracked::Hand(self.residual(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bundled_recordings_give_millimetre_noise_on_every_joint() {
        let noise = TrackingNoise::bundled().unwrap();
        assert_eq!(noise.sources.len(), 4);
        eprintln!(
            "tracks {} rms {:.3} mm dropouts {:.2}/s {:?}",
            noise.tracks.len(),
            noise.rms * 1e3,
            noise.dropout_rate,
            noise.dropout_lengths
        );
        assert!(noise.rms > 5e-5 && noise.rms < 5e-3, "{}", noise.rms);
    }

    /// A hand that sweeps across the view at 1.2 m/s, tracked at 90 fps
    /// and lost once for 0.2 s on the way, has no noise: every residual
    /// is its tracker's, and this tracker has none. Where the smoothing
    /// window is one-sided (as the hand comes into view, leaves it, or is
    /// lost) a residual would read the sweep as noise, some 25 mm of it.
    #[test]
    fn a_clean_hand_entering_leaving_and_lost_in_a_sweep_has_no_noise() {
        use crate::hand::{Side, rig::HandRig};
        use glam::Quat;
        let rig = HandRig::adult(Side::Right);
        let (rate, speed) = (90.0, 1.2);
        let times: Vec<f64> =
            (0..180).map(|k| k as f64 / rate).filter(|t| !(0.8..1.0).contains(t)).collect();
        let poses: Vec<HandPose> = times
            .iter()
            .map(|&t| {
                let at = Vec3::new((speed * t) as f32 - 1.0, 0.25, -0.1);
                rig.pose(at, Quat::from_rotation_y(0.3), [0.4, 0.2, 0.3, 0.5, 0.1])
            })
            .collect();
        let track = residual_track(&times, &poses.iter().collect::<Vec<_>>());
        let worst = track
            .residuals
            .iter()
            .flat_map(|r| r.joints.iter().map(|j| j.length()))
            .fold(0.0f32, f32::max);
        assert!(worst < 1e-5, "a residual of {} mm", worst * 1e3);
        // Kept: the two stretches' frames with whole windows, 90 ms in from
        // either end of each, joined one frame apart.
        let kept = |from: f64, to: f64| ((to - from - 0.18) * rate).round() as usize;
        let expected = kept(0.0, 71.0 / rate) + kept(1.0, 179.0 / rate);
        assert!(track.times.len().abs_diff(expected) <= 2, "{} frames", track.times.len());
        let gaps = track.times.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
        assert!((gaps - 1.0 / rate).abs() < 1e-9, "a gap of {gaps} s");
    }
}
