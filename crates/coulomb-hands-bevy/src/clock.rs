//! The physics' own schedule and clock. Each run of the plugin's schedule,
//! the time it runs on (the app's virtual time, or a fixed schedule's
//! timestep) is added to [`Time<HandClock>`], and [`HandPhysicsStep`] runs
//! once per whole world `dt` of it, so the physics rate is the world's
//! whatever the frame rate (as Bevy's fixed loop does, but on a clock of
//! its own: the app's `Time<Fixed>` and its fixed schedules are left as
//! they are).

use crate::physics::HandPhysics;
use bevy::ecs::schedule::ScheduleLabel;
use bevy::prelude::*;
use std::time::Duration;

/// The schedule of one physics step. The plugin's step runs in it, in
/// [`crate::WorldStep`]; an app's system that must see every step (not
/// every frame) goes here too. While it runs, `Time` is the physics clock.
#[derive(ScheduleLabel, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct HandPhysicsStep;

/// The physics clock's context: `Time<HandClock>` has advanced by one world
/// `dt` per step run, and keeps the virtual time not yet stepped.
#[derive(Reflect, Debug, Clone, Copy, Default)]
pub struct HandClock {
    /// Virtual time received and not yet stepped (less than one `dt` after
    /// a frame).
    overstep: Duration,
}

impl HandClock {
    /// Virtual time received and not yet stepped.
    pub fn overstep(&self) -> Duration {
        self.overstep
    }

    /// How many steps of `dt` the next run of the physics takes when it
    /// receives `delta` more: the whole `dt`s in the overstep and `delta`.
    pub(crate) fn steps_in(&self, delta: Duration, dt: Duration) -> u128 {
        (self.overstep + delta).as_nanos().checked_div(dt.as_nanos()).unwrap_or(0)
    }
}

/// Runs [`HandPhysicsStep`] once for each whole world `dt` of time
/// received (`Time`'s delta in the schedule the plugin runs in), with
/// `Time` set to the physics clock meanwhile and put back after.
pub(crate) fn run_steps(world: &mut World) {
    let Some(dt) = world.get_resource::<HandPhysics>().map(HandPhysics::timestep) else {
        return;
    };
    if dt.is_zero() {
        return;
    }
    let outer = *world.resource::<Time>();
    let mut clock = world.resource_mut::<Time<HandClock>>();
    let steps = clock.context().steps_in(outer.delta(), dt);
    clock.context_mut().overstep += outer.delta();
    let _ = world.try_schedule_scope(HandPhysicsStep, |world, schedule| {
        for _ in 0..steps {
            let mut clock = world.resource_mut::<Time<HandClock>>();
            // A step's system may have set the clock back: stop, never wrap.
            let Some(rest) = clock.context().overstep.checked_sub(dt) else { break };
            clock.context_mut().overstep = rest;
            clock.advance_by(dt);
            let generic = clock.as_generic();
            *world.resource_mut::<Time>() = generic;
            schedule.run(world);
        }
    });
    *world.resource_mut::<Time>() = outer;
}
