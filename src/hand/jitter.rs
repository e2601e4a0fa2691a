//! The tracker's jitter, measured on the hand as it is tracked.
//!
//! A hand moves smoothly: over a tenth of a second its joints follow
//! paths a parabola fits (its voluntary motion lies below about 5 Hz,
//! Brooks 1990). A tracker's error does not. So every
//! [`SAMPLE_INTERVAL`] each point is compared with the Savitzky–Golay
//! parabola through its samples within ±[`HALF_WINDOW`] intervals (±70
//! ms), and what the parabola cannot explain is jitter. The jitter σ̂ is
//! the median over a window of seconds of those residuals' mean square
//! per axis, scaled so that white noise of rms σ per axis reads σ. The
//! median, so that a hand that jumps (a tracker that finds it again) or a
//! brief glitch does not count; so σ̂ is the jitter a tracker makes most
//! of the time, below its rms when it also glitches.
//!
//! A residual is known [`HALF_WINDOW`] intervals late, and σ̂ follows a
//! change of tracker over about half the window.
//!
//! Part of it is the hand's own: a still hand trembles by about 30 µm
//! (physiological finger tremor, 8–12 Hz: Growdon et al. 2000, Elble
//! 2003), and a tracker that reports it reports the hand. Only what the
//! meter finds beyond that is the tracker's ([`tracker_jitter`]).
//!
//! How white the jitter is ([`JitterMeter::whiteness`]) is judged on
//! the residuals pooled [`POOL`] samples at a time. A tracker slower than
//! the samples is read between its frames, and a point drawn between two
//! frames is off by less than one on a frame: unpooled, white jitter at
//! 30 frames a second would read as uneven as a tracker that glitches.

use glam::Vec3;

/// How often the points are sampled (s): 100 Hz, the rate of most hand
/// trackers.
pub const SAMPLE_INTERVAL: f32 = 0.01;
/// Samples each side of the one judged: the parabola spans ±70 ms, long
/// enough that a hand's motion fits it and short enough that a tracker's
/// jitter does not.
pub const HALF_WINDOW: usize = 7;
const SPAN: usize = 2 * HALF_WINDOW + 1;
/// Samples pooled for the whiteness: 30 ms, a frame of a tracker at 33
/// Hz, the slowest headsets' hand tracking. Short beside a glitch's
/// spacing (5–9 a second in a Leap's recordings), so the pools' median
/// still misses the glitches.
pub const POOL: usize = 3;

/// A still hand's own tremor (m): the physiological finger tremor's mean
/// amplitude at rest, about 30 µm (Growdon et al. 2000).
pub const TREMOR: f32 = 30.0e-6;

/// The tracker's part of a measured jitter `measured` (m): what is beyond
/// the hand's own [`TREMOR`], the two independent so their variances
/// adding.
pub fn tracker_jitter(measured: f32) -> f32 {
    (measured * measured - TREMOR * TREMOR).max(0.0).sqrt()
}

/// The median over the mean of white noise's mean square over `n` points
/// (or samples of a point):
/// a χ² of k = 3n degrees of freedom, whose median is about
/// k·(1 − 2/9k)³ (Wilson & Hilferty 1931). So white noise reads a
/// whiteness of 1 however many points share it.
fn white_median_ratio(n: usize) -> f32 {
    let b = 1.0 - 2.0 / (27.0 * n as f32);
    b * b * b
}

/// The median of `values` (not empty; the upper one of an even count),
/// found in `scratch`, reused.
fn median(values: &[f32], scratch: &mut Vec<f32>) -> f32 {
    scratch.clear();
    scratch.extend_from_slice(values);
    let middle = scratch.len() / 2;
    *scratch.select_nth_unstable_by(middle, f32::total_cmp).1
}

/// The quadratic Savitzky–Golay smoothing weight of the sample `i` places
/// from the centre (Savitzky & Golay 1964): the parabola fitted by least
/// squares through the span, read at its centre.
fn savitzky_golay(i: f32) -> f32 {
    let m = HALF_WINDOW as f32;
    (3.0 * (3.0 * m * m + 3.0 * m - 1.0) - 15.0 * i * i)
        / ((2.0 * m + 3.0) * (2.0 * m + 1.0) * (2.0 * m - 1.0))
}

/// Measures the jitter of `N` points of one tracked hand.
#[derive(Debug, Clone)]
pub struct JitterMeter<const N: usize> {
    /// The last [`SPAN`] samples, oldest first once full (a ring).
    samples: Vec<[Vec3; N]>,
    next: usize,
    /// Time since the last sample (s).
    since: f32,
    /// Each judged sample's mean square residual per axis (m²), a ring of
    /// the window's length.
    history: Vec<f32>,
    written: usize,
    window: usize,
    /// The history sorted, reused.
    scratch: Vec<f32>,
    jitter: f32,
    /// The mean square residuals of the last [`POOL`] samples each (m²),
    /// a ring of the window's length in pools.
    pools: Vec<f32>,
    pooled: usize,
    /// The sum of the pool being filled (m²).
    filling: f32,
    /// See [`Self::whiteness`].
    whiteness: f32,
}

