//! Stage 6: a contact's forces go to rapier.

use crate::friction;
use crate::pipeline::InteractionWorld;
use crate::pipeline::firewall;
use crate::scene::ObjectId;
use glam::Vec3;

impl InteractionWorld {
    /// Applies a contact's sample forces `(force, point)` to its object with
    /// rapier's `add_force_at_point`, skipping any that is not finite, and
    /// adds them to the object's total hand force
    /// ([`friction::total_force`]: the samples of a contact share its force
    /// exactly, so their sum is the contacts' sum).
    pub(super) fn apply_forces(&mut self, object: ObjectId, forces: &[(Vec3, Vec3)]) {
        let slot = &mut self.objects[object.0 as usize];
        let body = &mut self.physics.bodies[slot.body];
        let finite = firewall::forces(forces);
        // One pass: each force is applied as it is added to the total.
        slot.hand_force = friction::total_force(
            slot.hand_force,
            finite.map(|&(f, at)| {
                body.add_force_at_point(f, at, true);
                f
            }),
        );
    }
}
