//! Flat arrays in and out, as JavaScript's typed arrays carry them: each
//! argument's length is checked and named before a number reaches the
//! library (which checks the numbers), and each result's layout is a
//! stride of numbers per item, written here once. Errors are the messages
//! the page shows.

use coulomb_hands::hand::{Capsule, HandPose, Palm};
use coulomb_hands::{Contact, ContactEvent, ObjectState};
use glam::{Quat, Vec3};

/// An argument's error: what is wrong with it.
type Error = String;

/// A hand pose's numbers: the palm's centre (3), rotation (4, x, y, z, w)
/// and half extents (3), then the 15 finger bones' capsules, thumb first,
/// proximal first, each its ends `a` (3) and `b` (3) and its radius (1).
pub const POSE: usize = 10 + 15 * 7;

/// An object state's numbers: position (3), rotation (4, x, y, z, w),
/// linear velocity (3), angular velocity (3), the hands' total force on it
/// (3, thesis Eq. 3.10), and 1 if rapier has put it to sleep, else 0.
pub const STATE: usize = 17;

/// A contact's numbers: object, hand and bone ids, its friction state (0
/// static, 1 dynamic, 2 separated), the point C on the surface (3), the
/// normal (3), the bone's point p (3), the force on the object (3, N),
/// the depth (m) and the normal force (N).
pub const CONTACT: usize = 18;

/// An event's numbers: kind (0 began, 1 ended), object, hand and bone ids,
/// the point C (3) and the time (s).
pub const EVENT: usize = 8;

/// `count` points from `3 × count` numbers.
pub fn vec3s(values: &[f32], what: &str, count: usize) -> Result<Vec<Vec3>, Error> {
    if values.len() != 3 * count {
        return Err(format!("{what}: expected {} numbers, got {}", 3 * count, values.len()));
    }
    Ok(values.chunks_exact(3).map(Vec3::from_slice).collect())
}

/// `count` rotations (x, y, z, w) from `4 × count` numbers, each made a
/// unit quaternion; a zero-length or non-finite one is an error.
pub fn quats(values: &[f32], what: &str, count: usize) -> Result<Vec<Quat>, Error> {
    if values.len() != 4 * count {
        return Err(format!("{what}: expected {} numbers, got {}", 4 * count, values.len()));
    }
    values
        .chunks_exact(4)
        .enumerate()
        .map(|(i, q)| {
            coulomb_hands::input::layouts::rotation([q[0], q[1], q[2], q[3]])
                .ok_or_else(|| format!("{what}[{i}]: zero-length or non-finite rotation"))
        })
        .collect()
}

/// A rotation (x, y, z, w), or none for no rotation.
pub fn rotation(values: &[f32]) -> Result<Quat, Error> {
    if values.is_empty() {
        return Ok(Quat::IDENTITY);
    }
    Ok(quats(values, "rotation", 1)?[0])
}

/// A pose's [`POSE`] numbers.
pub fn pose(pose: &HandPose) -> Vec<f32> {
    let p = &pose.palm;
    let mut out = Vec::with_capacity(POSE);
    out.extend(p.center.to_array());
    out.extend(p.rotation.to_array());
    out.extend(p.half_extents.to_array());
    for c in pose.fingers.iter().flatten() {
        out.extend(c.a.to_array());
        out.extend(c.b.to_array());
        out.push(c.radius);
    }
    out
}

/// The pose [`POSE`] numbers describe (their count checked here, the
/// numbers by the library when it is set).
pub fn pose_from(values: &[f32]) -> Result<HandPose, Error> {
    if values.len() != POSE {
        return Err(format!("pose: expected {POSE} numbers, got {}", values.len()));
    }
    let v3 = |i: usize| Vec3::from_slice(&values[i..i + 3]);
    let palm =
        Palm { center: v3(0), rotation: Quat::from_slice(&values[3..7]), half_extents: v3(7) };
    let capsule = |k: usize| {
        let at = 10 + 7 * k;
        Capsule { a: v3(at), b: v3(at + 3), radius: values[at + 6] }
    };
    let fingers = std::array::from_fn(|f| std::array::from_fn(|p| capsule(3 * f + p)));
    Ok(HandPose { palm, fingers })
}

/// States' [`STATE`] numbers, one after another; a removed object's
/// (`None`) are NaN.
pub fn states(states: impl Iterator<Item = Option<ObjectState>>) -> Vec<f32> {
    let mut out = Vec::new();
    for state in states {
        let Some(s) = state else {
            out.extend([f32::NAN; STATE]);
            continue;
        };
        out.extend(s.position.to_array());
        out.extend(s.rotation.to_array());
        out.extend(s.linvel.to_array());
        out.extend(s.angvel.to_array());
        out.extend(s.hand_force.to_array());
        out.push(if s.sleeping { 1.0 } else { 0.0 });
    }
    out
}

/// Contacts' [`CONTACT`] numbers, one after another.
pub fn contacts(contacts: &[Contact]) -> Vec<f32> {
    let mut out = Vec::with_capacity(CONTACT * contacts.len());
    for c in contacts {
        let state = f32::from(c.state.code());
        out.extend([c.object.0 as f32, c.hand.0 as f32, c.bone.index() as f32, state]);
        out.extend(c.point.to_array());
        out.extend(c.normal.to_array());
        out.extend(c.bone_point.to_array());
        out.extend(c.force.to_array());
        out.extend([c.depth, c.normal_force]);
    }
    out
}

/// Events' [`EVENT`] numbers, one after another.
pub fn events(events: &[ContactEvent]) -> Vec<f64> {
    let mut out = Vec::with_capacity(EVENT * events.len());
    for e in events {
        let kind = f64::from(e.kind.code());
        out.extend([kind, f64::from(e.object.0), f64::from(e.hand.0), e.bone.index() as f64]);
        out.extend(e.point.to_array().map(f64::from));
        out.push(e.time);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use coulomb_hands::Side;
    use coulomb_hands::hand::rig::HandRig;

    #[test]
    fn a_pose_comes_back_from_its_numbers_bit_for_bit() {
        let pose = HandRig::adult(Side::Left).pose(
            Vec3::new(0.01, 0.2, -0.1),
            Quat::from_rotation_z(0.3),
            [0.1, 0.2, 0.3, 0.4, 0.5],
        );
        let numbers = super::pose(&pose);
        assert_eq!(numbers.len(), POSE);
        assert_eq!(pose_from(&numbers).expect("a pose"), pose);
    }

    #[test]
    fn wrong_lengths_name_the_argument_and_the_count() {
        assert_eq!(pose_from(&[0.0; 3]).unwrap_err(), "pose: expected 115 numbers, got 3");
        assert_eq!(vec3s(&[1.0], "size", 1).unwrap_err(), "size: expected 3 numbers, got 1");
        let zero = quats(&[0.0; 8], "orientations", 2).unwrap_err();
        assert_eq!(zero, "orientations[0]: zero-length or non-finite rotation");
    }
}
