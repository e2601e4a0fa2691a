//! The collision driver, as MuJoCo's `engine_collision_driver.c` is: which
//! bones are near which objects, and exactly how near.
//!
//! New contacts are found through a chain of filters, cheapest first:
//! 1. the whole hand's bounding box against each object's (most objects of
//!    a scene are far from any hand): the caller's, through rapier's broad
//!    phase, from [`Detector::reach`];
//! 2. each bone's box, grown by the contact offset, against those objects;
//! 3. parry's exact closest features, within the contact offset.
//!
//! A live contact asks only the last question, within the release offset.

use super::ObjectView;
use crate::hand::{Bone, BoneShape, HandPose};
use glam::Vec3;
use rapier3d::math::Pose;
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::parry::query::epa::EPA;
use rapier3d::parry::query::gjk::{self, CsoPoint, GJKResult, VoronoiSimplex};
use rapier3d::parry::query::{self, Contact, Unsupported};
use rapier3d::parry::shape::{Ball, Cuboid, HalfSpace, Segment, Shape, SupportMap};

/// Closest-feature geometry between a bone and an object (world).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Proximity {
    /// On the bone's surface.
    pub bone_point: Vec3,
    /// On the object's surface.
    pub object_point: Vec3,
    /// The object's outward normal at `object_point`.
    pub object_normal: Vec3,
    /// Signed surface distance, negative when penetrating (m).
    pub distance: f32,
}

/// Finds bone–object proximities: the filter chain for new contacts and
/// the exact query for live ones. Holds its buffers from step to step.
#[derive(Default)]
pub(crate) struct Detector {
    /// A contact begins within this distance of the surface (m).
    pub contact_offset: f32,
    /// A contact ends beyond this distance (m).
    pub release_offset: f32,
    /// Per bone of the hand being searched (by [`Bone::index`]): its
    /// reach, the bone's box grown by the contact offset.
    reach: Vec<Aabb>,
    /// The penetration query's buffers ([`contact`]).
    epa: EPA,
}

impl std::fmt::Debug for Detector {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Detector { contact_offset, release_offset, reach, epa: _ } = self;
        f.debug_struct("Detector")
            .field("contact_offset", contact_offset)
            .field("release_offset", release_offset)
            .field("reach", reach)
            .finish_non_exhaustive()
    }
}

impl Detector {
    /// A detector for the given offsets (m).
    pub fn new(contact_offset: f32, release_offset: f32) -> Detector {
        Detector { contact_offset, release_offset, ..Detector::default() }
    }

    /// The closest features of a live contact's bone and object, if the
    /// bone's surface is still within the release offset.
    pub fn still_touching(&mut self, bone: &BoneShape, object: &ObjectView) -> Option<Proximity> {
        within(&mut self.epa, bone, object, self.release_offset)
    }

    /// Starts the search of one hand, posed `pose` (world): keeps each
    /// bone's reach, its box grown by the contact offset (world, m), by
    /// [`Bone::index`], and returns them.
    #[inline(always)]
    pub fn reach(&mut self, pose: &HandPose) -> &[Aabb] {
        self.reach.clear();
        for bone in Bone::all() {
            self.reach.push(bone_aabb(&pose.bone(bone)).loosened(self.contact_offset));
        }
        &self.reach
    }

    /// The rest of the filter chain for `bone` of the hand [`Self::reach`]
    /// started, posed `pose`, and an object whose box is `bounds` (world,
    /// m): if the bone's reach meets that box, `object()` is the object,
    /// and the closest features if the bone's surface is within the
    /// contact offset of it.
    #[inline(always)]
    pub fn new_touch<'v>(
        &mut self,
        pose: &HandPose,
        bone: Bone,
        bounds: &Aabb,
        object: impl FnOnce() -> ObjectView<'v>,
    ) -> Option<(ObjectView<'v>, Proximity)> {
        if !self.reach.get(bone.index())?.intersects(bounds) {
            return None;
        }
        let object = object();
        let prox = within(&mut self.epa, &pose.bone(bone), &object, self.contact_offset)?;
        Some((object, prox))
    }
}

/// The closest features if the bone's surface is within `offset` (m).
fn within(epa: &mut EPA, bone: &BoneShape, object: &ObjectView, offset: f32) -> Option<Proximity> {
    proximity(epa, bone, &object.pose, object.shape, offset).filter(|p| p.distance <= offset)
}

/// Closest features between a bone and an object within `prediction` (m).
///
/// A capsule is queried as its axis segment with the radius added back:
/// parry's GJK on the rounded capsule itself was measured to overestimate
/// distances by up to 1 mm, while the segment query is exact.
fn proximity(
    epa: &mut EPA,
    bone: &BoneShape,
    obj_pose: &Pose,
    obj_shape: &dyn Shape,
    prediction: f32,
) -> Option<Proximity> {
    let (hit, radius) = match bone {
        BoneShape::Capsule(c) => {
            let axis = Segment::new(c.a, c.b);
            let hit =
                contact(epa, &Pose::identity(), &axis, obj_pose, obj_shape, prediction + c.radius);
            (hit, c.radius)
        }
        BoneShape::Palm(p) => {
            let cube = Cuboid::new(p.half_extents);
            let palm = Pose::from_parts(p.center, p.rotation);
            (contact(epa, &palm, &cube, obj_pose, obj_shape, prediction), 0.0)
        }
    };
    let hit = hit.ok().flatten()?;
    let object_normal = hit.normal2.try_normalize()?;
    let prox = Proximity {
        bone_point: hit.point1 - radius * object_normal,
        object_point: hit.point2,
        object_normal,
        distance: hit.dist - radius,
    };
    let finite =
        prox.bone_point.is_finite() && prox.object_point.is_finite() && prox.distance.is_finite();
    finite.then_some(prox)
}

