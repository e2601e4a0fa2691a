//! Stage 5: every contact evaluates the contact law.

use super::{StepScratch, contact_key};
use crate::contact::ContactEventKind;
use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Updates every kept and new contact under its object's stability
    /// limit ([`crate::contact::Contact::update`]): a contact that has
    /// ended gets its `Ended` event, a new one that lives its `Began` event.
    /// Collects each object's sample forces for [`Self::apply_forces`].
    pub(super) fn update_contacts(&mut self, step: &mut StepScratch) {
        let settings = self.law_settings();
        for &o in &step.touched {
            step.forces[o].clear();
        }
        step.touched.clear();
        step.forces.resize_with(self.objects.len(), Vec::new);
        let mut contacts = Vec::with_capacity(step.candidates.len());
        for mut c in step.candidates.drain(..) {
            let o = c.contact.object.0 as usize;
            let object = self.object_view(o, step.limits[o]);
            // The contact appends its sample forces to its object's.
            std::mem::swap(&mut step.patch.applied, &mut step.forces[o]);
            let untouched = step.patch.applied.is_empty();
            let alive = c.contact.update(
                c.proximity,
                &step.detector,
                &c.motion,
                &object,
                &settings,
                &mut step.patch,
            );
            if untouched && !step.patch.applied.is_empty() {
                step.touched.push(o);
            }
            std::mem::swap(&mut step.patch.applied, &mut step.forces[o]);
            if !alive {
                self.push_event(ContactEventKind::Ended, &c.contact);
                continue;
            }
            if c.is_new {
                self.push_event(ContactEventKind::Began, &c.contact);
            }
            contacts.push(c.contact);
        }
        contacts.sort_by_key(contact_key);
        self.contacts = contacts;
    }
}
