//! What keeps the contact law sane on tracked hands, beyond the thesis:
//! a bone that teleports deep inside an object (a tracking glitch) must not
//! launch it, and a pure spring must not ring forever. Each is switched in
//! [`crate::InteractionConfig`] and off in [`crate::InteractionConfig::thesis`].

use super::FrictionCoefficients;
use super::gamma::MAX_PENETRATION_FRACTION;
use super::law::spring_force;
use glam::Vec3;

/// The penetration-speed limit on the depth the spring sees (m), from
/// `previous`, the limited depth of the last step. Speeds in m/s along the
/// contact normal: `approach_speed` is the object's, towards the bone;
/// `bone_speed` is the bone's, into the object.
///
/// Think of a virtual bone that the spring sees, chasing the tracked one:
/// * it sinks into the object at most `max_speed` faster than the object
///   comes at it, so a bone that jumps deep inside ramps in like a finger
///   pressing at `max_speed`, while an object falling onto a hand meets
///   the full spring;
/// * it moves, in the world, no faster than `max_speed` or the tracked
///   bone itself. A bone left deep inside an object by a glitch therefore
///   pushes it away no faster than `max_speed`, however light it is, where
///   a limit relative to the object alone would chase it at `max_speed`
///   plus its own growing speed. A hand that really swings fast still
///   pushes as fast as it moves.
#[inline]
pub fn speed_limited_depth(
    depth: f32,
    previous: f32,
    approach_speed: f32,
    bone_speed: f32,
    max_speed: f32,
    dt: f32,
) -> f32 {
    let into_object = max_speed + approach_speed.max(0.0);
    let in_world = approach_speed + max_speed.max(bone_speed);
    depth.min(previous + into_object.min(in_world) * dt)
}

/// The bone's velocity relative to the object (m/s), `bone − object`,
/// with its speed into the object (along `−n`) held to `max_speed`, so a
/// bone that teleports cannot kick the object through the damper either.
/// Relative, as the spring's depth limit is: a hand that sweeps an object
/// along at 3 m/s closes on it slowly, and its damper pushes as it should.
#[inline]
pub fn limited_relative_velocity(bone: Vec3, object: Vec3, n: Vec3, max_speed: f32) -> Vec3 {
    let relative = bone - object;
    let into = -relative.dot(n);
    if into > max_speed { relative + (into - max_speed) * n } else { relative }
}

/// The spring of [`spring_force`] with its normal stretch replaced by
/// `seen_depth` (m), the depth the safeguards let it see; the tangential
/// stretch is untouched.
#[inline]
pub fn spring_at_depth(gamma: f32, c: Vec3, p: Vec3, n: Vec3, seen_depth: f32) -> Vec3 {
    let depth = (c - p).dot(n);
    spring_force(gamma, c, p) + gamma * (seen_depth - depth) * n
}

/// The force cap: the spring never sees more than the thesis's assumed
/// deepest penetration, 20 % of the object's bounding diameter d (§3.5.6).
/// Deeper bones are tracking errors, not harder presses, so they push no
/// harder: the normal spring force stays ≤ γ·0.2·d, and friction ≤
/// max(μ_st, μ_dyn) times that.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceCap {
    /// The deepest penetration the spring sees (m).
    pub max_depth: f32,
}

impl ForceCap {
    /// The cap of an object whose bounding sphere is `diameter` across (m).
    #[inline]
    pub fn for_diameter(diameter: f32) -> ForceCap {
        ForceCap { max_depth: MAX_PENETRATION_FRACTION * diameter }
    }

    /// The depth the spring sees for a bone `depth` deep (m).
    #[inline]
    pub fn depth(self, depth: f32) -> f32 {
        depth.min(self.max_depth)
    }

    /// The largest normal spring force, `γ · 0.2 · d` (N).
    #[inline]
    pub fn normal_force(self, gamma: f32) -> f32 {
        gamma * self.max_depth
    }

    /// The friction `f_T` bounded by `max(μ_st, μ_dyn)` times
    /// [`Self::normal_force`]. Kinetic friction as written in the thesis
    /// scales an unbounded stretch, and a damper can add normal force beyond
    /// the spring's; this bounds both.
    #[inline]
    pub fn tangential(self, f_t: Vec3, mu: FrictionCoefficients, gamma: f32) -> Vec3 {
        // Multiplied as (μ·γ)·d_max, not μ·(γ·d_max): recorded traces and
        // sessions depend on the last bit.
        let cap = mu.max() * gamma * self.max_depth;
        let magnitude = f_t.length();
        if magnitude > cap { f_t * (cap / magnitude) } else { f_t }
    }
}

/// The damping coefficient `c = 2ζ√(γ m)` (N·s/m) that gives one contact
/// spring of stiffness γ on a body of mass `m` the damping ratio ζ.
#[inline]
pub fn damping_coefficient(gamma: f32, mass: f32, damping_ratio: f32) -> f32 {
    2.0 * damping_ratio * (gamma * mass).sqrt()
}

