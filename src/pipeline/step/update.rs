//! Stage 6: a contact evaluates the contact law.

use super::{StepScratch, Touch};
use crate::contact::{Contact, ContactEventKind};
use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Updates one kept or new contact with its share of its virtual
    /// finger's γ, under its object's stability limit ([`Contact::update`]),
    /// leaving its sample forces in `step.patch`. A contact that
    /// has ended gets its `Ended` event and `false`; a new one that lives
    /// gets its `Began` event.
    pub(super) fn update_contact(
        &mut self,
        contact: &mut Contact,
        touch: &Touch,
        is_new: bool,
        step: &mut StepScratch,
    ) -> bool {
        let o = contact.object.0 as usize;
        let object = self.object_view(o, step.limits[o]).shared(step.shares[touch.index]);
        step.patch.clear();
        let settings = &step.settings;
        let Touch { press, proximity, motion, .. } = touch;
        let alive = contact.update(
            press,
            *proximity,
            &step.detector,
            motion,
            &object,
            settings,
            &mut step.patch,
        );
        if !alive {
            self.push_event(ContactEventKind::Ended, contact);
        } else if is_new {
            self.push_event(ContactEventKind::Began, contact);
        }
        alive
    }
}
