//! Stage 8 of a step, for the grab baselines only
//! ([`crate::InteractionConfig::grab`]): a qualifying grasp moves its
//! object with the hand instead of friction ([`crate::grab`]). Friction
//! hands skip it.

use crate::contact::Contact;
use crate::grab::{GrabMethod, heuristic, kinematic};
use crate::hand::{HandId, HandPose};
use crate::pipeline::InteractionWorld;
use crate::pipeline::firewall;
use glam::Vec3;
use rapier3d::math::Pose;
use rapier3d::prelude::RigidBodyType;

/// An object held by a grab.
#[derive(Debug, Clone)]
pub(crate) struct Held {
    hand: HandId,
    /// The object's pose in the palm's frame at the grab: `M_object^hand`.
    in_palm: Pose,
    /// The digits' curls at the grab (heuristic).
    curls: [f32; 6],
    /// The velocities set while held (heuristic).
    throw: heuristic::ThrowHistory,
    /// The gravity scale to give back on release (heuristic).
    gravity_scale: f32,
}

/// Per object: its grab, if any, and when it may be grabbed again.
#[derive(Debug, Clone, Default)]
pub(crate) struct GrabSlot {
    pub held: Option<Held>,
    /// No grab before this time (s): the heuristic's cooldown after a throw.
    pub no_grab_until: f64,
}

/// The palm's frame as a pose: `M_hand`.
fn palm_frame(pose: &HandPose) -> Pose {
    Pose::from_parts(pose.palm.center, pose.palm.rotation)
}

impl InteractionWorld {
    /// Grabs, moves and lets go of objects by the configured baseline.
    /// Only an object a hand touches or holds can change, so only those
    /// are visited, in ascending order: the stage does not grow with the
    /// scene.
    pub(super) fn grab_objects(&mut self) {
        let Some(method) = self.config.grab else { return };
        let mut visits = std::mem::take(&mut self.scratch.grab_visits);
        visits.clear();
        visits.extend(self.contacts.iter().map(|c| c.object.0));
        visits.extend_from_slice(&self.grabbed);
        visits.sort_unstable();
        visits.dedup();
        self.grabbed.clear();
        for &o in &visits {
            let o = o as usize;
            let held = self.objects[o].grab.held.take();
            let held = match held {
                Some(held) => self.keep_or_release(o, method, held),
                None => self.try_grab(o, method),
            };
            if held.is_some() {
                self.grabbed.push(o as u32);
            }
            self.objects[o].grab.held = held;
        }
        self.scratch.grab_visits = visits;
    }

    /// One hand's contacts on object `o`, and that hand's pose.
    fn hand_on(&self, o: usize, hand: HandId) -> Option<(Vec<&Contact>, &HandPose)> {
        let pose = self.hands.get(hand.0 as usize)?.pose.as_ref()?;
        let id = crate::scene::ObjectId(o as u32);
        let contacts = self.contacts_on(id).iter().filter(|c| c.hand == hand).collect();
        Some((contacts, pose))
    }

    fn qualifies(method: GrabMethod, contacts: &[&Contact], pose: &HandPose) -> bool {
        match method {
            GrabMethod::Kinematic => kinematic::is_grasp(contacts),
            GrabMethod::Heuristic => heuristic::grabs(contacts, pose),
        }
    }

    /// The first hand, in order, whose contacts on object `o` qualify.
    fn try_grab(&mut self, o: usize, method: GrabMethod) -> Option<Held> {
        let slot = &self.objects[o];
        let body = &self.physics.bodies[slot.body];
        // A locked object (a fixture) stays where it is.
        if self.time < slot.grab.no_grab_until || body.body_type() != RigidBodyType::Dynamic {
            return None;
        }
        let object_pose = *body.position();
        let hands = (0..self.hands.len() as u32).map(HandId);
        let (hand, pose) = hands.filter_map(|h| Some((h, self.hand_on(o, h)?))).find_map(
            |(h, (contacts, pose))| Self::qualifies(method, &contacts, pose).then_some((h, pose)),
        )?;
        let mut held = Held {
            hand,
            in_palm: palm_frame(pose).inverse() * object_pose,
            curls: heuristic::curls(pose),
            throw: heuristic::ThrowHistory::default(),
            gravity_scale: body.gravity_scale(),
        };
        let body = &mut self.physics.bodies[self.objects[o].body];
        match method {
            GrabMethod::Kinematic => {
                body.set_body_type(RigidBodyType::KinematicPositionBased, true)
            }
            GrabMethod::Heuristic => body.set_gravity_scale(0.0, true),
        }
        self.carry(o, method, &mut held);
        Some(held)
    }

