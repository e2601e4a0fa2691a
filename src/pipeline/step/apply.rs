//! Stage 6: the forces go to rapier.

use super::StepScratch;
use crate::friction;
use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Applies every sample force at its point with rapier's
    /// `add_force_at_point`, skipping any that is not finite, and keeps
    /// each touched object's total hand force ([`friction::total_force`]:
    /// the samples of a contact share its force exactly, so their sum is
    /// the contacts' sum).
    pub(super) fn apply_forces(&mut self, step: &StepScratch) {
        for &o in &step.touched {
            let slot = &mut self.objects[o];
            let body = &mut self.physics.bodies[slot.body];
            let finite = step.forces[o].iter().filter(|(f, at)| f.is_finite() && at.is_finite());
            // One pass: each force is applied as it is added to the total.
            slot.hand_force = friction::total_force(finite.map(|&(f, at)| {
                body.add_force_at_point(f, at, true);
                f
            }));
        }
    }
}
