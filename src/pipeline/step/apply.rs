//! Stage 7: a contact's forces go to rapier.

use super::update::Stage;
use crate::contact::lanes;
use crate::pipeline::firewall;
use crate::scene::ObjectId;

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
        let (mut force, mut torque) = (body.user_force(), body.user_torque());
        let (mut total, mut pushed) = (slot.hand_force, false);
        if let Some((forces, points)) = self.patch.applied() {
            let origin = lanes::splat(com);
            for (j, (f, q)) in forces.chunks().iter().zip(points.chunks()).enumerate() {
                let torques = lanes::cross(lanes::sub(*q, origin), *f);
                // Bitmasks of lanes, four samples at once: those the
                // firewall passes, and of them, those pushing a dynamic body.
                let finite = firewall::forces(f, q);
                let pushing = if dynamic { finite & lanes::nonzero(f) } else { 0 };
                for k in 0..forces.used(j) {
                    if finite & (1 << k) == 0 {
                        continue;
                    }
                    let f = lanes::lane(f, k);
                    // Eq. 3.10 (`friction::total_force`) over the forces the
                    // firewall passed: only finite ones are summed.
                    total += f;
                    if pushing & (1 << k) != 0 {
                        force += f;
                        torque += lanes::lane(&torques, k);
                        pushed = true;
                    }
                }
            }
        }
        slot.hand_force = total;
        if pushed {
            body.reset_forces(false);
            body.reset_torques(false);
            body.add_force(force, false);
            body.add_torque(torque, false);
            body.wake_up(true);
        }
    }
}
