//! [`InteractionWorld`]'s API: what a program calls to build a world, pose
//! its hands and read what happened. One step is in [`super::step`].

use super::config::InteractionConfig;
use super::error::WorldError;
use super::firewall;
use super::record::{Call, Recorder};
use super::step::{StepScratch, near};
use super::{HandSlot, InteractionWorld, ObjectSlot};
use crate::contact::{Contact, ContactEvent};
use crate::hand::acting::ActingHand;
use crate::hand::{HandId, HandPose, Side};
use crate::scene::{Material, ObjectDesc, ObjectId, Scene, StaticDesc};
use glam::{Quat, Vec3};
use rapier3d::math::Pose;
use rapier3d::prelude::{
    ColliderBuilder, ColliderHandle, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle,
    RigidBodyType, SharedShape,
};
use std::any::Any;

/// Pose, velocity and hand force of an object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectState {
    /// Body origin (m).
    pub position: Vec3,
    /// Orientation (unit quaternion).
    pub rotation: Quat,
    /// Linear velocity of the centre of mass (m/s).
    pub linvel: Vec3,
    /// Angular velocity (rad/s).
    pub angvel: Vec3,
    /// The total of the hand contacts' forces on it in the last step (N):
    /// thesis Eq. 3.10, [`crate::friction::total_force`].
    pub hand_force: Vec3,
    /// Whether rapier has put it to sleep.
    pub sleeping: bool,
}

impl ObjectState {
    /// What a record that keeps a row per object id holds for a removed
    /// object: every number NaN, not sleeping.
    pub const REMOVED: ObjectState = ObjectState {
        position: Vec3::NAN,
        rotation: Quat::from_xyzw(f32::NAN, f32::NAN, f32::NAN, f32::NAN),
        linvel: Vec3::NAN,
        angvel: Vec3::NAN,
        hand_force: Vec3::NAN,
        sleeping: false,
    };
}

impl InteractionWorld {
    /// An empty world.
    pub fn new(config: InteractionConfig) -> Result<Self, WorldError> {
        firewall::config(&config)?;
        let mut physics = PhysicsWorld::new();
        physics.gravity = config.gravity;
        config.set_rapier_parameters(&mut physics.integration_parameters);
        Ok(InteractionWorld {
            physics,
            config,
            objects: Vec::new(),
            hand_shapes: Vec::new(),
            hands: Vec::new(),
            contacts: Vec::new(),
            events: Vec::new(),
            time: 0.0,
            scratch: StepScratch::new(&config),
            unindexed: Vec::new(),
            hosted: Vec::new(),
            host_moved: 0.0,
            forced: Vec::new(),
            reseating: Vec::new(),
            grabbed: Vec::new(),
            external: false,
            recorder: None,
        })
    }

    /// Shows every later accepted call to `recorder`; returns the one it
    /// replaces.
    pub fn set_recorder(&mut self, recorder: Box<dyn Recorder>) -> Option<Box<dyn Recorder>> {
        self.recorder.replace(recorder)
    }

    /// Stops recording and hands the recorder back, if it is an `R`. A
    /// recorder of another type stays in place.
    pub fn take_recorder<R: Recorder>(&mut self) -> Option<R> {
        let is_r = self.recorder.as_deref().is_some_and(|r| (r as &dyn Any).is::<R>());
        let recorder: Box<dyn Any> = if is_r { self.recorder.take()? } else { return None };
        recorder.downcast::<R>().ok().map(|r| *r)
    }

    pub(super) fn record(&mut self, call: impl FnOnce() -> Call) {
        if let Some(recorder) = self.recorder.as_mut() {
            recorder.record(&call());
        }
    }

    /// The settings the world was made with.
    pub fn config(&self) -> &InteractionConfig {
        &self.config
    }

    /// The rapier world, for reading and for advanced set-up (joints,
    /// solver parameters). Hands never appear in it. In host mode an
    /// object's collider is where the host last put it, but its body's
    /// pose is not written until rapier steps the world or
    /// [`Self::physics_mut`] is called: read the pose from
    /// [`Self::object_state`].
    pub fn physics(&self) -> &PhysicsWorld {
        &self.physics
    }

