//! Stage 5: a contact evaluates the contact law.

use super::{Candidate, StepScratch};
use crate::contact::{Contact, ContactEventKind};
use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Updates one kept or new contact under its object's stability limit
    /// ([`Contact::update`]), leaving its sample forces in
    /// `step.patch.applied`. A contact that has ended gets its `Ended`
    /// event and is gone (`None`); a new one that lives gets its `Began`
    /// event.
    pub(super) fn update_contact(
        &mut self,
        c: Candidate,
        step: &mut StepScratch,
    ) -> Option<Contact> {
        let Candidate { mut contact, proximity, motion, is_new } = c;
        let o = contact.object.0 as usize;
        let object = self.object_view(o, step.limits[o]);
        step.patch.applied.clear();
        let settings = self.law_settings();
        let alive =
            contact.update(proximity, &step.detector, &motion, &object, &settings, &mut step.patch);
        if !alive {
            self.push_event(ContactEventKind::Ended, &contact);
            return None;
        }
        if is_new {
            self.push_event(ContactEventKind::Began, &contact);
        }
        Some(contact)
    }
}
