//! Stage 4: how each contact presses, and its factor on γ as part of its
//! hand's virtual fingers ([`crate::friction::grip`]).

use super::StepScratch;
use super::stability::StabilityScale;
use crate::contact::{Contact, ObjectView, Press};
use crate::friction;
use crate::hand::HandId;
use crate::pipeline::InteractionWorld;
use crate::scene::ObjectId;

impl InteractionWorld {
    /// Finds every contact's [`Press`] (the kept contacts in their order,
    /// then the new ones) and, with the config's virtual fingers, each
    /// one's factor on γ among the pressing contacts of its hand on its
    /// object ([`friction::virtual_finger_factor`]); without them, or for a
    /// contact that does not press, the factor is 1.
    #[inline(always)]
    pub(super) fn press_contacts(&mut self, step: &mut StepScratch) {
        step.presses.clear();
        step.sides.clear();
        let settings = step.settings;
        // Each object's view once for its run of contacts (they are sorted
        // by object): the same view, looked up once.
        let mut view: Option<ObjectView> = None;
        let found = step.found.iter().map(|c| &c.contact);
        for contact in self.contacts.iter().chain(found) {
            let object = match view {
                Some(v) if v.id == contact.object => v,
                _ => {
                    *view.insert(self.object_view(contact.object.0 as usize, StabilityScale::NONE))
                }
            };
            // Kept and found contacts' hands are tracked (`keep_contacts`
            // ended the others); one that were not would press nowhere,
            // and end in stage 6.
            let press = match self.motion(contact.hand, contact.bone) {
                Some(motion) => contact.press(&object, &motion, &settings),
                None => Press::default(),
            };
            step.presses.push(press);
            step.sides.push(side_key(contact));
        }
        step.shares.clear();
        step.shares.resize(step.presses.len(), 1.0);
        if self.config.virtual_fingers {
            share_by_side(&step.sides, &step.presses, &mut step.order, &mut step.shares);
        }
    }
}

/// Whose virtual fingers a contact belongs to: its object's and its hand's.
pub(super) type SideKey = (ObjectId, HandId);

fn side_key(c: &Contact) -> SideKey {
    (c.object, c.hand)
}

/// Each pressing contact's factor on γ: `shares[i]` for
/// the contact of key `keys[i]` and press `presses[i]`. Contacts are
/// grouped by key through `order`, a buffer kept between steps.
#[inline(always)]
fn share_by_side(keys: &[SideKey], presses: &[Press], order: &mut Vec<usize>, shares: &mut [f32]) {
    let key = |i: usize| keys[i];
    order.clear();
    for (i, press) in presses.iter().enumerate() {
        if press.seen > 0.0 {
            order.push(i);
        }
    }
    // By key, then by index: equal keys keep the contacts' own order (the
    // same sums in the same order every run), as a stable sort would keep
    // them, without its scratch allocation. Kept contacts come sorted by
    // key, so a step that found none needs no sort.
    if !order.is_sorted_by_key(|&i| (key(i), i)) {
        order.sort_unstable_by_key(|&i| (key(i), i));
    }
    for group in order.chunk_by(|&a, &b| key(a) == key(b)) {
        if group.len() < 2 {
            continue;
        }
        for &i in group {
            let own = &presses[i];
            let pressing = group.iter().map(|&j| (presses[j].normal(), presses[j].seen));
            let sides = friction::sides(own.normal(), pressing);
            shares[i] = friction::virtual_finger_factor(own.seen, &sides);
        }
    }
}
