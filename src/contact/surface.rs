//! Dynamic surface-point updates (thesis §3.5.3, §3.7 "Surface Point
//! Updates", Fig. 3.8): a slipping contact point moves along the object's
//! surface by inverse ray casts, never through the object.

use glam::Vec3;
use rapier3d::math::Pose;
use rapier3d::parry::query::Ray;
use rapier3d::parry::shape::Shape;

/// A point on the object's surface with its outward normal (world).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePoint {
    /// The point on the surface (world, m).
    pub point: Vec3,
    /// Unit outward surface normal there (world).
    pub normal: Vec3,
}

/// A candidate whose normal points against the previous normal lies on a
/// face the contact cannot reach without passing through the object
/// (Fig. 3.8, R4/R5). Faces at a right angle (rolling over an edge) are
/// allowed; this small tolerance keeps exact right angles on the allowed side.
const BLOCKED_BELOW_COS: f32 = -1.0e-3;

/// Casts one inverse ray and accepts its hit only if it starts outside the
/// object and lands on a face that does not oppose `previous_normal`.
fn cast(
    shape: &dyn Shape,
    pose: &Pose,
    origin: Vec3,
    direction: Vec3,
    max_distance: f32,
    previous_normal: Vec3,
) -> Option<SurfacePoint> {
    let dir = direction.try_normalize()?;
    let ray = Ray::new(origin, dir);
    let hit = shape.cast_ray_and_get_normal(pose, &ray, max_distance, true)?;
    // A zero time of impact means the origin is inside the object: the
    // probe started behind a surface, so its answer is not a surface point
    // reachable from the current one.
    if hit.time_of_impact <= 1.0e-7 {
        return None;
    }
    let normal = hit.normal.try_normalize()?;
    if normal.dot(previous_normal) < BLOCKED_BELOW_COS {
        return None;
    }
    let point = ray.point_at(hit.time_of_impact);
    point.is_finite().then_some(SurfacePoint { point, normal })
}

/// Moves a slipping contact point along the surface.
///
/// * `current`: the contact point C and its normal before the update.
/// * `target`: where C should go (on C's tangent plane), if known.
/// * `bone_point`: the bone's current point p.
/// * `probe`: how far above the surface the inverse rays start (m).
///
/// First probe straight back onto the surface from `target + probe·n`;
/// if that finds nothing acceptable, cast the thesis's inverse ray from
/// `C + probe·n` towards the bone. `None` means every candidate was blocked
/// or missed, and C stays where it is.
pub fn slide(
    shape: &dyn Shape,
    pose: &Pose,
    current: SurfacePoint,
    target: Option<Vec3>,
    bone_point: Vec3,
    probe: f32,
) -> Option<SurfacePoint> {
    let n = current.normal;
    if let Some(t) = target {
        let reach = 2.0 * probe + (t - current.point).length();
        if let Some(hit) = cast(shape, pose, t + probe * n, -n, reach, n) {
            return Some(hit);
        }
    }
    let origin = current.point + probe * n;
    let to_bone = bone_point - origin;
    cast(shape, pose, origin, to_bone, to_bone.length() + probe, n)
}

/// Where a new contact's point C goes: on the object's face that the
/// closest-feature query found (`near`), straight along its normal from the
/// bone's `centre` (the bone point nearest the object's centre). This is
/// the thesis's ray cast onto the collider (§3.7 "Contact Point
/// Estimation"); it centres C on the overlap of a flat bone and a flat face
/// instead of at whichever corner the closest-feature query returned.
/// Falls back to `near` when the ray misses or lands on another face.
pub fn locate_contact(
    shape: &dyn Shape,
    pose: &Pose,
    near: SurfacePoint,
    centre: Vec3,
    reach: f32,
) -> SurfacePoint {
    let n = near.normal;
    // Start outside the object on the bone's side of the face.
    let back = (centre - near.point).dot(n).max(0.0) + reach;
    let origin = centre - (centre - near.point).dot(n) * n + back * n;
    match cast(shape, pose, origin, -n, back + reach, n) {
        Some(hit)
            if hit.normal.dot(n) > 0.9
                && (hit.point - near.point).length() <= reach + (centre - near.point).length() =>
        {
            hit
        }
        _ => near,
    }
}

/// The least cosine between a patch sample's surface normal and the normal
/// at C for the sample to count as on C's face: 30°, which lets a patch
/// follow a gently curved surface but not wrap round an edge.
pub(crate) const SAME_FACE_COS: f32 = 0.866;

