//! The plugin's tick allocates nothing of its own: in grasp-lift's hold,
//! the 48 ticks that a frame of 64 has over a frame of 16 allocate what 48
//! of the core's own steps do (rapier's step and the interaction layer
//! allocate a few times a step; the plugin adds nothing). One test in its
//! own binary: the counting allocator sees every thread of the process.

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands_bevy::prelude::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
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

/// Allocations of one frame of `ticks` physics ticks.
fn frame(app: &mut App, ticks: u64) -> usize {
    let steps = app.world().resource::<HandPhysics>().steps();
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(ticks)));
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    app.update();
    let count = ALLOCATIONS.load(Ordering::Relaxed) - before;
    let ran = app.world().resource::<HandPhysics>().steps() - steps;
    assert_eq!(ran as u64, ticks, "the frame's steps");
    count
}

#[test]
fn a_physics_step_allocates_nothing() {
    let scenario = Scenario::find("grasp-lift").expect("shipped");
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, CoulombHandsPlugin::default()))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(16)))
        .insert_resource(HandPhysics::of_scenario(&scenario).expect("a world"));
    // Into the hold: the hand grips the lifted cube from about 1.6 s on.
    while app.world().resource::<HandPhysics>().steps() < 2000 {
        app.update();
    }
    let (short, long) = (frame(&mut app, 16), frame(&mut app, 64));
    let mut physics = app.world_mut().resource_mut::<HandPhysics>();
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    for _ in 0..48 {
        assert!(physics.step(), "stepped");
    }
    let core = ALLOCATIONS.load(Ordering::Relaxed) - before;
    assert!(long - short <= core, "48 ticks allocate {} times, 48 core steps {core}", long - short);
}
