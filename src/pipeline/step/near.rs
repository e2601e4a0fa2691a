//! Which bones of a hand may be near which objects, found through rapier's
//! broad phase (a BVH over every collider's box) rather than by a scan of
//! every object, so the search grows with what is near the hands, not with
//! the scene.
//!
//! The BVH holds each collider's box as of rapier's last step, before that
//! step moved it, loosened by half rapier's prediction distance. So a hand's
//! box is looked up loosened by how far any awake object can have moved
//! since ([`InteractionWorld::motion_margin`]), and the objects added or
//! put down since then (which the BVH has not seen there) are added to what
//! it finds. Their exact boxes then pair them with the bones whose reach
//! they may meet.
//!
//! One answer serves a hand for several steps: it pairs each bone with the
//! objects whose boxes, loosened by a slack, met the bone's reach loosened
//! by the same slack. It is kept while every bone's reach stays inside its
//! loosened box and the objects have moved less than the slack since (the
//! margins of the steps between, summed). Objects added or put down, and a
//! program's writes to rapier, make every hand ask again.
//!
//! Invariant: every (bone, object) pair whose boxes meet is among the
//! answer's pairs. An object moved through [`InteractionWorld::physics_mut`]
//! is outside it until rapier's next step, as for rapier's own scene queries.

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

/// How far (m) a bone's reach may move, and the objects, before its
/// hand's answer is asked again. A hand moving at 1 m/s moves 1 mm a step
/// at 1 kHz: one answer serves about five steps.
const SLACK: f32 = 0.005;

/// The bones and objects near each hand, kept from step to step.
#[derive(Debug, Default)]
pub(crate) struct Nearby {
    /// Per hand, its last answer, while it may still serve.
    pub(super) answers: Vec<Option<Answer>>,
    /// The simulated time (s) at which the answers' drift was last
    /// advanced ([`Nearby::advance`]).
    advanced_at: Option<f64>,
    /// The objects' boxes loosened by the slack, and their places among
    /// the objects paired, while an answer is asked.
    grown: Vec<Aabb>,
    slots: Vec<u32>,
    /// This step's, for the hand being searched: per object of its answer,
    /// the hand's bones touching it already (a bit per
    /// [`crate::hand::Bone::index`]), and its box now, once computed.
    pub(super) known: Vec<u16>,
    pub(super) boxes: Vec<Option<Aabb>>,
}

/// One hand's bone–object pairs that may meet ([`Nearby`]).
#[derive(Debug, Default)]
pub(crate) struct Answer {
    /// Per bone (by [`crate::hand::Bone::index`]), the box its reach may
    /// move in (world, m).
    bones: Vec<Aabb>,
    /// The objects paired with a bone, ascending.
    pub objects: Vec<usize>,
    /// The pairs, as (bone index, place in `objects`), by bone, then
    /// object.
    pub pairs: Vec<(u8, u32)>,
    /// How far any object may have moved since it was asked (m).
    drift: f32,
}

impl Nearby {
    /// Forgets every hand's answer: objects were added, put down or moved
    /// by a program ([`InteractionWorld::physics_mut`]), which no drift
    /// bounds.
    pub fn forget(&mut self) {
        self.answers.iter_mut().for_each(|a| *a = None);
    }

    /// Starts a step at simulated `time` (s), after rapier's steps of `dt`
    /// (s), in which any object moved at most `margin` (m): each kept
    /// answer's drift grows by it. A step skipped (no hand tracked) leaves
    /// a rapier step unbounded, so it forgets them; the same time again
    /// (no rapier step since) adds nothing.
    pub fn advance(&mut self, margin: f32, time: f64, dt: f32) {
        let last = self.advanced_at.replace(time);
        if last == Some(time) {
            return;
        }
        if last.is_some_and(|t| t + dt as f64 == time) && margin.is_finite() {
            for answer in self.answers.iter_mut().flatten() {
                answer.drift += margin;
            }
        } else {
            self.forget();
        }
    }

