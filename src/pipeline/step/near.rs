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
//! One answer serves a hand for several steps: it is asked for the hand's
//! box loosened by a slack, and kept while the hand's box, loosened by how
//! far any object may have moved since (the margins of the steps between,
//! summed), stays inside what it answered for. Objects added or put down,
//! and a program's writes to rapier, make every hand ask again.
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
    /// Per hand, its last broad-phase answer, while it may still serve.
    answers: Vec<Option<Answer>>,
    /// The simulated time (s) at which the answers' drift was last
    /// advanced ([`Nearby::advance`]).
    advanced_at: Option<f64>,
}

/// How far beyond a hand's reach (m) its broad-phase query looks, so that
/// one answer serves the next steps while the hand stays inside that box
/// and the objects move less than what is left of it. A hand moving at
/// 1 m/s moves 1 mm a step at 1 kHz: one answer serves about ten steps.
const SLACK: f32 = 0.01;

/// One hand's broad-phase answer, kept from step to step.
#[derive(Debug)]
struct Answer {
    /// The box it answers for (world, m): every object whose box met it
    /// when it was asked is among `ids`.
    reach: Aabb,
    /// Those candidates, sorted.
    ids: Vec<usize>,
    /// How far any object may have moved since (m).
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

    /// Whether hand `h`'s answer from an earlier step still holds every
    /// object whose box may meet `hand` (world, m): `hand`, loosened by how
    /// far any object may have moved since, is inside the box it answered
    /// for.
    fn serves(&self, h: usize, hand: &Aabb) -> bool {
        let answer = self.answers.get(h).and_then(Option::as_ref);
        answer.is_some_and(|a| a.reach.contains(&hand.loosened(a.drift)))
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
        if margin.is_finite() { margin } else { f32::INFINITY }
    }

    /// Fills `near.found` with the objects whose boxes meet hand `h`'s box
    /// `hand` (world), in index order, given this step's
    /// [`Self::motion_margin`], after [`Nearby::advance`].
    pub(super) fn objects_near(&self, h: usize, hand: &Aabb, margin: f32, near: &mut Nearby) {
        if !near.serves(h, hand) {
            self.ask_broad_phase(h, hand, margin, near);
        }
        let colliders = &self.physics.colliders;
        let bounds = |o: usize| colliders[self.objects[o].collider].compute_aabb();
        let Nearby { ids, found, answers, .. } = near;
        found.clear();
        let Some(answer) = answers.get_mut(h).and_then(Option::as_mut) else {
            // No answer kept: every object is a candidate.
            for &o in ids.iter() {
                let bounds = bounds(o);
                if hand.intersects(&bounds) {
                    found.push((o, bounds));
                }
            }
            return;
        };
        // A candidate whose box is now outside the answer's box can meet
        // the hand's only after moving farther than the answer allows: it
        // is dropped from the answer.
        let reach = answer.reach;
        answer.ids.retain(|&o| {
            let bounds = bounds(o);
            if hand.intersects(&bounds) {
                found.push((o, bounds));
            }
            bounds.intersects(&reach)
        });
    }

    /// Asks rapier's broad phase for the objects near hand `h`'s box `hand`
    /// loosened by [`SLACK`], and keeps the answer for the next steps. With
    /// a margin that bounds nothing, every object is a candidate, in
    /// `near.ids`, and nothing is kept.
    fn ask_broad_phase(&self, h: usize, hand: &Aabb, margin: f32, near: &mut Nearby) {
        let physics = &self.physics;
        let objects = self.objects.len();
        if near.answers.len() <= h {
            near.answers.resize_with(h + 1, || None);
        }
        if !margin.is_finite() {
            // A speed that bounds nothing: every object is a candidate.
            near.answers[h] = None;
            near.ids.clear();
            near.ids.extend(0..objects);
            return;
        }
        let reach = hand.loosened(SLACK);
        let mut answer =
            near.answers[h].take().unwrap_or(Answer { reach, ids: Vec::new(), drift: 0.0 });
        let query = physics.broad_phase.as_query_pipeline(
            physics.narrow_phase.query_dispatcher(),
            &physics.bodies,
            &physics.colliders,
            QueryFilter::default(),
        );
        let found = query.intersect_aabb_conservative(reach.loosened(margin));
        let ids = &mut answer.ids;
        ids.clear();
        ids.extend(found.filter_map(|(_, collider)| tagged(collider.user_data, objects)));
        ids.extend(self.unindexed.iter().map(|&o| o as usize));
        ids.sort_unstable();
        ids.dedup();
        (answer.reach, answer.drift) = (reach, 0.0);
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
