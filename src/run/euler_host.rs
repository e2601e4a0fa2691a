//! A host engine in a few lines, for host mode's tests and measurements:
//! free rigid bodies under gravity, stepped by semi-implicit Euler (as
//! PhysX, and so Unity, and most engines step them), with no contacts of
//! their own. It stands for an engine whose step the library does not
//! control; rapier stepped from outside is the other
//! ([`crate::InteractionWorld::integrate_wrenches`]).

use super::RunError;
use super::drive::Host;
use crate::pipeline::InteractionWorld;
use crate::pipeline::host::{HandWrench, HostBody};
use crate::scene::ObjectId;
use glam::{Mat3, Quat, Vec3};

/// Bodies by object id, integrated by semi-implicit Euler at `dt` (s).
#[derive(Debug, Clone)]
pub struct EulerHost {
    /// Each object's state, by id.
    pub bodies: Vec<HostBody>,
    /// Gravity (m/s²).
    pub gravity: Vec3,
    /// The host's fixed step (s).
    pub dt: f32,
}

impl EulerHost {
    /// One body's step under the hands' wrench: velocities first (the
    /// force and torque, and gravity), then the pose from the new
    /// velocities, about the centre of mass.
    fn step_body(&self, body: &mut HostBody, wrench: &HandWrench) {
        let dt = self.dt;
        body.linvel += (wrench.force / body.mass + self.gravity) * dt;
        let axes = Mat3::from_quat(body.rotation * body.inertia_rotation);
        let inverse = axes * Mat3::from_diagonal(body.principal_inertia.recip()) * axes.transpose();
        body.angvel += inverse * wrench.torque * dt;
        let center = body.position + body.rotation * body.center_of_mass;
        let turn = Quat::from_scaled_axis(body.angvel * dt);
        body.rotation = (turn * body.rotation).normalize();
        body.position = center + body.linvel * dt - body.rotation * body.center_of_mass;
    }
}

impl Host for EulerHost {
    fn give_states(&mut self, world: &mut InteractionWorld) -> Result<(), RunError> {
        let bodies = self.bodies.iter().enumerate();
        let states: Vec<_> = bodies.map(|(i, b)| (ObjectId(i as u32), *b)).collect();
        Ok(world.set_host_bodies(&states)?)
    }

    fn integrate(&mut self, wrenches: &[HandWrench]) -> Result<(), RunError> {
        for wrench in wrenches {
            let mut body = self.bodies[wrench.object.0 as usize];
            self.step_body(&mut body, wrench);
            self.bodies[wrench.object.0 as usize] = body;
        }
        Ok(())
    }
}
