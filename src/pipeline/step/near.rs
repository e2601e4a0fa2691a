//! Which objects may be near a hand, found through rapier's broad phase (a
//! BVH over every collider's box) rather than by a scan of every object, so
//! the search grows with what is near the hands, not with the scene.
//!
//! The BVH holds each collider's box as of rapier's last step, before that
//! step moved it, loosened by half rapier's prediction distance. So a hand's
//! box is looked up loosened by how far any awake object can have moved
//! since ([`motion_margin`]), and the objects added or put down since then
//! (which the BVH has not seen there) are added to what it finds. The exact
//! boxes of those candidates then filter them as a scan of every object
//! would: the same objects, in the same order, so the same contacts.
//!
//! Invariant: every object whose box meets the hand's box is among the
//! candidates. An object moved through [`InteractionWorld::physics_mut`] is
//! outside it until rapier's next step, as for rapier's own scene queries.

use crate::pipeline::InteractionWorld;
use crate::scene::ObjectId;
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::prelude::QueryFilter;

/// The `user_data` of an object's rigid body and collider: its index plus
/// one, so that statics and bodies a program adds itself (0) are none.
pub(crate) fn object_tag(id: ObjectId) -> u128 {
    u128::from(id.0) + 1
}

/// The object a `user_data` tags, if it is one of the world's.
pub(super) fn tagged(user_data: u128, objects: usize) -> Option<usize> {
    let index = usize::try_from(user_data.checked_sub(1)?).ok()?;
    (index < objects).then_some(index)
}

/// The objects near one hand, by index, with their boxes now (world, m).
/// Buffers kept from step to step.
#[derive(Debug, Default)]
pub(crate) struct Nearby {
    /// Candidates from the BVH and the unindexed objects, sorted.
    ids: Vec<usize>,
    /// The candidates whose box meets the hand's, in index order.
    pub found: Vec<(usize, Aabb)>,
    /// Per object of `found`, the hand's bones touching it already, a bit
    /// per [`crate::hand::Bone::index`] (`find.rs`).
    pub known: Vec<u16>,
}

impl InteractionWorld {
    /// How far (m) any awake object may have moved since rapier's broad
    /// phase last saw it: its speed, plus its spin times its bounding
    /// diameter (a bound on any point's distance from its centre of mass),
    /// over one step. Scans the awake bodies only.
    pub(super) fn motion_margin(&self) -> f32 {
        let physics = &self.physics;
        let dt = physics.integration_parameters.dt;
        let moved = |handle| {
            let body = physics.bodies.get(handle)?;
            let slot = &self.objects[tagged(body.user_data, self.objects.len())?];
            Some((body.linvel().length() + body.angvel().length() * slot.diameter) * dt)
        };
        let margin = physics.islands.active_bodies().filter_map(moved).fold(0.0, f32::max);
        if margin.is_finite() { margin } else { f32::INFINITY }
    }

    /// Fills `near.found` with the objects whose boxes meet `hand` (world),
    /// in index order, given this step's [`Self::motion_margin`].
    pub(super) fn objects_near(&self, hand: &Aabb, margin: f32, near: &mut Nearby) {
        let physics = &self.physics;
        let objects = self.objects.len();
        near.ids.clear();
        if margin.is_finite() {
            let query = physics.broad_phase.as_query_pipeline(
                physics.narrow_phase.query_dispatcher(),
                &physics.bodies,
                &physics.colliders,
                QueryFilter::default(),
            );
            let found = query.intersect_aabb_conservative(hand.loosened(margin));
            near.ids.extend(found.filter_map(|(_, collider)| tagged(collider.user_data, objects)));
            near.ids.extend(self.unindexed.iter().map(|&o| o as usize));
        } else {
            // A speed that bounds nothing: every object is a candidate.
            near.ids.extend(0..objects);
        }
        near.ids.sort_unstable();
        near.ids.dedup();
        near.found.clear();
        for &o in &near.ids {
            let bounds = physics.colliders[self.objects[o].collider].compute_aabb();
            if hand.intersects(&bounds) {
                near.found.push((o, bounds));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_name_objects_only() {
        assert_eq!(tagged(object_tag(ObjectId(7)), 8), Some(7));
        assert_eq!(tagged(object_tag(ObjectId(7)), 7), None);
        assert_eq!(tagged(0, 8), None);
        assert_eq!(tagged(u128::MAX, 8), None);
    }
}