/// `parry`'s [`query::contact`], step for step, but with an [`EPA`] kept
/// from query to query: for two support maps (a bone, and any convex
/// object but a ball or a half-space) that overlap, as a pressing palm and
/// a finger sunk past its radius do, parry's
/// `contact_support_map_support_map` builds a new one, four heap buffers,
/// every query. `EPA::closest_points` clears its buffers first, so the
/// same points and normals come out, to the bit. Other pairs go to
/// [`query::contact`] itself.
fn contact(
    epa: &mut EPA,
    pos1: &Pose,
    g1: &dyn Shape,
    pos2: &Pose,
    g2: &dyn Shape,
    prediction: f32,
) -> Result<Option<Contact>, Unsupported> {
    let (Some(s1), Some(s2)) = (general_support_map(g1), general_support_map(g2)) else {
        return query::contact(pos1, g1, pos2, g2, prediction);
    };
    // parry's `contact` and `contact_support_map_support_map`.
    let pos12 = pos1.inv_mul(pos2);
    let dir = pos12.translation.try_normalize().unwrap_or(Vec3::X);
    let simplex = &mut VoronoiSimplex::new();
    simplex.reset(CsoPoint::from_shapes(&pos12, s1, s2, dir));
    let mut found = gjk::closest_points(&pos12, s1, s2, prediction, true, simplex);
    if found == GJKResult::Intersection {
        found = match epa.closest_points(&pos12, s1, s2, simplex) {
            Some((p1, p2, n)) => GJKResult::ClosestPoints(p1, p2, n),
            None => GJKResult::NoIntersection(Vec3::X),
        };
    }
    let GJKResult::ClosestPoints(point1, point2_1, normal1) = found else { return Ok(None) };
    let dist = (point2_1 - point1).dot(normal1);
    let point2 = pos12.inverse_transform_point(point2_1);
    let normal2 = pos12.rotation.inverse() * -normal1;
    let mut hit = Contact::new(point1, point2, normal1, normal2, dist);
    hit.transform_by_mut(pos1, pos2);
    Ok(Some(hit))
}

/// `g` as a support map, unless parry's dispatcher sends it elsewhere
/// before support maps: a ball or a half-space.
fn general_support_map(g: &dyn Shape) -> Option<&dyn SupportMap> {
    let special = g.as_shape::<Ball>().is_some() || g.as_shape::<HalfSpace>().is_some();
    g.as_support_map().filter(|_| !special)
}

/// A bone's bounding box (world).
fn bone_aabb(bone: &BoneShape) -> Aabb {
    match bone {
        BoneShape::Capsule(c) => Aabb::new(c.a.min(c.b), c.a.max(c.b)).loosened(c.radius),
        BoneShape::Palm(p) => {
            Cuboid::new(p.half_extents).compute_aabb(&Pose::from_parts(p.center, p.rotation))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;
    use rapier3d::parry::shape::{Cylinder, SharedShape};

    /// The bits of a contact, or of its absence.
    fn bits(hit: Result<Option<Contact>, Unsupported>) -> Option<Vec<u32>> {
        let hit = hit.expect("supported")?;
        let vectors = [hit.point1, hit.point2, hit.normal1, hit.normal2];
        let floats = vectors.iter().flat_map(|v| v.to_array()).chain([hit.dist]);
        Some(floats.map(f32::to_bits).collect())
    }

    /// A bone's axis and a palm box against a box, a cylinder and a ball,
    /// apart, grazing and sunk in (where parry runs EPA), with one EPA kept
    /// across all the queries: parry's own answers, to the bit.
    #[test]
    fn the_kept_epa_answers_as_parry_does() {
        let mut epa = EPA::new();
        let axis = Segment::new(Vec3::new(-0.011, 0.003, 0.002), Vec3::new(0.017, -0.004, 0.009));
        let palm = Cuboid::new(Vec3::new(0.041, 0.013, 0.047));
        let objects = [
            SharedShape::cuboid(0.023, 0.031, 0.019),
            SharedShape::new(Cylinder::new(0.027, 0.018)),
            SharedShape::ball(0.026),
        ];
        let (mut sunk, mut apart) = (0, 0);
        for (k, object) in objects.iter().enumerate() {
            for step in 0..40 {
                let t = step as f32 * 0.0031 - 0.05;
                let turn = Quat::from_euler(glam::EulerRot::XYZ, 0.3 * t + 0.2, -1.7 * t, 0.9);
                let at = Pose::from_parts(Vec3::new(t, 0.6 * t + 0.004, -0.35 * t), turn);
                let bone =
                    Pose::from_parts(Vec3::new(0.001, -0.002, 0.0), Quat::from_rotation_y(0.4));
                for (g1, pos1) in [(&axis as &dyn Shape, &bone), (&palm, &Pose::identity())] {
                    let ours = contact(&mut epa, pos1, g1, &at, object.as_ref(), 0.01);
                    let parry = query::contact(pos1, g1, &at, object.as_ref(), 0.01);
                    match ours {
                        Ok(Some(hit)) if hit.dist < 0.0 => sunk += 1,
                        _ => apart += 1,
                    }
                    assert_eq!(bits(ours), bits(parry), "object {k}, step {step}");
                }
            }
        }
        assert!(sunk > 40 && apart > 40, "{sunk} sunk, {apart} apart");
    }
}
