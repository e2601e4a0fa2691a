//! Criterion benchmarks of one interaction step (the book's "Benchmarks"):
//! the bone sweep of `coulomb-hands bench` (6 to 128 bones in contact, 8
//! samples each) and the reference scene with its tower asleep and awake.

use coulomb_hands::InteractionWorld;
use coulomb_hands::run::bench::{
    SWEEP_BONES, WARM_UP, bench_config, held_boxes_scene, keep_awake, sweep_scene,
};
use criterion::{
    BenchmarkGroup, Criterion, criterion_group, criterion_main, measurement::WallTime,
};
use std::hint::black_box;

/// Times `world`'s interaction layer alone and its full step, as `name/…`.
fn both_halves(group: &mut BenchmarkGroup<WallTime>, name: &str, world: &mut InteractionWorld) {
    group.bench_function(format!("{name}/interaction_layer"), |b| {
        b.iter(|| black_box(&mut *world).apply_hand_forces())
    });
    group.bench_function(format!("{name}/full_step"), |b| b.iter(|| black_box(&mut *world).step()));
}

fn bones_in_contact(c: &mut Criterion) {
    let mut group = c.benchmark_group("sweep");
    for bones in SWEEP_BONES {
        let (mut world, _) = sweep_scene(bench_config(), bones / 2).unwrap();
        for _ in 0..WARM_UP {
            world.step();
        }
        both_halves(&mut group, &format!("{bones}_bones"), &mut world);
    }
    group.finish();
}

fn reference_scene(c: &mut Criterion) {
    let mut group = c.benchmark_group("reference_scene");
    for (name, awake) in [("asleep", false), ("awake", true)] {
        let (mut world, _) = held_boxes_scene(bench_config(), 16, true).unwrap();
        if awake {
            keep_awake(&mut world);
        }
        // The first second: the tower settles (and, with sleeping on, falls asleep).
        for _ in 0..1000 {
            world.step();
        }
        both_halves(&mut group, name, &mut world);
    }
    group.finish();
}

criterion_group!(benches, bones_in_contact, reference_scene);
criterion_main!(benches);
