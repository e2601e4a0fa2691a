//! Where a slipping spring re-anchors (§3.5.3 with Coulomb's kinetic
//! friction). One rule serves a whole contact, whose point C slides over
//! the object, and each sample of its skin patch, which slips on its own
//! share of the cone (torsional slip).

use super::FrictionCoefficients;
use glam::Vec3;

/// Whether a spring of stiffness γ (N/m, shared by N samples as γ/N each,
/// with their normal force split alike) whose tangential stretch is
/// `stretch_t` (m) is outside the static friction cone:
/// `|stretch_t| > μ_st · f_n / γ`, with `f_n` the normal force (N).
#[inline]
pub fn slips(stretch_t: Vec3, normal_force: f32, mu: FrictionCoefficients, gamma: f32) -> bool {
    stretch_t.length_squared() > static_stretch_squared(normal_force, mu, gamma)
}

/// `(μ_st · f_n / γ)²` (m²): the squared stretch beyond which [`slips`]
/// says a spring slips, for code that compares many stretches at once.
#[inline]
pub fn static_stretch_squared(normal_force: f32, mu: FrictionCoefficients, gamma: f32) -> f32 {
    let limit = mu.static_mu * normal_force / gamma;
    limit * limit
}

/// The tangential stretch `|C − p|_t` (m) that a slipping spring keeps: the
/// stretch whose spring force equals the kinetic friction `μ_dyn·f_n`, so
/// the spring stays on the boundary of the dynamic cone instead of snapping
/// back to zero force. Where μ_dyn > μ_st the stretch stops at the static
/// cone: a spring re-anchored beyond it would keep slipping and pull harder
/// than it can hold, feeding energy in.
#[inline]
pub fn kinetic_stretch(normal_force: f32, mu: FrictionCoefficients, gamma: f32) -> f32 {
    if gamma <= 0.0 {
        return 0.0;
    }
    (mu.dynamic_mu.min(mu.static_mu) * normal_force.max(0.0) / gamma).max(0.0)
}

/// The slip rule: a slipping spring re-anchors so that its tangential
/// stretch keeps the direction of `stretch_t` and the length
/// [`kinetic_stretch`]. Whole contacts and patch samples both use it.
#[inline]
pub fn slipped_stretch(
    stretch_t: Vec3,
    normal_force: f32,
    mu: FrictionCoefficients,
    gamma: f32,
) -> Vec3 {
    stretch_t.normalize_or_zero() * kinetic_stretch(normal_force, mu, gamma)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MU: FrictionCoefficients = FrictionCoefficients { static_mu: 0.5, dynamic_mu: 0.4 };
    const ALUMINIUM: FrictionCoefficients =
        FrictionCoefficients { static_mu: 0.38, dynamic_mu: 0.6 };

    #[test]
    fn kinetic_stretch_balances_kinetic_friction() {
        let s = kinetic_stretch(2.0, MU, 400.0);
        assert!((400.0 * s - 0.4 * 2.0).abs() < 1e-6);
        assert_eq!(kinetic_stretch(-1.0, MU, 400.0), 0.0);
        // μ_dyn above μ_st (aluminium's published pair): stop at the static cone.
        assert!((400.0 * kinetic_stretch(2.0, ALUMINIUM, 400.0) - 0.38 * 2.0).abs() < 1e-6);
    }

    #[test]
    fn a_slipped_spring_never_pulls_harder_than_it_held() {
        // 1.5 N normal, γ 300 N/m: the static cone holds 0.57 N of aluminium
        // friction, a stretch of 1.9 mm. Stretched 2.5 mm, it slips, and it
        // re-anchors at or inside the static cone whatever μ_dyn says.
        let stretch = Vec3::new(0.0015, 0.0, -0.002);
        assert!(slips(stretch, 1.5, ALUMINIUM, 300.0));
        let kept = slipped_stretch(stretch, 1.5, ALUMINIUM, 300.0);
        // On the static cone (to rounding), not out at μ_dyn's 0.9 N.
        assert!((300.0 * kept.length() - 0.38 * 1.5).abs() < 1e-5, "{kept:?}");
        assert!(kept.normalize().dot(stretch.normalize()) > 0.9999, "the slip keeps its direction");
        // Within the cone it sticks.
        assert!(!slips(Vec3::new(0.0015, 0.0, 0.0), 1.5, ALUMINIUM, 300.0));
    }
}
