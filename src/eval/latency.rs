//! How far the hand that acts lags the tracked hand
//! ([`crate::hand::acting`]): the time the tracking filter adds, on a step
//! and on a 1 Hz sine, of the whole hand and of its grip, with a clean
//! tracker and under real tracking noise.
//!
//! The hand is the users' grip ([`super::grip`]) in the air, still for
//! [`SETTLE`] seconds (so the world has measured the tracker's jitter, as
//! it has for a hand tracked a while), then:
//!
//! * **hand step**: the whole hand jumps [`STEP`] sideways; the time until
//!   the acting palm has covered half of it;
//! * **hand sine**: the whole hand swings ±[`SWING`] at 1 Hz; the delay of
//!   the acting palm's 1 Hz component (its phase over 2π·1 Hz), and its
//!   gain;
//! * **grip step** and **grip sine**: the hand closes from open at once, or
//!   opens and closes at 1 Hz; the same, of the index fingertip along its
//!   path;
//! * **hand reach** and **grip reach**: the whole hand moves [`STEP`]
//!   sideways, or the grip closes from open, in [`REACH`] along a
//!   minimum-jerk path (Flash & Hogan 1985, "The coordination of arm
//!   movements", J. Neuroscience 5(7)), the smoothest a hand makes; the time
//!   the acting point reaches half the move after the tracked one does.
//!
//! A step is a jump no hand makes, which a filter that tells glitches from
//! motion may rightly hold back; the reaches are what a quick hand does.
//!
//! Under noise, the acting hands of many noise streams are averaged, so
//! the noise averages out of what is measured and the lag stays.

use super::grip::grip;
use super::noise::{Residual, TrackingNoise};
use super::{NoiseUnit, check_some};
use crate::hand::{HandPose, Side};
pub use crate::output::report::{LatencyRow, LatencyStudy};
use crate::pipeline::{InteractionConfig, InteractionWorld};
use crate::run::RunError;
use glam::{Quat, Vec3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::path::PathBuf;

/// How long the hand keeps still before it moves (s).
pub const SETTLE: f64 = 3.0;
/// How far the hand steps (m).
pub const STEP: f32 = 0.05;
/// How far the hand swings each way (m).
pub const SWING: f32 = 0.05;
/// How long a reach takes (s): 5 cm in 150 ms peaks at 0.63 m/s and
/// 12.8 m/s², a quick hand's (real hands' gross accelerations in the
/// leapjs-playback recordings reach about 21 m/s²).
pub const REACH: f64 = 0.15;
/// How long the sines run (s); their first period is left out.
const SINE_FOR: f64 = 4.0;
/// The sine's frequency (Hz).
const SINE_HZ: f64 = 1.0;
/// The grip's cube half size and squeeze (m): the users'.
const GRIP: (f32, f32) = (0.02, 0.0045);
/// Where the hand is (m): in the air, nothing to touch.
const AT: Vec3 = Vec3::new(0.0, 0.3, 0.0);

/// What is measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    /// The whole hand jumps sideways.
    HandStep,
    /// The whole hand swings at 1 Hz.
    HandSine,
    /// The hand closes at once.
    GripStep,
    /// The hand opens and closes at 1 Hz.
    GripSine,
    /// The whole hand moves sideways along a minimum-jerk path.
    HandReach,
    /// The hand closes along a minimum-jerk path.
    GripReach,
}

