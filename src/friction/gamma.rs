//! The contact stiffness γ (§3.5.6).

/// The largest interpenetration depth the thesis assumes when it derives γ
/// (§3.5.6): 20 % of the object's bounding-sphere diameter.
pub const MAX_PENETRATION_FRACTION: f32 = 0.2;

/// Eq. 3.11: the smallest γ (N/m) that lets one contact hold the object's
/// weight at the assumed maximum penetration, `γ ≥ m·g / (μ · 0.2 · d)`.
///
/// `mass` in kg, `gravity` in m/s², `diameter` of the bounding sphere in m.
pub fn auto_gamma(mass: f32, gravity: f32, static_mu: f32, diameter: f32) -> f32 {
    mass * gravity / (static_mu * MAX_PENETRATION_FRACTION * diameter)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::friction::ForceCap;

    #[test]
    fn auto_gamma_matches_eq_3_11_and_the_force_cap() {
        // m g = μ γ 0.2 d must hold at the returned γ.
        let (m, g, mu, d) = (0.1, 9.81, 0.5, 0.06);
        let gamma = auto_gamma(m, g, mu, d);
        assert!((mu * gamma * 0.2 * d - m * g).abs() < 1e-5);
        // The cap is the normal force at 20 % penetration: μ times it is the weight.
        let cap = ForceCap::for_diameter(d).normal_force(gamma);
        assert!((cap - gamma * 0.2 * d).abs() < 1e-6);
        assert!((mu * cap - m * g).abs() < 1e-5);
    }
}