    /// Mutable access to the rapier world, for solver settings, joints and
    /// scripted set-up. Do not insert hand bones (a colliding bone would
    /// bypass the friction model), and do not remove the bodies or colliders
    /// of objects added with [`Self::add_object`]: the world indexes them.
    /// What is written here bypasses the NaN firewall (`firewall.rs`).
    /// rapier's substeps are set from the config before each step
    /// ([`InteractionConfig::engine_substeps`]), so set them there; a
    /// body's own `additional_solver_iterations` are kept (an object the
    /// hands push runs at least [`super::HAND_SUBSTEPS`] for that step).
    pub fn physics_mut(&mut self) -> &mut PhysicsWorld {
        // What is handed out is current: a host's poses on their bodies.
        self.unhost();
        self.external = true;
        &mut self.physics
    }

    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Adds static scenery (ground, tables). Hands do not touch it.
    pub fn add_static(&mut self, desc: &StaticDesc) -> Result<ColliderHandle, WorldError> {
        let shape = firewall::fixed(desc)?;
        Ok(self.insert_static(desc, shape))
    }

    /// Adds scenery the firewall admitted.
    fn insert_static(&mut self, desc: &StaticDesc, shape: SharedShape) -> ColliderHandle {
        let collider = ColliderBuilder::new(shape)
            .position(Pose::from_parts(desc.position, desc.rotation))
            .friction(desc.friction);
        let body = self.physics.insert_body(RigidBodyBuilder::fixed());
        self.record(|| Call::AddStatic(desc.clone()));
        self.physics.insert_collider(collider, Some(body))
    }

    /// Removes static scenery added by [`Self::add_static`], with its fixed
    /// body, waking what rested on it. Returns `false` (and removes
    /// nothing) for an unknown handle or an object's collider.
    pub fn remove_static(&mut self, handle: ColliderHandle) -> bool {
        if self.objects.iter().any(|o| o.collider == handle) {
            return false;
        }
        let Some(body) = self.physics.colliders.get(handle).and_then(|c| c.parent()) else {
            return false;
        };
        if !self.physics.bodies.get(body).is_some_and(|b| b.is_fixed()) {
            return false;
        }
        self.physics.remove_body_with_colliders(body, true).is_some()
    }

    /// Adds a dynamic object that hands can touch.
    pub fn add_object(&mut self, desc: &ObjectDesc) -> Result<ObjectId, WorldError> {
        let admitted = firewall::object(desc, self.config.gamma, self.config.gravity.length())?;
        Ok(self.insert_object(desc, admitted))
    }

    /// Adds an object the firewall admitted.
    fn insert_object(&mut self, desc: &ObjectDesc, admitted: firewall::Admitted) -> ObjectId {
        let firewall::Admitted { shape, hand_shape, gamma, diameter, reach, mass_properties } =
            admitted;
        let pose = Pose::from_parts(desc.position, desc.rotation);
        let id = ObjectId(self.objects.len() as u32);
        let tag = near::object_tag(id);
        let body = self.physics.insert_body(RigidBodyBuilder::dynamic().pose(pose).user_data(tag));
        let collider = match mass_properties {
            Some(props) => ColliderBuilder::new(shape).mass_properties(props),
            None => ColliderBuilder::new(shape).mass(desc.mass),
        };
        let collider = collider.friction(desc.material.surface_friction).user_data(tag);
        let collider = self.physics.insert_collider(collider, Some(body));
        self.unindexed.push(id.0);
        self.objects.push(ObjectSlot {
            name: desc.name.clone(),
            body,
            collider,
            material: desc.material.clone(),
            gamma,
            diameter,
            reach,
            mass: desc.mass,
            hand_force: Vec3::ZERO,
            reseat: false,
            forced: false,
            pushed: false,
            hosted: false,
            host_mass: None,
            host_pose: Pose::IDENTITY,
            host_com: Vec3::ZERO,
            raised: None,
            grab: Default::default(),
            removed: false,
            implicit: None,
        });
        self.hand_shapes.push(hand_shape);
        self.record(|| Call::AddObject(desc.clone()));
        id
    }

