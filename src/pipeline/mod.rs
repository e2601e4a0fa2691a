//! The interaction pipeline: hand poses → contacts → friction forces →
//! rapier step. [`InteractionWorld`] is the crate's public entry point.
//!
//! Guarantees:
//! * Hand bones are not bodies in the physics engine, so there is never an
//!   engine collision response between a bone and an object: bones act only
//!   through the forces computed in [`crate::contact`].
//! * Every force handed to rapier is finite; poses and object descriptions
//!   are validated before they touch the world, and a rejected call leaves
//!   the world as it was.
//! * Same calls, same results: all iteration is in a fixed order.

use crate::contact::{
    BoneMotion, Contact, ContactEvent, ContactEventKind, LawSettings, ObjectView, Proximity, Scratch,
    patch::PatchConfig,
};
use crate::friction::{self, FrictionState, KineticFriction};
use crate::hand::{Bone, BoneShape, HandPose, PoseError, Side, BONES_PER_HAND};
use crate::material::Material;
use crate::session::{Call, Session};
use crate::object::{GammaMode, ObjectDesc, ObjectError, ObjectId, StaticDesc};
use glam::Vec3;
use rapier3d::math::Pose;
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d::parry::query;
use rapier3d::parry::shape::{Cuboid, Segment, Shape};
use rapier3d::prelude::{
    ColliderBuilder, ColliderHandle, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle, RigidBodyType,
};

/// Handle of a hand in an [`InteractionWorld`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
pub struct HandId(pub u32);

impl std::fmt::Display for HandId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "hand {}", self.0)
    }
}

/// Settings of the interaction layer. Units: s, m, N, m/s. In files, a
/// missing field takes its default and an unknown one is an error.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct InteractionConfig {
    /// Physics time step (s); default 1 ms, the haptic rate. Contact springs
    /// are explicit forces: a longer step is still stable (the stability
    /// limit softens γ for objects too light for it) but light objects then
    /// feel softer.
    pub dt: f32,
    /// Gravity (m/s²).
    pub gravity: Vec3,
    /// A contact begins when a bone's surface comes within this distance of
    /// an object (m): the thesis's Default Contact Offset.
    pub contact_offset: f32,
    /// A contact ends when the bone's surface is farther than this (m).
    /// Larger than `contact_offset`, so tracking jitter at the threshold does
    /// not flicker begin/end events.
    pub release_offset: f32,
    /// Contact stiffness γ for objects without their own (§3.5.6).
    pub gamma: GammaMode,
    /// Eq. 3.8 as written, or Coulomb's kinetic friction (default).
    pub kinetic: KineticFriction,
    /// Skin patch sampling (§3.5.4).
    pub patch: PatchConfig,
    /// Damping ratio ζ of each contact spring, or `None` for the thesis's
    /// pure spring. The damper acts on the bone-vs-object velocity at the
    /// contact with `c = 2ζ√(γ m)`.
    pub damping_ratio: Option<f32>,
    /// Cap each contact's spring at the thesis's assumed 20 % maximum
    /// penetration of the object's bounding diameter d: its normal spring
    /// force stays ≤ `γ·0.2·d` however deep a bone is.
    pub force_cap: bool,
    /// The penetration depth a contact's spring sees may grow by at most
    /// this speed (m/s), or `None` for no limit. Real fingers press slower;
    /// a bone that teleports deep inside is a tracking glitch.
    pub max_penetration_speed: Option<f32>,
    /// How far above the surface the inverse rays of slipping contacts
    /// start (m).
    pub probe_offset: f32,
    /// Natural frequency of rapier's soft object–object and object–ground
    /// contacts (Hz). Stiffer than the step rate collapses stacks, so the
    /// world uses at most `1/dt`. rapier's 30 Hz default
    /// lets a 54-block tower sink 28 mm in 2 s; 240 Hz at a 1 ms step,
    /// 0.6 mm.
    pub contact_frequency: f32,
    /// rapier's friction between objects and with the ground: one Coulomb
    /// cone per contact point (default), or rapier's faster simplified
    /// model (one cone per group of 4 points plus a twist constraint),
    /// which lets a block pushed out of a tower drag the levels above it.
    pub object_friction: ObjectFriction,
}

/// How rapier solves friction between objects (not hand contacts, which
/// are always the thesis's model).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum ObjectFriction {
    #[default]
    Coulomb,
    Simplified,
}

