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
use crate::hand::{Bone, BoneShape};
use glam::Vec3;
use rapier3d::math::Pose;
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::parry::query;
use rapier3d::parry::shape::{Cuboid, Segment, Shape};

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
#[derive(Debug, Default)]
pub(crate) struct Detector {
    /// A contact begins within this distance of the surface (m).
    pub contact_offset: f32,
    /// A contact ends beyond this distance (m).
    pub release_offset: f32,
    /// Per bone of the hand being searched: its shape now and its reach,
    /// the bone's box grown by the contact offset.
    reach: Vec<(Bone, BoneShape, Aabb)>,
}

impl Detector {
    /// A detector for the given offsets (m).
    pub fn new(contact_offset: f32, release_offset: f32) -> Detector {
        Detector { contact_offset, release_offset, ..Detector::default() }
    }

    /// The closest features of a live contact's bone and object, if the
    /// bone's surface is still within the release offset.
    pub fn still_touching(&self, bone: &BoneShape, object: &ObjectView) -> Option<Proximity> {
        within(bone, object, self.release_offset)
    }

    /// Starts the search of one hand: keeps each of `bones` (the hand's
    /// tracked bones, as they are now) with its reach, and returns the
    /// whole hand's reach (world), the box to find objects near; `None`
    /// for no bones.
    #[inline(always)]
    pub fn reach(&mut self, bones: impl Iterator<Item = (Bone, BoneShape)>) -> Option<Aabb> {
        self.reach.clear();
        let mut hand: Option<Aabb> = None;
        for (bone, now) in bones {
            let reach = bone_aabb(&now).loosened(self.contact_offset);
            hand = Some(hand.map_or(reach, |h| h.merged(&reach)));
            self.reach.push((bone, now, reach));
        }
        hand
    }

    /// The new touches of the hand [`Self::reach`] started, through the
    /// rest of the filter chain. `near` holds the objects whose boxes meet
    /// the hand's reach, in index order, with their boxes; `view(o)` is
    /// object `o` itself. `known[k]` has a bit (by [`Bone::index`]) for
    /// each bone in contact with `near[k]` already: those pairs are left
    /// out before their exact query. `touch` is called for every bone
    /// whose surface is within the contact offset of an object, in bone
    /// order, then object order.
    #[inline(always)]
    pub fn new_touches<'v>(
        &self,
        near: &[(usize, Aabb)],
        known: &[u16],
        view: impl Fn(usize) -> ObjectView<'v>,
        mut touch: impl FnMut(Bone, &ObjectView<'v>, Proximity),
    ) {
        for (bone, now, reach) in &self.reach {
            let bit = 1 << bone.index();
            for (&(o, bounds), &known) in near.iter().zip(known) {
                if !reach.intersects(&bounds) || known & bit != 0 {
                    continue;
                }
                let object = view(o);
                if let Some(prox) = within(now, &object, self.contact_offset) {
                    touch(*bone, &object, prox);
                }
            }
        }
    }
}

/// The closest features if the bone's surface is within `offset` (m).
fn within(bone: &BoneShape, object: &ObjectView, offset: f32) -> Option<Proximity> {
    proximity(bone, &object.pose, object.shape, offset).filter(|p| p.distance <= offset)
}

/// Closest features between a bone and an object within `prediction` (m).
///
/// A capsule is queried as its axis segment with the radius added back:
/// parry's GJK on the rounded capsule itself was measured to overestimate
/// distances by up to 1 mm, while the segment query is exact.
fn proximity(
    bone: &BoneShape,
    obj_pose: &Pose,
    obj_shape: &dyn Shape,
    prediction: f32,
) -> Option<Proximity> {
    let (hit, radius) = match bone {
        BoneShape::Capsule(c) => {
            let axis = Segment::new(c.a, c.b);
            let hit = query::contact(
                &Pose::identity(),
                &axis,
                obj_pose,
                obj_shape,
                prediction + c.radius,
            );
            (hit, c.radius)
        }
        BoneShape::Palm(p) => {
            let cube = Cuboid::new(p.half_extents);
            let palm = Pose::from_parts(p.center, p.rotation);
            (query::contact(&palm, &cube, obj_pose, obj_shape, prediction), 0.0)
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

/// A bone's bounding box (world).
fn bone_aabb(bone: &BoneShape) -> Aabb {
    match bone {
        BoneShape::Capsule(c) => Aabb::new(c.a.min(c.b), c.a.max(c.b)).loosened(c.radius),
        BoneShape::Palm(p) => {
            Cuboid::new(p.half_extents).compute_aabb(&Pose::from_parts(p.center, p.rotation))
        }
    }
}
