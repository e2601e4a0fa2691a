//! A Bevy plugin for coulomb-hands: tracked hands grasp and push the
//! objects of an interaction world through friction contact forces, in a
//! Bevy app.
//!
//! The app inserts an [`interaction::Interaction`] (a world, its hands'
//! sources and observers) as non-send data and adds
//! [`CoulombHandsPlugin`]. Then, every frame:
//!
//! 1. before the fixed loop, [`entities::spawn_entities`] spawns entities
//!    for new objects and hands, and the fixed timestep is set to the
//!    world's `dt`;
//! 2. each `FixedUpdate` tick runs one physics step through the core's
//!    driver ([`coulomb_hands::run::drive::Driver::step`]), so the physics
//!    rate is the world's, whatever the frame rate, and writes the step's
//!    contact events as [`contacts::ContactBegan`] and
//!    [`contacts::ContactEnded`] messages;
//! 3. after the fixed loop, the objects' and bones' `Transform`s and the
//!    [`contacts::Contacts`] resource are set from the world.
//!
//! The core uses glam 0.33 and Bevy glam 0.32; [`convert`] is the one
//! place where they meet.

pub mod contacts;
pub mod convert;
pub mod entities;
pub mod interaction;
pub mod sources;

use bevy::app::{RunFixedMainLoop, RunFixedMainLoopSystems};
use bevy::ecs::schedule::{ScheduleLabel, SingleThreadedExecutor};
use bevy::prelude::*;
use std::time::Duration;

/// Adds the interaction's systems, messages and resources to an app.
#[derive(Debug, Clone, Copy, Default)]
pub struct CoulombHandsPlugin;

/// The plugin's systems, to order an app's own around them.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InteractionSystems {
    /// Before the fixed loop: entities spawned, the timestep matched.
    Prepare,
    /// In `FixedUpdate`: one physics step, its contact messages written.
    Step,
    /// After the fixed loop: transforms and contacts set from the world.
    Sync,
}

impl Plugin for CoulombHandsPlugin {
    fn build(&self, app: &mut App) {
        // A thousand fixed ticks a second: the multi-threaded executor's cost
        // per schedule run (about 0.05 ms each, five schedules a tick, more
        // with a renderer busy on the other cores) would be ten times the
        // physics step's. The fixed schedules run on one thread instead; an
        // app whose own fixed systems want threads can set theirs back.
        for label in [
            FixedFirst.intern(),
            FixedPreUpdate.intern(),
            FixedUpdate.intern(),
            FixedPostUpdate.intern(),
            FixedLast.intern(),
        ] {
            app.edit_schedule(label, |s| {
                s.set_executor(SingleThreadedExecutor::new());
            });
        }
        app.add_message::<contacts::ContactBegan>()
            .add_message::<contacts::ContactEnded>()
            .init_resource::<contacts::Contacts>()
            .init_resource::<entities::InteractionEntities>()
            .configure_sets(
                RunFixedMainLoop,
                (
                    InteractionSystems::Prepare
                        .in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
                    InteractionSystems::Sync.in_set(RunFixedMainLoopSystems::AfterFixedMainLoop),
                ),
            )
            .add_systems(
                RunFixedMainLoop,
                (match_fixed_timestep, entities::spawn_entities)
                    .in_set(InteractionSystems::Prepare),
            )
            .add_systems(FixedUpdate, contacts::step_interaction.in_set(InteractionSystems::Step))
            .add_systems(
                RunFixedMainLoop,
                (entities::sync_transforms, contacts::sync_contacts)
                    .in_set(InteractionSystems::Sync),
            );
    }
}

/// Sets Bevy's fixed timestep to the world's physics step, so each
/// `FixedUpdate` tick is one step of `dt`.
fn match_fixed_timestep(
    interaction: Option<NonSend<interaction::Interaction>>,
    mut fixed: ResMut<Time<Fixed>>,
) {
    let Some(interaction) = interaction else { return };
    let dt = Duration::from_secs_f64(f64::from(interaction.world().config().dt));
    // Bevy refuses a zero timestep; a world's dt below a nanosecond would
    // round to it, and is left at the last one.
    if fixed.timestep() != dt && !dt.is_zero() {
        fixed.set_timestep(dt);
    }
}
