//! The interaction pipeline: hand poses → contacts → friction forces →
//! rapier step. [`InteractionWorld`] is the crate's public entry point.
//!
//! * [`config`]: [`InteractionConfig`], its validation and the rapier
//!   parameters it implies;
//! * [`method`]: the methods the evaluation compares, as configs;
//! * [`world`]: the world's API (add objects and hands, set poses, read
//!   contacts, events and states); the world's state, [`InteractionWorld`]
//!   and its slots, is defined here, so that every stage and the API read
//!   it from their parent, and import no sibling that imports them back;
//! * `error.rs`: [`WorldError`];
//! * [`step`]: one step, stage by stage (the stability limit of explicit
//!   contact springs, stage 5, among them);
//! * `firewall.rs`: the NaN firewall, the one gate of every value that
//!   enters rapier, and [`InteractionWorld::first_non_finite`];
//! * [`record`]: the hook that sees every call, for session recording;
//! * [`host`]: host-engine mode, where a host's bodies take the hands'
//!   wrenches, and [`frame`]: a host's frame and units, converted.
//!
//! Guarantees:
//! * Hand bones are not bodies in the physics engine, so there is never an
//!   engine collision response between a bone and an object: bones act only
//!   through the forces computed in [`crate::contact`].
//! * Every force handed to rapier is finite; the config, poses and object
//!   descriptions are validated before they touch the world, all in
//!   `firewall.rs`, and a rejected call leaves the world as it was.
//! * Same calls, same results: all iteration is in a fixed order.

pub mod config;
mod error;
pub(crate) mod firewall;
pub mod frame;
pub mod host;
pub mod method;
pub mod record;
pub mod step;
pub mod world;

pub use config::{
    ConfigError, ENGINE_SUBSTEPS, HAND_SUBSTEPS, HAPTIC_STEP, InteractionConfig, ObjectFriction,
    SPECULATIVE_SPEED,
};
pub use error::WorldError;
pub use host::{HandWrench, HostBody};
pub use method::Method;
pub use record::{Call, Recorder};
pub use world::ObjectState;

use crate::contact::{Contact, ContactEvent};
use crate::hand::acting::ActingHand;
use crate::hand::{HandPose, Side};
use crate::scene::Material;
use glam::Vec3;
use rapier3d::math::Pose;
use rapier3d::prelude::{
    ColliderHandle, PhysicsWorld, RigidBody, RigidBodyHandle, RigidBodySet, SharedShape,
};
use step::StepScratch;

/// What the world keeps per object besides rapier's body.
pub(in crate::pipeline) struct ObjectSlot {
    pub name: String,
    pub body: RigidBodyHandle,
    pub collider: ColliderHandle,
    pub material: Material,
    /// Contact stiffness γ (N/m) before the stability limit.
    pub gamma: f32,
    /// Bounding-sphere diameter (m).
    pub diameter: f32,
    /// The farthest any of its points is from its origin (m).
    pub reach: f32,
    /// Mass (kg).
    pub mass: f32,
    /// Eq. 3.10 of the last step (N).
    pub hand_force: Vec3,
    /// Set by [`InteractionWorld::reseat_contacts`]: its contacts end at
    /// the next step and begin afresh from the hand's pose then.
    pub reseat: bool,
    /// Whether it is in [`InteractionWorld::forced`].
    pub forced: bool,
    /// Whether a host has set its state since rapier last stepped it
    /// ([`InteractionWorld::hosted`]), and the mass properties it gave
    /// last.
    pub hosted: bool,
    pub host_mass: Option<host::MassState>,
    /// While hosted: the pose the host gave last and its centre of mass
    /// in the world (m). Its body keeps only its velocities, mass and the
    /// hands' forces: rapier's `set_position` would also recompute a world
    /// inertia nobody reads in this mode. [`ObjectSlot::pose`] and
    /// [`ObjectSlot::center_of_mass`] read whichever holds.
    pub host_pose: Pose,
    pub host_com: Vec3,
    /// Whether a hand pushed it this step: stage 7 set a force on its
    /// body and woke it (its contacts may all have hovered).
    pub pushed: bool,
    /// The substeps `set_substeps` added to its body this step, to be given
    /// back in stage 1.
    pub raised: Option<step::Raised>,
    /// Its grab, for the grab baselines.
    pub grab: step::GrabSlot,
    /// Set by [`InteractionWorld::remove_object`]: its body and collider
    /// are gone from rapier, and its id names nothing.
    pub removed: bool,
    /// Its motion and hand wrench when its springs last stepped by backward
    /// Euler (`step/implicit.rs`), from which the next step tells the other
    /// forces on it.
    pub implicit: Option<step::ImplicitMemory>,
}