/// The cosine between `n` and the object's surface normal straight below
/// `q`, a point of C's tangent plane, if the surface is there within
/// `depth` (m) of the plane. A point beyond an edge finds a side face
/// (a small cosine), another part of the object, or nothing.
pub fn face_cos(shape: &dyn Shape, pose: &Pose, q: Vec3, n: Vec3, depth: f32) -> Option<f32> {
    surface_below(shape, pose, q, n, depth).map(|hit| hit.normal.dot(n))
}

/// The object's surface straight below `q`, a point of C's tangent plane
/// (normal `n`), if it is there within `depth` (m) of the plane.
pub(crate) fn surface_below(
    shape: &dyn Shape,
    pose: &Pose,
    q: Vec3,
    n: Vec3,
    depth: f32,
) -> Option<SurfacePoint> {
    let lift = depth.max(1.0e-4);
    cast(shape, pose, q + lift * n, -n, 2.0 * lift, n)
}

/// The closest surface point of the object to `q` (world).
pub fn project_to_surface(shape: &dyn Shape, pose: &Pose, q: Vec3) -> Vec3 {
    let projected = shape.project_point(pose, q, false).point;
    if projected.is_finite() { projected } else { q }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapier3d::parry::shape::{Compound, Cuboid, SharedShape};

    fn up(point: Vec3) -> SurfacePoint {
        SurfacePoint { point, normal: Vec3::Y }
    }

    #[test]
    fn slides_along_a_flat_face_to_the_target() {
        let cube = Cuboid::new(Vec3::splat(0.05));
        let pose = Pose::identity();
        let start = up(Vec3::new(0.0, 0.05, 0.0));
        let target = Vec3::new(0.02, 0.05, 0.01);
        let bone = Vec3::new(0.03, 0.047, 0.01);
        let s = slide(&cube, &pose, start, Some(target), bone, 0.004).unwrap();
        assert!((s.point - target).length() < 1e-5);
        assert!((s.normal - Vec3::Y).length() < 1e-5);
    }

    #[test]
    fn a_target_past_a_convex_edge_keeps_c_on_the_surface() {
        let cube = Cuboid::new(Vec3::splat(0.05));
        let pose = Pose::identity();
        // The target lies beyond the +x edge, where the straight-down probe
        // finds nothing; the inverse ray towards the bone (inside, near the
        // edge) lands on the top face next to the edge.
        let start = up(Vec3::new(0.049, 0.05, 0.0));
        let bone = Vec3::new(0.048, 0.03, 0.0);
        let s = slide(&cube, &pose, start, Some(Vec3::new(0.07, 0.05, 0.0)), bone, 0.004).unwrap();
        assert!((s.normal - Vec3::Y).length() < 1e-5, "{s:?}");
        assert!((s.point.y - 0.05).abs() < 1e-5 && (0.045..=0.05).contains(&s.point.x), "{s:?}");
    }

    /// A U-shaped bracket: two arms rising from a base, gap between them.
    fn u_shape() -> SharedShape {
        let part = |x: f32, y: f32, hx: f32, hy: f32| {
            (Pose::translation(x, y, 0.0), SharedShape::cuboid(hx, hy, 0.02))
        };
        SharedShape::new(Compound::new(vec![
            part(0.0, 0.0, 0.05, 0.01),    // base, top at y = 0.01
            part(-0.04, 0.05, 0.01, 0.04), // left arm, inner face x = -0.03
            part(0.04, 0.05, 0.01, 0.04),  // right arm, inner face x = 0.03
        ]))
    }

    #[test]
    fn never_jumps_across_the_gap_of_a_u() {
        let u = u_shape();
        let pose = Pose::identity();
        // Contact on the left arm's inner face (normal +x), bone pushed
        // through the gap towards the right arm.
        let start = SurfacePoint { point: Vec3::new(-0.03, 0.06, 0.0), normal: Vec3::X };
        let bone = Vec3::new(0.035, 0.06, 0.0); // inside the right arm
        let s = slide(&*u.0, &pose, start, None, bone, 0.004);
        // The thesis ray towards the bone hits the right arm's inner face,
        // whose normal (-x) opposes the previous one: rejected, C stays.
        assert!(s.is_none(), "jumped to {s:?}");
    }
}
