//! `bench`: step times of the benchmark scene.

use coulomb_hands::InteractionConfig;
use coulomb_hands::run::bench::{held_boxes_scene, time_steps};

pub fn bench(steps: usize, boxes: usize, tower: bool) -> Result<(), String> {
    let (mut world, _) =
        held_boxes_scene(InteractionConfig::default(), boxes, tower).map_err(|e| e.to_string())?;
    let r = time_steps(&mut world, steps);
    println!(
        "scene: 2 hands, {boxes} held boxes, tower: {tower}; {} bones pressing, {} objects",
        r.bones_pressing, r.objects
    );
    println!("interaction layer (contacts + forces): {:8.2} µs/step", r.interaction_layer_us);
    println!("full step (with rapier):               {:8.2} µs/step", r.full_step_us);
    println!("full step in the first second (settling): {:5.2} µs/step", r.settling_us);
    Ok(())
}
