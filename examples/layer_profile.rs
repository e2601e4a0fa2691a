//! Steady workloads for instruction-count profiles (the book's
//! "Benchmarks", under callgrind): the bench's sweep scene with `BONES`
//! bones pressing (default 32), or with `awake` the reference scene with
//! sleeping off, warmed up, then `STEPS` full steps (default 2000).
//!
//! ```sh
//! cargo build --release --example layer_profile
//! valgrind --tool=callgrind --toggle-collect='*apply_hand_forces*' \
//!     target/release/examples/layer_profile 32 2000
//! valgrind --tool=callgrind --toggle-collect='*step_physics*' \
//!     target/release/examples/layer_profile awake 300
//! ```

use coulomb_hands::run::bench::{
    WARM_UP, bench_config, bones_pressing, held_boxes_scene, keep_awake, sweep_scene,
};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let scene = args.next().unwrap_or_else(|| "32".into());
    let steps = args.next().map(|a| a.parse::<usize>()).transpose()?.unwrap_or(2000);
    let mut world = if scene == "awake" {
        let (mut world, _) = held_boxes_scene(bench_config(), 16, true)?;
        keep_awake(&mut world);
        world
    } else {
        sweep_scene(bench_config(), scene.parse::<usize>()? / 2)?.0
    };
    for _ in 0..WARM_UP + steps {
        world.step();
    }
    println!("{scene}: {} bones pressing after {steps} steps", bones_pressing(&world));
    Ok(())
}
