//! A tracker's glitches: where in a noise a joint strays far from its
//! smoothed track, for how long and how far.
//!
//! A Leap Motion's residuals are mostly a fraction of a millimetre, with
//! rare strays of centimetres where it lost sight of a finger (a fist, a
//! hand side-on) and guessed. Those strays, not the small jitter, are what
//! drop a grip (the book's "Tracking noise"), so a census
//! of them says what a hand model must tell from motion: which joints
//! stray, how far, and for how long.

use super::noise::{JOINTS, TrackingNoise};
use crate::run::RunError;

/// One joint's stray: a run of frames whose residual is past the census's
/// threshold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Glitch {
    /// The recorded hand it is in (the noise's track index).
    pub track: usize,
    /// The joint, in the order of [`JOINTS`]: the palm's centre, then four
    /// per digit, thumb first, from the base of the proximal bone to the tip.
    pub joint: usize,
    /// When it began (s, from its track's first frame).
    pub start: f64,
    /// From its first frame past the threshold to the first frame back
    /// within it (s); to its track's last frame if it never came back.
    pub duration: f64,
    /// Its largest residual (m).
    pub peak: f32,
}

/// The glitches of a noise as recorded, unscaled.
#[derive(Debug, Clone, PartialEq)]
pub struct GlitchCensus {
    /// A residual past this is a glitch (m).
    pub threshold: f32,
    /// The seconds of tracked hand looked at.
    pub seconds: f64,
    /// Every glitch, track by track, joint by joint, in time.
    pub glitches: Vec<Glitch>,
}

impl GlitchCensus {
    /// The glitches of `noise` past `threshold` (m). An error if the
    /// threshold is not a positive length.
    pub fn of(noise: &TrackingNoise, threshold: f32) -> Result<GlitchCensus, RunError> {
        if !(threshold.is_finite() && threshold > 0.0) {
            let reason = format!("a positive length in metres, got {threshold}");
            return Err(RunError::Study { field: "threshold", reason });
        }
        let mut census = GlitchCensus { threshold, seconds: 0.0, glitches: Vec::new() };
        for (track, (times, residuals)) in noise.tracks().enumerate() {
            census.seconds += times.last().copied().unwrap_or(0.0);
            for joint in 0..JOINTS {
                let sizes: Vec<f32> = residuals.iter().map(|r| r.joints[joint].length()).collect();
                census.glitches.extend(
                    strays(times, &sizes, threshold).map(|(start, duration, peak)| Glitch {
                        track,
                        joint,
                        start,
                        duration,
                        peak,
                    }),
                );
            }
        }
        Ok(census)
    }

    /// Glitches a second of tracked hand.
    pub fn rate(&self) -> f64 {
        if self.seconds > 0.0 { self.glitches.len() as f64 / self.seconds } else { 0.0 }
    }

    /// The glitches of the joints `joints` (indices into [`JOINTS`]).
    pub fn of_joints(&self, joints: std::ops::Range<usize>) -> impl Iterator<Item = &Glitch> {
        self.glitches.iter().filter(move |g| joints.contains(&g.joint))
    }
}

/// The runs of `sizes` past `threshold`, each as its start and duration
/// (s, by `times`, to the first frame back within it or to the last frame)
/// and its largest size.
fn strays<'a>(
    times: &'a [f64],
    sizes: &'a [f32],
    threshold: f32,
) -> impl Iterator<Item = (f64, f64, f32)> + 'a {
    let mut k = 0;
    std::iter::from_fn(move || {
        let start = k + sizes.get(k..)?.iter().position(|&s| s > threshold)?;
        let back = sizes[start..].iter().position(|&s| s <= threshold).map(|n| start + n);
        let end = back.unwrap_or(sizes.len() - 1);
        k = back.unwrap_or(sizes.len());
        let peak = sizes[start..back.unwrap_or(sizes.len())].iter().copied().fold(0.0, f32::max);
        Some((times[start], times[end] - times[start], peak))
    })
}

/// The `p`-quantile (0 to 1) of `values`, linearly interpolated; NaN if
/// there are none.
pub fn quantile(values: impl Iterator<Item = f64>, p: f64) -> f64 {
    let mut sorted: Vec<f64> = values.collect();
    sorted.sort_by(f64::total_cmp);
    crate::output::report::quantile(&sorted, p)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stray is timed from its first frame past the threshold to its
    /// first frame back, and one still out at the end runs to the end.
    #[test]
    fn strays_are_timed_from_out_to_back() {
        let times: Vec<f64> = (0..10).map(|k| f64::from(k) * 0.02).collect();
        let sizes = [0.001, 0.007, 0.012, 0.004, 0.0, 0.0, 0.006, 0.001, 0.003, 0.009];
        let found: Vec<_> = strays(&times, &sizes, 0.005).collect();
        assert_eq!(found.len(), 3, "{found:?}");
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(found[0].0, 0.02) && close(found[0].1, 0.04) && found[0].2 == 0.012);
        assert!(close(found[1].0, 0.12) && close(found[1].1, 0.02) && found[1].2 == 0.006);
        assert!(close(found[2].0, 0.18) && close(found[2].1, 0.0) && found[2].2 == 0.009);
        assert_eq!(strays(&times, &[0.0; 10], 0.005).count(), 0);
    }

    /// The bundled Leap noise is mostly under a millimetre: its 5 mm strays
    /// come less than once a second per joint, reach past a centimetre,
    /// and last tens of milliseconds, not seconds.
    #[test]
    fn a_census_of_the_bundled_noise_finds_rare_centimetre_strays() {
        let noise = TrackingNoise::bundled().unwrap();
        let census = GlitchCensus::of(&noise, 0.005).unwrap();
        let per_joint = census.rate() / JOINTS as f64;
        assert!(per_joint > 0.0 && per_joint < 1.0, "{per_joint} a joint a second");
        let peak = census.glitches.iter().map(|g| g.peak).fold(0.0, f32::max);
        assert!(peak > 0.01, "the largest stray {peak} m");
        for g in &census.glitches {
            assert!(g.peak > 0.005 && g.duration >= 0.0 && g.joint < JOINTS, "{g:?}");
        }
        let median = quantile(census.glitches.iter().map(|g| g.duration), 0.5);
        assert!(median > 0.005 && median < 0.1, "a median stray of {median} s");
    }

    #[test]
    fn a_threshold_that_is_no_length_is_an_error_naming_it() {
        let noise = TrackingNoise::bundled().unwrap();
        for bad in [0.0, -0.001, f32::NAN, f32::INFINITY] {
            let error = GlitchCensus::of(&noise, bad).unwrap_err().to_string();
            assert!(error.contains("threshold"), "{error}");
        }
    }
}
