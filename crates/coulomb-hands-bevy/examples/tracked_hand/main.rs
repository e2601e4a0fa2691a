//! README's "In a Bevy app": the cube is an entity, each frame an app system
//! (`push_joints`) writes the joints of a tracked hand, and an observer
//! hears the cube it touches.
mod tracker; // a stand-in for an XR runtime: a real recorded hand, as OpenXR joints

use bevy::prelude::*;
use coulomb_hands::{InteractionConfig, InteractionWorld, ObjectDesc, Side, StaticDesc};
use coulomb_hands_bevy::prelude::*;

fn main() -> Result<AppExit, Box<dyn std::error::Error>> {
    let mut world = InteractionWorld::new(InteractionConfig::default())?;
    world.add_static(&StaticDesc::ground(0.0, 0.5))?;
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, CoulombHandsPlugin::default()));
    app.insert_resource(HandPhysics::new(world));
    let cube = ObjectDesc::cuboid("cube", glam::Vec3::splat(0.04), 0.05, glam::Vec3::ZERO);
    app.world_mut().spawn((ObjectDescription(cube), Transform::from_translation(tracker::CUBE)));
    app.world_mut().spawn(AppHand::new(Side::Right));
    app.add_systems(Update, (push_joints, tracker::exit_when_done));
    app.add_observer(|touch: On<ObjectTouched>, names: Query<&Name>| {
        let name = names.get(touch.entity).map_or("?", Name::as_str);
        println!("{:.3} s: the {} touched the {name}", touch.contact.time, touch.contact.kind);
    });
    Ok(app.run())
}

fn push_joints(time: Res<Time>, mut hands: Query<(&AppHand, &mut HandInput)>) {
    for (hand, mut input) in &mut hands {
        let joints = tracker::openxr_joints(time.elapsed_secs());
        input.set_openxr(hand.side, &joints).unwrap_or_else(|e| warn!("{e}"));
    }
}
