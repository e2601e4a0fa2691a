//! The NaN firewall: the one place that guards every value entering the
//! physics world, and the check that the world stayed finite.
//!
//! | what enters rapier | guard | called by |
//! |---|---|---|
//! | the config (dt, gravity, offsets, γ) | [`config`] | `InteractionWorld::new` |
//! | statics: shape, pose, friction | [`fixed`] | `add_static`, `add_scene` |
//! | objects: shape, pose, mass, material, γ | [`object`] | `add_object`, `add_scene` |
//! | hand poses, the source of every contact | [`pose`] | `set_hand_pose` |
//! | an object put at a new pose | [`placement`] | `place_object` |
//! | the hand forces rapier integrates | [`forces`] | stage 7, `apply_forces` |
//! | a grabbed object's pose, velocities | [`kinematic_target`], [`velocities`] | stage 8, grab |
//!
//! A rejected call is an error naming the field and leaves the world as it
//! was; a force that is not finite (which finite poses and objects never
//! produce) is dropped. What a program writes into rapier itself through
//! [`InteractionWorld::physics_mut`] is outside the firewall.
//! [`InteractionWorld::first_non_finite`] checks the result.

use super::InteractionWorld;
use super::config::InteractionConfig;
use super::error::WorldError;
use crate::contact::lanes::Chunk;
use crate::friction;
use crate::hand::HandPose;
use crate::scene::{GammaMode, ObjectDesc, ObjectError, StaticDesc};
use glam::Vec3;
use rapier3d::parry::shape::SharedShape;
use rapier3d::prelude::MassProperties;
use wide::f32x4;

/// The config, before a world is made from it.
pub(super) fn config(config: &InteractionConfig) -> Result<(), WorldError> {
    Ok(config.validate()?)
}

/// A static's description; returns its collision shape.
pub(super) fn fixed(desc: &StaticDesc) -> Result<SharedShape, WorldError> {
    Ok(desc.validate()?)
}

/// An object as it enters the world.
pub(super) struct Admitted {
    pub shape: SharedShape,
    /// The shape its hand contacts query instead, if not `shape`
    /// ([`crate::scene::HandSurface::Exact`]).
    pub hand_shape: Option<SharedShape>,
    /// Its contact stiffness γ (N/m), finite and > 0.
    pub gamma: f32,
    /// Its bounding sphere's diameter (m).
    pub diameter: f32,
    /// How far any point of it is from its origin, at most (m): what a
    /// turn about the origin moves it by, per radian.
    pub reach: f32,
    /// Its own mass properties, where it gives its own inertia
    /// ([`ObjectDesc::inertia`]): its shape's centre of mass, its mass
    /// and those moments. `None`: the shape's own at its mass.
    pub mass_properties: Option<MassProperties>,
}

/// An object's description, and the γ it gets under `mode`
/// ([`friction::auto_gamma`] for [`GammaMode::Auto`], at gravity of
/// magnitude `gravity`, m/s²).
pub(super) fn object(
    desc: &ObjectDesc,
    mode: GammaMode,
    gravity: f32,
) -> Result<Admitted, WorldError> {
    let shape = desc.validate()?;
    let hand_shape = desc.hand_shape()?;
    let bounds = shape.compute_local_bounding_sphere();
    let diameter = 2.0 * bounds.radius();
    let reach = bounds.center().length() + bounds.radius();
    let mass_properties = match desc.inertia {
        Some(inertia) => {
            // The farthest any of its mass can be from its centre of mass.
            let com = shape.mass_properties(1.0).local_com;
            let reach = bounds.radius() + com.distance(bounds.center());
            crate::scene::object::check_inertia(&desc.name, inertia, desc.mass, reach)?;
            Some(MassProperties::new(com, desc.mass, inertia))
        }
        None => None,
    };
    let gamma = match desc.gamma.unwrap_or(mode) {
        GammaMode::Fixed(g) => g,
        GammaMode::Auto => {
            let (mass, mu) = (desc.mass, desc.material.skin.static_mu);
            friction::auto_gamma(mass, gravity, mu, diameter)
        }
    };
    if !(gamma.is_finite() && gamma > 0.0) {
        let why = format!("automatic γ is {gamma}: needs gravity, μ_st and size > 0");
        return Err(ObjectError::new(&desc.name, "gamma", why).into());
    }
    Ok(Admitted { shape, hand_shape, gamma, diameter, reach, mass_properties })
}

/// A hand pose for hand number `hand`.
pub(super) fn pose(hand: u32, pose: &HandPose) -> Result<(), WorldError> {
    Ok(pose.validate(hand)?)
}

