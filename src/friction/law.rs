//! The thesis's contact law, Eq. 3.4–3.8, and the total force, Eq. 3.10.

use super::{FrictionCoefficients, FrictionState, KineticFriction, ResolvedForce};
use glam::Vec3;
use std::ops::Add;

/// Eq. 3.4: the spring contact force `f = γ(C − p)` on the bone.
#[inline]
pub fn spring_force(gamma: f32, c: Vec3, p: Vec3) -> Vec3 {
    gamma * (c - p)
}

/// Eq. 3.5 and Eq. 3.6: the normal part `(f·n)n` and the tangential rest
/// `f − (f·n)n` of a force, for a unit normal `n`.
#[inline]
pub fn split_normal_tangential(f: Vec3, n: Vec3) -> (Vec3, Vec3) {
    let normal = f.dot(n) * n;
    (normal, f - normal)
}

/// Eq. 3.7: the force is inside the friction cone of half-angle `atan μ_st`
/// around `n`: `f·n > 0 ∧ |f_t| ≤ μ_st (f·n)`.
#[inline]
pub fn inside_friction_cone(f: Vec3, n: Vec3, static_mu: f32) -> bool {
    let f_n = f.dot(n);
    let (_, f_t) = split_normal_tangential(f, n);
    f_n > 0.0 && f_t.length() <= static_mu * f_n
}

/// Eq. 3.8: the tangential force of a contact, given its tangential part
/// `f_t`, its normal magnitude `f·n`, and whether it is inside the cone.
///
/// Outside the cone, [`KineticFriction::Thesis`] scales `f_t` by μ_dyn;
/// [`KineticFriction::Coulomb`] gives it the magnitude `μ_dyn·|f_n|`.
#[inline]
pub fn tangential_friction(
    f_t: Vec3,
    normal_magnitude: f32,
    inside: bool,
    dynamic_mu: f32,
    kinetic: KineticFriction,
) -> Vec3 {
    if inside {
        return f_t;
    }
    match kinetic {
        KineticFriction::Thesis => dynamic_mu * f_t,
        KineticFriction::Coulomb => {
            (dynamic_mu * normal_magnitude.abs()).min(f_t.length()) * f_t.normalize_or_zero()
        }
    }
}

/// The cone and the kinetic rule together (§3.5.5): the reaction `f`
/// resolved into `f_n` and `f_T`, with its [`FrictionState`].
///
/// A force with `f·n ≤ 0` (the bone is not pressing) yields no force and
/// [`FrictionState::Separated`]: the kinetic rule read literally would keep a pulling
/// normal force and a tangential force, which is adhesion, not friction.
#[inline]
pub fn resolve(
    f: Vec3,
    n: Vec3,
    mu: FrictionCoefficients,
    kinetic: KineticFriction,
) -> ResolvedForce {
    let (normal, f_t) = split_normal_tangential(f, n);
    let f_n = f.dot(n);
    if f_n <= 0.0 || !f_n.is_finite() {
        return ResolvedForce::SEPARATED;
    }
    let inside = inside_friction_cone(f, n, mu.static_mu);
    ResolvedForce {
        normal,
        tangential: tangential_friction(f_t, f_n, inside, mu.dynamic_mu, kinetic),
        state: if inside { FrictionState::Static } else { FrictionState::Dynamic },
    }
}

