//! Stacks no hand touches, kept awake, stand at the default substeps: the
//! engine's own contacts run `engine_substeps` (2 by default, fewer than
//! rapier's 4), so a scene that is not bundled must not creep apart. With
//! 1 substep, a pyramid's blocks creep sideways 4 mm in 5 s; with 2 or 4,
//! under half a millimetre.

use coulomb_hands::run::bench::keep_awake;
use coulomb_hands::{InteractionConfig, InteractionWorld, ObjectDesc, StaticDesc};
use glam::Vec3;

/// Boxes of `size` (m), their centres and masses (kg).
type Stack = Vec<(Vec3, Vec3, f32)>;

/// The most any box moved sideways and down (m) in `seconds` awake.
fn creep(stack: &Stack, seconds: f32) -> (f32, f32) {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let ids: Vec<_> = stack
        .iter()
        .enumerate()
        .map(|(i, &(size, at, mass))| {
            world.add_object(&ObjectDesc::cuboid(&format!("box {i}"), size, mass, at)).unwrap()
        })
        .collect();
    keep_awake(&mut world);
    for _ in 0..(seconds / world.config().dt).round() as usize {
        world.step();
    }
    let moved = ids.iter().zip(stack).map(|(&id, &(_, at, _))| {
        let state = world.object_state(id).unwrap();
        assert!(!state.sleeping, "kept awake");
        state.position - at
    });
    moved.fold((0.0, 0.0), |(side, down), d| (side.max(d.with_y(0.0).length()), down.max(-d.y)))
}

#[test]
fn a_pyramid_and_a_column_stand_awake_at_the_default_substeps() {
    // 36 blocks of 4 cm and 100 g, each row half a block in from the one below.
    let pyramid: Stack = (0..8)
        .flat_map(|row| {
            (0..8 - row).map(move |k| {
                let x = -0.14 + 0.02 * row as f32 + 0.0401 * k as f32;
                (Vec3::splat(0.04), Vec3::new(x, 0.02 + 0.04 * row as f32, 0.0), 0.1)
            })
        })
        .collect();
    // 30 blocks of 4 cm and 50 g on one another, 1.2 m tall.
    let column: Stack = (0..30)
        .map(|i| (Vec3::splat(0.04), Vec3::new(0.0, 0.02 + 0.04 * i as f32, 0.0), 0.05))
        .collect();
    for (name, stack) in [("pyramid", pyramid), ("column", column)] {
        let (side, down) = creep(&stack, 5.0);
        // Sideways, a millimetre at most. Down, what the contacts' softness
        // (240 Hz) lets the blocks give under the weight above them: 3.9 mm
        // at the column's top, with 4 substeps as with 2.
        assert!(side < 0.001, "{name}: a block crept {:.2} mm sideways", side * 1e3);
        assert!(down < 0.005, "{name}: a block sank {:.2} mm", down * 1e3);
    }
}