impl Motion {
    /// All six, in the order reports list them.
    pub const ALL: [Motion; 6] = [
        Motion::HandStep,
        Motion::HandSine,
        Motion::HandReach,
        Motion::GripStep,
        Motion::GripSine,
        Motion::GripReach,
    ];

    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Motion::HandStep => "hand step",
            Motion::HandSine => "hand sine",
            Motion::GripStep => "grip step",
            Motion::GripSine => "grip sine",
            Motion::HandReach => "hand reach",
            Motion::GripReach => "grip reach",
        }
    }

    fn is_sine(self) -> bool {
        matches!(self, Motion::HandSine | Motion::GripSine)
    }

    /// The tracked hand, without noise, `t` seconds in.
    fn pose(self, t: f64) -> HandPose {
        let moving = t - SETTLE;
        let sine = (std::f64::consts::TAU * SINE_HZ * moving.max(0.0)).sin() as f32;
        let reach = minimum_jerk(moving / REACH);
        let (shift, closure) = match self {
            Motion::HandStep => (if moving >= 0.0 { STEP } else { 0.0 }, 1.0),
            Motion::HandSine => (SWING * sine, 1.0),
            Motion::GripStep => (0.0, if moving >= 0.0 { 1.0 } else { 0.0 }),
            Motion::GripSine => {
                (0.0, 0.5 - 0.5 * (std::f64::consts::TAU * SINE_HZ * moving.max(0.0)).cos() as f32)
            }
            Motion::HandReach => (STEP * reach, 1.0),
            Motion::GripReach => (0.0, reach),
        };
        let (half, squeeze) = GRIP;
        grip(half, closure, squeeze).transformed(Vec3::ZERO, Quat::IDENTITY, AT + Vec3::X * shift)
    }

    /// The point measured, and the direction along which it is measured.
    fn measure(self, pose: &HandPose) -> Vec3 {
        match self {
            Motion::HandStep | Motion::HandSine | Motion::HandReach => pose.palm.center,
            Motion::GripStep | Motion::GripSine | Motion::GripReach => pose.fingers[1][2].b,
        }
    }
}

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct LatencyOptions {
    /// The noise strengths, in `noise_unit`s (0: a clean tracker).
    pub noise: Vec<f32>,
    /// What the strengths count.
    pub noise_unit: NoiseUnit,
    /// The recordings to take the noise from (none: the bundled ones).
    pub noise_from: Vec<PathBuf>,
    /// Or white noise, drawn for a tracker at this frame rate (Hz).
    pub noise_white: Option<f32>,
    /// Noise streams averaged per strength.
    pub streams: usize,
    /// The world's settings, whose tracking filter is measured.
    pub config: InteractionConfig,
}

impl Default for LatencyOptions {
    fn default() -> Self {
        LatencyOptions {
            noise: Self::NOISE_MM.to_vec(),
            noise_unit: NoiseUnit::RmsMm,
            noise_from: Vec::new(),
            noise_white: None,
            streams: Self::STREAMS,
            config: InteractionConfig::default(),
        }
    }
}

impl LatencyOptions {
    /// The default strengths: a clean tracker, and 1, 2 and 3 mm rms.
    pub const NOISE_MM: [f32; 4] = [0.0, 1.0, 2.0, 3.0];
    /// The default noise streams averaged per strength.
    pub const STREAMS: usize = 16;
}

/// Runs the study: every [`Motion`] at every noise strength.
pub fn latency(options: &LatencyOptions) -> Result<LatencyStudy, RunError> {
    for &level in &options.noise {
        options.noise_unit.check(level)?;
    }
    check_some("noise", options.noise.len())?;
    check_some("streams", options.streams)?;
    let noise = TrackingNoise::choose(&options.noise_from, options.noise_white)?;
    let mut rows = Vec::new();
    for &level in &options.noise {
        let scale = options.noise_unit.scale(&noise, level)?;
        let streams = if scale > 0.0 { options.streams } else { 1 };
        for motion in Motion::ALL {
            let (tracked, acting) = mean_paths(motion, &options.config, &noise, scale, streams)?;
            let (latency_ms, gain) = if motion.is_sine() {
                let (delay, gain) = sine_delay(&tracked, &acting, options.config.dt);
                (delay * 1e3, Some(gain))
            } else {
                (half_time(&tracked, &acting, options.config.dt) * 1e3, None)
            };
            rows.push(LatencyRow {
                motion: motion.name().to_string(),
                noise: scale,
                noise_rms_mm: noise.rms_mm(scale),
                latency_ms,
                gain,
            });
        }
    }
    Ok(LatencyStudy { streams: options.streams, rows })
}

