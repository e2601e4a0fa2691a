//! Stage 7b: the springs of an object too light for an explicit step
//! (stage 5 marked it `implicit`) step by backward Euler
//! (`friction/implicit.rs`): its contacts' forces, summed on its body by
//! stage 7 at their full γ, are corrected to the forces at the end of the
//! step, so that whoever integrates the body next (rapier, or a host
//! engine at 90 Hz) moves it stably.
//!
//! The other forces on the body (gravity, the ground, a host's own) are
//! told from its motion: the velocity it has now, against what it had and
//! the hand wrench it was given the step before, is what they did. On its
//! first such step, gravity alone. So a held object is in equilibrium with
//! the correction zero, and an object on a table is not thought to fall.

use super::StepScratch;
use super::stability::nominal_damping;
use crate::contact::Contact;
use crate::friction::FrictionState;
use crate::friction::implicit::{self, Body, Spring, Wrench};
use crate::pipeline::{InteractionWorld, host};
use glam::{Mat3, Vec3};

/// An object's motion and hand wrench at a step whose springs were
/// implicit (world frame: m/s, rad/s, N, N·m; the world's time, s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ImplicitMemory {
    time: f64,
    linvel: Vec3,
    angvel: Vec3,
    wrench: Wrench,
}

impl InteractionWorld {
    /// Corrects the hand wrench of each object marked implicit this step.
    pub(super) fn implicit_springs(&mut self, step: &StepScratch) {
        for &o in &step.touched {
            let slot = &mut self.objects[o];
            let memory = slot.implicit.take();
            if step.limits[o].implicit && slot.pushed {
                self.correct(o, memory);
            }
        }
    }

    /// Object `o`'s correction, and what the next step needs of it.
    fn correct(&mut self, o: usize, memory: Option<ImplicitMemory>) {
        let (dt, time) = (self.config.dt, self.time);
        let slot = &self.objects[o];
        let body = &self.physics.bodies[slot.body];
        let props = &body.mass_properties().local_mprops;
        let rotation = slot.pose(&self.physics.bodies).rotation;
        let axes = Mat3::from_quat(rotation * props.principal_inertia_local_frame);
        let state = Body {
            mass: props.mass(),
            inertia: axes * Mat3::from_diagonal(props.principal_inertia()) * axes.transpose(),
            linvel: body.linvel(),
            angvel: body.angvel(),
        };
        let (center, explicit) = (
            slot.center_of_mass(body),
            Wrench { force: body.user_force(), torque: body.user_torque() },
        );
        let weight = Wrench { force: self.config.gravity * state.mass, torque: Vec3::ZERO };
        let external = match memory {
            // What moved it last step besides the hands, as far as the hands'
            // own forces account for its departure from the weight: a table
            // pressed by a finger, or the gravity of another host, yes; the
            // impulse of a landing, which lasts one step, no.
            Some(m) if m.time + f64::from(dt) == time => {
                let seen = Wrench {
                    force: (state.linvel - m.linvel) * (state.mass / dt) - m.wrench.force,
                    torque: state.inertia * ((state.angvel - m.angvel) / dt) - m.wrench.torque,
                };
                let bound = |last: Vec3, now: Vec3| last.length() + now.length();
                let (force, torque) = (seen.force - weight.force, seen.torque);
                Wrench {
                    force: weight.force
                        + force.clamp_length_max(bound(m.wrench.force, explicit.force)),
                    torque: torque.clamp_length_max(bound(m.wrench.torque, explicit.torque)),
                }
            }
            _ => weight,
        };
        let first = self.contacts.partition_point(|c| (c.object.0 as usize) < o);
        let count = self.contacts[first..].partition_point(|c| c.object.0 as usize == o);
        let damping = nominal_damping(&self.config, slot);
        // As the contact law had it: a baseline's hand has no skin friction.
        let skin = self.config.hand_friction.then_some(slot.material.skin.static_mu);
        let (gamma, static_mu) = (slot.gamma, skin.unwrap_or(0.0));
        let spring = |c: &Contact| Spring {
            offset: c.point - center,
            normal: c.normal,
            bone_velocity: c.bone_velocity,
            stiffness: c.stiffness,
            damping: damping * c.stiffness / gamma,
            sticking: c.state == FrictionState::Static,
        };
        let pressing = |c: &Contact| c.state != FrictionState::Separated;
        let run = first..first + count;
        let springs: Vec<Spring> =
            self.contacts[run.clone()].iter().filter(|c| pressing(c)).map(spring).collect();
        let Some(change) = implicit::velocity_change(&state, &springs, dt, explicit, external)
        else {
            return;
        };
        let mut wrench = explicit;
        let mut total = slot.hand_force;
        let mut corrected = Vec::with_capacity(springs.len());
        for (c, s) in self.contacts[run.clone()].iter().filter(|c| pressing(c)).zip(&springs) {
            let force = implicit::corrected_force(s, c.force, &state, dt, change, static_mu);
            let force = if force.is_finite() { force } else { c.force };
            let delta = force - c.force;
            wrench.force += delta;
            wrench.torque += s.offset.cross(delta);
            total += delta;
            corrected.push(force);
        }
        if !(wrench.force.is_finite() && wrench.torque.is_finite() && total.is_finite()) {
            // The firewall's rule: nothing that is not finite reaches rapier.
            return;
        }
        for (c, force) in self.contacts[run].iter_mut().filter(|c| pressing(c)).zip(corrected) {
            c.force = force;
            c.normal_force = (-force.dot(c.normal)).max(0.0);
        }
        let slot = &mut self.objects[o];
        slot.hand_force = total;
        host::push(&mut self.physics.bodies[slot.body], wrench.force, wrench.torque);
        slot.implicit =
            Some(ImplicitMemory { time, linvel: state.linvel, angvel: state.angvel, wrench });
    }
}