impl Default for InteractionConfig {
    fn default() -> Self {
        InteractionConfig {
            dt: 1.0 / 1000.0,
            gravity: Vec3::new(0.0, -9.81, 0.0),
            contact_offset: 0.004,
            release_offset: 0.008,
            gamma: GammaMode::default(),
            kinetic: KineticFriction::Coulomb,
            patch: PatchConfig::default(),
            damping_ratio: Some(0.5),
            force_cap: true,
            max_penetration_speed: Some(1.0),
            probe_offset: 0.004,
            contact_frequency: 240.0,
            object_friction: ObjectFriction::Coulomb,
        }
    }
}

/// Why a configuration was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("config: {field}: {reason}")]
pub struct ConfigError {
    pub field: &'static str,
    pub reason: String,
}

impl InteractionConfig {
    /// The thesis's method exactly: pure spring, no cap, no speed limit,
    /// Eq. 3.8 as written.
    pub fn thesis() -> Self {
        InteractionConfig {
            kinetic: KineticFriction::Thesis,
            damping_ratio: None,
            force_cap: false,
            max_penetration_speed: None,
            ..Self::default()
        }
    }

    pub fn validate(&self) -> Result<(), ConfigError> {
        let err = |field, reason: String| Err(ConfigError { field, reason });
        let pos = |v: f32| v.is_finite() && v > 0.0;
        if !pos(self.dt) || self.dt > 0.1 {
            return err("dt", format!("must be in (0, 0.1] s, got {}", self.dt));
        }
        if !pos(self.contact_frequency) {
            return err("contact_frequency", format!("must be a positive number of Hz, got {}", self.contact_frequency));
        }
        if !self.gravity.is_finite() {
            return err("gravity", format!("must be finite, got {:?}", self.gravity));
        }
        if !pos(self.contact_offset) {
            return err("contact_offset", format!("must be positive, got {}", self.contact_offset));
        }
        if !(self.release_offset.is_finite() && self.release_offset >= self.contact_offset) {
            return err("release_offset", format!("must be ≥ contact_offset, got {}", self.release_offset));
        }
        if let GammaMode::Fixed(g) = self.gamma
            && !pos(g) {
                return err("gamma", format!("must be positive, got {g}"));
            }
        if self.patch.samples == 0 || self.patch.samples == 2 || self.patch.samples > 64 {
            // Two samples cannot be centred on C (one sits on it).
            return err("patch.samples", format!("must be 1 or 3..=64, got {}", self.patch.samples));
        }
        for (field, v) in [
            ("patch.finger_radius", self.patch.finger_radius),
            ("patch.thumb_radius", self.patch.thumb_radius),
            ("patch.palm_radius", self.patch.palm_radius),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return err(field, format!("must be finite and ≥ 0, got {v}"));
            }
        }
        if let Some(z) = self.damping_ratio
            && !(z.is_finite() && z >= 0.0) {
                return err("damping_ratio", format!("must be finite and ≥ 0, got {z}"));
            }
        if let Some(v) = self.max_penetration_speed
            && !pos(v) {
                return err("max_penetration_speed", format!("must be positive, got {v}"));
            }
        if !pos(self.probe_offset) {
            return err("probe_offset", format!("must be positive, got {}", self.probe_offset));
        }
        Ok(())
    }
}

