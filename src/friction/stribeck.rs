//! The fade from static to kinetic friction with sliding speed (Stribeck
//! 1902): skin that creeps over a surface slower than a few millimetres a
//! second still holds with its static friction; only skin that slides
//! drops to its kinetic friction.
//!
//! The thesis's law drops a contact to μ_dyn the instant it leaves the
//! cone. On one contact that is Coulomb's law. On many contacts under one
//! rigid object it is not what an object feels: the object does not move,
//! so each light contact that reaches its cone first creeps by a fraction
//! of a millimetre, drops to μ_dyn, and hands its load on; the next follows,
//! and the object slides before its slope reaches atan μ_st (the book's
//! "Static friction that fades with speed"). Measured skin friction does
//! not drop at the first micro-slip: it falls from its static to its
//! kinetic value over the sliding speed, as friction does in the mixed-lubrication regime that
//! the finger pad works in (Pasumarty et al. 2011, "Friction of the human
//! finger pad: influence of moisture, occlusion and velocity", Tribol.
//! Lett. 44:117). The exponential form is the common one (Olsson et al.
//! 1998, "Friction models and friction compensation", Eur. J. Control
//! 4:176).

use super::FrictionCoefficients;

/// Stribeck's curve: the kinetic coefficient of skin sliding at `speed`
/// (m/s) over the surface, `μ_dyn + (μ_st − μ_dyn)·exp(−(v/v_s)²)`, with
/// `v_s` the `stribeck_speed` (m/s). At rest it is μ_st; a few `v_s` on,
/// μ_dyn. A non-finite speed slides (μ_dyn).
#[inline]
pub fn kinetic_mu(mu: FrictionCoefficients, speed: f32, stribeck_speed: f32) -> f32 {
    let ratio = speed / stribeck_speed;
    let fade = (-(ratio * ratio)).exp();
    let fade = if fade.is_finite() { fade } else { 0.0 };
    mu.dynamic_mu + (mu.static_mu - mu.dynamic_mu) * fade
}

impl FrictionCoefficients {
    /// These coefficients for skin sliding at `speed` (m/s): the static
    /// coefficient kept, the kinetic one from [`kinetic_mu`].
    #[inline]
    pub fn sliding_at(self, speed: f32, stribeck_speed: f32) -> FrictionCoefficients {
        FrictionCoefficients { dynamic_mu: kinetic_mu(self, speed, stribeck_speed), ..self }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SKIN: FrictionCoefficients = FrictionCoefficients { static_mu: 0.7, dynamic_mu: 0.45 };

    #[test]
    fn creeping_skin_keeps_its_static_friction_and_sliding_skin_its_kinetic() {
        let v_s = 0.004;
        assert_eq!(kinetic_mu(SKIN, 0.0, v_s), 0.7);
        // A tenth of v_s: within 1 % of the static difference.
        assert!((kinetic_mu(SKIN, 0.0004, v_s) - 0.7).abs() < 0.01 * 0.25);
        // At v_s: 1/e of the way.
        let at = kinetic_mu(SKIN, v_s, v_s);
        assert!((at - (0.45 + 0.25 / std::f32::consts::E)).abs() < 1e-6);
        // Three v_s on: kinetic, to 0.02 % of the difference (e^−9).
        assert!((kinetic_mu(SKIN, 3.0 * v_s, v_s) - 0.45).abs() < 2e-4 * 0.25);
        // Falls monotonically, whichever way the skin slides.
        let speeds = [0.0, 0.001, 0.003, 0.006, 0.02, 1.0];
        let mus = speeds.map(|v| kinetic_mu(SKIN, v, v_s));
        assert!(mus.windows(2).all(|w| w[1] <= w[0]), "{mus:?}");
        assert_eq!(kinetic_mu(SKIN, -0.003, v_s), kinetic_mu(SKIN, 0.003, v_s));
    }

    #[test]
    fn a_bad_speed_slides_and_the_static_coefficient_is_kept() {
        assert_eq!(kinetic_mu(SKIN, f32::INFINITY, 0.004), 0.45);
        assert_eq!(kinetic_mu(SKIN, f32::NAN, 0.004), 0.45);
        let at = SKIN.sliding_at(0.002, 0.004);
        assert_eq!(at.static_mu, 0.7);
        assert!(at.dynamic_mu > 0.45 && at.dynamic_mu < 0.7);
    }
}