    /// Carries a held object on, or lets it go when the hand has opened or
    /// lost tracking.
    fn keep_or_release(&mut self, o: usize, method: GrabMethod, mut held: Held) -> Option<Held> {
        let holds = self.hand_on(o, held.hand).is_some_and(|(contacts, pose)| {
            Self::qualifies(method, &contacts, pose)
                || (method == GrabMethod::Heuristic && heuristic::keeps_hold(&held.curls, pose))
        });
        if holds {
            self.carry(o, method, &mut held);
            Some(held)
        } else {
            self.let_go(o, method, held);
            None
        }
    }

    /// Moves a held object towards `M_object^hand · M_hand`: exactly there
    /// (kinematic), or by the velocity that reaches it in one step
    /// (heuristic). Hand forces on it are cleared: the grab moves it.
    fn carry(&mut self, o: usize, method: GrabMethod, held: &mut Held) {
        let Some(pose) = self.hands.get(held.hand.0 as usize).and_then(|h| h.pose.as_ref()) else {
            return;
        };
        let target = palm_frame(pose) * held.in_palm;
        let (dt, time) = (self.config.dt, self.time);
        let body = &mut self.physics.bodies[self.objects[o].body];
        match method {
            GrabMethod::Kinematic => {
                if let Some(target) = firewall::kinematic_target(target) {
                    body.set_next_kinematic_position(target);
                }
            }
            GrabMethod::Heuristic => {
                let com = body.mass_properties().local_mprops.local_com;
                let from = *body.position() * com;
                let to = target * com;
                let linvel = heuristic::chase_velocity(from, to, dt);
                let turn = target.rotation * body.position().rotation.inverse();
                let angvel = turn.to_scaled_axis() / dt;
                if let Some((linvel, angvel)) = firewall::velocities(linvel, angvel) {
                    body.reset_forces(true);
                    body.reset_torques(true);
                    body.set_linvel(linvel, true);
                    body.set_angvel(angvel, true);
                    held.throw.push(time, linvel);
                }
            }
        }
    }

    /// Lets a held object go: dynamic again with the velocity it was
    /// carried at (kinematic), or thrown or stopped (heuristic).
    fn let_go(&mut self, o: usize, method: GrabMethod, held: Held) {
        let time = self.time;
        let slot = &mut self.objects[o];
        let body = &mut self.physics.bodies[slot.body];
        match method {
            GrabMethod::Kinematic => body.set_body_type(RigidBodyType::Dynamic, true),
            GrabMethod::Heuristic => {
                body.set_gravity_scale(held.gravity_scale, true);
                match held.throw.throw() {
                    Some(v) => {
                        body.set_linvel(v, true);
                        slot.grab.no_grab_until = time + heuristic::REGRAB_COOLDOWN;
                    }
                    None => {
                        body.set_linvel(Vec3::ZERO, true);
                        body.set_angvel(Vec3::ZERO, true);
                    }
                }
            }
        }
    }

    /// Ends object `o`'s grab without a throw (the object is placed
    /// elsewhere): dynamic, its gravity back.
    pub(in crate::pipeline) fn end_grab(&mut self, o: usize) {
        let slot = &mut self.objects[o];
        if let Some(held) = slot.grab.held.take() {
            let body = &mut self.physics.bodies[slot.body];
            body.set_body_type(RigidBodyType::Dynamic, true);
            body.set_gravity_scale(held.gravity_scale, true);
        }
    }

    /// The hand holding object `id` by a grab baseline, if any.
    pub fn held_by(&self, id: crate::scene::ObjectId) -> Option<HandId> {
        self.objects.get(id.0 as usize)?.grab.held.as_ref().map(|h| h.hand)
    }
}