    /// Whether hand `h`'s answer still holds every pair of its bones, whose
    /// reach boxes are `reach` (world, m, by bone index), and objects whose
    /// boxes may meet: the objects have moved less than the slack since it
    /// was asked, and each reach is inside the box it answered for.
    fn serves(&self, h: usize, reach: &[Aabb]) -> bool {
        let Some(answer) = self.answers.get(h).and_then(Option::as_ref) else { return false };
        let inside = answer.bones.iter().zip(reach).all(|(within, now)| within.contains(now));
        answer.drift <= SLACK && answer.bones.len() == reach.len() && inside
    }
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
        // A host moves its objects itself (`host.rs`).
        let margin = margin.max(self.host_moved);
        if margin.is_finite() { margin } else { f32::INFINITY }
    }

    /// Makes `near.answers[h]` hand `h`'s pairs of bones and objects that
    /// may meet, its bones' reach boxes being `reach` (world, m, by bone
    /// index), given this step's [`Self::motion_margin`], after
    /// [`Nearby::advance`]; and empties this step's `known` and `boxes`
    /// for its objects.
    pub(super) fn pairs_near(&self, h: usize, reach: &[Aabb], margin: f32, near: &mut Nearby) {
        if !near.serves(h, reach) {
            self.ask_broad_phase(h, reach, margin, near);
        }
        let answer = near.answers.get(h).and_then(Option::as_ref);
        let objects = answer.map_or(0, |a| a.objects.len());
        near.known.clear();
        near.known.resize(objects, 0);
        near.boxes.clear();
        near.boxes.resize(objects, None);
    }

    /// Object `o`'s box now (world, m).
    pub(super) fn object_box(&self, o: usize) -> Aabb {
        self.physics.colliders[self.objects[o].collider].compute_aabb()
    }

    /// Asks rapier's broad phase for the objects near hand `h`, whose
    /// bones' reach boxes are `reach`, and pairs them with the bones: each
    /// bone with the objects whose boxes, loosened by [`SLACK`], meet its
    /// reach loosened by the same. With a margin that bounds nothing, every
    /// object is a candidate, and the answer serves this step only.
    fn ask_broad_phase(&self, h: usize, reach: &[Aabb], margin: f32, near: &mut Nearby) {
        let physics = &self.physics;
        let objects = self.objects.len();
        if near.answers.len() <= h {
            near.answers.resize_with(h + 1, || None);
        }
        let mut answer = near.answers[h].take().unwrap_or_default();
        answer.bones.clear();
        answer.bones.extend(reach.iter().map(|r| r.loosened(SLACK)));
        let ids = &mut answer.objects;
        ids.clear();
        if margin.is_finite() {
            let hand = answer.bones.iter().fold(Aabb::new_invalid(), |h, b| h.merged(b));
            let query = physics.broad_phase.as_query_pipeline(
                physics.narrow_phase.query_dispatcher(),
                &physics.bodies,
                &physics.colliders,
                QueryFilter::default(),
            );
            let found = query.intersect_aabb_conservative(hand.loosened(SLACK + margin));
            let tagged = found.filter_map(|(_, collider)| tagged(collider.user_data, objects));
            // rapier's tree keeps a removed collider's leaf until its step.
            ids.extend(tagged.filter(|&o| !self.objects[o].removed));
            ids.extend(self.unindexed.iter().map(|&o| o as usize));
            // Nor has it seen a host's objects move.
            ids.extend(self.hosted.iter().map(|&o| o as usize));
            ids.sort_unstable();
            ids.dedup();
            answer.drift = 0.0;
        } else {
            // A speed that bounds nothing: every object is a candidate.
            ids.extend((0..objects).filter(|&o| !self.objects[o].removed));
            answer.drift = f32::INFINITY;
        }
        near.grown.clear();
        near.grown.extend(ids.iter().map(|&o| self.object_box(o).loosened(SLACK)));
        answer.pairs.clear();
        near.slots.clear();
        near.slots.resize(ids.len(), u32::MAX);
        for (b, within) in answer.bones.iter().enumerate() {
            for (i, bounds) in near.grown.iter().enumerate() {
                if within.intersects(bounds) {
                    near.slots[i] = 0;
                    answer.pairs.push((b as u8, i as u32));
                }
            }
        }
        // Only the objects paired are kept, renumbered in order, so that a
        // step's work grows with the pairs, not with the objects nearby.
        let mut kept = 0;
        for (i, slot) in near.slots.iter_mut().enumerate() {
            if *slot == 0 {
                (ids[kept], *slot) = (ids[i], kept as u32);
                kept += 1;
            }
        }
        ids.truncate(kept);
        for (_, i) in answer.pairs.iter_mut() {
            *i = near.slots[*i as usize];
        }
        near.answers[h] = Some(answer);
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