    /// Removes an object: its body and collider leave rapier, waking what
    /// rested on it; its contacts end at the next step (an `Ended` event
    /// each, as for a hand that lost tracking); a grab baseline lets go of
    /// it. Its id is not given again: the other objects keep theirs, and
    /// calls that name it fail with [`WorldError::NoSuchObject`].
    pub fn remove_object(&mut self, id: ObjectId) -> Result<(), WorldError> {
        self.slot(id)?;
        let o = id.0 as usize;
        self.end_grab(o);
        self.grabbed.retain(|&g| g != id.0);
        self.forced.retain(|&f| f != id.0);
        self.unindexed.retain(|&u| u != id.0);
        self.hosted.retain(|&u| u != id.0);
        let slot = &mut self.objects[o];
        (slot.removed, slot.forced, slot.raised) = (true, false, None);
        slot.hand_force = Vec3::ZERO;
        slot.reseat = true;
        self.reseating.push(id.0);
        self.physics.remove_body_with_colliders(slot.body, true);
        // The kept broad-phase answers may name it.
        self.scratch.near.forget();
        self.record(|| Call::RemoveObject(id.0));
        Ok(())
    }

    /// Adds a whole scene: its ground, statics, objects and towers, in that
    /// order. Its gravity belongs to the config
    /// ([`InteractionConfig::with_scene`]). Every part is admitted before any
    /// is added: a scene the world refuses leaves it as it was.
    pub fn add_scene(&mut self, scene: &Scene) -> Result<(), WorldError> {
        let ground = scene.ground.map(|g| StaticDesc::ground(g.height, g.friction));
        let statics: Vec<&StaticDesc> = ground.iter().chain(&scene.statics).collect();
        let blocks: Vec<ObjectDesc> = scene.towers.iter().flat_map(|t| t.blocks()).collect();
        let objects: Vec<&ObjectDesc> = scene.objects.iter().chain(&blocks).collect();
        let fixed = statics.iter().map(|s| firewall::fixed(s)).collect::<Result<Vec<_>, _>>()?;
        let (gamma, gravity) = (self.config.gamma, self.config.gravity.length());
        let admitted = objects.iter().map(|o| firewall::object(o, gamma, gravity));
        let admitted = admitted.collect::<Result<Vec<_>, _>>()?;
        for (desc, shape) in statics.into_iter().zip(fixed) {
            self.insert_static(desc, shape);
        }
        for (desc, admitted) in objects.into_iter().zip(admitted) {
            self.insert_object(desc, admitted);
        }
        Ok(())
    }

    /// Adds a hand with no pose yet (untracked).
    pub fn add_hand(&mut self, side: Side) -> HandId {
        let acting = self.config.tracking.map(ActingHand::new);
        let (pose, prev, tracked) = (None, None, None);
        self.hands.push(HandSlot { side, pose, prev, tracked, acting, pose_mark: 0, prev_mark: 0 });
        self.record(|| Call::AddHand(side));
        HandId(self.hands.len() as u32 - 1)
    }

    /// Sets a hand's tracked pose for the next step. Call it every step
    /// (interpolating a slower tracker) so bone velocities are smooth.
    /// With the config's tracking filter, the hand that acts follows it
    /// from the next step's first stage ([`crate::hand::acting`]); a hand
    /// that was not tracked acts where it is tracked at once. A rejected
    /// pose leaves the world untouched.
    pub fn set_hand_pose(&mut self, hand: HandId, pose: &HandPose) -> Result<(), WorldError> {
        let slot = self.hands.get_mut(hand.0 as usize).ok_or(WorldError::NoSuchHand(hand))?;
        firewall::pose(hand.0, pose)?;
        let begins = slot.pose.is_none();
        if let Some(acting) = slot.acting.as_mut() {
            if begins {
                acting.begin(pose);
            }
            slot.tracked = Some(pose.clone());
        }
        // With the filter, the hand that acts moves in the step's first stage.
        if begins || slot.acting.is_none() {
            slot.pose = Some(pose.clone());
            slot.pose_mark += 1;
        }
        self.record(|| Call::SetHandPose(hand.0, Box::new(pose.clone())));
        Ok(())
    }

