//! Before rapier's step: how many substeps it runs, for the objects the
//! hands push and for the rest.
//!
//! rapier adds a body's user force to its velocity substep by substep, so
//! the substeps decide how the hands' explicit springs and dampers move
//! what they push (`pipeline::stability`). Those run at least
//! [`HAND_SUBSTEPS`] always. The bodies no hand pushes may run fewer
//! ([`InteractionConfig::engine_substeps`]): a tower under a hand is mostly
//! bodies the hand does not touch.

use super::near::tagged;
use crate::pipeline::InteractionWorld;
use crate::pipeline::config::HAND_SUBSTEPS;
#[cfg(doc)]
use crate::pipeline::config::InteractionConfig;

impl InteractionWorld {
    /// Sets rapier's substeps for this step: the config's
    /// [`InteractionConfig::engine_substeps`], and for each object pushed
    /// this step (stage 7's), as many more as make [`HAND_SUBSTEPS`]. rapier
    /// then runs each body with the most substeps of any body it is in
    /// contact with, through its per-body `additional_solver_iterations`;
    /// stage 1 takes them off.
    ///
    /// Telling those bodies apart costs rapier a pass over the world's
    /// contact pairs every step, more than it saves while every awake body
    /// is pushed (held objects among sleeping ones): then every body runs
    /// [`HAND_SUBSTEPS`] (or the config's, if more). With the default of 4,
    /// every body runs 4, rapier's default, as before this choice existed.
    pub(super) fn set_substeps(&mut self) {
        let engine = self.config.engine_substeps;
        let apart = engine < HAND_SUBSTEPS && self.awake_unpushed();
        let (all, added) =
            if apart { (engine, HAND_SUBSTEPS - engine) } else { (engine.max(HAND_SUBSTEPS), 0) };
        self.physics.integration_parameters.num_solver_iterations = all;
        if added > 0 {
            for &o in &self.forced {
                let body = self.objects[o as usize].body;
                self.physics.bodies[body].set_additional_solver_iterations(added);
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
