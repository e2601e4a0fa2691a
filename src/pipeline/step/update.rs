//! Stages 6 and 7, contact by contact: a contact evaluates the contact
//! law, and its forces go to rapier (`apply.rs`) while its patch is still
//! in cache.

use super::{Candidate, Stage, StepScratch, motion_of, push_event, view_of};
use crate::contact::detect::Proximity;
use crate::contact::{Contact, ContactEventKind};
use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Updates every contact and applies its forces: the kept ones in
    /// place, in their order, then the new ones. Ended contacts are
    /// dropped; the rest are then sorted by [`super::contact_key`].
    #[inline(always)]
    pub(super) fn update_contacts(&mut self, step: &mut StepScratch) {
        let mut contacts = std::mem::take(&mut self.contacts);
        let mut found = std::mem::take(&mut step.found);
        let InteractionWorld {
            physics,
            config,
            objects,
            hands,
            events,
            forced,
            time,
            hand_shapes,
            ..
        } = self;
        let StepScratch { kept, presses, shares, limits, settings, detector, patch, .. } = step;
        let mut stage = Stage {
            colliders: &physics.colliders,
            hand_shapes,
            config,
            hands,
            presses,
            shares,
            limits,
            settings,
            detector,
            objects,
            bodies: &mut physics.bodies,
            forced,
            events,
            time: *time,
            patch,
            view: None,
            run: None,
        };
        let mut live = 0;
        for (i, kept) in kept.iter().enumerate() {
            // The poses have not changed since `keep_contacts` found it.
            if stage.update(&mut contacts[i], kept.proximity, i, false) {
                // A swap in place would still copy the contact three times.
                if live != i {
                    contacts.swap(live, i);
                }
                live += 1;
            }
        }
        contacts.truncate(live);
        let first_new = kept.len();
        for (j, Candidate { mut contact, proximity }) in found.drain(..).enumerate() {
            if stage.update(&mut contact, proximity, first_new + j, true) {
                contacts.push(contact);
            }
        }
        stage.flush();
        step.found = found;
        // Kept contacts stay in order, so a step that found none is sorted
        // already: checked, it skips the stable sort's scratch allocation.
        if !contacts.is_sorted_by_key(super::contact_key) {
            contacts.sort_by_key(super::contact_key);
        }
        self.contacts = contacts;
    }
}

impl Stage<'_> {
    /// Updates one kept or new contact, the `index`-th in update order,
    /// with its share of its virtual finger's γ under its object's
    /// stability limit ([`Contact::update`]), and applies its forces. A
    /// contact that has ended gets its `Ended` event and `false`; a new
    /// one that lives gets its `Began` event.
    #[inline(always)]
    fn update(
        &mut self,
        contact: &mut Contact,
        proximity: Option<Proximity>,
        index: usize,
        is_new: bool,
    ) -> bool {
        let o = contact.object.0 as usize;
        let view = match self.view {
            Some(view) if view.id == contact.object => view,
            _ => {
                let (objects, bodies) = (&*self.objects, &*self.bodies);
                let view = view_of(
                    o,
                    objects,
                    bodies,
                    self.colliders,
                    self.hand_shapes,
                    self.config,
                    self.limits[o],
                );
                *self.view.insert(view)
            }
        };
        let object = view.shared(self.shares[index]);
        self.patch.clear();
        let (press, settings) = (&self.presses[index], self.settings);
        // Its hand is tracked (`keep_contacts` ended the others): a
        // contact whose hand were not would end.
        let alive = match motion_of(self.hands, contact.hand, contact.bone) {
            Some(motion) => {
                let detector = &mut *self.detector;
                contact.update(press, proximity, detector, &motion, &object, settings, self.patch)
            }
            None => false,
        };
        if !alive {
            push_event(self.events, self.time, ContactEventKind::Ended, contact);
            return false;
        }
        if is_new {
            push_event(self.events, self.time, ContactEventKind::Began, contact);
        }
        self.apply_forces(contact.object);
        true
    }
}
