//! Contact springs stable at any step: backward Euler on an object's
//! springs, for steps too long for explicit ones (a host engine's 90 Hz).
//!
//! An explicit spring of stiffness γ on a body is stable only while
//! `dt²·Σγw` stays small (stage 5's budget). Softening γ to fit keeps it
//! stable but weakens the grip: a pinch then presses, and can hold, only a
//! fraction of what the law says. Backward Euler keeps the full γ: the
//! springs' forces are those at the end of the step, after the body has
//! moved under them (Baraff and Witkin 1998, "Large steps in cloth
//! simulation", §4, linearised as their Eq. 15). For the springs
//! `f_i = K_i·(d_i − dt·(J_i·v⁺ − u_i)) − C_i·J_i·(v⁺ − v)` on a body of
//! mass matrix `M`, under the other forces `f_ext`, the velocity change
//! solves
//!
//! `(M + dt·Σ J_iᵀ (C_i + dt·K_i) J_i)·Δv = dt·(f_exp − dt·Σ J_iᵀ K_i (J_i·v − u_i) + f_ext)`
//!
//! where `f_exp` is the springs' explicit wrench (each at its full γ), `J_i`
//! maps the body's twist to contact `i`'s point velocity and `u_i` is the
//! bone's velocity there. Each contact's force then changes by
//! `−K_i·dt·(J_i·v − u_i) − (C_i + dt·K_i)·J_i·Δv`.
//! An explicit integrator that applies the corrected wrench gets exactly
//! the implicit velocity, so a host's own integrator is stable with it. In
//! equilibrium (`v = 0`, `f_exp + f_ext = 0`) the correction is zero: a
//! held object is held by the full-stiffness springs, as at 1 kHz.
//!
//! Each contact's spring acts in every direction, the bone taken to go on
//! at its velocity over the step. A slipping contact's tangential force is
//! kinetic friction: corrected as a spring would be, it may stop the slip
//! but never exceed kinetic friction, so friction never throws the body
//! back past the bone within a step. Each corrected force stays inside its
//! friction cone ([`corrected_force`]).

use glam::{Mat3, Vec3};
use nalgebra::{Matrix3x6, Matrix6, Vector6};

/// One contact spring on a body, as the implicit step sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spring {
    /// The contact point relative to the body's centre of mass (m).
    pub offset: Vec3,
    /// The object's outward surface normal there (unit).
    pub normal: Vec3,
    /// The bone's velocity there (m/s), which it is taken to keep over the
    /// step.
    pub bone_velocity: Vec3,
    /// The spring's stiffness γ (N/m).
    pub stiffness: f32,
    /// Its damper (N·s/m).
    pub damping: f32,
    /// Whether it sticks (its tangential force a spring, within
    /// `static_mu` of its normal force) or slips (kinetic friction, which
    /// the correction may lessen, as far as stopping the slip, but never
    /// raise: [`corrected_force`]).
    pub sticking: bool,
}

/// A body's motion and inertia now (world frame: kg, kg·m², m/s, rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Its mass (kg).
    pub mass: f32,
    /// Its inertia tensor in the world frame (kg·m²).
    pub inertia: Mat3,
    /// Its centre of mass's velocity (m/s).
    pub linvel: Vec3,
    /// Its angular velocity (rad/s).
    pub angvel: Vec3,
}

/// A force through the centre of mass (N) and a torque about it (N·m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wrench {
    /// The force (N).
    pub force: Vec3,
    /// The torque about the centre of mass (N·m).
    pub torque: Vec3,
}

impl Spring {
    /// `J`: the body's twist (v, ω) to this point's velocity, `v + ω × r`.
    fn jacobian(&self) -> Matrix3x6<f32> {
        let r = self.offset;
        #[rustfmt::skip]
        let j = Matrix3x6::new(
            1.0, 0.0, 0.0, 0.0, r.z, -r.y,
            0.0, 1.0, 0.0, -r.z, 0.0, r.x,
            0.0, 0.0, 1.0, r.y, -r.x, 0.0,
        );
        j
    }

    /// The point's velocity for a twist.
    fn point_velocity(&self, linvel: Vec3, angvel: Vec3) -> Vec3 {
        linvel + angvel.cross(self.offset)
    }
}

fn matrix(m: Mat3) -> nalgebra::Matrix3<f32> {
    nalgebra::Matrix3::from_column_slice(&m.to_cols_array())
}