impl ObjectSlot {
    /// Its body's origin: the host's pose while hosted, else its body's.
    pub(in crate::pipeline) fn pose(&self, bodies: &RigidBodySet) -> Pose {
        if self.hosted { self.host_pose } else { *bodies[self.body].position() }
    }

    /// Its centre of mass in the world (m), of `body`, its own.
    pub(in crate::pipeline) fn center_of_mass(&self, body: &RigidBody) -> Vec3 {
        // The place chosen, then one load: this is read per contact.
        *if self.hosted { &self.host_com } else { &body.mass_properties().world_com }
    }
}

/// What the world keeps per hand.
pub(in crate::pipeline) struct HandSlot {
    pub side: Side,
    /// The hand that acts: the tracked hand through the config's tracking
    /// filter, from the step's first stage (`step/follow.rs`).
    pub pose: Option<HandPose>,
    /// The pose of the previous step, for bone velocities.
    pub prev: Option<HandPose>,
    /// The pose the tracker last set.
    pub tracked: Option<HandPose>,
    /// The tracking filter's state, with the config's filter.
    pub acting: Option<ActingHand>,
    /// Which pose `pose` is, and which `prev`: a count of the poses set,
    /// so that what was computed from a pose is known to hold for it.
    pub pose_mark: u64,
    pub prev_mark: u64,
}

/// A rapier world plus hands that act on its objects only through Coulomb
/// friction contact forces.
pub struct InteractionWorld {
    pub(in crate::pipeline) physics: PhysicsWorld,
    pub(in crate::pipeline) config: InteractionConfig,
    pub(in crate::pipeline) objects: Vec<ObjectSlot>,
    /// Per object, the shape its hand contacts query instead of its
    /// collider's (a mesh's exact triangles), or `None`. Apart from the
    /// slots so a step's object view may borrow it while the slots change.
    pub(in crate::pipeline) hand_shapes: Vec<Option<SharedShape>>,
    pub(in crate::pipeline) hands: Vec<HandSlot>,
    /// Sorted by (object, hand, bone): each object's contacts are one run.
    pub(in crate::pipeline) contacts: Vec<Contact>,
    pub(in crate::pipeline) events: Vec<ContactEvent>,
    pub(in crate::pipeline) time: f64,
    pub(in crate::pipeline) scratch: StepScratch,
    /// Objects added or put down since rapier's last step: its broad phase
    /// has not seen them where they are (`step/near.rs`).
    pub(in crate::pipeline) unindexed: Vec<u32>,
    /// Objects whose state a host sets (`host.rs`), which rapier's broad
    /// phase never sees move: the contact search takes their exact boxes,
    /// and `host_moved` (m), the farthest the host moved any of them
    /// since the last step, bounds how far its answers drift.
    pub(in crate::pipeline) hosted: Vec<u32>,
    pub(in crate::pipeline) host_moved: f32,
    /// Objects given hand forces this step, whose forces the next step
    /// clears (`step/clear.rs`), each once ([`ObjectSlot::forced`]).
    pub(in crate::pipeline) forced: Vec<u32>,
    /// Objects whose contacts end at the next step ([`ObjectSlot::reseat`]).
    pub(in crate::pipeline) reseating: Vec<u32>,
    /// Objects a grab baseline held after the last step, ascending: with
    /// the touched ones, all that stage 8 (`step/grab.rs`) visits.
    pub(in crate::pipeline) grabbed: Vec<u32>,
    /// Whether a program may have written to rapier ([`Self::physics_mut`])
    /// since the last step began: then every body's forces are cleared.
    pub(in crate::pipeline) external: bool,
    pub(in crate::pipeline) recorder: Option<Box<dyn Recorder>>,
}