/// A new pose for object `name`: a finite position within range and a unit
/// rotation, returned normalised.
pub(super) fn placement(
    name: &str,
    position: Vec3,
    rotation: glam::Quat,
) -> Result<glam::Quat, WorldError> {
    crate::scene::object::finite_vec(name, "position", position)?;
    crate::scene::object::unit_quat(name, "rotation", rotation)?;
    Ok(rotation.normalize())
}

/// Which of four samples' `(force, point)` may reach rapier, as a bitmask
/// of lanes: only finite ones (`x·0` is exactly 0 for a finite `x`, and
/// NaN for any other, so one sum of them tests all six components).
#[inline]
pub(super) fn forces(force: &Chunk, point: &Chunk) -> u32 {
    let zero = f32x4::ZERO;
    let [fx, fy, fz] = force.map(|c| c * zero);
    let [px, py, pz] = point.map(|c| c * zero);
    ((((fx + fy) + fz) + ((px + py) + pz)).simd_eq(zero)).to_bitmask()
}

/// A kinematically carried object's next pose, if finite.
pub(super) fn kinematic_target(pose: rapier3d::math::Pose) -> Option<rapier3d::math::Pose> {
    (pose.translation.is_finite() && pose.rotation.is_finite()).then_some(pose)
}

/// A grabbed object's velocities (m/s, rad/s), if finite.
pub(super) fn velocities(linvel: Vec3, angvel: Vec3) -> Option<(Vec3, Vec3)> {
    (linvel.is_finite() && angvel.is_finite()).then_some((linvel, angvel))
}

impl InteractionWorld {
    /// The first value of the world that is not finite, named (`"object
    /// box: linvel"`, `"contact 2: force"`), or `None` when all are: every
    /// rapier body's pose, velocities and accumulated force and torque, and
    /// every contact's points, normal, depth, forces and samples.
    pub fn first_non_finite(&self) -> Option<String> {
        for (handle, body) in self.physics.bodies.iter() {
            let object = self.objects.iter().find(|o| o.body == handle);
            let name = object.map_or("a static body".to_string(), |o| format!("object {}", o.name));
            let pose = body.position();
            let fields = [
                ("position", pose.translation.is_finite()),
                ("rotation", pose.rotation.is_finite()),
                ("linvel", body.linvel().is_finite()),
                ("angvel", body.angvel().is_finite()),
                ("force", body.user_force().is_finite()),
                ("torque", body.user_torque().is_finite()),
            ];
            if let Some((field, _)) = fields.iter().find(|(_, ok)| !ok) {
                return Some(format!("{name}: {field}"));
            }
        }
        for (i, c) in self.contacts.iter().enumerate() {
            let fields = [
                ("point", c.point.is_finite()),
                ("normal", c.normal.is_finite()),
                ("bone_point", c.bone_point.is_finite()),
                ("depth", c.depth.is_finite()),
                ("force", c.force.is_finite()),
                ("normal_force", c.normal_force.is_finite()),
                ("stiffness", c.stiffness.is_finite()),
                ("samples", c.samples.iter().all(|s| s.is_finite())),
            ];
            if let Some((field, _)) = fields.iter().find(|(_, ok)| !ok) {
                return Some(format!("contact {i}: {field}"));
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::ObjectDesc;

    #[test]
    fn only_finite_forces_pass() {
        use crate::contact::lanes::Vec3Lanes;
        let lanes = |pairs: [(Vec3, Vec3); 4]| {
            let on_object = Vec3Lanes::from_items(pairs.map(|p| p.0));
            let at = Vec3Lanes::from_items(pairs.map(|p| p.1));
            forces(&on_object.chunks()[0], &at.chunks()[0])
        };
        let big = Vec3::new(f32::MAX, -f32::MAX, 3.5e-41);
        let pairs = [
            (big, Vec3::new(0.0, -0.0, 1.5)),
            (Vec3::new(f32::NAN, 0.0, 0.0), Vec3::ZERO),
            (Vec3::X, Vec3::new(0.0, f32::INFINITY, 0.0)),
            (Vec3::new(0.2, 0.1, f32::NEG_INFINITY), Vec3::Y),
        ];
        assert_eq!(lanes(pairs), 0b0001);
        let [a, b, c, d] = pairs;
        assert_eq!(lanes([b, a, (d.1, c.1), a]), 0b1010);
    }

    #[test]
    fn the_check_names_the_first_value_that_is_not_finite() {
        let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
        let desc = ObjectDesc::cuboid("crate", Vec3::splat(0.1), 0.4, Vec3::Y);
        let id = world.add_object(&desc).unwrap();
        world.step();
        assert_eq!(world.first_non_finite(), None);
        // Written behind the firewall's back, through rapier itself.
        let body = world.object_body(id).unwrap();
        world.physics_mut().bodies[body].set_angvel(Vec3::new(0.0, f32::NAN, 0.0), false);
        assert_eq!(world.first_non_finite().as_deref(), Some("object crate: angvel"));
    }
}
