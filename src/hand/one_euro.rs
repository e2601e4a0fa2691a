//! The 1€ filter (Casiez, Roussel & Vogel 2012, "1€ Filter: a simple
//! speed-based low-pass filter for noisy input in interactive systems",
//! CHI '12), one point or one turn at a time.
//!
//! A first-order low-pass whose cutoff rises with the signal's speed: a
//! point that keeps still is smoothed hard, since there jitter shows and
//! lag does not; a point that moves is followed closely, since there lag
//! shows and jitter does not. Here the speed is counted in widths of the
//! tracker's own jitter σ̂ per second ([`super::jitter`]), so one setting
//! serves every tracker: a clean tracker's hand is followed exactly, a
//! noisy one's is smoothed as much as its jitter asks.
//!
//! The state is the lag, the filtered value less the raw one, so a point
//! that keeps still is exactly where the tracker says, to the bit.

use glam::{Quat, Vec3};

/// One 1€ filter's settings.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OneEuro {
    /// The cutoff of a point that keeps still under 1 mm of jitter (Hz),
    /// higher in proportion under less: [`OneEuro::step`].
    pub min_cutoff: f32,
    /// How fast the cutoff rises with speed: Hz per jitter width per
    /// second, so dimensionless. A steady motion is followed at most
    /// `σ̂/(2π·beta)` behind.
    pub beta: f32,
    /// The cutoff of the speed estimate (Hz): how long a motion must last
    /// before the filter believes it.
    pub derivative_cutoff: f32,
    /// The lowest cutoff of a still point (Hz), whatever the jitter: a
    /// filter slower than the hand's own grasp makes a grip that closes
    /// after the hand has lifted ([`OneEuro::step`]). 0: none.
    #[serde(default)]
    pub least_cutoff: f32,
    /// The lowest cutoff of a still point under white jitter (Hz): a
    /// tracker whose every frame is off alike, without glitches, is
    /// smoothed no slower than this. It falls steeply as the jitter is
    /// less white ([`OneEuro::step`]), so a tracker whose error is its
    /// rare glitches is smoothed as without it. 0: none.
    #[serde(default)]
    pub white_cutoff: f32,
}

