//! Stage 5 of a step: the stability limit of each object's contact springs.
//!
//! Contact springs and dampers are explicit forces: set once a step, and
//! added by rapier substep by substep, so over a step of N substeps (the
//! at least [`super::config::HAND_SUBSTEPS`] for a pushed object) they move a body by
//! `v·dt + (N+1)/(2N)·a·dt²`, symplectic Euler's `a·dt²` for N = 1. A set
//! of springs Σγ_i on a body (each contact's share of its virtual finger's
//! γ) is stable while `dt²·Σ γ_i w_i` stays well below 4, where
//! `w_i = 1/m + |r_i|²/I_min` bounds how much the contact point at lever
//! arm `r_i` accelerates per newton (linear plus rotational). The dampers
//! need `dt·Σ c_i w_i < 2`. Both sums are kept ≤ 1: there, for N from 1 to
//! 4 and damping ratios from 0.3, a spring and its damper on a body decay.
//! A light object in a many-finger grasp gets a proportionally softer γ (it
//! then needs deeper fingers for the same force: the friction threshold, a
//! force ratio, is unchanged). This only binds for light objects in
//! many-finger grasps, or for long steps.
//!
//! With the config's `step_aware` (the default), an object whose stiffness
//! sum is over budget, and any touched object at a step longer than the
//! haptic 2 ms, is not softened: it keeps its full γ and damping, and stage
//! 7b (`implicit.rs`) steps its springs by backward Euler.

use super::StepScratch;
use crate::friction;
use crate::pipeline::config::InteractionConfig;
use crate::pipeline::{InteractionWorld, ObjectSlot};
use glam::Vec3;

/// Factors (≤ 1) on an object's contact stiffness and damping that keep the
/// explicit contact forces stable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StabilityScale {
    pub stiffness: f32,
    pub damping: f32,
    /// How many hand contacts share the object this step (≥ 1 where any
    /// does): they share the budget of the patches' rocking springs too.
    pub contacts: u32,
    /// Whether the object's springs keep their full γ and damping and step
    /// by backward Euler (`implicit.rs`), where the factors would be below 1
    /// and the config is step-aware.
    pub implicit: bool,
}

impl StabilityScale {
    /// No limit: the object's own γ and damping.
    pub const NONE: StabilityScale =
        StabilityScale { stiffness: 1.0, damping: 1.0, contacts: 1, implicit: false };
}

/// An object's contact damping `c` before the stability limit (N·s/m).
pub(super) fn nominal_damping(config: &InteractionConfig, slot: &ObjectSlot) -> f32 {
    let zeta = config.damping_ratio;
    zeta.map_or(0.0, |z| friction::damping_coefficient(slot.gamma, slot.mass, z))
}

impl InteractionWorld {
    /// Sets the stability limit of each object with a contact this step
    /// (`step.limits[o]`; the other objects' entries are stale and unread,
    /// so a step's cost does not grow with the scene).
    #[inline(always)]
    pub(super) fn stability_limits(&mut self, step: &mut StepScratch) {
        let dt = self.config.dt;
        let none = StabilityScale { stiffness: 0.0, damping: 0.0, contacts: 0, implicit: false };
        step.limits.resize(self.objects.len(), none);
        // The kept contacts, then the new ones: the order they are updated
        // in, and of their shares of their virtual fingers' γ.
        let found = step.found.iter().map(|c| &c.contact);
        let contacts = || self.contacts.iter().chain(found.clone());
        for c in contacts() {
            step.limits[c.object.0 as usize] = none;
        }
        step.touched.clear();
        // What the object's body says, looked up once for a run of its
        // contacts: its centre of mass, largest 1/inertia and damping.
        let mut body_of: Option<(usize, Vec3, f32, f32)> = None;
        for (c, &share) in contacts().zip(&step.shares) {
            let o = c.object.0 as usize;
            let slot = &self.objects[o];
            let (_, center_of_mass, inv_inertia, damping) = match body_of {
                Some(known) if known.0 == o => known,
                _ => {
                    let body = &self.physics.bodies[slot.body];
                    let inv_inertia =
                        body.mass_properties().local_mprops.inv_principal_inertia.max_element();
                    let damping = nominal_damping(&self.config, slot);
                    *body_of.insert((o, slot.center_of_mass(body), inv_inertia, damping))
                }
            };
            let r = c.point - center_of_mass;
            let w = share * (1.0 / slot.mass + r.length_squared() * inv_inertia);
            let limit = &mut step.limits[o];
            if limit.contacts == 0 {
                step.touched.push(o);
            }
            limit.stiffness += slot.gamma * w;
            limit.damping += damping * w;
            limit.contacts += 1;
        }
        for &o in &step.touched {
            let limit = &mut step.limits[o];
            if !self.config.stability_limit {
                (limit.stiffness, limit.damping) = (1.0, 1.0);
                continue;
            }
            let (stiffness, damping) = (limit.stiffness * dt * dt, limit.damping * dt);
            // Backward Euler where explicit springs would be unstable, and
            // at every step longer than the haptic one, where they are
            // stable but err: a host's 240 Hz lets a pinch at 1.2 times its
            // threshold slip. (Where only the dampers are over budget, as
            // for light objects at 1 kHz, softening them is stable and
            // changes no grip.)
            let host_rate = dt > crate::pipeline::HAPTIC_STEP;
            if self.config.step_aware && (stiffness > 1.0 || host_rate) {
                (limit.stiffness, limit.damping, limit.implicit) = (1.0, 1.0, true);
                continue;
            }
            // The sums become the factors that keep them ≤ 1.
            limit.stiffness = (1.0 / stiffness).min(1.0);
            limit.damping = (1.0 / damping).min(1.0);
        }
    }
}
