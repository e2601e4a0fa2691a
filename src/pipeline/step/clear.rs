//! Stage 1: clear last step's hand forces.

use crate::pipeline::InteractionWorld;
use glam::Vec3;

impl InteractionWorld {
    /// Clears last step's user forces and torques, and each object's hand
    /// force total. rapier keeps user forces until they are cleared, and
    /// `reset_forces` does not clear torques.
    pub(super) fn clear_forces(&mut self) {
        for slot in self.objects.iter_mut() {
            let body = &mut self.physics.bodies[slot.body];
            body.reset_forces(false);
            body.reset_torques(false);
            slot.hand_force = Vec3::ZERO;
        }
    }
}
