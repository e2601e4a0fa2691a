//! The plugin's tick allocates nothing of its own: in grasp-lift's hold,
//! between the end of one physics step and the start of the next within a
//! frame (the plugin's step system, its schedule and clock, Bevy's schedule
//! run), no allocation happens. The steps themselves are the core's: rapier
//! and the interaction layer allocate a few times a step, and that is not
//! the plugin's. One test in its own binary: the counting allocator sees
//! every thread of the process.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::pipeline::InteractionWorld;
use coulomb_hands::run::RunError;
use coulomb_hands::run::drive::{Observer, StepView};
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands_bevy::prelude::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

/// The system allocator, counting allocations.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is the system allocator's, with the same arguments.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: the caller's contract is `System`'s.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: the caller's contract is `System`'s.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: the caller's contract is `System`'s.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The allocation count when the last step ended, while `WATCHING`.
static STEP_ENDED: AtomicUsize = AtomicUsize::new(0);
/// Allocations between a step's end and the next step's start.
static BETWEEN: AtomicUsize = AtomicUsize::new(0);
/// Gaps counted.
static GAPS: AtomicUsize = AtomicUsize::new(0);
/// Whether a step of the current frame has ended (the frame's own work,
/// before its first step, is not a tick's).
static WATCHING: AtomicBool = AtomicBool::new(false);

/// Counts, with atomics only (no allocation of its own), what is
/// allocated between two steps.
struct Gaps;

impl Observer for Gaps {
    fn before_step(&mut self, _: &mut InteractionWorld, _: f64) -> Result<(), RunError> {
        if WATCHING.load(Ordering::Relaxed) {
            let now = ALLOCATIONS.load(Ordering::Relaxed);
            BETWEEN.fetch_add(now - STEP_ENDED.load(Ordering::Relaxed), Ordering::Relaxed);
            GAPS.fetch_add(1, Ordering::Relaxed);
        }
        Ok(())
    }

    fn after_step(&mut self, _: &StepView) -> Result<(), RunError> {
        STEP_ENDED.store(ALLOCATIONS.load(Ordering::Relaxed), Ordering::Relaxed);
        WATCHING.store(true, Ordering::Relaxed);
        Ok(())
    }
}

#[test]
fn the_plugin_allocates_nothing_between_two_steps() {
    let scenario = Scenario::find("grasp-lift").expect("shipped");
    let mut physics = HandPhysics::of_scenario(&scenario).expect("a world");
    physics.observe(Gaps);
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, CoulombHandsPlugin::default()))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(16)))
        .insert_resource(physics);
    // Into the hold: the hand grips the lifted cube from about 1.6 s on.
    while app.world().resource::<HandPhysics>().steps() < 2000 {
        app.update();
    }
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(64)));
    BETWEEN.store(0, Ordering::Relaxed);
    GAPS.store(0, Ordering::Relaxed);
    for _ in 0..4 {
        WATCHING.store(false, Ordering::Relaxed);
        app.update();
    }
    // Four frames of 64 steps: 63 gaps each.
    assert_eq!(GAPS.load(Ordering::Relaxed), 4 * 63);
    let between = BETWEEN.load(Ordering::Relaxed);
    assert_eq!(between, 0, "{between} allocations between steps, over {} ticks", 4 * 63);
}
