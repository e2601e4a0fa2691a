//! Stage 1: clear last step's hand forces.

use crate::pipeline::InteractionWorld;
use glam::Vec3;

impl InteractionWorld {
    /// Clears last step's user forces and torques, and each object's hand
    /// force total. rapier keeps user forces until they are cleared, and
    /// `reset_forces` does not clear torques.
    ///
    /// Only the objects the hands pushed last step carry any, so only they
    /// are cleared: a body written to through rapier's mutable accessors
    /// counts as modified in rapier's next step, and touching every body
    /// would make both this stage and rapier's step grow with the scene.
    /// After [`Self::physics_mut`], which may have added forces anywhere,
    /// every body that carries a force or torque is cleared.
    ///
    /// The objects pushed last step also get their own substeps back
    /// (`substeps.rs`): `set_substeps` raises them again for those the hands
    /// push this step.
    pub(in crate::pipeline) fn clear_forces(&mut self) {
        if std::mem::take(&mut self.external) {
            for slot in self.objects.iter_mut().filter(|o| !o.removed) {
                if let Some(raised) = slot.raised.take() {
                    raised.restore(&mut self.physics.bodies[slot.body]);
                }
                let body = &self.physics.bodies[slot.body];
                let loaded = body.user_force() != Vec3::ZERO || body.user_torque() != Vec3::ZERO;
                if loaded && let Some(body) = self.physics.bodies.get_mut(slot.body) {
                    body.reset_forces(false);
                    body.reset_torques(false);
                }
                slot.hand_force = Vec3::ZERO;
                slot.forced = false;
                slot.pushed = false;
            }
            self.forced.clear();
            return;
        }
        for o in self.forced.drain(..) {
            let slot = &mut self.objects[o as usize];
            let body = &mut self.physics.bodies[slot.body];
            body.reset_forces(false);
            body.reset_torques(false);
            if let Some(raised) = slot.raised.take() {
                raised.restore(body);
            }
            slot.hand_force = Vec3::ZERO;
            slot.forced = false;
            slot.pushed = false;
        }
    }
}
