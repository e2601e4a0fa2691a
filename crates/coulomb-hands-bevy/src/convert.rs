//! The one place where the core's glam (0.33, rapier's) meets Bevy's
//! (0.32): vectors and rotations cross by their components, so the two
//! versions never need to agree on a type.

use bevy::math::{Quat, Vec3};
use bevy::transform::components::Transform;

/// A core vector as Bevy's.
pub fn to_bevy_vec3(v: glam::Vec3) -> Vec3 {
    Vec3::from_array(v.to_array())
}

/// A core rotation as Bevy's.
pub fn to_bevy_quat(q: glam::Quat) -> Quat {
    Quat::from_array(q.to_array())
}

/// A Bevy vector as the core's.
pub fn to_core_vec3(v: Vec3) -> glam::Vec3 {
    glam::Vec3::from_array(v.to_array())
}

/// A Bevy rotation as the core's.
pub fn to_core_quat(q: Quat) -> glam::Quat {
    glam::Quat::from_array(q.to_array())
}

/// The transform of a core pose: a position (m) and a rotation.
pub fn transform(position: glam::Vec3, rotation: glam::Quat) -> Transform {
    Transform::from_translation(to_bevy_vec3(position)).with_rotation(to_bevy_quat(rotation))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_cross_unchanged_both_ways() {
        let v = glam::Vec3::new(0.1, -2.5, 3e-7);
        let q = glam::Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0);
        assert_eq!(to_core_vec3(to_bevy_vec3(v)), v);
        assert_eq!(to_core_quat(to_bevy_quat(q)), q);
        let t = transform(v, q);
        assert_eq!((t.translation.to_array(), t.rotation.to_array()), (v.to_array(), q.to_array()));
    }
}
