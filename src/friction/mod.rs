//! The Coulomb friction contact law of thesis §3.5.5–3.5.6, as pure math.
//!
//! Nothing here knows about rapier: every function takes and returns plain
//! [`glam::Vec3`]/`f32` values, so this file can be read beside the thesis.
//! Each equation has exactly one home, whose doc comment cites it.
//!
//! # Sign convention (used everywhere in the crate)
//! * `n` is the **outward** unit surface normal of the object at the contact
//!   point `C`.
//! * `p` is the tracked bone's point that pushes into the object.
//! * `f = γ(C − p)` (Eq. 3.4) is the force **on the bone** (the reaction).
//!   While the bone presses into the object, `C` lies outside `p` along `n`,
//!   so `f · n > 0`: that is the first clause of Eq. 3.7.
//! * The force **on the object** is the opposite, `−(f_n + f_T)`: it pushes
//!   the object the way the bone penetrates and drags it along with the bone.
//!
//! Units: lengths in metres, forces in newtons, γ in N/m.

use glam::Vec3;

/// Static and dynamic friction coefficients between skin and a material.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FrictionCoefficients {
    /// μ_st: bounds the tangential force of a sticking contact (Eq. 3.7).
    pub static_mu: f32,
    /// μ_dyn: scales the tangential force of a slipping contact (Eq. 3.8).
    pub dynamic_mu: f32,
}

/// How a slipping contact's tangential force is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum KineticFriction {
    /// Eq. 3.8 as written in the thesis: `f_T = μ_dyn · f_t`. Its magnitude
    /// grows with the tangential spring stretch and is **not** bounded by
    /// `μ_dyn·|f_n|`, so a fast tangential hand motion can transmit more
    /// friction than Coulomb's law allows.
    Thesis,
    /// Coulomb's kinetic friction: `f_T = μ_dyn·|f_n|` along `f_t`'s
    /// direction. The default, because it is the law the thesis names and it
    /// makes the simulated slip threshold independent of how fast the hand
    /// moves (tested in `tests/physics`). It never exceeds the spring's own
    /// tangential force `|f_t|`, so a material whose measured μ_dyn is above
    /// its μ_st cannot make friction push harder than the skin is stretched.
    #[default]
    Coulomb,
}

/// Whether a contact sticks, slips, or does not press at all.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum FrictionState {
    /// Inside the friction cone: `C` stays fixed on the object.
    Static,
    /// Outside the cone: the contact slips and `C` moves along the surface.
    Dynamic,
    /// `f · n ≤ 0`: the bone does not press into the object. A contact cannot
    /// pull (no adhesion), so it transmits no force at all.
    Separated,
}

/// The result of the contact law for one contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResolvedForce {
    /// `f_n`, the normal part of the reaction on the bone (N).
    pub normal: Vec3,
    /// `f_T`, the tangential friction part of the reaction on the bone (N).
    pub tangential: Vec3,
    /// Which branch of Eq. 3.7/3.8 applied.
    pub state: FrictionState,
}

impl ResolvedForce {
    /// The force applied to the object: the opposite of the reaction (N).
    pub fn on_object(&self) -> Vec3 {
        -(self.normal + self.tangential)
    }
}

/// Eq. 3.4: the spring contact force `f = γ(C − p)` on the bone.
pub fn spring_force(gamma: f32, c: Vec3, p: Vec3) -> Vec3 {
    gamma * (c - p)
}

/// Eq. 3.5 and Eq. 3.6: the normal part `(f·n)n` and the tangential rest
/// `f − (f·n)n` of a force, for a unit normal `n`.
pub fn split_normal_tangential(f: Vec3, n: Vec3) -> (Vec3, Vec3) {
    let normal = f.dot(n) * n;
    (normal, f - normal)
}

/// Eq. 3.7: the force is inside the friction cone of half-angle `atan μ_st`
/// around `n`: `f·n > 0 ∧ |f_t| ≤ μ_st (f·n)`.
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

