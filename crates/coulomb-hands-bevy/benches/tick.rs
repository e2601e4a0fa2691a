//! The plugin's cost per physics tick in a headless app: grasp-lift held
//! in its grasp, app frames of 16 ms (a 60 Hz display's), so each frame
//! runs 16 ticks of the plugin's clock. Reported per tick: the step itself
//! and the scheduling around it (Bevy's main schedule per frame included,
//! spread over its ticks).

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands_bevy::prelude::*;
use criterion::{Criterion, criterion_group, criterion_main};
use std::time::Duration;

/// Ticks per frame.
const TICKS: u32 = 16;

fn app() -> App {
    let scenario = Scenario::find("grasp-lift").expect("shipped");
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, CoulombHandsPlugin::default()))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(TICKS.into())))
        .insert_resource(HandPhysics::of_scenario(&scenario).expect("a world"));
    // Into the hold: the hand grips the lifted cube from about 1.6 s on.
    while app.world().resource::<HandPhysics>().steps() < 2000 {
        app.update();
    }
    app
}

fn tick(c: &mut Criterion) {
    let mut app = app();
    let mut group = c.benchmark_group("plugin");
    group.throughput(criterion::Throughput::Elements(TICKS.into()));
    group.bench_function("frame of 16 ticks, grasp-lift held", |b| b.iter(|| app.update()));
    group.finish();
}

criterion_group!(benches, tick);
criterion_main!(benches);
