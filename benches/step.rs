//! Criterion benchmarks of one interaction step (see README "Benchmarks").

use coulomb_hands::InteractionConfig;
use coulomb_hands::run::bench::held_boxes_scene;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn bones_in_contact(c: &mut Criterion) {
    let mut group = c.benchmark_group("two_hands");
    for boxes in [3usize, 8, 16] {
        let bones = 2 * boxes;
        let (mut world, _) = held_boxes_scene(InteractionConfig::default(), boxes, false).unwrap();
        for _ in 0..50 {
            world.step();
        }
        group.bench_function(format!("{bones}_bones/interaction_layer"), |b| {
            b.iter(|| black_box(&mut world).apply_hand_forces())
        });
        group.bench_function(format!("{bones}_bones/full_step"), |b| {
            b.iter(|| black_box(&mut world).step())
        });
    }
    group.finish();
}

fn reference_scene(c: &mut Criterion) {
    let (mut world, _) = held_boxes_scene(InteractionConfig::default(), 16, true).unwrap();
    for _ in 0..50 {
        world.step();
    }
    let mut group = c.benchmark_group("reference_scene");
    group.bench_function("interaction_layer", |b| {
        b.iter(|| black_box(&mut world).apply_hand_forces())
    });
    group.bench_function("full_step", |b| b.iter(|| black_box(&mut world).step()));
    group.finish();
}

criterion_group!(benches, bones_in_contact, reference_scene);
criterion_main!(benches);
