//! Stage 3: new contacts begin where bones come within the contact offset.

use super::{Candidate, StepScratch};
use crate::contact::Contact;
use crate::hand::HandId;
use crate::pipeline::InteractionWorld;
use crate::pipeline::stability::StabilityScale;
use rapier3d::parry::bounding_volume::Aabb;

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
            let reach = step.detector.reach(pose);
            let margin = *margin.get_or_insert_with(|| {
                let margin = world.motion_margin();
                step.near.advance(margin, world.time, world.config.dt);
                margin
            });
            world.objects_near(h, &reach, margin, &mut step.near);
            let near = &step.near.found;
            known_bones(kept, near, hand, &mut step.near.known);
            let view = |o| world.object_view(o, StabilityScale::NONE);
            let known = &step.near.known;
            step.detector.new_touches(pose, near, known, view, |bone, object, prox| {
                let Some(motion) = world.motion(hand, bone) else { return };
                let contact = Contact::begin(hand, bone, &prox, &motion, object, &settings);
                let proximity = Some(prox);
                step.found.push(Candidate { contact, proximity });
            });
        }
    }
}

/// For each object of `near` (in index order), which of `hand`'s bones
/// touch it already, a bit per [`crate::hand::Bone::index`], into `known`: `contacts`
/// are sorted by [`super::contact_key`], so one pass over both finds them.
#[inline(always)]
fn known_bones(contacts: &[Contact], near: &[(usize, Aabb)], hand: HandId, known: &mut Vec<u16>) {
    known.clear();
    known.resize(near.len(), 0);
    let mut k = 0;
    for c in contacts {
        let o = c.object.0 as usize;
        while k < near.len() && near[k].0 < o {
            k += 1;
        }
        if k == near.len() {
            break;
        }
        if near[k].0 == o && c.hand == hand {
            known[k] |= 1 << c.bone.index();
        }
    }
}