/// Eq. 3.10: the total force of a hand's contacts on one object,
/// `F = Σ (f_n + f_T)` (N): `total` plus each further force on the object,
/// added one after another in order, so that it can be summed contact by
/// contact, and sample by sample of a contact's patch, as the forces are
/// applied. Only forces that are applied belong in it: the step leaves out
/// any that is not finite (its firewall) before it sums.
#[inline(always)]
pub fn total_force<F: Add<Output = F>>(total: F, on_object: impl IntoIterator<Item = F>) -> F {
    on_object.into_iter().fold(total, |sum, f| sum + f)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MU: FrictionCoefficients = FrictionCoefficients { static_mu: 0.5, dynamic_mu: 0.4 };

    #[test]
    fn spring_force_points_from_bone_to_surface() {
        // Bone 2 mm inside a floor whose outward normal is +y.
        let f = spring_force(400.0, Vec3::ZERO, Vec3::new(0.0, -0.002, 0.0));
        assert!((f - Vec3::new(0.0, 0.8, 0.0)).length() < 1e-6);
        assert!(f.dot(Vec3::Y) > 0.0, "a pressing bone has f·n > 0");
    }

    #[test]
    fn cone_inside_outside_boundary_and_negative_normal() {
        let n = Vec3::Y;
        // Inside: tangential 0.4 of normal < 0.5.
        assert!(inside_friction_cone(Vec3::new(0.4, 1.0, 0.0), n, 0.5));
        // Outside: tangential 0.6 of normal > 0.5.
        assert!(!inside_friction_cone(Vec3::new(0.6, 1.0, 0.0), n, 0.5));
        // On the boundary (exactly representable): inside, since Eq. 3.7 uses ≤.
        assert!(inside_friction_cone(Vec3::new(0.5, 1.0, 0.0), n, 0.5));
        assert!(!inside_friction_cone(Vec3::new(0.5 + 1e-4, 1.0, 0.0), n, 0.5));
        // Negative normal component: never inside, even with no tangential part.
        assert!(!inside_friction_cone(Vec3::new(0.0, -1.0, 0.0), n, 0.5));
        assert!(!inside_friction_cone(Vec3::ZERO, n, 0.5));
    }

    #[test]
    fn split_is_orthogonal_and_complete() {
        let n = Vec3::new(1.0, 2.0, -0.5).normalize();
        let f = Vec3::new(0.3, -1.2, 4.0);
        let (fn_, ft) = split_normal_tangential(f, n);
        assert!(ft.dot(n).abs() < 1e-5);
        assert!((fn_ + ft - f).length() < 1e-6);
    }

    #[test]
    fn static_contact_keeps_the_whole_force() {
        let f = Vec3::new(0.3, 1.0, 0.0);
        let r = resolve(f, Vec3::Y, MU, KineticFriction::Coulomb);
        assert_eq!(r.state, FrictionState::Static);
        assert!((r.normal + r.tangential - f).length() < 1e-6);
        assert!((r.on_object() + f).length() < 1e-6);
    }

    #[test]
    fn thesis_and_coulomb_kinetic_forms_differ_outside_the_cone() {
        // Tangential 3 N against 1 N normal: far outside the cone.
        let f = Vec3::new(3.0, 1.0, 0.0);
        let thesis = resolve(f, Vec3::Y, MU, KineticFriction::Thesis);
        let coulomb = resolve(f, Vec3::Y, MU, KineticFriction::Coulomb);
        assert_eq!(thesis.state, FrictionState::Dynamic);
        assert_eq!(coulomb.state, FrictionState::Dynamic);
        // Thesis Eq. 3.8: μ_dyn · f_t = 1.2 N, above μ_dyn·|f_n| = 0.4 N.
        assert!((thesis.tangential.length() - 1.2).abs() < 1e-5);
        // Coulomb: exactly μ_dyn·|f_n|, same direction.
        assert!((coulomb.tangential.length() - 0.4).abs() < 1e-5);
        assert!(coulomb.tangential.normalize().dot(Vec3::X) > 0.9999);
        // Both keep the same normal part.
        assert_eq!(thesis.normal, coulomb.normal);
    }

    #[test]
    fn pulling_contact_transmits_nothing() {
        let r = resolve(Vec3::new(0.2, -1.0, 0.0), Vec3::Y, MU, KineticFriction::Thesis);
        assert_eq!(r.state, FrictionState::Separated);
        assert_eq!(r.on_object(), Vec3::ZERO);
    }

    #[test]
    fn coulomb_friction_never_exceeds_the_springs_own_pull() {
        // Just outside a μ_st 0.38 cone, with μ_dyn 0.6: μ_dyn·f_n = 0.6 N
        // would exceed the 0.4 N the spring actually pulls with.
        let alu = FrictionCoefficients { static_mu: 0.38, dynamic_mu: 0.6 };
        let r = resolve(Vec3::new(0.4, 1.0, 0.0), Vec3::Y, alu, KineticFriction::Coulomb);
        assert_eq!(r.state, FrictionState::Dynamic);
        assert!((r.tangential.length() - 0.4).abs() < 1e-6);
    }

    #[test]
    fn the_total_adds_every_contact_force_in_order() {
        let forces =
            [Vec3::new(0.1, 2.0, 0.0), Vec3::new(-0.3, 0.5, 0.2), Vec3::new(0.0, 0.0, -0.7)];
        let sum = total_force(Vec3::ZERO, forces);
        assert!((sum - Vec3::new(-0.2, 2.5, -0.5)).length() < 1e-6);
        assert_eq!(total_force(Vec3::ZERO, []), Vec3::ZERO);
        // Contact by contact, it comes to the same bits: the same sums in
        // the same order.
        let first = total_force(Vec3::ZERO, forces[..1].iter().copied());
        assert_eq!(total_force(first, forces[1..].iter().copied()), sum);
    }
}