impl OneEuro {
    /// Checks that every field is finite, the cutoffs positive (the least
    /// and white cutoffs ≥ 0) and `beta` not negative; the error names the
    /// field by `names`, the names of `min_cutoff`, `beta`,
    /// `derivative_cutoff`, `least_cutoff` and `white_cutoff` where the
    /// filter is set.
    pub fn validate(&self, names: [&'static str; 5]) -> Result<(), (&'static str, String)> {
        let [min_cutoff, beta, derivative_cutoff, least_cutoff, white_cutoff] = names;
        for (field, v) in
            [(min_cutoff, self.min_cutoff), (derivative_cutoff, self.derivative_cutoff)]
        {
            if !(v.is_finite() && v > 0.0) {
                return Err((field, format!("must be a positive number of Hz, got {v}")));
            }
        }
        let fields = [
            (beta, self.beta),
            (least_cutoff, self.least_cutoff),
            (white_cutoff, self.white_cutoff),
        ];
        for (field, v) in fields {
            if !(v.is_finite() && v >= 0.0) {
                return Err((field, format!("must be finite and ≥ 0, got {v}")));
            }
        }
        Ok(())
    }
}

/// How sharply [`OneEuro::white_cutoff`] is kept for white jitter: it is
/// scaled by the whiteness to this power. A Leap Motion's jitter, mostly
/// glitches, reads a whiteness of 0.17–0.69 on the hand's shape and
/// 0.16–0.55 on its gross motion (15 leapjs-playback recordings; 0.74 and
/// 0.58 on their most even streams), white noise 0.99 on the shape from 20
/// to 100 frames a second (0.71–0.97 on the gross motion's one point): at
/// the fourth power the Leap's keeps under a third of the white cutoff,
/// white noise nearly all of it on the shape and a quarter to nine tenths
/// on the gross motion (the book's "Tracking noise", read on 21 joints by
/// `examples/whiteness.rs`).
pub const WHITENESS_POWER: i32 = 4;

/// The jitter (m) under which a still point's cutoff is
/// [`OneEuro::min_cutoff`].
pub const JITTER_UNIT: f32 = 0.001;

/// The exponential smoothing factor of a first-order low-pass at `cutoff`
/// (Hz) sampled every `dt` (s): `α = 1/(1 + τ/dt)`, τ = 1/(2π·cutoff).
#[inline]
pub fn smoothing(cutoff: f32, dt: f32) -> f32 {
    let tau = 1.0 / (std::f32::consts::TAU * cutoff);
    dt / (dt + tau)
}

impl OneEuro {
    /// This filter for one step of `dt` (s) under a tracker of jitter
    /// `jitter` (m): what every point of a hand shares that step.
    ///
    /// A still point's cutoff, `min_cutoff·1 mm/σ̂`, falls as the jitter
    /// grows, but never below [`OneEuro::least_cutoff`]: under a tracker
    /// whose every frame is 2 mm off (white jitter, not the rare glitches
    /// of a Leap's), it would reach 0.7 Hz, and the speed term, counted in
    /// jitter widths, would add almost nothing to a closing grip. The
    /// grip's pads would then close 130 ms behind the tracked hand, after
    /// the hand had lifted. A reach-to-grasp closes its aperture over its
    /// last 200–300 ms (Jeannerod 1984); a cutoff of 2 Hz, a time constant
    /// of 80 ms, keeps the lag within a third of that.
    ///
    /// Under white jitter the least cutoff is [`OneEuro::white_cutoff`]
    /// times its `whiteness` (in [0, 1], [`super::jitter`]: the share of
    /// the jitter's power that an ordinary sample has, 1 for white noise)
    /// to the [`WHITENESS_POWER`]. What a faster filter lets through of
    /// white jitter is small and alike every frame, and a grip holds
    /// through it; what it lets through of a glitch is a finger thrown
    /// centimetres, which drops what it holds. So the more of the jitter's
    /// power lies in rare samples, the closer the least cutoff stays to
    /// [`OneEuro::least_cutoff`].
    #[inline]
    pub fn step(&self, jitter: f32, whiteness: f32, dt: f32) -> EuroStep {
        // 2π·dt per jitter width: the cutoff's terms, as smoothing factors.
        let per_width = std::f32::consts::TAU * dt / jitter;
        let white = self.white_cutoff * whiteness.clamp(0.0, 1.0).powi(WHITENESS_POWER);
        let least_cutoff = self.least_cutoff.max(white);
        let least = std::f32::consts::TAU * dt * least_cutoff;
        EuroStep {
            dt,
            derivative: smoothing(self.derivative_cutoff, dt),
            still: (per_width * (self.min_cutoff * JITTER_UNIT)).max(least),
            per_speed: per_width * self.beta,
            exact: jitter <= 0.0,
        }
    }
}

/// A [`OneEuro`] filter's factors for one step ([`OneEuro::step`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EuroStep {
    dt: f32,
    /// The speed estimate's smoothing factor.
    derivative: f32,
    /// `2π·dt·min_cutoff·1 mm/σ̂` and `2π·dt·beta/σ̂`.
    still: f32,
    per_speed: f32,
    /// A tracker without jitter: followed exactly.
    exact: bool,
}

impl EuroStep {
    /// The smoothing factor of a point moving at `speed` (m/s): that of
    /// Casiez et al.'s cutoff `min_cutoff + beta·speed`, both terms counted
    /// in the jitter σ̂, `f_c = (min_cutoff·1 mm + beta·speed)/σ̂`; as
    /// `α = x/(1 + x)` with `x = 2π·f_c·dt`. So a still point is smoothed
    /// for a time in proportion to the jitter, and keeps the same small
    /// part of it whatever the tracker: jitter lies above the cutoff (a
    /// tracker's, mostly 5–15 Hz), where a first-order low-pass passes it
    /// in proportion to the cutoff. 1, so the point is followed exactly,
    /// for a tracker without jitter.
    #[inline]
    pub fn alpha(&self, speed: f32) -> f32 {
        let x = self.still + self.per_speed * speed;
        if self.exact || !x.is_finite() { 1.0 } else { x / (1.0 + x) }
    }
}

