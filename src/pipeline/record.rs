//! The world's one outward hook: a [`Recorder`] sees every call that
//! changes the world, in order, the way rapier's pipeline knows only its
//! `EventHandler` and `PhysicsHooks`. Recording sessions to files
//! ([`crate::output::session`]) is built on it.

use crate::hand::{HandPose, Side};
use crate::scene::{ObjectDesc, StaticDesc};
use glam::{Quat, Vec3};

/// One call that changed a world, as data. Hands and objects are named by
/// their index (`HandId.0`, `ObjectId.0`).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Call {
    /// [`crate::InteractionWorld::add_static`].
    AddStatic(StaticDesc),
    /// [`crate::InteractionWorld::add_object`].
    AddObject(ObjectDesc),
    /// [`crate::InteractionWorld::add_hand`].
    AddHand(Side),
    /// [`crate::InteractionWorld::set_hand_pose`].
    SetHandPose(u32, Box<HandPose>),
    /// [`crate::InteractionWorld::clear_hand_pose`].
    ClearHandPose(u32),
    /// [`crate::InteractionWorld::set_object_locked`].
    SetObjectLocked(u32, bool),
    /// [`crate::InteractionWorld::reseat_contacts`].
    ReseatContacts(u32),
    /// [`crate::InteractionWorld::place_object`].
    PlaceObject(u32, Vec3, Quat),
    /// [`crate::InteractionWorld::remove_object`].
    RemoveObject(u32),
    /// [`crate::InteractionWorld::step_physics`], which ends every step.
    Step,
    /// [`crate::InteractionWorld::set_host_body`].
    SetHostBody(u32, super::host::HostBody),
    /// [`crate::InteractionWorld::host_step`], which ends a host-mode step.
    HostStep,
}

/// Sees every call that changes a world, after the world accepted it.
/// Calls the world rejected are not seen. It is `'static` so the world can
/// hand it back by type ([`crate::InteractionWorld::take_recorder`]), and
/// `Send + Sync` so a world that records can still live in an app's
/// resource.
pub trait Recorder: std::any::Any + Send + Sync {
    /// One accepted call.
    fn record(&mut self, call: &Call);
}
