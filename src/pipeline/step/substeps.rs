//! Before rapier's step: how many substeps it runs, for the objects the
//! hands push and for the rest.
//!
//! rapier adds a body's user force to its velocity substep by substep, so
//! the substeps decide how the hands' explicit springs and dampers move
//! what they push (`step/stability.rs`). Those run at least
//! [`HAND_SUBSTEPS`] always. The bodies no hand pushes may run fewer
//! ([`InteractionConfig::engine_substeps`]): a tower under a hand is mostly
//! bodies the hand does not touch.

use super::near::tagged;
use crate::pipeline::InteractionWorld;
use crate::pipeline::config::HAND_SUBSTEPS;
#[cfg(doc)]
use crate::pipeline::config::InteractionConfig;
use rapier3d::dynamics::RigidBody;

/// The substeps an object's body had of its own (rapier's per-body
/// `additional_solver_iterations`, 0 unless a program set them through
/// `physics_mut`) and those `set_substeps` gave it for one step.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Raised {
    own: usize,
    set: usize,
}

impl Raised {
    /// Gives the body its own substeps back, unless a program has set
    /// others since: then the program's stand.
    pub(super) fn restore(self, body: &mut RigidBody) {
        if body.additional_solver_iterations() == self.set {
            body.set_additional_solver_iterations(self.own);
        }
    }
}

impl InteractionWorld {
    /// Sets rapier's substeps for this step: the config's
    /// [`InteractionConfig::engine_substeps`], and for each object pushed
    /// this step (stage 7's), as many more as make [`HAND_SUBSTEPS`]. rapier
    /// then runs each body with the most substeps of any body it is in
    /// contact with, through its per-body `additional_solver_iterations`;
    /// stage 1 gives each body its own back. A body that has as many of its
    /// own (a program's, through `physics_mut`) keeps them.
    ///
    /// Telling those bodies apart costs rapier a pass over the world's
    /// contact pairs every step, more than it saves while every awake body
    /// is pushed (held objects among sleeping ones): then every body runs
    /// [`HAND_SUBSTEPS`] (or the config's, if more). With 4 or more in the
    /// config, every body runs the config's.
    pub(super) fn set_substeps(&mut self) {
        let engine = self.config.engine_substeps;
        let apart = engine < HAND_SUBSTEPS && self.awake_unpushed();
        let (all, added) =
            if apart { (engine, HAND_SUBSTEPS - engine) } else { (engine.max(HAND_SUBSTEPS), 0) };
        self.physics.integration_parameters.num_solver_iterations = all;
        if added > 0 {
            for &o in &self.forced {
                let slot = &mut self.objects[o as usize];
                let body = &mut self.physics.bodies[slot.body];
                let own = body.additional_solver_iterations();
                if own < added {
                    body.set_additional_solver_iterations(added);
                    slot.raised = Some(Raised { own, set: added });
                }
            }
        }
    }

    /// Whether a dynamic body the hands do not push is awake: rapier's
    /// awake bodies, scanned until one is found.
    fn awake_unpushed(&self) -> bool {
        let (physics, objects) = (&self.physics, &self.objects);
        physics.islands.active_bodies().any(|handle| {
            let Some(body) = physics.bodies.get(handle) else { return false };
            let pushed = tagged(body.user_data, objects.len()).is_some_and(|o| objects[o].forced);
            body.is_dynamic() && !body.is_sleeping() && !pushed
        })
    }
}