/// One filtered point, kept as its lag behind the raw one.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EuroPoint {
    /// The filtered point less the raw one (m).
    pub lag: Vec3,
    /// The speed estimate (m/s): the raw velocity, low-passed.
    velocity: Vec3,
    /// The last raw point (m).
    raw: Vec3,
}

impl EuroPoint {
    /// A point that starts exactly where the tracker puts it, still.
    pub fn new(raw: Vec3) -> EuroPoint {
        EuroPoint { lag: Vec3::ZERO, velocity: Vec3::ZERO, raw }
    }

    /// The speed estimate (m/s).
    pub fn speed(&self) -> f32 {
        self.velocity.length()
    }

    /// Still and without lag: a point that does not move stays exactly
    /// where it is tracked.
    pub fn at_rest(&self) -> bool {
        self.lag == Vec3::ZERO && self.velocity == Vec3::ZERO
    }

    /// Takes the next raw point, a `step` after the last; returns the new
    /// lag (m).
    #[inline]
    pub fn advance(&mut self, raw: Vec3, step: &EuroStep) -> Vec3 {
        let speed = self.track(raw, step);
        self.follow(raw, step.alpha(speed))
    }

    /// The first half of [`Self::advance`]: takes the next raw point into
    /// the speed estimate; returns the estimated speed (m/s). A group of
    /// points that moves as one ([`super::acting`]'s shape) shares one
    /// smoothing factor from their speeds.
    #[inline]
    pub fn track(&mut self, raw: Vec3, step: &EuroStep) -> f32 {
        let moved = raw - self.raw;
        self.velocity += step.derivative * (moved / step.dt - self.velocity);
        self.velocity.length()
    }

    /// The second half of [`Self::advance`]: follows `raw`, the point
    /// [`Self::track`] took, with the smoothing factor `alpha`; returns the
    /// new lag (m).
    #[inline]
    pub fn follow(&mut self, raw: Vec3, alpha: f32) -> Vec3 {
        let moved = raw - self.raw;
        // The filtered point was `raw_old + lag`; now `raw + (1 − α)·(that − raw)`.
        // A point that did not move keeps its lag to the bit.
        let behind = if moved == Vec3::ZERO { self.lag } else { self.lag - moved };
        self.lag = behind * (1.0 - alpha);
        self.raw = raw;
        if !(self.lag.is_finite() && self.velocity.is_finite()) {
            // A step so short that a move's speed overflows: follow exactly.
            *self = EuroPoint::new(raw);
        }
        self.lag
    }
}

/// One filtered orientation, kept as its lag: the filtered turn is the
/// raw turn times `lag`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EuroTurn {
    /// The raw turn's inverse times the filtered turn.
    pub lag: Quat,
    /// The angular velocity estimate (rad/s), low-passed.
    spin: Vec3,
    /// The last raw turn.
    raw: Quat,
}

impl EuroTurn {
    /// A turn that starts exactly as the tracker reports it, still.
    pub fn new(raw: Quat) -> EuroTurn {
        EuroTurn { lag: Quat::IDENTITY, spin: Vec3::ZERO, raw }
    }

    /// Still and without lag.
    pub fn at_rest(&self) -> bool {
        self.lag == Quat::IDENTITY && self.spin == Vec3::ZERO
    }

