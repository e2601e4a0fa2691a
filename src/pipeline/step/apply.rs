//! Stage 7: a contact's forces go to rapier.

use super::update::Stage;
use crate::contact::lanes;
use crate::pipeline::firewall;
use crate::scene::ObjectId;
use glam::Vec3A;

impl Stage<'_> {
    /// Applies the sample forces of the contact just updated (in
    /// `self.patch`) to its object, as rapier's `add_force_at_point` would
    /// one by one, skipping any that is not finite ([`firewall::forces`]),
    /// and adds them to the object's total hand force
    /// ([`crate::friction::total_force`]: the samples of a contact share
    /// its force exactly, so their sum is the contacts' sum).
    ///
    /// The body's force and torque are summed here and written back once:
    /// the same sums, in the same order, as `add_force_at_point` per sample
    /// (so the same bits), without its per-sample checks and wake-ups.
    #[inline(always)]
    pub(super) fn apply_forces(&mut self, object: ObjectId) {
        let slot = &mut self.objects[object.0 as usize];
        if !slot.forced {
            slot.forced = true;
            self.forced.push(object.0);
        }
        let body = &mut self.bodies[slot.body];
        let dynamic = body.is_dynamic();
        let com = body.center_of_mass();
        let (mut force, mut torque) = (body.user_force().into(), body.user_torque().into());
        let (mut total, mut pushed) = (Vec3A::from(slot.hand_force), false);
        if let Some((forces, points)) = self.patch.applied() {
            let origin = lanes::splat(com);
            for (j, (f, q)) in forces.chunks().iter().zip(points.chunks()).enumerate() {
                // Bitmasks of lanes, four samples at once: those the
                // firewall passes, and of them, those pushing a dynamic
                // body. The others add -0.0: the bits of skipping them.
                let finite = firewall::forces(f, q) & forces.used_mask(j);
                // Eq. 3.10 (`friction::total_force`) over the forces the
                // firewall passed: only finite ones are summed.
                lanes::add_in_order(&mut total, &lanes::keep(f, finite));
                let pushing = if dynamic { finite & lanes::nonzero(f) } else { 0 };
                if pushing != 0 {
                    let torques = lanes::cross(lanes::sub(*q, origin), *f);
                    lanes::add_in_order(&mut force, &lanes::keep(f, pushing));
                    lanes::add_in_order(&mut torque, &lanes::keep(&torques, pushing));
                    pushed = true;
                }
            }
        }
        slot.hand_force = total.into();
        if pushed {
            body.reset_forces(false);
            body.reset_torques(false);
            body.add_force(force.into(), false);
            body.add_torque(torque.into(), false);
            body.wake_up(true);
        }
    }
}