/// The measured point of the tracked hand (without noise) and the mean of
/// the acting hands over `streams` noise streams, step by step, along the
/// motion's direction (m).
fn mean_paths(
    motion: Motion,
    config: &InteractionConfig,
    noise: &TrackingNoise,
    scale: f32,
    streams: usize,
) -> Result<(Vec<f64>, Vec<f64>), RunError> {
    let dt = f64::from(config.dt);
    let steps = ((SETTLE + SINE_FOR) / dt).round() as usize;
    let start = motion.measure(&motion.pose(0.0));
    let end = match motion {
        Motion::HandSine => start + Vec3::X,
        Motion::GripSine => motion.measure(&motion.pose(SETTLE + 0.5 / SINE_HZ)),
        _ => motion.measure(&motion.pose(SETTLE + REACH)),
    };
    let along = (end - start).normalize_or_zero();
    let reading = |p: Vec3| f64::from((p - start).dot(along));
    let tracked: Vec<f64> =
        (0..steps).map(|k| reading(motion.measure(&motion.pose(k as f64 * dt)))).collect();
    let mut acting = vec![0.0; steps];
    for stream in 0..streams {
        let mut world = InteractionWorld::new(*config)?;
        let hand = world.add_hand(Side::Right);
        let mut rng = ChaCha8Rng::seed_from_u64(stream as u64 + 1);
        let noise = (scale > 0.0).then(|| noise.stream(scale, &mut rng));
        for (k, sum) in acting.iter_mut().enumerate() {
            let t = k as f64 * dt;
            let pose = motion.pose(t);
            let residual = noise.as_ref().map_or(Residual::default(), |n| n.residual(t));
            world.set_hand_pose(hand, &residual.apply(&pose))?;
            world.step();
            let now = world.hand_pose(hand).map_or(pose.palm.center, |p| motion.measure(p));
            *sum += reading(now) / streams as f64;
        }
    }
    Ok((tracked, acting))
}

/// The time (s) from when the tracked path has covered half of its move
/// (at once, for a step) until the acting path has.
fn half_time(tracked: &[f64], acting: &[f64], dt: f32) -> f64 {
    let begin = (SETTLE / f64::from(dt)).round() as usize;
    let half = 0.5 * tracked.last().copied().unwrap_or(0.0);
    let reached =
        |path: &[f64]| path[begin..].iter().position(|&x| (x - half) * half.signum() >= 0.0);
    match (reached(tracked), reached(acting)) {
        (Some(from), Some(to)) => (to as f64 - from as f64) * f64::from(dt),
        _ => f64::INFINITY,
    }
}

/// The minimum-jerk path's share of its move at `tau`, the share of its
/// time gone (clamped to [0, 1]): 10τ³ − 15τ⁴ + 6τ⁵ (Flash & Hogan 1985).
fn minimum_jerk(tau: f64) -> f32 {
    let tau = tau.clamp(0.0, 1.0);
    (tau.powi(3) * (10.0 - 15.0 * tau + 6.0 * tau * tau)) as f32
}

/// The delay (s) of the acting path's 1 Hz component behind the tracked
/// path's, and the ratio of their amplitudes, over the sine's whole
/// periods after its first.
fn sine_delay(tracked: &[f64], acting: &[f64], dt: f32) -> (f64, f64) {
    let dt = f64::from(dt);
    let begin = ((SETTLE + 1.0 / SINE_HZ) / dt).round() as usize;
    let component = |path: &[f64]| {
        let (mut c, mut s) = (0.0, 0.0);
        for (k, x) in path.iter().enumerate().skip(begin) {
            let phase = std::f64::consts::TAU * SINE_HZ * (k as f64 * dt - SETTLE);
            c += x * phase.cos();
            s += x * phase.sin();
        }
        (s.atan2(c), s.hypot(c))
    };
    let ((tracked_phase, tracked_size), (acting_phase, acting_size)) =
        (component(tracked), component(acting));
    use std::f64::consts::{PI, TAU};
    let behind = (acting_phase - tracked_phase).rem_euclid(TAU);
    let behind = if behind > PI { behind - TAU } else { behind };
    (behind / (TAU * SINE_HZ), acting_size / tracked_size)
}