/// Errors of [`InteractionWorld`] calls.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WorldError {
    #[error(transparent)]
    Pose(#[from] PoseError),
    #[error(transparent)]
    Object(#[from] ObjectError),
    #[error(transparent)]
    Config(#[from] ConfigError),
    #[error("{0} does not exist")]
    NoSuchHand(HandId),
    #[error("{0} does not exist")]
    NoSuchObject(ObjectId),
}

/// Pose, velocity and hand force of an object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectState {
    /// Body origin (m).
    pub position: Vec3,
    pub rotation: glam::Quat,
    /// Linear velocity of the centre of mass (m/s).
    pub linvel: Vec3,
    /// Angular velocity (rad/s).
    pub angvel: Vec3,
    /// Eq. 3.10: the sum of all hand contact forces applied last step (N).
    pub hand_force: Vec3,
    pub sleeping: bool,
}

struct ObjectSlot {
    name: String,
    body: RigidBodyHandle,
    collider: ColliderHandle,
    material: Material,
    gamma: f32,
    /// Bounding-sphere diameter (m).
    diameter: f32,
    mass: f32,
    hand_force: Vec3,
    /// Set when the object is unlocked: its contacts end at the next step
    /// and begin afresh from the hand's pose then.
    reseat: bool,
}

struct HandSlot {
    side: Side,
    pose: Option<HandPose>,
    /// The pose of the previous step, for bone velocities.
    prev: Option<HandPose>,
}

/// A rapier world plus hands that act on its objects only through Coulomb
/// friction contact forces.
pub struct InteractionWorld {
    physics: PhysicsWorld,
    config: InteractionConfig,
    objects: Vec<ObjectSlot>,
    hands: Vec<HandSlot>,
    /// Sorted by (hand, bone, object).
    contacts: Vec<Contact>,
    events: Vec<ContactEvent>,
    time: f64,
    scratch: Scratch,
    /// Every call so far, when recording.
    recording: Option<Session>,
}

fn contact_key(c: &Contact) -> (HandId, usize, ObjectId) {
    (c.hand, c.bone.index(), c.object)
}

/// Closest features between a bone and an object within `prediction` (m).
///
/// A capsule is queried as its axis segment with the radius added back:
/// parry's GJK on the rounded capsule itself was measured to overestimate
/// distances by up to 1 mm, while the segment query is exact.
fn proximity(bone: &BoneShape, obj_pose: &Pose, obj_shape: &dyn Shape, prediction: f32) -> Option<Proximity> {
    let (hit, radius) = match bone {
        BoneShape::Capsule(c) => {
            let axis = Segment::new(c.a, c.b);
            (query::contact(&Pose::identity(), &axis, obj_pose, obj_shape, prediction + c.radius), c.radius)
        }
        BoneShape::Palm(p) => {
            let cube = Cuboid::new(p.half_extents);
            (query::contact(&Pose::from_parts(p.center, p.rotation), &cube, obj_pose, obj_shape, prediction), 0.0)
        }
    };
    let hit = hit.ok().flatten()?;
    let object_normal = hit.normal2.try_normalize()?;
    let prox = Proximity {
        bone_point: hit.point1 - radius * object_normal,
        object_point: hit.point2,
        object_normal,
        distance: hit.dist - radius,
    };
    (prox.bone_point.is_finite() && prox.object_point.is_finite() && prox.distance.is_finite())
        .then_some(prox)
}

fn bone_aabb(bone: &BoneShape) -> Aabb {
    match bone {
        BoneShape::Capsule(c) => {
            Aabb::new(c.a.min(c.b), c.a.max(c.b)).loosened(c.radius)
        }
        BoneShape::Palm(p) => Cuboid::new(p.half_extents).compute_aabb(&Pose::from_parts(p.center, p.rotation)),
    }
}

impl InteractionWorld {
    /// An empty world.
    pub fn new(config: InteractionConfig) -> Result<Self, WorldError> {
        config.validate()?;
        let mut physics = PhysicsWorld::new();
        physics.gravity = config.gravity;
        physics.integration_parameters.dt = config.dt;
        let p = &mut physics.integration_parameters;
        p.friction_model = match config.object_friction {
            ObjectFriction::Coulomb => rapier3d::dynamics::FrictionModel::Coulomb,
            ObjectFriction::Simplified => rapier3d::dynamics::FrictionModel::Simplified,
        };
        let frequency = config.contact_frequency.min(1.0 / config.dt);
        p.contact_softness.natural_frequency = frequency;
        p.static_contact_softness.natural_frequency = p.static_contact_softness.natural_frequency.max(frequency);
        Ok(InteractionWorld {
            physics,
            config,
            objects: Vec::new(),
            hands: Vec::new(),
            contacts: Vec::new(),
            events: Vec::new(),
            time: 0.0,
            scratch: Scratch::default(),
            recording: None,
        })
    }

    /// An empty world that records every call made on it (see
    /// [`crate::session`]).
    pub fn new_recording(config: InteractionConfig) -> Result<Self, WorldError> {
        let mut world = Self::new(config)?;
        world.recording = Some(Session::new(config));
        Ok(world)
    }

    /// The session recorded so far, leaving recording on.
    pub fn recording(&self) -> Option<&Session> {
        self.recording.as_ref()
    }

    /// Stops recording and returns the session.
    pub fn take_recording(&mut self) -> Option<Session> {
        self.recording.take()
    }

    fn record(&mut self, call: impl FnOnce() -> Call) {
        if let Some(session) = self.recording.as_mut() {
            session.calls.push(call());
        }
    }

    pub fn config(&self) -> &InteractionConfig {
        &self.config
    }

    /// The rapier world, for reading and for advanced set-up (joints,
    /// solver parameters). Hands never appear in it.
    pub fn physics(&self) -> &PhysicsWorld {
        &self.physics
    }

    /// Mutable access to the rapier world, for solver settings, joints and
    /// scripted set-up. Do not insert hand bones (a colliding bone would
    /// bypass the friction model), and do not remove the bodies or colliders
    /// of objects added with [`Self::add_object`]: the world indexes them.
    pub fn physics_mut(&mut self) -> &mut PhysicsWorld {
        &mut self.physics
    }

    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Adds static scenery (ground, tables). Hands do not touch it.
    pub fn add_static(&mut self, desc: &StaticDesc) -> Result<ColliderHandle, WorldError> {
        let shape = desc.validate()?;
        let collider = ColliderBuilder::new(shape)
            .position(Pose::from_parts(desc.position, desc.rotation))
            .friction(desc.friction);
        let body = self.physics.insert_body(RigidBodyBuilder::fixed());
        self.record(|| Call::AddStatic(desc.clone()));
        Ok(self.physics.insert_collider(collider, Some(body)))
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
        let shape = desc.validate()?;
        let diameter = 2.0 * shape.compute_local_bounding_sphere().radius();
        let gamma = match desc.gamma.unwrap_or(self.config.gamma) {
            GammaMode::Fixed(g) => g,
            GammaMode::Auto => friction::auto_gamma(
                desc.mass,
                self.config.gravity.length(),
                desc.material.skin.static_mu,
                diameter,
            ),
        };
        if !(gamma.is_finite() && gamma > 0.0) {
            return Err(ObjectError::new(
                &desc.name,
                "gamma",
                format!("automatic γ is {gamma}: needs gravity, μ_st and size > 0"),
            )
            .into());
        }
        let body = self.physics.insert_body(
            RigidBodyBuilder::dynamic().pose(Pose::from_parts(desc.position, desc.rotation)),
        );
        let collider = ColliderBuilder::new(shape).mass(desc.mass).friction(desc.material.surface_friction);
        let collider = self.physics.insert_collider(collider, Some(body));
        let id = ObjectId(self.objects.len() as u32);
        self.objects.push(ObjectSlot {
            name: desc.name.clone(),
            body,
            collider,
            material: desc.material.clone(),
            gamma,
            diameter,
            mass: desc.mass,
            hand_force: Vec3::ZERO,
            reseat: false,
        });
        self.record(|| Call::AddObject(desc.clone()));
        Ok(id)
    }

    /// Adds a hand with no pose yet (untracked).
    pub fn add_hand(&mut self, side: Side) -> HandId {
        self.hands.push(HandSlot { side, pose: None, prev: None });
        self.record(|| Call::AddHand(side));
        HandId(self.hands.len() as u32 - 1)
    }

    /// Sets a hand's tracked pose for the next step. Call it every step
    /// (interpolating a slower tracker) so bone velocities are smooth.
    /// A rejected pose leaves the world untouched.
    pub fn set_hand_pose(&mut self, hand: HandId, pose: &HandPose) -> Result<(), WorldError> {
        let slot = self.hands.get_mut(hand.0 as usize).ok_or(WorldError::NoSuchHand(hand))?;
        pose.validate(hand.0)?;
        slot.pose = Some(pose.clone());
        self.record(|| Call::SetHandPose(hand.0, Box::new(pose.clone())));
        Ok(())
    }

    /// Marks a hand as untracked: its contacts end at the next step.
    pub fn clear_hand_pose(&mut self, hand: HandId) -> Result<(), WorldError> {
        let slot = self.hands.get_mut(hand.0 as usize).ok_or(WorldError::NoSuchHand(hand))?;
        slot.pose = None;
        slot.prev = None;
        self.record(|| Call::ClearHandPose(hand.0));
        Ok(())
    }

    /// The hand's current pose, if tracked.
    pub fn hand_pose(&self, hand: HandId) -> Option<&HandPose> {
        self.hands.get(hand.0 as usize)?.pose.as_ref()
    }

    pub fn hand_side(&self, hand: HandId) -> Option<Side> {
        self.hands.get(hand.0 as usize).map(|h| h.side)
    }

    pub fn hand_count(&self) -> usize {
        self.hands.len()
    }

    pub fn object_count(&self) -> usize {
        self.objects.len()
    }

    pub fn object_name(&self, id: ObjectId) -> Option<&str> {
        self.objects.get(id.0 as usize).map(|o| o.name.as_str())
    }

    /// The contact stiffness γ in use for an object (N/m).
    pub fn object_gamma(&self, id: ObjectId) -> Option<f32> {
        self.objects.get(id.0 as usize).map(|o| o.gamma)
    }

    /// The object's rapier body, for reading or scripted set-up.
    pub fn object_body(&self, id: ObjectId) -> Option<RigidBodyHandle> {
        self.objects.get(id.0 as usize).map(|o| o.body)
    }

    /// Holds an object fixed in place (`true`) or lets it move again: a
    /// fixture, e.g. to keep an object where a recorded hand will close on
    /// it. A locked object still has contacts and their forces computed;
    /// they just do not move it.
    pub fn set_object_locked(&mut self, id: ObjectId, locked: bool) -> Result<(), WorldError> {
        let slot = self.objects.get(id.0 as usize).ok_or(WorldError::NoSuchObject(id))?;
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
        let slot = self.objects.get_mut(id.0 as usize).ok_or(WorldError::NoSuchObject(id))?;
        slot.reseat = true;
        self.record(|| Call::ReseatContacts(id.0));
        Ok(())
    }

    /// Whether the hand contacts on an object could hold it up, without
    /// flinging it: some two pressing contacts push from roughly opposite
    /// sides (normals more than 120° apart), their static friction,
    /// μ_st·Σ f_n, exceeds the object's weight, and the hand force plus
    /// gravity would accelerate it by less than g.
    pub fn is_gripped(&self, id: ObjectId) -> bool {
        let Some(slot) = self.objects.get(id.0 as usize) else { return false };
        let pressing: Vec<&Contact> =
            self.contacts.iter().filter(|c| c.object == id && c.normal_force > 0.0).collect();
        let opposed = pressing
            .iter()
            .enumerate()
            .any(|(i, a)| pressing[i + 1..].iter().any(|b| a.normal.dot(b.normal) < -0.5));
        let friction: f32 = pressing.iter().map(|c| c.normal_force).sum::<f32>() * slot.material.skin.static_mu;
        let weight = slot.mass * self.config.gravity.length();
        let net = slot.hand_force + slot.mass * self.config.gravity;
        opposed && friction > weight && net.length() < weight
    }

    /// The current state of an object.
    pub fn object_state(&self, id: ObjectId) -> Result<ObjectState, WorldError> {
        let slot = self.objects.get(id.0 as usize).ok_or(WorldError::NoSuchObject(id))?;
        let body = &self.physics.bodies[slot.body];
        Ok(ObjectState {
            position: body.translation(),
            rotation: *body.rotation(),
            linvel: body.linvel(),
            angvel: body.angvel(),
            hand_force: slot.hand_force,
            sleeping: body.is_sleeping(),
        })
    }

    /// All active contacts after the last step, ordered by (hand, bone, object).
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    /// Contact begin/end events of the last step.
    pub fn events(&self) -> &[ContactEvent] {
        &self.events
    }

    /// One full step: hand forces, then the physics engine.
    pub fn step(&mut self) {
        self.apply_hand_forces();
        self.step_physics();
    }

    /// Advances rapier by `dt` with the forces set by
    /// [`Self::apply_hand_forces`]: gravity and object–object contacts are
    /// the engine's.
    pub fn step_physics(&mut self) {
        self.record(|| Call::Step);
        self.physics.step();
        self.time += self.config.dt as f64;
        for hand in self.hands.iter_mut() {
            hand.prev = hand.pose.clone();
        }
    }

    /// An object's contact damping `c` before the stability limit (N·s/m).
    fn nominal_damping(&self, slot: &ObjectSlot) -> f32 {
        self.config.damping_ratio.map_or(0.0, |z| friction::damping_coefficient(slot.gamma, slot.mass, z))
    }

    /// The object as the contact law sees it this step, with its contact
    /// stiffness and damping scaled by the stability limit.
    fn object_view(&self, index: usize, limit: StabilityScale) -> ObjectView<'_> {
        let slot = &self.objects[index];
        let body = &self.physics.bodies[slot.body];
        let collider = &self.physics.colliders[slot.collider];
        let damping = self.nominal_damping(slot);
        ObjectView {
            id: ObjectId(index as u32),
            pose: *collider.position(),
            shape: collider.shape(),
            linvel: body.linvel(),
            angvel: body.angvel(),
            center_of_mass: body.center_of_mass(),
            gamma: slot.gamma * limit.stiffness,
            damping: damping * limit.damping,
            max_depth: self.config.force_cap.then_some(friction::MAX_PENETRATION_FRACTION * slot.diameter),
            mu: slot.material.skin,
        }
    }

    /// The stability limit of each object for this step's contacts.
    ///
    /// Contact springs and dampers are explicit forces, integrated by rapier
    /// with symplectic Euler. A set of springs Σγ on a body is stable while
    /// `dt²·Σ γ_i w_i` stays well below 4, where `w_i = 1/m + |r_i|²/I_min`
    /// bounds how much the contact point at lever arm `r_i` accelerates per
    /// newton (linear plus rotational). The dampers need `dt·Σ c_i w_i < 2`.
    /// Both sums are kept ≤ 1; a light object in a many-finger grasp gets a
    /// proportionally softer γ (it then needs deeper fingers for the same
    /// force: the friction threshold, a force ratio, is unchanged).
    fn stability_limits(&self, contacts: &[(Contact, Option<Proximity>, BoneMotion)]) -> Vec<StabilityScale> {
        let dt = self.config.dt;
        let mut sums = vec![(0.0f32, 0.0f32); self.objects.len()];
        for (contact, _, _) in contacts {
            let o = contact.object.0 as usize;
            let slot = &self.objects[o];
            let body = &self.physics.bodies[slot.body];
            let inv_inertia = body.mass_properties().local_mprops.inv_principal_inertia.max_element();
            let r = contact.point - body.center_of_mass();
            let w = 1.0 / slot.mass + r.length_squared() * inv_inertia;
            let damping = self.nominal_damping(slot);
            sums[o].0 += slot.gamma * w;
            sums[o].1 += damping * w;
        }
        sums.into_iter()
            .map(|(k, c)| StabilityScale {
                stiffness: (1.0 / (k * dt * dt)).min(1.0),
                damping: (1.0 / (c * dt)).min(1.0),
            })
            .collect()
    }

    fn settings(&self) -> LawSettings {
        LawSettings {
            dt: self.config.dt,
            kinetic: self.config.kinetic,
            max_penetration_speed: self.config.max_penetration_speed,
            probe_offset: self.config.probe_offset,
            patch: self.config.patch,
        }
    }

    fn motion(&self, hand: HandId, bone: Bone) -> Option<BoneMotion> {
        let slot = self.hands.get(hand.0 as usize)?;
        let now = slot.pose.as_ref()?;
        let prev = slot.prev.as_ref().unwrap_or(now);
        Some(BoneMotion { now: now.bone(bone), prev: prev.bone(bone), palm_now: now.palm, palm_prev: prev.palm })
    }

    fn push_event(&mut self, kind: ContactEventKind, c: &Contact) {
        self.events.push(ContactEvent {
            kind,
            hand: c.hand,
            bone: c.bone,
            object: c.object,
            point: c.point,
            time: self.time,
        });
    }

    /// Applies every finite force at its point; returns their sum.
    fn apply(&mut self, object: ObjectId, forces: &[(Vec3, Vec3)]) {
        let slot = &mut self.objects[object.0 as usize];
        let body = &mut self.physics.bodies[slot.body];
        for &(f, at) in forces {
            if f.is_finite() && at.is_finite() {
                body.add_force_at_point(f, at, true);
                slot.hand_force += f;
            }
        }
    }

    /// Finds, updates, begins and ends contacts, and sets this step's hand
    /// forces on the objects. The first half of [`Self::step`].
    pub fn apply_hand_forces(&mut self) {
        self.events.clear();
        for slot in self.objects.iter_mut() {
            let body = &mut self.physics.bodies[slot.body];
            body.reset_forces(false);
            body.reset_torques(false);
            slot.hand_force = Vec3::ZERO;
        }
        let settings = self.settings();
        let no_limit = StabilityScale { stiffness: 1.0, damping: 1.0 };

        // 1. Existing contacts. A contact that was static last step needs no
        //    distance query (see `Contact::update`); the others must still be
        //    within the release offset.
        let release = self.config.release_offset;
        let mut live: Vec<(Contact, Option<Proximity>, BoneMotion)> = Vec::with_capacity(self.contacts.len());
        for contact in std::mem::take(&mut self.contacts) {
            if self.objects[contact.object.0 as usize].reseat {
                self.push_event(ContactEventKind::Ended, &contact);
                continue;
            }
            let Some(motion) = self.motion(contact.hand, contact.bone) else {
                self.push_event(ContactEventKind::Ended, &contact);
                continue;
            };
            if contact.state == FrictionState::Static {
                live.push((contact, None, motion));
                continue;
            }
            let view = self.object_view(contact.object.0 as usize, no_limit);
            match proximity(&motion.now, &view.pose, view.shape, release).filter(|p| p.distance <= release) {
                Some(prox) => live.push((contact, Some(prox), motion)),
                None => self.push_event(ContactEventKind::Ended, &contact),
            }
        }

        for slot in self.objects.iter_mut() {
            slot.reseat = false;
        }

        // 2. New contacts: bones within the contact offset of an object.
        let kept = live.len();
        let object_boxes: Vec<Aabb> = self
            .objects
            .iter()
            .map(|o| self.physics.colliders[o.collider].compute_aabb())
            .collect();
        let mut near_hand = Vec::with_capacity(object_boxes.len());
        let mut bone_reach = Vec::with_capacity(BONES_PER_HAND);
        for h in 0..self.hands.len() {
            let hand = HandId(h as u32);
            // Bones' reach, then the objects near the whole hand: most
            // objects of a scene are far from any hand.
            bone_reach.clear();
            for b in 0..BONES_PER_HAND {
                if let Some(motion) = self.motion(hand, Bone::from_index(b)) {
                    bone_reach.push((b, motion, bone_aabb(&motion.now).loosened(self.config.contact_offset)));
                }
            }
            let Some(hand_reach) = bone_reach.iter().map(|r| r.2).reduce(|a, b| a.merged(&b)) else { continue };
            near_hand.clear();
            near_hand.extend((0..object_boxes.len()).filter(|&o| hand_reach.intersects(&object_boxes[o])));
            for &(b, motion, reach) in &bone_reach {
                let bone = Bone::from_index(b);
                for &o in &near_hand {
                    let key = (hand, b, ObjectId(o as u32));
                    if !reach.intersects(&object_boxes[o])
                        || live[..kept].binary_search_by_key(&key, |(c, _, _)| contact_key(c)).is_ok()
                    {
                        continue;
                    }
                    let view = self.object_view(o, no_limit);
                    let Some(prox) = proximity(&motion.now, &view.pose, view.shape, self.config.contact_offset)
                        .filter(|p| p.distance <= self.config.contact_offset)
                    else {
                        continue;
                    };
                    let contact = Contact::begin(hand, bone, &prox, &motion, &view, &settings);
                    live.push((contact, Some(prox), motion));
                }
            }
        }

        // 3. Forces, under each object's stability limit.
        let limits = self.stability_limits(&live);
        let mut scratch = std::mem::take(&mut self.scratch);
        let mut contacts = Vec::with_capacity(live.len());
        for (i, (mut contact, prox, motion)) in live.into_iter().enumerate() {
            let o = contact.object.0 as usize;
            let view = self.object_view(o, limits[o]);
            let mut query = || {
                proximity(&motion.now, &view.pose, view.shape, release).filter(|p| p.distance <= release)
            };
            let alive = contact.update(prox, &mut query, &motion, &view, &settings, &mut scratch);
            if !alive {
                self.push_event(ContactEventKind::Ended, &contact);
                continue;
            }
            if i >= kept {
                self.push_event(ContactEventKind::Began, &contact);
            }
            self.apply(contact.object, &scratch.forces);
            contacts.push(contact);
        }
        contacts.sort_by_key(contact_key);
        self.contacts = contacts;
        self.scratch = scratch;
    }
}

/// Factors (≤ 1) on an object's contact stiffness and damping that keep the
/// explicit contact forces stable; see [`InteractionWorld::stability_limits`].
#[derive(Debug, Clone, Copy)]
struct StabilityScale {
    stiffness: f32,
    damping: f32,
}
