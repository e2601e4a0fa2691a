//! The bench's scenes measure what they say: every bone a sweep scene is
//! named after presses on a box, every held box stays held while the bench
//! times it, and the reference scene's tower sleeps, or stays awake with
//! sleeping off. Its times are read from the clock it is given.

use crate::position;
use coulomb_hands::InteractionWorld;
use coulomb_hands::run::bench::{
    SWEEP_BONES, WARM_UP, bench_config, bones_pressing, cluttered_scene, held_boxes_scene,
    keep_awake, sweep_scene, time_split_with,
};
use coulomb_hands::run::drive::{Driver, StepView};

/// Runs `steps` steps through the driver, calling `each` after each.
fn steps(world: &mut InteractionWorld, steps: usize, mut each: impl FnMut(&InteractionWorld)) {
    let mut observe = |step: &StepView| {
        each(step.world);
        Ok(())
    };
    Driver::new(world).run(steps, &mut [&mut observe]).expect("no hand sources to fail");
}

/// Asserts that every object named `box…` is within 1 mm of `start`.
#[track_caller]
fn boxes_held(world: &InteractionWorld, start: &[glam::Vec3]) {
    for id in world.object_ids() {
        let name = world.object_name(id).expect("object exists");
        let moved = (position(world, id) - start[id.0 as usize]).length();
        assert!(!name.starts_with("box") || moved < 1e-3, "{name} moved {moved} m");
    }
}

#[test]
fn every_sweep_scene_presses_with_its_bones_and_holds_its_boxes() {
    for bones in SWEEP_BONES {
        let (mut world, hands) = sweep_scene(bench_config(), bones / 2).expect("a valid scene");
        assert_eq!(hands.len(), bones.div_ceil(16), "{bones} bones");
        assert_eq!(world.object_count(), bones / 2);
        let start: Vec<_> = world.object_ids().map(|id| position(&world, id)).collect();
        steps(&mut world, WARM_UP, |_| {});
        // What the bench times: every step presses with every bone.
        steps(&mut world, 300, |world| assert_eq!(bones_pressing(world), bones));
        boxes_held(&world, &start);
    }
}

#[test]
fn the_reference_scene_presses_32_bones_and_its_tower_sleeps_or_stays_awake() {
    for awake in [false, true] {
        let (mut world, _) = held_boxes_scene(bench_config(), 16, true).expect("a valid scene");
        if awake {
            keep_awake(&mut world);
        }
        let start: Vec<_> = world.object_ids().map(|id| position(&world, id)).collect();
        steps(&mut world, 1000 + WARM_UP, |_| {});
        steps(&mut world, 300, |world| assert_eq!(bones_pressing(world), 32));
        boxes_held(&world, &start);
        for id in world.object_ids() {
            let name = world.object_name(id).expect("object exists");
            let state = world.object_state(id).expect("object exists");
            // The tower stands: no block moved more than 2 mm.
            let moved = (state.position - start[id.0 as usize]).length();
            assert!(moved < 2e-3, "{name} moved {moved} m");
            let tower = name.starts_with("block");
            assert_eq!(state.sleeping, tower && !awake, "{name}, sleeping off: {awake}");
        }
    }
}

#[test]
fn a_cluttered_scene_holds_its_boxes_while_its_clutter_rests_asleep() {
    let mut world = cluttered_scene(bench_config(), 340).expect("a valid scene");
    assert_eq!(world.object_count(), 340);
    let start: Vec<_> = world.object_ids().map(|id| position(&world, id)).collect();
    steps(&mut world, 1000, |_| {});
    steps(&mut world, 150, |world| assert_eq!(bones_pressing(world), 32));
    boxes_held(&world, &start);
    for id in world.object_ids() {
        let name = world.object_name(id).expect("object exists");
        if !name.starts_with("clutter") {
            continue;
        }
        let state = world.object_state(id).expect("object exists");
        let moved = (state.position - start[id.0 as usize]).length();
        assert!(
            moved < 2e-3 && state.sleeping,
            "{name} moved {moved} m, asleep {}",
            state.sleeping
        );
    }
}

#[test]
fn the_bench_reads_the_clock_it_is_given() {
    // A clock that moves 1 µs at each reading: the stopwatch reads it before a
    // step, between its halves and after it, so each half takes 1 µs.
    let now = std::cell::Cell::new(std::time::Duration::ZERO);
    let clock = || now.replace(now.get() + std::time::Duration::from_micros(1));
    let mut world = InteractionWorld::new(bench_config()).expect("the bench's config");
    let times = time_split_with(&mut world, 250, &clock, &mut |_| {}).expect("no hands to fail");
    assert_eq!((times.interaction_us, times.rapier_us, times.full_us), (1.0, 1.0, 2.0));
}
