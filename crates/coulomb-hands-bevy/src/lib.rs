//! A Bevy plugin for coulomb-hands: tracked hands grasp and push the
//! objects of an interaction world through friction contact forces, in a
//! Bevy app.
//!
//! The app adds [`CoulombHandsPlugin`] and inserts a
//! [`physics::HandPhysics`] resource (a world, its hands' sources and
//! observers). Objects it spawns are entities with an
//! [`objects::ObjectDescription`] and a `Transform`; hands its own systems
//! track are entities with [`input::AppHand`], whose [`input::HandInput`]
//! they write each frame. Then, every frame, in [`RunFixedMainLoop`]
//! (before `Update`; or in the schedule given to
//! [`CoulombHandsPlugin::new`]):
//!
//! 1. [`HandPhysicsSystems::Prepare`]: entities are spawned for the
//!    world's new objects and hands, the app's new objects and hands are
//!    added to the world, and the app hands' inputs handed to it;
//! 2. [`HandPhysicsSystems::Step`]: the plugin's own schedule,
//!    [`clock::HandPhysicsStep`], runs once per world `dt` of the frame's
//!    time, each run one physics step ([`WorldStep`]) through the core's
//!    driver ([`coulomb_hands::run::drive::Driver::step`]). Each step
//!    writes its contact events as [`contacts::ContactBegan`] and
//!    [`contacts::ContactEnded`] messages, and triggers
//!    [`contacts::ObjectTouched`] and [`contacts::ObjectReleased`] on the
//!    objects' entities;
//! 3. [`HandPhysicsSystems::Sync`]: the objects' and bones' `Transform`s
//!    and the [`contacts::Contacts`] resource are set from the world.
//!
//! Despawning an object's entity removes the object from the world, at
//! once (an observer of its [`entities::InteractionObject`]'s removal).
//! The physics keeps its own clock (`Time<`[`clock::HandClock`]`>`): the
//! app's `Time<Fixed>` and fixed schedules keep Bevy's defaults. A step
//! allocates nothing.
//!
//! The core uses glam 0.33 and Bevy glam 0.32; [`convert`] is the one
//! place where they meet. The core's ids and kinds are reflected through
//! the remote wrappers of [`reflect`].

pub mod clock;
pub mod contacts;
pub mod convert;
pub mod entities;
pub mod input;
mod link;
pub mod objects;
pub mod physics;
pub mod prelude;
pub mod reflect;

use bevy::app::{RunFixedMainLoop, RunFixedMainLoopSystems};
use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::{Schedule, ScheduleLabel, SingleThreadedExecutor};
use bevy::prelude::*;

/// Adds the physics' schedule, clock, systems, messages and resources to
/// an app.
#[derive(Debug, Clone, Copy)]
pub struct CoulombHandsPlugin {
    /// Where [`HandPhysicsSystems`] run; `None`: around Bevy's fixed loop.
    schedule: Option<Interned<dyn ScheduleLabel>>,
}

impl Default for CoulombHandsPlugin {
    /// The plugin in [`RunFixedMainLoop`]: links and steps before Bevy's
    /// fixed loop, syncs after it, so `FixedUpdate` and `Update` see the
    /// frame's physics.
    fn default() -> Self {
        CoulombHandsPlugin { schedule: None }
    }
}

impl CoulombHandsPlugin {
    /// The plugin with its three sets chained in `schedule`: `PostUpdate`,
    /// say, for an app whose `Update` systems write the hands that the
    /// frame's steps should see (as avian's `PhysicsPlugins::new` takes the
    /// schedule physics runs in). The steps follow the time that schedule
    /// runs on: in a fixed schedule, its fixed timestep.
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        CoulombHandsPlugin { schedule: Some(schedule.intern()) }
    }
}

/// The plugin's systems in the app's schedule, to order an app's own
/// around them.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HandPhysicsSystems {
    /// Entities linked to the world (new objects and hands, the app's
    /// described objects and hands added), and the app hands' inputs
    /// handed to the world.
    Prepare,
    /// The frame's physics steps: [`clock::HandPhysicsStep`] run once per
    /// world `dt` of the frame's time.
    Step,
    /// Transforms and contacts set from the world.
    Sync,
}

/// The world's step, inside [`clock::HandPhysicsStep`]: a system of that
/// schedule that writes to the world before the step goes `.before(WorldStep)`,
/// one that reads the step's contacts `.after(WorldStep)`.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct WorldStep;

impl Plugin for CoulombHandsPlugin {
    fn build(&self, app: &mut App) {
        // A thousand steps a second: the multi-threaded executor's cost per
        // schedule run would be ten times the physics step's, so the
        // step's own schedule runs on one thread.
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
            .add_observer(objects::remove_object);
        let (prepare, step, sync) =
            (HandPhysicsSystems::Prepare, HandPhysicsSystems::Step, HandPhysicsSystems::Sync);
        let schedule = match self.schedule {
            None => {
                app.configure_sets(
                    RunFixedMainLoop,
                    (
                        (prepare, step)
                            .chain()
                            .in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
                        sync.in_set(RunFixedMainLoopSystems::AfterFixedMainLoop),
                    ),
                );
                RunFixedMainLoop.intern()
            }
            Some(schedule) => {
                app.configure_sets(schedule, (prepare, step, sync).chain());
                schedule
            }
        };
        app.add_systems(
            schedule,
            (
                (link::link_entities, input::push_inputs).chain().in_set(prepare),
                clock::run_steps.in_set(step),
                (entities::sync_transforms, contacts::sync_contacts).in_set(sync),
            ),
        )
        .add_systems(clock::HandPhysicsStep, contacts::step_physics.in_set(WorldStep));
    }
}