    /// Marks a hand as untracked: its contacts end at the next step.
    pub fn clear_hand_pose(&mut self, hand: HandId) -> Result<(), WorldError> {
        let slot = self.hands.get_mut(hand.0 as usize).ok_or(WorldError::NoSuchHand(hand))?;
        slot.pose = None;
        slot.prev = None;
        slot.tracked = None;
        slot.pose_mark += 1;
        self.record(|| Call::ClearHandPose(hand.0));
        Ok(())
    }

    /// The hand that acts, if tracked: the pose its contacts saw in the
    /// last step (or, for a hand tracked since, the pose set).
    pub fn hand_pose(&self, hand: HandId) -> Option<&HandPose> {
        self.hands.get(hand.0 as usize)?.pose.as_ref()
    }

    /// The hand as the tracker last set it, if tracked: without the
    /// config's tracking filter, the hand that acts.
    pub fn tracked_pose(&self, hand: HandId) -> Option<&HandPose> {
        let slot = self.hands.get(hand.0 as usize)?;
        slot.tracked.as_ref().or(slot.pose.as_ref())
    }

    /// The tracker's jitter as measured on the hand (m, rms per axis as
    /// white noise would give it: [`crate::hand::jitter`]), with the
    /// config's tracking filter; 0 until measured.
    pub fn hand_jitter(&self, hand: HandId) -> Option<f32> {
        self.hands.get(hand.0 as usize)?.acting.as_ref().map(ActingHand::jitter)
    }

    /// Which hand it is.
    pub fn hand_side(&self, hand: HandId) -> Option<Side> {
        self.hands.get(hand.0 as usize).map(|h| h.side)
    }

    /// Hands added so far.
    pub fn hand_count(&self) -> usize {
        self.hands.len()
    }

    /// Objects added so far, removed ones included: their ids are
    /// `0..object_count()`, and the next object added gets the id
    /// `object_count()`.
    pub fn object_count(&self) -> usize {
        self.objects.len()
    }