fn six(a: Vec3, b: Vec3) -> Vector6<f32> {
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

/// Backward Euler's velocity change of a body (linear, angular) over a step
/// of `dt` under its contact springs, whose explicit wrench is `explicit`,
/// and the other forces on it, `external` (gravity, the ground): the
/// module's equation. `None` if the system cannot be solved (a body without
/// mass or inertia).
pub fn velocity_change(
    body: &Body,
    springs: &[Spring],
    dt: f32,
    explicit: Wrench,
    external: Wrench,
) -> Option<(Vec3, Vec3)> {
    let mut system = Matrix6::<f32>::zeros();
    system.fixed_view_mut::<3, 3>(0, 0).copy_from(&(nalgebra::Matrix3::identity() * body.mass));
    system.fixed_view_mut::<3, 3>(3, 3).copy_from(&matrix(body.inertia));
    let mut rhs = six(explicit.force + external.force, explicit.torque + external.torque) * dt;
    let twist = six(body.linvel, body.angvel);
    for spring in springs {
        let j = spring.jacobian();
        let jt_j = j.transpose() * j;
        let bone = spring.bone_velocity;
        system += jt_j * (dt * (spring.damping + dt * spring.stiffness));
        // The spring's stretch over the step, as the body and bone move on.
        rhs -= (jt_j * twist - j.transpose() * nalgebra::Vector3::new(bone.x, bone.y, bone.z))
            * (dt * dt * spring.stiffness);
    }
    let dv = system.cholesky()?.solve(&rhs);
    let (linear, angular) = (Vec3::new(dv[0], dv[1], dv[2]), Vec3::new(dv[3], dv[4], dv[5]));
    (linear.is_finite() && angular.is_finite()).then_some((linear, angular))
}

/// A contact's force on the object at the end of the step, from its
/// explicit force `explicit` (on the object, N), for the body's velocity
/// now and its change `(dv, dw)`: the module's correction, then kept in
/// the contact's friction cone. The normal force stays pressing (≥ 0); a
/// sticking contact's tangential force stays within `static_mu` times it
/// (the static cone of [`super::law`]); a slipping one's is at most its
/// kinetic friction, scaled with the normal force.
pub fn corrected_force(
    spring: &Spring,
    explicit: Vec3,
    body: &Body,
    dt: f32,
    (dv, dw): (Vec3, Vec3),
    static_mu: f32,
) -> Vec3 {
    let velocity = spring.point_velocity(body.linvel, body.angvel) - spring.bone_velocity;
    let change = spring.point_velocity(dv, dw);
    let k = spring.stiffness;
    // The force on the object pushes it along −n; the object moving along
    // +n, into the bone, deepens the press and raises that force (a
    // negative change along +n), as moving away lessens it.
    let delta = -(velocity * (dt * k) + change * (spring.damping + dt * k));
    let n = spring.normal;
    let pressing = |f: Vec3| (-f.dot(n)).max(0.0);
    let explicit_normal = pressing(explicit);
    let total = explicit + delta;
    let normal = pressing(total);
    let tangential = |f: Vec3| f - n * f.dot(n);
    let tangent = if spring.sticking {
        tangential(total).clamp_length_max(static_mu * normal)
    } else if explicit_normal > 0.0 {
        // Kinetic friction at the new normal force, or less where the
        // correction stops the slip.
        let kinetic = tangential(explicit).length() * (normal / explicit_normal);
        tangential(total).clamp_length_max(kinetic)
    } else {
        Vec3::ZERO
    };
    tangent - n * normal
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 1-D spring on a point mass stepped with the corrected force by
    /// semi-implicit Euler: stable and settling at any step, however stiff,
    /// where the explicit spring alone diverges.
    #[test]
    fn a_stiff_spring_on_a_light_body_settles_at_a_long_step() {
        let (mass, k, dt) = (0.03f32, 900.0f32, 1.0 / 75.0);
        assert!(dt * dt * k / mass > 4.0, "explicit would diverge");
        let body_at = |v: f32| Body {
            mass,
            inertia: Mat3::from_diagonal(Vec3::splat(1e-5)),
            linvel: Vec3::new(0.0, v, 0.0),
            angvel: Vec3::ZERO,
        };
        // The bone presses the body's underside (normal −y) 6 mm in; the
        // spring pushes it up against gravity.
        let spring = |_: f32| Spring {
            offset: Vec3::ZERO,
            normal: Vec3::NEG_Y,
            bone_velocity: Vec3::ZERO,
            stiffness: k,
            damping: 0.0,
            sticking: false,
        };
        let (mut y, mut v) = (0.006f32, 0.0f32); // y: penetration depth
        let gravity = Vec3::new(0.0, -9.81 * mass, 0.0);
        let mut largest = 0.0f32;
        for step in 0..300 {
            let body = body_at(v);
            let explicit = Vec3::new(0.0, k * y, 0.0);
            let wrench = Wrench { force: explicit, torque: Vec3::ZERO };
            let external = Wrench { force: gravity, torque: Vec3::ZERO };
            let change = velocity_change(&body, &[spring(y)], dt, wrench, external).unwrap();
            let f = corrected_force(&spring(y), explicit, &body, dt, change, 0.5);
            v += (f.y + gravity.y) / mass * dt;
            y -= v * dt;
            if step > 200 {
                largest = largest.max((y - 9.81 * mass / k).abs());
            }
        }
        // At rest where the full-stiffness spring carries the weight.
        assert!(largest < 1e-5, "settled within {largest} m of mg/k");
    }
}