/// The whole contact law: Eq. 3.5–3.8 applied to a reaction force `f`.
///
/// A force with `f·n ≤ 0` (the bone is not pressing) yields no force and
/// [`FrictionState::Separated`]: Eq. 3.8 read literally would keep a pulling
/// normal force and a tangential force, which is adhesion, not friction.
pub fn resolve(
    f: Vec3,
    n: Vec3,
    mu: FrictionCoefficients,
    kinetic: KineticFriction,
) -> ResolvedForce {
    let (normal, f_t) = split_normal_tangential(f, n);
    let f_n = f.dot(n);
    if f_n <= 0.0 || !f_n.is_finite() {
        return ResolvedForce {
            normal: Vec3::ZERO,
            tangential: Vec3::ZERO,
            state: FrictionState::Separated,
        };
    }
    let inside = inside_friction_cone(f, n, mu.static_mu);
    ResolvedForce {
        normal,
        tangential: tangential_friction(f_t, f_n, inside, mu.dynamic_mu, kinetic),
        state: if inside { FrictionState::Static } else { FrictionState::Dynamic },
    }
}

/// The largest interpenetration depth the thesis assumes when it derives γ
/// (§3.5.6): 20 % of the object's bounding-sphere diameter.
pub const MAX_PENETRATION_FRACTION: f32 = 0.2;

/// Eq. 3.11: the smallest γ that lets one contact hold the object's weight
/// at the assumed maximum penetration, `γ ≥ m·g / (μ · 0.2 · d)`.
///
/// `mass` in kg, `gravity` in m/s², `diameter` of the bounding sphere in m.
pub fn auto_gamma(mass: f32, gravity: f32, static_mu: f32, diameter: f32) -> f32 {
    mass * gravity / (static_mu * MAX_PENETRATION_FRACTION * diameter)
}

/// The per-contact force cap: the normal force of a bone at the deepest
/// penetration the thesis assumes, `γ · 0.2 · d` (N). Deeper bones are
/// tracking errors, not harder presses, so they push no harder.
pub fn force_cap(gamma: f32, diameter: f32) -> f32 {
    gamma * MAX_PENETRATION_FRACTION * diameter
}

/// The damping coefficient `c = 2ζ√(γ m)` (N·s/m) that gives one contact
/// spring of stiffness γ on a body of mass `m` the damping ratio ζ.
pub fn damping_coefficient(gamma: f32, mass: f32, damping_ratio: f32) -> f32 {
    2.0 * damping_ratio * (gamma * mass).sqrt()
}

/// The Kelvin–Voigt reaction on the bone: Eq. 3.4 plus a damper on the
/// relative velocity. `relative_velocity` is the bone's velocity minus the
/// object's velocity at the contact (m/s); `C − p` shrinks at that rate.
pub fn damped_spring_force(spring: Vec3, damping: f32, relative_velocity: Vec3) -> Vec3 {
    spring - damping * relative_velocity
}

/// The tangential stretch `|C − p|_t` (m) that a slipping contact keeps
/// after its surface point has moved: the stretch whose spring force equals
/// the kinetic friction `μ_dyn·f_n` (Coulomb), so the contact stays on the
/// boundary of the dynamic cone instead of snapping back to zero force.
/// Where μ_dyn > μ_st the stretch stops at the static cone: a contact
/// re-anchored beyond it would keep slipping and pull harder than it can
/// hold, feeding energy in.
pub fn kinetic_stretch(normal_magnitude: f32, mu: FrictionCoefficients, gamma: f32) -> f32 {
    if gamma <= 0.0 {
        return 0.0;
    }
    (mu.dynamic_mu.min(mu.static_mu) * normal_magnitude.max(0.0) / gamma).max(0.0)
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
    fn auto_gamma_matches_eq_3_11_and_the_thesis_value() {
        // m g = μ γ 0.2 d must hold at the returned γ.
        let (m, g, mu, d) = (0.1, 9.81, 0.5, 0.06);
        let gamma = auto_gamma(m, g, mu, d);
        assert!((mu * gamma * 0.2 * d - m * g).abs() < 1e-5);
        // The cap is the normal force at 20 % penetration.
        assert!((force_cap(gamma, d) - gamma * 0.2 * d).abs() < 1e-6);
    }

    #[test]
    fn kinetic_stretch_balances_kinetic_friction() {
        let s = kinetic_stretch(2.0, MU, 400.0);
        assert!((400.0 * s - 0.4 * 2.0).abs() < 1e-6);
        assert_eq!(kinetic_stretch(-1.0, MU, 400.0), 0.0);
        // μ_dyn above μ_st (aluminium's published pair): stop at the static cone.
        let alu = FrictionCoefficients { static_mu: 0.38, dynamic_mu: 0.6 };
        assert!((400.0 * kinetic_stretch(2.0, alu, 400.0) - 0.38 * 2.0).abs() < 1e-6);
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
}