    /// Every object ever added, by id (`0..object_count()`), with its
    /// state, or `None` once removed: what a record that keeps one row
    /// per object indexes by, so that a removal shifts no other row.
    pub fn object_slots(&self) -> impl Iterator<Item = (ObjectId, Option<ObjectState>)> + '_ {
        (0..self.object_count() as u32).map(|i| (ObjectId(i), self.object_state(ObjectId(i)).ok()))
    }

    /// The ids of the objects in the world (not removed), in order.
    pub fn object_ids(&self) -> impl Iterator<Item = ObjectId> + '_ {
        self.objects.iter().enumerate().filter(|(_, o)| !o.removed).map(|(i, _)| ObjectId(i as u32))
    }

    /// The object's slot, unless it was never added or was removed.
    pub(super) fn slot(&self, id: ObjectId) -> Result<&ObjectSlot, WorldError> {
        let slot = self.objects.get(id.0 as usize).filter(|o| !o.removed);
        slot.ok_or(WorldError::NoSuchObject(id))
    }

    /// The object's name, as given in its description.
    pub fn object_name(&self, id: ObjectId) -> Option<&str> {
        self.slot(id).ok().map(|o| o.name.as_str())
    }

    /// The contact stiffness γ in use for an object (N/m).
    pub fn object_gamma(&self, id: ObjectId) -> Option<f32> {
        self.slot(id).ok().map(|o| o.gamma)
    }

    /// The object's mass (kg).
    pub fn object_mass(&self, id: ObjectId) -> Option<f32> {
        self.slot(id).ok().map(|o| o.mass)
    }

    /// The object's material.
    pub fn object_material(&self, id: ObjectId) -> Option<&Material> {
        self.slot(id).ok().map(|o| &o.material)
    }

    /// The object's rapier body, for reading or scripted set-up.
    pub fn object_body(&self, id: ObjectId) -> Option<RigidBodyHandle> {
        self.slot(id).ok().map(|o| o.body)
    }

    /// Holds an object fixed in place (`true`) or lets it move again: a
    /// fixture, e.g. to keep an object where a recorded hand will close on
    /// it. A locked object still has contacts and their forces computed;
    /// they just do not move it.
    pub fn set_object_locked(&mut self, id: ObjectId, locked: bool) -> Result<(), WorldError> {
        let slot = self.slot(id)?;
        let kind = if locked { RigidBodyType::Fixed } else { RigidBodyType::Dynamic };
        if let Some(body) = self.physics.bodies.get_mut(slot.body) {
            body.set_body_type(kind, true);
        }
        self.record(|| Call::SetObjectLocked(id.0, locked));
        Ok(())
    }

    /// Ends the object's contacts at the next step, to begin afresh from
    /// the bones' pose then (an `Ended` then a `Began` event each).
    ///
    /// For a fixture released while the hand is not gripping it: contacts
    /// formed while bones travelled through an immovable body hold that
    /// whole sweep in their friction springs and contact points; once the
    /// object is free, only where the hand is now should push it.
    pub fn reseat_contacts(&mut self, id: ObjectId) -> Result<(), WorldError> {
        self.slot(id)?;
        self.objects[id.0 as usize].reseat = true;
        self.reseating.push(id.0);
        self.record(|| Call::ReseatContacts(id.0));
        Ok(())
    }

    /// Puts an object at `position` (m) and `rotation`, at rest and awake,
    /// as if picked up and set down there: its velocities are zeroed and
    /// its contacts re-seated ([`Self::reseat_contacts`]). A soak puts its
    /// objects back this way before each loop. A non-finite position, one
    /// beyond [`crate::hand::MAX_COORDINATE`] or a rotation that is not a
    /// unit quaternion is rejected, and nothing changes.
    pub fn place_object(
        &mut self,
        id: ObjectId,
        position: Vec3,
        rotation: Quat,
    ) -> Result<(), WorldError> {
        let rotation = firewall::placement(&self.slot(id)?.name, position, rotation)?;
        let slot = &mut self.objects[id.0 as usize];
        slot.reseat = true;
        self.reseating.push(id.0);
        self.end_grab(id.0 as usize);
        let slot = &mut self.objects[id.0 as usize];
        if let Some(body) = self.physics.bodies.get_mut(slot.body) {
            body.set_position(Pose::from_parts(position, rotation), true);
            body.set_linvel(Vec3::ZERO, true);
            body.set_angvel(Vec3::ZERO, true);
            // A hosted one too is here until its host sets it again.
            (slot.host_pose, slot.host_com) = (*body.position(), body.center_of_mass());
        }
        // rapier moves colliders with their bodies only in its step; the
        // contacts found before it must see the object where it now is.
        let physics = &mut self.physics;
        physics.bodies.propagate_modified_body_positions_to_colliders(&mut physics.colliders);
        self.unindexed.push(id.0);
        self.record(|| Call::PlaceObject(id.0, position, rotation));
        Ok(())
    }

    /// The current state of an object.
    pub fn object_state(&self, id: ObjectId) -> Result<ObjectState, WorldError> {
        let slot = self.slot(id)?;
        let body = &self.physics.bodies[slot.body];
        let pose = slot.pose(&self.physics.bodies);
        Ok(ObjectState {
            position: pose.translation,
            rotation: pose.rotation,
            linvel: body.linvel(),
            angvel: body.angvel(),
            hand_force: slot.hand_force,
            sleeping: body.is_sleeping(),
        })
    }

    /// All active contacts after the last step, ordered by (object, hand,
    /// bone).
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    /// The active contacts on one object, ordered by (hand, bone).
    pub fn contacts_on(&self, id: ObjectId) -> &[Contact] {
        let start = self.contacts.partition_point(|c| c.object < id);
        let end = self.contacts.partition_point(|c| c.object <= id);
        &self.contacts[start..end]
    }

    /// Contact begin/end events of the last step.
    pub fn events(&self) -> &[ContactEvent] {
        &self.events
    }
}
