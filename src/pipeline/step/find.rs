//! Stage 3: new contacts begin where bones come within the contact offset.

use super::near::Nearby;
use super::stability::StabilityScale;
use super::{Candidate, StepScratch};
use crate::contact::Contact;
use crate::hand::{Bone, HandId};
use crate::pipeline::InteractionWorld;

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
            world.pairs_near(h, reach, margin, &mut step.near);
            let Nearby { answers, known, boxes, .. } = &mut step.near;
            let Some(answer) = answers.get(h).and_then(Option::as_ref) else { continue };
            known_bones(kept, &answer.objects, hand, known);
            // In bone order, then object order, each pair through the rest
            // of the collision driver's filter chain.
            for &(b, i) in &answer.pairs {
                let (bone, i) = (Bone::from_index(b as usize), i as usize);
                if known[i] & 1 << bone.index() != 0 {
                    continue;
                }
                let o = answer.objects[i];
                let bounds = *boxes[i].get_or_insert_with(|| world.object_box(o));
                let view = || world.object_view(o, StabilityScale::NONE);
                let Some((object, prox)) = step.detector.new_touch(pose, bone, &bounds, view)
                else {
                    continue;
                };
                let Some(motion) = world.motion(hand, bone) else { continue };
                let contact = Contact::begin(hand, bone, &prox, &motion, &object, &settings);
                let proximity = Some(prox);
                step.found.push(Candidate { contact, proximity });
            }
        }
    }
}

/// For each of `objects` (ascending), which of `hand`'s bones touch it
/// already, a bit per [`Bone::index`], into `known`: `contacts` are sorted
/// by [`super::contact_key`], so one pass over both finds them.
#[inline(always)]
fn known_bones(contacts: &[Contact], objects: &[usize], hand: HandId, known: &mut [u16]) {
    let mut k = 0;
    for c in contacts {
        let o = c.object.0 as usize;
        while k < objects.len() && objects[k] < o {
            k += 1;
        }
        if k == objects.len() {
            break;
        }
        if objects[k] == o && c.hand == hand {
            known[k] |= 1 << c.bone.index();
        }
    }
}
