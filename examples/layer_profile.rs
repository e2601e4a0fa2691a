//! Steady workloads for instruction-count profiles (the book's
//! "Benchmarks", under callgrind): the bench's sweep scene with `BONES`
//! bones pressing (default 32); with `awake`, the reference scene with
//! sleeping off; with `objects:N`, the cluttered scene of N objects (its
//! warm-up one second, for the clutter to fall asleep). Warmed up, then
//! `STEPS` full steps (default 2000). With a third argument `host`, the
//! steps run in host mode: a second world of the same scene is the host,
//! giving its states (`set_host_body`) and integrating the wrenches
//! (`host_step`, `integrate_wrenches`).
//!
//! ```sh
//! valgrind --tool=callgrind --toggle-collect='*set_host_body*' \
//!     --toggle-collect='*host_step*' target/release/examples/layer_profile 32 2000 host
//! cargo build --release --example layer_profile
//! valgrind --tool=callgrind --toggle-collect='*apply_hand_forces*' \
//!     target/release/examples/layer_profile 32 2000
//! valgrind --tool=callgrind --toggle-collect='*step_physics*' \
//!     target/release/examples/layer_profile awake 300
//! valgrind --tool=callgrind --toggle-collect='*apply_hand_forces*' \
//!     target/release/examples/layer_profile objects:2000 300
//! ```

use coulomb_hands::run::bench::{
    WARM_UP, bench_config, bones_pressing, cluttered_scene, held_boxes_scene, keep_awake,
    sweep_scene,
};

/// The cluttered scenes' untimed first second, at the bench's 1 ms step.
const ONE_SECOND: usize = 1000;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let scene = args.next().unwrap_or_else(|| "32".into());
    let steps = args.next().map(|a| a.parse::<usize>()).transpose()?.unwrap_or(2000);
    let (mut world, warm_up) = if scene == "awake" {
        let (mut world, _) = held_boxes_scene(bench_config(), 16, true)?;
        keep_awake(&mut world);
        (world, WARM_UP)
    } else if let Some(objects) = scene.strip_prefix("objects:") {
        (cluttered_scene(bench_config(), objects.parse()?)?, ONE_SECOND)
    } else {
        (sweep_scene(bench_config(), scene.parse::<usize>()? / 2)?.0, WARM_UP)
    };
    if args.next().as_deref() == Some("host") {
        let mut host = sweep_scene(bench_config(), scene.parse::<usize>()? / 2)?.0;
        for _ in 0..warm_up + steps {
            for o in 0..host.object_count() {
                let id = coulomb_hands::ObjectId(o as u32);
                let body = &host.physics().bodies[host.object_body(id).ok_or("no body")?];
                world.set_host_body(id, &coulomb_hands::HostBody::of_rapier(body))?;
            }
            host.integrate_wrenches(&world.host_step()?)?;
        }
        println!("{scene} (host mode): {} bones pressing", bones_pressing(&world));
        return Ok(());
    }
    for _ in 0..warm_up + steps {
        world.step();
    }
    println!("{scene}: {} bones pressing after {steps} steps", bones_pressing(&world));
    Ok(())
}
