//! The interaction pipeline: hand poses → contacts → friction forces →
//! rapier step. [`InteractionWorld`] is the crate's public entry point.
//!
//! * [`config`]: [`InteractionConfig`], its validation and the rapier
//!   parameters it implies;
//! * [`method`]: the methods the evaluation compares, as configs;
//! * [`world`]: the world's API (add objects and hands, set poses, read
//!   contacts, events and states);
//! * [`step`]: one step, stage by stage;
//! * `stability.rs`: the stability limit of explicit contact springs;
//! * `firewall.rs`: the NaN firewall, the one gate of every value that
//!   enters rapier, and [`InteractionWorld::first_non_finite`];
//! * [`record`]: the hook that sees every call, for session recording.
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
pub(crate) mod firewall;
pub mod method;
pub mod record;
pub(crate) mod stability;
pub mod step;
pub mod world;

pub use config::{
    ConfigError, ENGINE_SUBSTEPS, HAND_SUBSTEPS, HAPTIC_STEP, InteractionConfig, ObjectFriction,
    SPECULATIVE_SPEED,
};
pub use method::Method;
pub use record::{Call, Recorder};
pub use world::{InteractionWorld, ObjectState, WorldError};
