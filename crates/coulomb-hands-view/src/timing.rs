//! The wall time of the physics steps, for the HUD and the exit summary:
//! each step alone, and each tick of the plugin's clock (the step plus its
//! schedule's run).

use crate::hud::{HudLines, HudSection};
use crate::sets::ViewerSystems;
use bevy::prelude::*;
use coulomb_hands_bevy::prelude::*;
use std::collections::HashSet;
use std::time::Instant;

/// The running means of a step's and a tick's wall time.
#[derive(Resource, Debug, Default)]
pub struct StepTimer {
    tick: Option<(Instant, usize)>,
    frame: Option<(Instant, usize)>,
    /// Mean wall time of one physics step (µs), smoothed over steps.
    pub mean_us: f64,
    /// Mean wall time of one tick of the physics clock (µs), smoothed over
    /// frames.
    pub tick_us: f64,
}

/// A running mean that forgets slowly.
fn smooth(mean: f64, x: f64, weight: f64) -> f64 {
    if mean == 0.0 { x } else { (1.0 - weight) * mean + weight * x }
}

/// In a tick, just before the step.
fn start_step(mut timer: ResMut<StepTimer>, physics: Option<Res<HandPhysics>>) {
    timer.tick = physics.map(|p| (Instant::now(), p.steps()));
}

/// In a tick, just after the step: its time, if it stepped.
fn stop_step(mut timer: ResMut<StepTimer>, physics: Option<Res<HandPhysics>>) {
    let (Some((t0, n0)), Some(p)) = (timer.tick.take(), physics) else { return };
    if p.steps() > n0 {
        timer.mean_us = smooth(timer.mean_us, t0.elapsed().as_secs_f64() * 1e6, 0.01);
    }
}

/// Before the frame's ticks.
fn start_ticks(mut timer: ResMut<StepTimer>, physics: Option<Res<HandPhysics>>) {
    timer.frame = physics.map(|p| (Instant::now(), p.steps()));
}

/// After them: the mean per step this frame joins the running figure.
fn stop_ticks(mut timer: ResMut<StepTimer>, physics: Option<Res<HandPhysics>>) {
    let (Some((t0, n0)), Some(p)) = (timer.frame.take(), physics) else { return };
    let steps = p.steps().saturating_sub(n0);
    if steps > 0 {
        let us = t0.elapsed().as_secs_f64() * 1e6 / steps as f64;
        timer.tick_us = smooth(timer.tick_us, us, 0.1);
    }
}

/// The HUD's line: the step's cost and the bones in contact.
fn hud_line(timer: Res<StepTimer>, physics: Option<Res<HandPhysics>>, mut hud: ResMut<HudLines>) {
    let Some(physics) = physics else { return };
    let world = physics.world();
    let bones: HashSet<_> = world.contacts().iter().map(|c| (c.hand, c.bone)).collect();
    let line = format!(
        "physics step {:.1} us, tick {:.1} us (dt {} ms) | bones in contact {}",
        timer.mean_us,
        timer.tick_us,
        world.config().dt * 1000.0,
        bones.len()
    );
    hud.set(HudSection::Timing, vec![line]);
}

/// The timer's systems, around the plugin's.
#[derive(Debug, Clone, Copy, Default)]
pub struct TimingPlugin;

impl Plugin for TimingPlugin {
    fn build(&self, app: &mut App) {
        use bevy::app::RunFixedMainLoop;
        app.init_resource::<StepTimer>()
            .add_systems(
                HandPhysicsStep,
                (start_step.before(WorldStep), stop_step.after(WorldStep)),
            )
            .add_systems(
                RunFixedMainLoop,
                (
                    start_ticks.before(HandPhysicsSystems::Step).after(HandPhysicsSystems::Prepare),
                    stop_ticks.after(HandPhysicsSystems::Step),
                ),
            )
            .add_systems(Update, hud_line.in_set(ViewerSystems::HudLines));
    }
}