/// The Kelvin–Voigt reaction on the bone: the spring plus a damper on the
/// relative velocity. `relative_velocity` is the bone's velocity minus the
/// object's velocity at the contact (m/s); `C − p` shrinks at that rate.
#[inline]
pub fn damped_spring_force(spring: Vec3, damping: f32, relative_velocity: Vec3) -> Vec3 {
    spring - damping * relative_velocity
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_jump_ramps_in_at_the_speed_limit_but_an_approaching_object_does_not() {
        // A bone 30 mm deep at once, 1 m/s limit, 1 ms steps: 1 mm a step.
        let mut seen = 0.0;
        for bone_speed in [30.0, 0.0, 0.0] {
            seen = speed_limited_depth(0.03, seen, 0.0, bone_speed, 1.0, 0.001);
        }
        assert!((seen - 0.003).abs() < 1e-7, "{seen}");
        // An object arriving at 2.5 m/s adds its own approach.
        assert!((speed_limited_depth(0.03, 0.0, 2.5, 0.0, 1.0, 0.001) - 0.0035).abs() < 1e-7);
        // A shallow bone is seen as it is.
        assert_eq!(speed_limited_depth(0.0004, 0.0, 0.0, 0.0, 1.0, 0.001), 0.0004);
    }

    #[test]
    fn a_bone_left_deep_inside_pushes_a_receding_object_no_faster_than_the_limit() {
        // The object already flees at 1.5 m/s from a still bone 20 mm
        // inside: the spring's depth shrinks by 0.5 mm a step.
        let seen = speed_limited_depth(0.02, 0.004, -1.5, 0.0, 1.0, 0.001);
        assert!((seen - 0.0035).abs() < 1e-7, "{seen}");
        // A bone that really pushes at 3 m/s keeps up with an object
        // receding at 2.8 m/s: its depth may still grow.
        let pushed = speed_limited_depth(0.02, 0.004, -2.8, 3.0, 1.0, 0.001);
        assert!((pushed - 0.0042).abs() < 1e-7, "{pushed}");
    }

    #[test]
    fn only_the_speed_into_the_object_relative_to_it_is_limited() {
        let v = Vec3::new(0.7, -3.0, 0.2); // 3 m/s into a face with n = +y
        let limited = limited_relative_velocity(v, Vec3::ZERO, Vec3::Y, 1.0);
        assert!((limited - Vec3::new(0.7, -1.0, 0.2)).length() < 1e-6);
        let away = Vec3::new(0.7, 3.0, 0.2);
        assert_eq!(limited_relative_velocity(away, Vec3::ZERO, Vec3::Y, 1.0), away);
        // The same bone behind an object that already moves away at 2.4 m/s
        // closes on it at 0.6 m/s: not limited.
        let object = Vec3::new(0.0, -2.4, 0.0);
        let closing = limited_relative_velocity(v, object, Vec3::Y, 1.0);
        assert!((closing - Vec3::new(0.7, -0.6, 0.2)).length() < 1e-6, "{closing:?}");
    }

    #[test]
    fn the_spring_sees_the_limited_depth_along_the_normal_only() {
        let (c, p) = (Vec3::ZERO, Vec3::new(0.002, -0.01, 0.0)); // 10 mm deep
        let f = spring_at_depth(300.0, c, p, Vec3::Y, 0.004);
        assert!((f - Vec3::new(-0.6, 1.2, 0.0)).length() < 1e-5, "{f:?}");
    }

    #[test]
    fn the_cap_bounds_depth_normal_force_and_friction() {
        let cap = ForceCap::for_diameter(0.05); // 10 mm
        assert!((cap.max_depth - 0.01).abs() < 1e-7);
        assert_eq!(cap.depth(0.03), cap.max_depth);
        assert_eq!(cap.depth(0.004), 0.004);
        assert!((cap.normal_force(250.0) - 2.5).abs() < 1e-5);
        let mu = FrictionCoefficients { static_mu: 0.3, dynamic_mu: 0.7 };
        // Friction is held to max(μ) · 2.5 N = 1.75 N, keeping its direction.
        let t = cap.tangential(Vec3::new(3.0, 0.0, 4.0), mu, 250.0);
        assert!((t - Vec3::new(1.05, 0.0, 1.4)).length() < 1e-5, "{t:?}");
        assert_eq!(cap.tangential(Vec3::new(1.0, 0.0, 0.0), mu, 250.0), Vec3::X);
    }

    #[test]
    fn the_damper_opposes_the_relative_velocity() {
        let c = damping_coefficient(400.0, 0.05, 0.5);
        assert!((c - 2.0 * 0.5 * (20.0f32).sqrt()).abs() < 1e-6);
        let f = damped_spring_force(Vec3::Y, c, Vec3::new(0.0, -0.1, 0.0));
        assert!(f.y > 1.0, "a bone moving in presses harder: {f:?}");
    }
}