impl<const N: usize> JitterMeter<N> {
    /// A meter whose median spans `window` seconds.
    pub fn new(window: f32) -> Self {
        let window = ((window / SAMPLE_INTERVAL).round() as usize).max(1);
        JitterMeter {
            samples: Vec::with_capacity(SPAN),
            next: 0,
            since: 0.0,
            history: Vec::with_capacity(window),
            written: 0,
            window,
            scratch: Vec::with_capacity(window),
            jitter: 0.0,
            pools: Vec::with_capacity(window.div_ceil(POOL)),
            pooled: 0,
            filling: 0.0,
            whiteness: 0.0,
        }
    }

    /// The jitter (m, rms per axis as white noise would give it), 0 until
    /// a first sample is judged.
    pub fn jitter(&self) -> f32 {
        self.jitter
    }

    /// The hand was lost: the next points start a new path. What was
    /// measured is kept, as the tracker's.
    pub fn break_path(&mut self) {
        self.samples.clear();
        self.next = 0;
        self.since = 0.0;
    }

    /// The points `dt` (s) after the last call.
    pub fn observe(&mut self, points: &[Vec3; N], dt: f32) {
        self.since += dt;
        // Half a step early, so rounding never skips a sample.
        if !self.samples.is_empty() && self.since < SAMPLE_INTERVAL - 0.5 * dt {
            return;
        }
        self.since = 0.0;
        if self.samples.len() < SPAN {
            self.samples.push(*points);
        } else {
            self.samples[self.next] = *points;
        }
        self.next = (self.next + 1) % SPAN;
        if self.samples.len() == SPAN {
            self.judge();
        }
    }

    /// The residual of the centre sample, added to the history, and the
    /// median taken.
    fn judge(&mut self) {
        let sample = |k: usize| &self.samples[(self.next + k) % SPAN];
        let mut sum = 0.0;
        for j in 0..N {
            let mut fit = Vec3::ZERO;
            for k in 0..SPAN {
                fit += savitzky_golay(k as f32 - HALF_WINDOW as f32) * sample(k)[j];
            }
            sum += (sample(HALF_WINDOW)[j] - fit).length_squared();
        }
        // White noise leaves 1 − w₀ of its variance in the residual.
        let variance = sum / (3 * N) as f32 / (1.0 - savitzky_golay(0.0));
        if self.history.len() < self.window {
            self.history.push(variance);
        } else {
            self.history[self.written % self.window] = variance;
        }
        self.written += 1;
        self.jitter = median(&self.history, &mut self.scratch).sqrt();
        self.filling += variance;
        if self.written.is_multiple_of(POOL) {
            self.pool();
        }
    }

    /// The pool just filled, added to the pools, and the whiteness judged.
    fn pool(&mut self) {
        let pool = self.filling / POOL as f32;
        self.filling = 0.0;
        let length = self.window.div_ceil(POOL);
        if self.pools.len() < length {
            self.pools.push(pool);
        } else {
            self.pools[self.pooled % length] = pool;
        }
        self.pooled += 1;
        let median = median(&self.pools, &mut self.scratch);
        let mean = self.pools.iter().sum::<f32>() / self.pools.len() as f32;
        self.whiteness =
            if mean > 0.0 { (median / mean / white_median_ratio(N * POOL)).min(1.0) } else { 0.0 };
    }