    /// Takes the next raw turn, a `filter` step after the last; `lever`
    /// (m) turns the angular speed into the speed of the body's far edge,
    /// which the filter compares with the jitter. Returns the filtered
    /// turn.
    #[inline]
    pub fn advance(&mut self, raw: Quat, filter: &EuroStep, lever: f32) -> Quat {
        let (step, behind) = if raw == self.raw {
            (Vec3::ZERO, self.lag)
        } else {
            let step = (self.raw.inverse() * raw).normalize();
            let step = if step.w < 0.0 { -step } else { step };
            (step.to_scaled_axis(), (raw.inverse() * self.raw * self.lag).normalize())
        };
        self.spin += filter.derivative * (step / filter.dt - self.spin);
        let alpha = filter.alpha(self.spin.length() * lever);
        self.lag = if behind == Quat::IDENTITY {
            behind
        } else {
            let behind = if behind.w < 0.0 { -behind } else { behind };
            Quat::from_scaled_axis(behind.to_scaled_axis() * (1.0 - alpha))
        };
        self.raw = raw;
        if !(self.lag.is_finite() && self.spin.is_finite()) {
            *self = EuroTurn::new(raw);
        }
        if self.lag == Quat::IDENTITY { raw } else { (raw * self.lag).normalize() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILTER: OneEuro = OneEuro {
        min_cutoff: 1.0,
        beta: 0.01,
        derivative_cutoff: 1.0,
        least_cutoff: 0.0,
        white_cutoff: 0.0,
    };

    #[test]
    fn a_still_point_is_exactly_where_the_tracker_says() {
        let at = Vec3::new(0.31, 1.17, -0.42);
        let mut p = EuroPoint::new(at);
        for _ in 0..50 {
            assert_eq!(p.advance(at, &FILTER.step(0.002, 1.0, 0.001)), Vec3::ZERO);
        }
        assert!(p.at_rest());
    }

    #[test]
    fn a_clean_tracker_is_followed_exactly_and_a_noisy_one_smoothed() {
        let (dt, to) = (0.001, Vec3::new(0.0, 0.0, 0.0037));
        let mut clean = EuroPoint::new(Vec3::ZERO);
        assert_eq!(clean.advance(to, &FILTER.step(0.0, 1.0, dt)), Vec3::ZERO);
        assert_eq!(clean.advance(to * 2.0, &FILTER.step(0.0, 1.0, dt)), Vec3::ZERO);
        // A 3.7 mm jump under 2 mm of jitter: at 1 ms, the still cutoff of
        // 0.5 Hz (plus the little the speed estimate adds) moves the point
        // 0.4 % of the way.
        let mut noisy = EuroPoint::new(Vec3::ZERO);
        let lag = noisy.advance(to, &FILTER.step(0.002, 1.0, dt));
        let moved = (to + lag).z / to.z;
        assert!(moved > 0.0035 && moved < 0.0042, "{moved}");
    }

    /// The cutoff (Hz) a still point is smoothed at by `step`, of `dt` (s):
    /// [`smoothing`] read backwards.
    fn still_cutoff(step: EuroStep, dt: f32) -> f32 {
        let alpha = step.alpha(0.0);
        alpha / (1.0 - alpha) / (std::f32::consts::TAU * dt)
    }

    #[test]
    fn under_large_jitter_a_still_point_is_smoothed_no_slower_than_the_least_cutoff() {
        // Under 2.6 mm of jitter the still cutoff would be 0.38 Hz; the
        // least, 1.7 Hz, holds. Under 0.2 mm it is 5 Hz, above the least.
        let floored = OneEuro { least_cutoff: 1.7, ..FILTER };
        let dt = 0.001;
        let cutoff = |f: &OneEuro, jitter: f32| still_cutoff(f.step(jitter, 1.0, dt), dt);
        assert!((cutoff(&FILTER, 0.0026) - 0.385).abs() < 0.001, "{}", cutoff(&FILTER, 0.0026));
        assert!((cutoff(&floored, 0.0026) - 1.7).abs() < 1e-3, "{}", cutoff(&floored, 0.0026));
        assert!((cutoff(&floored, 0.0002) - 5.0).abs() < 1e-3, "{}", cutoff(&floored, 0.0002));
        assert_eq!(floored.step(0.0, 1.0, dt).alpha(0.0), 1.0);
    }

    #[test]
    fn under_white_jitter_a_still_point_is_smoothed_no_slower_than_the_white_cutoff() {
        // Under 1.9 mm of jitter the still cutoff would be 0.53 Hz and the
        // least 1.3 Hz; jitter that is white lifts the floor to 7.1 Hz,
        // 0.8 white to 0.8⁴ of it, 2.908 Hz; glitches leave the least.
        let white = OneEuro { least_cutoff: 1.3, white_cutoff: 7.1, ..FILTER };
        let dt = 0.001;
        let cutoff = |whiteness: f32| still_cutoff(white.step(0.0019, whiteness, dt), dt);
        assert!((cutoff(1.0) - 7.1).abs() < 2e-3, "{}", cutoff(1.0));
        assert!((cutoff(0.8) - 2.908).abs() < 1e-3, "{}", cutoff(0.8));
        assert!((cutoff(0.5) - 1.3).abs() < 1e-3, "{}", cutoff(0.5));
        assert!((cutoff(0.0) - 1.3).abs() < 1e-3, "{}", cutoff(0.0));
        // Under little jitter the still cutoff is above either floor.
        let still = still_cutoff(white.step(0.0001, 1.0, dt), dt);
        assert!((still - 10.0).abs() < 5e-3, "{still}");
    }

    #[test]
    fn a_steady_motion_is_followed_within_its_lag_bound() {
        // 0.2 m/s for 2 s under 1.3 mm of jitter: the lag settles below
        // σ̂/(2π·beta) = 20.7 mm, at v/(2π·f_c), f_c 2.3 Hz.
        let (dt, v, jitter) = (0.001, 0.2, 0.0013);
        let mut p = EuroPoint::new(Vec3::ZERO);
        let mut lag = Vec3::ZERO;
        for k in 1..=2000 {
            lag = p.advance(Vec3::X * (v * k as f32 * dt), &FILTER.step(jitter, 1.0, dt));
        }
        let f_c = (FILTER.min_cutoff * JITTER_UNIT + FILTER.beta * v) / jitter;
        let expected = v / (std::f32::consts::TAU * f_c);
        assert!((-lag.x - expected).abs() < 0.02 * expected, "{lag:?} vs {expected}");
        assert!(-lag.x < jitter / (std::f32::consts::TAU * FILTER.beta));
    }

    #[test]
    fn a_still_turn_is_exact_and_a_turn_under_jitter_lags() {
        let q = Quat::from_rotation_y(0.83);
        let mut t = EuroTurn::new(q);
        let (noisy, clean) = (FILTER.step(0.002, 1.0, 0.001), FILTER.step(0.0, 1.0, 0.001));
        assert_eq!(t.advance(q, &noisy, 0.05), q);
        let to = Quat::from_rotation_y(0.9);
        let out = t.advance(to, &noisy, 0.05);
        let went = (q.inverse() * out).to_scaled_axis().y / 0.07;
        assert!(went > 0.0 && went < 0.02, "{went}");
        assert!(EuroTurn::new(q).advance(to, &clean, 0.05).angle_between(to) < 1e-6);
    }

    #[test]
    fn a_speed_that_overflows_follows_exactly_and_stays_finite() {
        let mut p = EuroPoint::new(Vec3::ZERO);
        let (far, tiny) = (Vec3::splat(9.5), FILTER.step(0.002, 1.0, 1e-38));
        assert_eq!(p.advance(far, &tiny), Vec3::ZERO);
        assert!(p.advance(-far, &tiny).is_finite());
        let mut t = EuroTurn::new(Quat::IDENTITY);
        assert!(t.advance(Quat::from_rotation_z(3.0), &tiny, 0.05).is_finite());
    }

    #[test]
    fn settings_out_of_range_name_their_field() {
        const NAMES: [&str; 5] =
            ["min_cutoff", "beta", "derivative_cutoff", "least_cutoff", "white_cutoff"];
        let bad = OneEuro { beta: -1.0, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "beta");
        let bad = OneEuro { min_cutoff: f32::NAN, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "min_cutoff");
        let bad = OneEuro { derivative_cutoff: 0.0, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "derivative_cutoff");
        let bad = OneEuro { least_cutoff: -2.0, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "least_cutoff");
        let bad = OneEuro { least_cutoff: f32::INFINITY, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "least_cutoff");
        let bad = OneEuro { white_cutoff: -0.1, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "white_cutoff");
        let bad = OneEuro { white_cutoff: f32::NAN, ..FILTER };
        assert_eq!(bad.validate(NAMES).unwrap_err().0, "white_cutoff");
        assert!(FILTER.validate(NAMES).is_ok());
    }
}
