//! Stage 3: new contacts begin where bones come within the contact offset.

use super::{Candidate, StepScratch, contact_key};
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
            let margin = *margin.get_or_insert_with(|| world.motion_margin());
            world.objects_near(&reach, margin, &mut step.near);
            let known = |bone: Bone, o: usize| {
                let key = (ObjectId(o as u32), hand, bone.index());
                kept.binary_search_by_key(&key, contact_key).is_ok()
            };
            let view = |o| world.object_view(o, StabilityScale::NONE);
            let near = &step.near.found;
            step.detector.new_touches(near, view, known, |bone, object, prox| {
                let Some(motion) = world.motion(hand, bone) else { return };
                let contact = Contact::begin(hand, bone, &prox, &motion, object, &settings);
                let proximity = Some(prox);
                step.found.push(Candidate { contact, proximity, motion });
            });
        }
    }
}
