//! Stage 2: existing contacts are kept, or end.

use super::stability::StabilityScale;
use super::{Kept, StepScratch};
use crate::contact::{Contact, ContactEventKind};
use crate::friction::FrictionState;
use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Keeps last step's contacts that still touch. A contact that was
    /// static last step is kept without a distance query: its bone point is
    /// pressed in below C, inside the cone. The others are kept only while
    /// the bone is within the release offset. A contact ends when its hand
    /// lost tracking or its object's contacts are re-seated.
    #[inline(always)]
    pub(super) fn keep_contacts(&mut self, step: &mut StepScratch) {
        step.kept.clear();
        // In place, as `update_contacts` does: a kept contact is moved only
        // to close a gap an ended one left. Written out, not shared with it
        // through a helper taking a closure: the closure is left out of
        // line, in the baseline build (the cost is in the book's
        // "Benchmarks").
        let mut contacts = std::mem::take(&mut self.contacts);
        let (rolling, dt) = (step.settings.rolling, step.settings.dt);
        let mut keep = |contact: &mut Contact| {
            let reseat = self.objects[contact.object.0 as usize].reseat;
            let motion = self.motion(contact.hand, contact.bone).filter(|_| !reseat);
            let Some(motion) = motion else {
                self.push_event(ContactEventKind::Ended, contact);
                return false;
            };
            let proximity = if contact.state == FrictionState::Static {
                None
            } else {
                let object = self.object_view(contact.object.0 as usize, StabilityScale::NONE);
                let Some(prox) = step.detector.still_touching(&motion.now(), &object) else {
                    self.push_event(ContactEventKind::Ended, contact);
                    return false;
                };
                Some(prox)
            };
            if rolling {
                let object = self.object_view(contact.object.0 as usize, StabilityScale::NONE);
                match contact.state {
                    FrictionState::Static => contact.anchor.roll(&motion, &object, dt),
                    FrictionState::Dynamic => contact.anchor.slide_spin(&motion, &object, dt),
                    _ => contact.anchor.rolled = glam::Vec3::ZERO,
                }
            }
            step.kept.push(Kept { proximity });
            true
        };
        let mut live = 0;
        for i in 0..contacts.len() {
            if keep(&mut contacts[i]) {
                if live != i {
                    contacts.swap(live, i);
                }
                live += 1;
            }
        }
        contacts.truncate(live);
        self.contacts = contacts;
        for o in self.reseating.drain(..) {
            self.objects[o as usize].reseat = false;
        }
    }
}
