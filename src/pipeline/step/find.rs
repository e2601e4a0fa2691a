//! Stage 3: new contacts begin where bones come within the contact offset.

use super::{Candidate, StepScratch};
use crate::contact::Contact;
use crate::hand::{Bone, HandId};
use crate::pipeline::InteractionWorld;
use crate::pipeline::stability::StabilityScale;
use crate::scene::ObjectId;

impl InteractionWorld {
    /// Begins a contact for every bone within the contact offset of an
    /// object it is not yet touching, hand by hand, through the collision
    /// driver's filter chain ([`crate::contact::detect`]) over the objects
    /// rapier's broad phase puts near the hand (`near.rs`). C is placed by
    /// the thesis's ray towards the collider, under the bone's point
    /// nearest the object's centre.
    #[inline(always)]
    pub(super) fn find_new_contacts(&mut self, step: &mut StepScratch) {
        let world = &*self;
        let settings = step.settings;
        let kept = &world.contacts;
        step.found.clear();
        let mut margin = None;
        for h in 0..world.hands.len() {
            let hand = HandId(h as u32);
            // A bone's motion is looked up only for a touch.
            let Some(pose) = world.hands[h].pose.as_ref() else { continue };
            let bones = Bone::all().map(|bone| (bone, pose.bone(bone)));
            let Some(reach) = step.detector.reach(bones) else { continue };
            let margin = *margin.get_or_insert_with(|| {
                let margin = world.motion_margin();
                step.near.advance(margin, world.time, world.config.dt);
                margin
            });
            world.objects_near(h, &reach, margin, &mut step.near);
            let near = &step.near.found;
            step.near.known.clear();
            for &(o, _) in near {
                step.near.known.push(known_bones(kept, o, hand));
            }
            let view = |o| world.object_view(o, StabilityScale::NONE);
            step.detector.new_touches(near, &step.near.known, view, |bone, object, prox| {
                let Some(motion) = world.motion(hand, bone) else { return };
                let contact = Contact::begin(hand, bone, &prox, &motion, object, &settings);
                let proximity = Some(prox);
                step.found.push(Candidate { contact, proximity });
            });
        }
    }
}

/// Which of `hand`'s bones touch object `o` already, a bit per
/// [`Bone::index`]: `contacts` are sorted by [`super::contact_key`], so those
/// contacts are one run, found by one binary search.
fn known_bones(contacts: &[Contact], o: usize, hand: HandId) -> u16 {
    let side = (ObjectId(o as u32), hand);
    let start = contacts.partition_point(|c| (c.object, c.hand) < side);
    let run = contacts[start..].iter().take_while(|c| (c.object, c.hand) == side);
    run.fold(0, |known, c| known | 1 << c.bone.index())
}