    /// How white the jitter is, in [0, 1]: the median of its pools' mean
    /// squares ([`POOL`]) over their mean, the share of its power that an
    /// ordinary pool has, over white noise's own share. About 1 for white
    /// noise, whose every pool is off alike; near 0 for a tracker whose
    /// error is its rare glitches, whose power the median does not see. 0
    /// until a first pool is judged; over the first few pools, any tracker
    /// reads about 1.
    pub fn whiteness(&self) -> f32 {
        self.whiteness
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_distr::{Distribution, Normal};

    #[test]
    fn the_weights_fit_a_parabola_exactly() {
        let weight = |k: usize| savitzky_golay(k as f32 - HALF_WINDOW as f32);
        let total: f32 = (0..SPAN).map(weight).sum();
        assert!((total - 1.0).abs() < 1e-6, "{total}");
        let parabola = |k: usize| {
            let i = k as f32 - HALF_WINDOW as f32;
            2.0 + 0.3 * i - 0.05 * i * i
        };
        let fit: f32 = (0..SPAN).map(|k| weight(k) * parabola(k)).sum();
        assert!((fit - 2.0).abs() < 1e-5, "{fit}");
    }

    #[test]
    fn a_smoothly_moving_hand_has_no_jitter_and_white_noise_reads_its_rms() {
        let mut smooth = JitterMeter::<8>::new(1.0);
        let mut noisy = JitterMeter::<8>::new(1.0);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let normal = Normal::new(0.0f32, 0.0013).unwrap();
        let mut shake = || Vec3::new(normal.sample(&mut rng), normal.sample(&mut rng), 0.0);
        for k in 0..3000 {
            let t = k as f32 * 0.001;
            // Eight points on a reach: 12 cm at up to 0.13 m/s, each point
            // also closing in on the hand's centre, faster the farther out.
            let path: [Vec3; 8] = std::array::from_fn(|j| {
                let reach = Vec3::new(0.06 * (1.0 - (2.1 * t).cos()), 0.3, 0.0);
                reach + Vec3::Y * 0.01 * (j as f32 + 1.0) * t * t
            });
            smooth.observe(&path, 0.001);
            noisy.observe(&path.map(|p| p + shake()), 0.001);
        }
        assert!(smooth.jitter() < TREMOR, "{}", smooth.jitter());
        // Noise of 1.3 mm rms on two axes of each point: two thirds of the
        // variance per axis; the median of 16 noisy axes reads a little low.
        let expected = 0.0013 * (2.0f32 / 3.0).sqrt();
        assert!((noisy.jitter() - expected).abs() < 0.1 * expected, "{}", noisy.jitter());
    }

    #[test]
    fn white_noise_is_white_and_rare_glitches_are_not() {
        // Two still points under 0.9 mm of white noise a sample; and under
        // 0.3 mm of it plus a glitch of 6 mm on one sample in forty: the
        // glitches hold more than half the power, in their own samples and
        // their neighbours', and the median sees little of it, as in a
        // Leap's recordings (0.17–0.69, the book's "Tracking noise").
        let mut white = JitterMeter::<2>::new(1.5);
        let mut glitchy = JitterMeter::<2>::new(1.5);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(23);
        let (loud, quiet) =
            (Normal::new(0.0f32, 0.0009).unwrap(), Normal::new(0.0f32, 0.0003).unwrap());
        let at = [Vec3::new(0.1, 0.25, -0.05), Vec3::new(0.13, 0.24, -0.04)];
        assert_eq!(white.whiteness(), 0.0);
        for k in 0..2500 {
            let mut shake = |n: &Normal<f32>| Vec3::from_array([(); 3].map(|_| n.sample(&mut rng)));
            white.observe(&[at[0] + shake(&loud), at[1] + shake(&loud)], 0.001);
            let thrown = if (k / 10) % 40 == 5 { Vec3::Z * 0.006 } else { Vec3::ZERO };
            glitchy.observe(&[at[0] + thrown + shake(&quiet), at[1] + shake(&quiet)], 0.001);
        }
        assert!(white.whiteness() > 0.95, "{}", white.whiteness());
        assert!((0.3..0.7).contains(&glitchy.whiteness()), "{}", glitchy.whiteness());
    }

    #[test]
    fn a_slow_trackers_white_noise_read_between_its_frames_is_white() {
        // Twelve still points under 1.1 mm of white noise a frame from a
        // tracker at 27 frames a second, drawn between frames as a replay
        // draws them: the meter's samples fall anywhere between two frames,
        // and one midway is off by 0.7 as much as one on a frame.
        let mut meter = JitterMeter::<12>::new(2.0);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(41);
        let normal = Normal::new(0.0f32, 0.0011).unwrap();
        let mut frame = || -> [Vec3; 12] {
            std::array::from_fn(|j| {
                let shake = Vec3::from_array([(); 3].map(|_| normal.sample(&mut rng)));
                Vec3::new(0.02 * j as f32, 0.3, 0.0) + shake
            })
        };
        let (mut last, mut next) = (frame(), frame());
        let mut frames = 1;
        for k in 0..4000 {
            let t = k as f32 * 0.001;
            while t >= frames as f32 / 27.0 {
                (last, next) = (next, frame());
                frames += 1;
            }
            let between = (t * 27.0).fract();
            meter.observe(&std::array::from_fn(|j| last[j].lerp(next[j], between)), 0.001);
        }
        assert!(meter.whiteness() > 0.9, "{}", meter.whiteness());
    }

    #[test]
    fn the_hands_own_tremor_is_not_the_trackers() {
        assert_eq!(tracker_jitter(0.0), 0.0);
        assert_eq!(tracker_jitter(TREMOR), 0.0);
        assert!((tracker_jitter(0.0005) - 0.0005).abs() < 1e-6);
        assert!((tracker_jitter(50e-6) - 40e-6).abs() < 1e-9);
    }

    #[test]
    fn a_jump_does_not_count_as_jitter() {
        let mut meter = JitterMeter::<1>::new(2.0);
        for k in 0..3000 {
            let x = if k < 1500 { 0.0 } else { 0.05 };
            meter.observe(&[Vec3::new(x, 0.2, 0.0)], 0.001);
        }
        // A still point's residual is float rounding, far below tremor.
        assert!(meter.jitter() < 1e-7, "{}", meter.jitter());
    }
}
