//! A Bevy plugin for coulomb-hands: tracked hands grasp and push the
//! objects of an interaction world through friction contact forces, in a
//! Bevy app.
//!
//! The app adds [`CoulombHandsPlugin`] and inserts a
//! [`physics::HandPhysics`] resource (a world, its hands' sources and
//! observers). Hands its own systems track are entities with
//! [`input::AppHand`], whose [`input::HandInput`] they write each frame.
//! Then, every frame, in [`RunFixedMainLoop`] (before `Update`):
//!
//! 1. [`HandPhysicsSystems::Prepare`]: entities are spawned for new objects
//!    and hands, and the app hands' inputs
//!    handed to the world;
//! 2. [`HandPhysicsSystems::Step`]: the plugin's own schedule,
//!    [`clock::HandPhysicsStep`], runs once per world `dt` of the frame's
//!    virtual time, each run one physics step through the core's driver
//!    ([`coulomb_hands::run::drive::Driver::step`]). Each step writes its
//!    contact events as [`contacts::ContactBegan`] and
//!    [`contacts::ContactEnded`] messages, and triggers
//!    [`contacts::ObjectTouched`] and [`contacts::ObjectReleased`] on the
//!    objects' entities;
//! 3. [`HandPhysicsSystems::Sync`]: the objects' and bones' `Transform`s
//!    and the [`contacts::Contacts`] resource are set from the world.
//!
//! The physics keeps its own clock (`Time<`[`clock::HandClock`]`>`): the
//! app's `Time<Fixed>` and fixed schedules keep Bevy's defaults.
//!
//! The core uses glam 0.33 and Bevy glam 0.32; [`convert`] is the one
//! place where they meet. The core's ids and kinds are reflected through
//! the remote wrappers of [`reflect`].

pub mod clock;
pub mod contacts;
pub mod convert;
pub mod entities;
pub mod input;
pub mod physics;
pub mod prelude;
pub mod reflect;

use bevy::app::{RunFixedMainLoop, RunFixedMainLoopSystems};
use bevy::ecs::schedule::{Schedule, SingleThreadedExecutor};
use bevy::prelude::*;

/// Adds the physics' schedule, clock, systems, messages and resources to
/// an app.
#[derive(Debug, Clone, Copy, Default)]
pub struct CoulombHandsPlugin;

/// The plugin's systems, to order an app's own around them.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HandPhysicsSystems {
    /// Before the fixed loop: entities spawned, app hands' inputs handed
    /// to the world.
    Prepare,
    /// Before the fixed loop, after `Prepare`: the frame's physics steps,
    /// each a run of [`clock::HandPhysicsStep`]; inside that schedule, the
    /// step itself.
    Step,
    /// After the fixed loop: transforms and contacts set from the world.
    Sync,
}

impl Plugin for CoulombHandsPlugin {
    fn build(&self, app: &mut App) {
        // A thousand steps a second: the multi-threaded executor's cost per
        // schedule run (about 0.05 ms) would be ten times the physics
        // step's, so the step's own schedule runs on one thread.
        let mut step = Schedule::new(clock::HandPhysicsStep);
        step.set_executor(SingleThreadedExecutor::new());
        app.add_schedule(step)
            .insert_resource(Time::<clock::HandClock>::default())
            .add_message::<contacts::ContactBegan>()
            .add_message::<contacts::ContactEnded>()
            .add_message::<physics::HandPhysicsReplaced>()
            .init_resource::<contacts::Contacts>()
            .init_resource::<contacts::Touched>()
            .init_resource::<entities::InteractionEntities>()
            .register_type::<entities::InteractionObject>()
            .register_type::<entities::InteractionHand>()
            .register_type::<entities::HandBone>()
            .register_type::<input::AppHand>()
            .register_type::<input::HandInput>()
            .register_type::<physics::HandPhysics>()
            .register_type::<contacts::Contacts>()
            .register_type::<entities::InteractionEntities>()
            .register_type::<Time<clock::HandClock>>()
            .configure_sets(
                RunFixedMainLoop,
                (
                    (HandPhysicsSystems::Prepare, HandPhysicsSystems::Step)
                        .chain()
                        .in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
                    HandPhysicsSystems::Sync.in_set(RunFixedMainLoopSystems::AfterFixedMainLoop),
                ),
            )
            .add_systems(
                RunFixedMainLoop,
                (
                    (entities::spawn_entities, input::push_inputs)
                        .chain()
                        .in_set(HandPhysicsSystems::Prepare),
                    clock::run_steps.in_set(HandPhysicsSystems::Step),
                    (entities::sync_transforms, contacts::sync_contacts)
                        .in_set(HandPhysicsSystems::Sync),
                ),
            )
            .add_systems(
                clock::HandPhysicsStep,
                (entities::spawn_entities, contacts::step_physics)
                    .chain()
                    .in_set(HandPhysicsSystems::Step),
            );
    }
}
