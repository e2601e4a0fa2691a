//! What a scenario run recorded, step by step, for its checks.

use crate::pipeline::{InteractionWorld, ObjectState};
use crate::run::RunError;
use crate::run::drive::{Observer, StepView};
use glam::{Quat, Vec3};

/// What a run recorded, step by step, for the checks.
#[derive(Debug, Clone, Default)]
pub struct History {
    /// Physics step (s).
    pub dt: f32,
    /// Object names, by id (a removed object's stays).
    pub names: Vec<String>,
    /// `poses[step][object]` after that step, by id (NaN once removed).
    pub poses: Vec<Vec<(Vec3, Quat)>>,
    /// `velocities[step][object]`: linear velocity after that step (m/s).
    pub velocities: Vec<Vec<Vec3>>,
    /// `contacts[step][object]`: hand contacts pressing on it (normal force
    /// > 0) after that step.
    pub contacts: Vec<Vec<u32>>,
    /// `hand_forces[step][object]`: the hands' total force on it in that
    /// step (N, [`crate::ObjectState::hand_force`]).
    pub hand_forces: Vec<Vec<Vec3>>,
    /// `palms[step][hand]`: palm centre and rotation, if tracked.
    pub palms: Vec<Vec<Option<(Vec3, Quat)>>>,
    /// The world's gravity (m/s²), for ballistic predictions.
    pub gravity: Vec3,
}

impl History {
    /// An empty history of `world`'s objects.
    pub fn new(world: &InteractionWorld) -> History {
        let (dt, gravity) = (world.config().dt, world.config().gravity);
        let mut history = History { dt, gravity, ..History::default() };
        history.name_new_objects(world);
        history
    }

    /// Names the objects added since the last call, by id; one removed
    /// before it was seen is nameless.
    fn name_new_objects(&mut self, world: &InteractionWorld) {
        for (id, _) in world.object_slots().skip(self.names.len()) {
            self.names.push(world.object_name(id).unwrap_or("").to_string());
        }
    }

    /// The step whose state is the one at time `t` (clamped to the run).
    pub(super) fn step(&self, t: f32) -> usize {
        ((t / self.dt).round().max(1.0) as usize - 1).min(self.poses.len().saturating_sub(1))
    }

    pub(super) fn end(&self) -> f32 {
        self.poses.len() as f32 * self.dt
    }

    pub(super) fn steps(&self, from: f32, to: Option<f32>) -> std::ops::RangeInclusive<usize> {
        self.step(from)..=self.step(to.unwrap_or(self.end()))
    }
}

impl Observer for History {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let world = step.world;
        self.name_new_objects(world);
        let objects = world.object_count();
        let mut poses = Vec::with_capacity(objects);
        let mut velocities = Vec::with_capacity(objects);
        let mut hand_forces = Vec::with_capacity(objects);
        for (_, state) in world.object_slots() {
            let s = state.unwrap_or(ObjectState::REMOVED);
            poses.push((s.position, s.rotation));
            velocities.push(s.linvel);
            hand_forces.push(s.hand_force);
        }
        let mut contacts = vec![0u32; objects];
        for c in world.contacts().iter().filter(|c| c.normal_force > 0.0) {
            contacts[c.object.0 as usize] += 1;
        }
        let palm = |h: &crate::run::drive::HandFrame| {
            h.sample.as_ref().map(|s| (s.pose.palm.center, s.pose.palm.rotation))
        };
        self.poses.push(poses);
        self.velocities.push(velocities);
        self.hand_forces.push(hand_forces);
        self.contacts.push(contacts);
        self.palms.push(step.hands.iter().map(palm).collect());
        Ok(())
    }
}
